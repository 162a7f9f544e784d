// Laying out luminaires in the view (docs/studio.md, "Layout"): placing one from the catalogue
// where it is dropped or clicked (mounted on a ceiling: aimed down; on a wall or any other
// surface: aimed along its normal; 2 cm off the surface), selecting (a click on a marker; a
// luminaire of an array selects its whole group, Alt-click the one), moving the selection by
// dragging a marker along its mounting surface (a ceiling's plane for luminaires aimed up or
// down, else the wall's), turning C0, dimming, duplicating and deleting the selection, arrays
// (rows × columns at a spacing centred on a ceiling point, or a count filling a rectangle picked
// on the ceiling with an edge distance: one group, named GROUP-rRcC), undo and redo (Ctrl+Z,
// Ctrl+Shift+Z / Ctrl+Y), "Save layout" (the lighting state) and "Export scene" (the scene JSON
// with the layout as ordinary luminaires, from the server). Every change is a state edit: an
// added luminaire is a state entry with a position and a distribution (docs/lighting-state.md);
// deleting a luminaire of the scene switches it off.
import { CATALOGUE_TYPE } from './catalogue.js';
import { effectiveLuminaire, groupOf, layoutLuminaires, turnC0 } from './luminaire_model.js';
import { downloadBlob, el, notice, numberInput, row, select, sliderNumber } from './ui.js';

const MOUNT_OFFSET = 0.02; // m between the surface and the photometric centre
const DUPLICATE_STEP = 0.5; // m
const CLICK_PX = 4;
const r4 = (x) => Number(x.toFixed(4));
const add = (a, b) => a.map((v, k) => v + b[k]);
const sub = (a, b) => a.map((v, k) => v - b[k]);
const scale = (a, s) => a.map((v) => v * s);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a) => scale(a, 1 / (Math.hypot(...a) || 1));

// How a luminaire hangs on the surface a pick hit: position 2 cm off it, aim down on a
// ceiling, along the normal elsewhere.
export function mounting(point, normal) {
  const ceiling = normal[1] < -0.7;
  const aim = ceiling ? [0, -1, 0] : norm(normal);
  return { ceiling, position: add(point, scale(normal, MOUNT_OFFSET)).map(r4), aim: aim.map(r4) };
}

// Array positions: rows × cols at spacing (sx along x, sz along z) centred on `centre`.
export function gridPositions(centre, rows, cols, sx, sz) {
  const out = [];
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      out.push({ r, c, p: [centre[0] + (c - (cols - 1) / 2) * sx, centre[1], centre[2] + (r - (rows - 1) / 2) * sz] });
    }
  }
  return out;
}

// `count` positions filling the rectangle between corners a and b (height a's): columns along
// x and rows along z in the rectangle's proportion; `edge` m from its sides (null: half a
// spacing, the uniform layout), row by row.
export function fillPositions(a, b, count, edge) {
  const x0 = Math.min(a[0], b[0]), x1 = Math.max(a[0], b[0]), z0 = Math.min(a[2], b[2]), z1 = Math.max(a[2], b[2]);
  const W = Math.max(x1 - x0, 1e-6), D = Math.max(z1 - z0, 1e-6);
  const cols = Math.max(1, Math.min(count, Math.round(Math.sqrt((count * W) / D))));
  const rows = Math.ceil(count / cols);
  const along = (lo, len, n, k) => {
    if (edge === null || edge === undefined) return lo + ((k + 0.5) * len) / n;
    return n === 1 ? lo + len / 2 : lo + edge + (k * (len - 2 * edge)) / (n - 1);
  };
  const out = [];
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols && out.length < count; c++) out.push({ r, c, p: [along(x0, W, cols, c), a[1], along(z0, D, rows, r)] });
  }
  return out;
}

export class LayoutTools {
  // deps: {viewer, store, markers, catalogue, pick(ray) → Promise<reply>, send(msg) → seq|null,
  //        sceneName() → string}
  constructor(container, stage, deps) {
    Object.assign(this, deps);
    this.container = container;
    this.selected = new Set();
    this.mode = null; // null | {kind: 'place', entry} | {kind: 'grid'|'fill', corners: []}
    this.hello = null;
    this._build();
    this._installPointer(stage);
    this._installDrop(stage);
    this._installKeys();
    this.store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this.selected.clear();
    this.refresh();
  }

  // ---- the panel

  _build() {
    const c = this.container;
    this.undoButton = el('button', { type: 'button', text: '↶ Undo', dataset: { testid: 'undo' }, title: 'Undo the last change (Ctrl+Z)', onclick: () => this.store.undo() });
    this.redoButton = el('button', { type: 'button', text: '↷ Redo', dataset: { testid: 'redo' }, title: 'Redo (Ctrl+Shift+Z or Ctrl+Y)', onclick: () => this.store.redo() });
    const save = el('button', { type: 'button', text: 'Save layout', dataset: { testid: 'save-layout' }, title: 'Download the lighting state (the layout with every other change): relight probe/render/report --state', onclick: () => this.store.save(`${this.sceneName()}-layout.json`) });
    const exportScene = el('button', { type: 'button', text: 'Export scene', dataset: { testid: 'export-scene' }, title: 'Download the scene JSON with this layout as ordinary luminaires, for a new precompute', onclick: () => this.requestExport() });
    c.append(el('div', { class: 'row' }, [this.undoButton, this.redoButton, el('span', { class: 'spacer' }), save, exportScene]));

    this.selectionText = el('span', { class: 'hint', dataset: { testid: 'layout-selection' } });
    this.selectionBox = el('div', { class: 'layout-selection' });
    const b = (text, testid, title, fn) => el('button', { type: 'button', class: 'small', text, dataset: { testid }, title, onclick: fn });
    this.dimmer = sliderNumber({ min: 0, max: 100, step: 0.1, value: 1, numberMax: 1e8, factor: 100, unit: '%', testid: 'layout-dimmer', title: 'Dimmer of every selected luminaire, in % of its photometry', onChange: (v) => this.forSelection((e) => (e.dimmer = v), 'layout-dim') });
    this.selectionBox.append(
      el('div', { class: 'row' }, [this.selectionText]),
      el('div', { class: 'row' }, [
        b('Duplicate', 'duplicate', 'A copy of each selected luminaire 0.5 m along its mounting surface', () => this.duplicate()),
        b('Delete', 'delete', 'Remove the selected luminaires (Delete); a luminaire of the scene is switched off', () => this.deleteSelection()),
        b('C0 −15°', 'c0-minus', 'Turn the photometric C0 plane about the aim', () => this.turnC0(-15)),
        b('C0 +15°', 'c0-plus', 'Turn the photometric C0 plane about the aim', () => this.turnC0(15)),
      ]),
      row('Dimmer', this.dimmer.element, 'Dimmer of the selection'),
    );
    c.append(this.selectionBox);

    // The array tool.
    this.arrayKind = select([['grid', 'rows × columns at a spacing'], ['fill', 'a count in a rectangle']], { testid: 'array-kind', title: 'Grid: centred on the point you click on the ceiling. Fill: click two corners of a rectangle on the ceiling.', onChange: () => this.refresh() });
    const num = (value, testid, title, min = 0) => numberInput({ value, min, step: 'any', testid, title, width: '4.5em', onChange: () => {} });
    this.rows = num(2, 'array-rows', 'Rows (along z)', 1);
    this.cols = num(3, 'array-cols', 'Columns (along x)', 1);
    this.sx = num(1.2, 'array-sx', 'Spacing between columns, m');
    this.sz = num(1.2, 'array-sz', 'Spacing between rows, m');
    this.count = num(6, 'array-count', 'How many luminaires fill the rectangle', 1);
    this.edge = numberInput({ min: 0, step: 'any', testid: 'array-edge', title: 'Distance of the outer luminaires from the rectangle\'s sides, m (empty: half a spacing, a uniform layout)', width: '4.5em', onChange: () => {} });
    this.gridRows = el('div', {}, [row('Grid', [this.rows, '×', this.cols], 'rows × columns'), row('Spacing', [this.sx, this.sz, 'm'], 'along x, along z')]);
    this.fillRows = el('div', {}, [row('Count', this.count, 'luminaires in the rectangle'), row('Edge', [this.edge, 'm'], 'distance from the sides')]);
    this.arrayButton = el('button', { type: 'button', text: 'Place array…', dataset: { testid: 'array-place' }, title: 'Then click the ceiling (grid: its centre; fill: two corners). Uses the catalogue luminaire chosen, else the selected luminaire\'s distribution.', onclick: () => this.startArray() });
    c.append(el('div', { class: 'layout-array' }, [row('Array', this.arrayKind), this.gridRows, this.fillRows, el('div', { class: 'row' }, [this.arrayButton])]));
    this.banner = el('div', { class: 'hint', dataset: { testid: 'layout-banner' } });
    c.append(this.banner);
  }

  refresh() {
    if (!this.hello) return;
    const names = new Set(layoutLuminaires(this.hello, this.store.doc).map((l) => l.name));
    for (const n of [...this.selected]) if (!names.has(n)) this.selected.delete(n);
    this.undoButton.disabled = !this.store.canUndo();
    this.redoButton.disabled = !this.store.canRedo();
    const sel = [...this.selected];
    this.selectionBox.hidden = sel.length === 0;
    this.selectionText.textContent = sel.length ? `Selected: ${sel.length > 4 ? `${sel.slice(0, 4).join(', ')} … (${sel.length})` : sel.join(', ')}` : '';
    if (sel.length) this.dimmer.set(this.effective(sel[0]).dimmer);
    const fill = this.arrayKind.value === 'fill';
    this.gridRows.hidden = fill;
    this.fillRows.hidden = !fill;
    this.markers.selectedNames = this.selected;
    this.markers.update();
    const m = this.mode;
    this.banner.textContent = !m ? '' : m.kind === 'place' ? `Click a ceiling or wall to place “${m.entry.summary.luminaire || m.entry.name}” (Esc cancels)` : m.kind === 'grid' ? 'Click the ceiling where the array is centred (Esc cancels)' : `Click corner ${m.corners.length + 1} of 2 on the ceiling (Esc cancels)`;
  }

  // ---- the state

  lum(name) {
    return layoutLuminaires(this.hello, this.store.doc).find((l) => l.name === name);
  }

  effective(name) {
    return effectiveLuminaire(this.lum(name), this.store.doc.luminaires?.[name]);
  }

  // fn(entry, name, effective) for each selected luminaire, as one undo step per gesture.
  forSelection(fn, gesture = null) {
    if (!this.selected.size) return;
    this.store.edit(() => {
      for (const name of this.selected) {
        const eff = this.effective(name);
        fn(this.store.luminaire(name), name, eff);
      }
    }, gesture);
  }

  freeName(prefix) {
    const taken = new Set(layoutLuminaires(this.hello, this.store.doc).map((l) => l.name));
    for (let n = 1; ; n++) if (!taken.has(`${prefix}${n}`) && ![...taken].some((t) => groupOf(t) === `${prefix}${n}`)) return `${prefix}${n}`;
  }

  // A position kept inside the scene's bounds (the server refuses one outside).
  inside(p) {
    const b = this.hello.bounds;
    if (!b) return p.map(r4);
    return p.map((v, k) => r4(Math.min(Math.max(v, b.min[k] + 1e-3), b.max[k] - 1e-3)));
  }

  select(names, add = false) {
    if (!add) this.selected.clear();
    for (const n of names) this.selected.add(n);
    this.refresh();
  }

  // ---- placing

  setMode(mode) {
    this.mode = mode;
    this.viewer.canvas.classList.toggle('placing', !!mode);
    this.refresh();
  }

  // The distribution a new luminaire gets: the catalogue's armed entry, else the first
  // selected luminaire's.
  distributionToPlace() {
    const e = this.catalogue.armed;
    if (e) return { type: e.type, file: e.file };
    const first = [...this.selected][0];
    return first ? JSON.parse(JSON.stringify(this.effective(first).distribution)) : null;
  }

  async placeAt(x, y, distribution) {
    const reply = await this.pick(this.viewer.rayAt(x, y));
    if (!reply.hit) return notice('Nothing there to mount a luminaire on.', 'error');
    if (reply.portal) return notice('A luminaire cannot hang on a window.', 'error');
    const m = mounting(reply.point, reply.normal);
    const name = this.freeName('L');
    this.store.edit((doc) => {
      doc.luminaires ??= {};
      doc.luminaires[name] = { position: this.inside(m.position), distribution, aim: m.aim };
    }, null);
    this.select([name]);
    notice(`“${name}” placed on the ${m.ceiling ? 'ceiling' : 'surface'} at (${m.position.map((v) => v.toFixed(2)).join(', ')})`);
    return name;
  }

  startArray() {
    if (!this.distributionToPlace()) return notice('Choose a luminaire in the catalogue (or select one) first.', 'error');
    this.setMode({ kind: this.arrayKind.value, corners: [] });
  }

  async arrayClick(x, y) {
    const m = this.mode;
    const reply = await this.pick(this.viewer.rayAt(x, y));
    if (!reply.hit || reply.normal[1] > -0.7) return notice('Click a point on the ceiling.', 'error');
    const point = add(reply.point, scale(reply.normal, MOUNT_OFFSET));
    if (m.kind === 'fill' && m.corners.length === 0) {
      m.corners.push(point);
      return this.refresh();
    }
    const value = (input, fallback) => (input.value === '' ? fallback : Number(input.value));
    const positions = m.kind === 'grid'
      ? gridPositions(point, Math.max(1, Math.round(value(this.rows, 1))), Math.max(1, Math.round(value(this.cols, 1))), value(this.sx, 1), value(this.sz, 1))
      : fillPositions(m.corners[0], [point[0], m.corners[0][1], point[2]], Math.max(1, Math.round(value(this.count, 1))), this.edge.value === '' ? null : Number(this.edge.value));
    const distribution = this.distributionToPlace();
    const group = this.freeName('A');
    const names = positions.map(({ r, c }) => `${group}-r${r + 1}c${c + 1}`);
    this.store.edit((doc) => {
      doc.luminaires ??= {};
      positions.forEach(({ p }, k) => (doc.luminaires[names[k]] = { position: this.inside(p), distribution: JSON.parse(JSON.stringify(distribution)), aim: [0, -1, 0] }));
    }, null);
    this.setMode(null);
    this.catalogue.arm(null);
    this.select(names);
    notice(`Array ${group}: ${names.length} luminaires`);
  }

  // ---- operations on the selection

  duplicate() {
    const copies = [];
    this.store.edit((doc) => {
      for (const name of this.selected) {
        const eff = this.effective(name);
        const step = Math.abs(eff.aim[1]) >= 0.5 ? [DUPLICATE_STEP, 0, 0] : scale(norm([-eff.aim[2], 0, eff.aim[0]]), DUPLICATE_STEP);
        const copy = this.freeName('L');
        const entry = { position: this.inside(add(eff.position, step)), distribution: JSON.parse(JSON.stringify(eff.distribution)), aim: eff.aim.map(r4), c0: eff.c0.map(r4) };
        if (eff.dimmer !== 1) entry.dimmer = eff.dimmer;
        if (!eff.on) entry.on = false;
        const src = doc.luminaires?.[name] ?? {};
        if (src.cct_kelvin !== undefined) entry.cct_kelvin = src.cct_kelvin;
        else entry.color = eff.color.map(r4);
        doc.luminaires ??= {};
        doc.luminaires[copy] = entry;
        copies.push(copy);
      }
    }, null);
    this.select(copies);
  }

  deleteSelection() {
    if (!this.selected.size) return;
    this.store.edit((doc) => {
      for (const name of this.selected) {
        if (this.lum(name)?.added) delete doc.luminaires[name];
        else this.store.luminaire(name).on = false;
      }
    }, null);
    this.selected.clear();
    this.refresh();
  }

  turnC0(deg) {
    this.forSelection((e, name, eff) => (e.c0 = turnC0(eff.c0, eff.aim, deg).map(r4)), 'layout-c0');
  }

  requestExport() {
    this.store.sendNow(false); // the server exports the latest state it received
    if (this.send({ type: 'export_scene' }) === null) notice('Export: not connected', 'error');
  }

  // The server's `scene` reply: the exported scene as a download.
  onExport(msg) {
    this.lastExport = msg.scene;
    downloadBlob(new Blob([JSON.stringify(msg.scene, null, 2) + '\n'], { type: 'application/json' }), `${this.sceneName()}-layout-scene.json`);
  }

  // ---- the view

  // A click in the view while placing; false when no placing mode is on.
  click(x, y) {
    const m = this.mode;
    if (!m) return false;
    const done = (p) => p.catch((e) => notice(`Layout: ${e.message}`, 'error'));
    if (m.kind === 'place') {
      this.setMode(null);
      this.catalogue.arm(null);
      done(this.placeAt(x, y, { type: m.entry.type, file: m.entry.file }));
    } else {
      done(this.arrayClick(x, y));
    }
    return true;
  }

  // Where the pointer's ray meets the luminaire's mounting surface (a horizontal plane through
  // it when aimed up or down, else the vertical plane facing its aim), or null.
  _onMount(x, y, eff) {
    const { origin, direction } = this.viewer.rayAt(x, y);
    const n = Math.abs(eff.aim[1]) >= 0.5 ? [0, 1, 0] : norm([eff.aim[0], 0, eff.aim[2]]);
    const denom = dot(n, direction);
    if (Math.abs(denom) < 1e-6) return null;
    const t = dot(n, sub(eff.position, origin)) / denom;
    return t > 0 ? add(origin, scale(direction, t)) : null;
  }

  _installPointer(stage) {
    const canvas = this.viewer.canvas;
    stage.addEventListener('pointerdown', (e) => {
      if (e.button !== 0 || e.target !== canvas || this.drag || this.mode || !this.hello) return;
      const [x, y] = this.viewer.canvasPoint(e);
      const name = this.markers.hit(x, y);
      if (!name) return;
      e.stopPropagation();
      e.preventDefault();
      stage.setPointerCapture(e.pointerId);
      const group = groupOf(name);
      const names = e.altKey || !group ? [name] : layoutLuminaires(this.hello, this.store.doc).map((l) => l.name).filter((n) => groupOf(n) === group);
      const keep = e.shiftKey || (this.selected.has(name) && names.every((n) => this.selected.has(n)));
      if (!keep) this.select(names);
      else if (e.shiftKey) this.select(names, true);
      const eff = this.effective(name);
      this.drag = {
        pointerId: e.pointerId,
        start: [x, y],
        moved: false,
        key: `layout-move-${performance.now()}`,
        grab: this._onMount(x, y, eff),
        eff,
        from: new Map([...this.selected].map((n) => [n, this.effective(n).position])),
      };
    }, true);
    stage.addEventListener('pointermove', (e) => {
      const d = this.drag;
      if (!d || e.pointerId !== d.pointerId) return;
      e.stopPropagation();
      const [x, y] = this.viewer.canvasPoint(e);
      if (!d.moved && Math.hypot(x - d.start[0], y - d.start[1]) < CLICK_PX) return;
      d.moved = true;
      const at = d.grab && this._onMount(x, y, d.eff);
      if (!at) return;
      const delta = sub(at, d.grab);
      this.store.edit(() => {
        for (const [n, p] of d.from) this.store.luminaire(n).position = this.inside(add(p, delta));
      }, d.key);
    }, true);
    const end = (e) => {
      if (!this.drag || e.pointerId !== this.drag.pointerId) return;
      e.stopPropagation();
      this.drag = null;
      if (stage.hasPointerCapture(e.pointerId)) stage.releasePointerCapture(e.pointerId);
    };
    stage.addEventListener('pointerup', end, true);
    stage.addEventListener('pointercancel', end, true);
  }

  _installDrop(stage) {
    stage.addEventListener('dragover', (e) => {
      if (![...e.dataTransfer.types].includes(CATALOGUE_TYPE)) return;
      e.preventDefault();
      e.dataTransfer.dropEffect = 'copy';
    });
    stage.addEventListener('drop', (e) => {
      const id = e.dataTransfer.getData(CATALOGUE_TYPE);
      const entry = id && this.catalogue.entry(id);
      if (!entry) return;
      e.preventDefault();
      const [x, y] = this.viewer.canvasPoint(e);
      this.placeAt(x, y, { type: entry.type, file: entry.file }).catch((err) => notice(`Layout: ${err.message}`, 'error'));
    });
  }

  _installKeys() {
    window.addEventListener('keydown', (e) => {
      const t = e.target;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT')) return;
      const mod = e.ctrlKey || e.metaKey;
      if (mod && e.code === 'KeyZ') {
        e.preventDefault();
        if (e.shiftKey) this.store.redo();
        else this.store.undo();
      } else if (mod && e.code === 'KeyY') {
        e.preventDefault();
        this.store.redo();
      } else if ((e.key === 'Delete' || e.key === 'Backspace') && this.selected.size) {
        e.preventDefault();
        this.deleteSelection();
      } else if (e.key === 'Escape' && this.mode) {
        this.setMode(null);
        this.catalogue.arm(null);
      }
    });
  }
}
