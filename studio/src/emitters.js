// Near-field emitters (hello.emitters; docs/lighting-state.md, "Emitters"): the Emitters
// panel and the emitters' markers in the 3D view.
//
// The panel: one block per emitter (hello order i) with on/off (data-testid emitter-on-i), a
// luminance slider 0 … 2× the scene's (emitter-luminance-i, in cd/m²; its number box takes
// more), a colour picker (emitter-color-i; a chromaticity, the server scales it to luminance
// 1) with "Scene's colour", and the placement: translate x, y, z in metres from where the
// scene put it and the turn about the vertical through its pivot (rotate_deg).
//
// The markers: a sphere at each emitter's current position (pivot + translate) in its light
// colour (faint when off) with a ring of its size (half the diagonal of its bounding box)
// and its name. Dragging a marker with the left mouse button moves the emitter in the
// horizontal plane at its height: the pointer's ray meets the plane y = pivot.y +
// translate.y, and every move edits the state (sent at most once per animation frame; the
// server coalesces). A press on a marker is the emitter's, not the camera's or a probe.
import * as THREE from 'three';
import { hexToLinear, linearToHex, luminance } from './colors.js';
import { clearGroup, sceneDiagonal } from './overlay.js';
import { el, numberInput, onValue, row, setIfIdle, sliderNumber } from './ui.js';

const round4 = (x) => Number(x.toFixed(4));

// What an emitter is under the current state: the scene's values overridden by the entry.
export function effectiveEmitter(scene, entry = {}) {
  const raw = entry.color ?? scene.color ?? [1, 1, 1];
  const y = luminance(raw);
  const translate = entry.translate ?? [0, 0, 0];
  return {
    name: scene.name,
    on: entry.on ?? true,
    luminance: entry.luminance ?? scene.luminance,
    color: y > 0 ? raw.map((c) => c / y) : [1, 1, 1],
    colorChanged: entry.color !== undefined,
    translate,
    rotate: entry.rotate_deg ?? 0,
    position: scene.pivot.map((p, k) => p + translate[k]),
  };
}

// A step of about a hundredth of `range`, rounded to 1, 2 or 5 times a power of ten.
function niceStep(range) {
  if (!(range > 0)) return 1;
  const raw = range / 100;
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
}

export class EmitterPanel {
  constructor(container, store) {
    this.container = container;
    this.store = store;
    this.blocks = [];
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    this.blocks = (hello.emitters || []).map((e, i) => this._block(e, i));
    if (!this.blocks.length) this.container.append(el('p', { class: 'hint', text: 'This scene has no near-field emitters.' }));
    else this.container.append(el('p', { class: 'hint', text: 'Drag an emitter’s marker in the view to move it at its height.' }));
    this.refresh();
  }

  entry(name) {
    return this.store.doc.emitters?.[name] || {};
  }

  _edit(name, fn) {
    this.store.edit(() => fn(this.store.emitter(name)));
  }

  _block(em, i) {
    const name = em.name;
    const b = { em, i };
    b.swatch = el('span', { class: 'swatch' });
    b.summaryInfo = el('span', { class: 'summary-info' });
    const details = el('details', { class: 'emitter', open: true, dataset: { emitter: name, index: String(i) } }, [
      el('summary', { title: `Emitter "${name}": ${em.luminance} cd/m², centred at (${em.pivot.map((x) => x.toFixed(2)).join(', ')}) m, ${(2 * em.size).toFixed(2)} m across` }, [
        b.swatch,
        el('span', { class: 'lum-name', text: name }),
        b.summaryInfo,
      ]),
    ]);

    b.on = el('input', { type: 'checkbox', dataset: { testid: `emitter-on-${i}` }, title: 'Switch the emitter on or off (off keeps its other settings)' });
    onValue(b.on, (v) => this._edit(name, (e) => (v ? delete e.on : (e.on = false))), (x) => x.checked);
    const reset = el('button', { type: 'button', class: 'small', text: 'Reset', title: "Back to the scene's settings and place for this emitter (remove it from the state)" });
    reset.addEventListener('click', () => this.store.edit((doc) => delete doc.emitters?.[name]));
    details.append(el('div', { class: 'row' }, [el('label', { class: 'check' }, [b.on, ' on']), el('span', { class: 'spacer' }), reset]));

    const max = 2 * em.luminance;
    b.luminance = sliderNumber({
      min: 0,
      max,
      step: niceStep(max),
      numberMax: 1e12,
      value: em.luminance,
      unit: 'cd/m²',
      testid: `emitter-luminance-${i}`,
      title: `Luminance of the emitting surface, cd/m² (the scene's: ${em.luminance}; the slider goes to twice that, the number box takes more)`,
      onChange: (v) => this._edit(name, (e) => (e.luminance = v)),
    });
    details.append(row('Luminance', b.luminance.element, 'Luminance of the emitting surface, cd/m²'));

    b.colorPicker = el('input', { type: 'color', dataset: { testid: `emitter-color-${i}` }, title: 'Light colour (only its chromaticity counts: it is scaled to luminance 1)' });
    onValue(b.colorPicker, (hex) => this._edit(name, (e) => (e.color = hexToLinear(hex).map(round4))));
    const sceneColor = el('button', { type: 'button', class: 'small', text: "Scene's colour", title: "Back to the scene's colour" });
    sceneColor.addEventListener('click', () => this._edit(name, (e) => delete e.color));
    details.append(row('Colour', [b.colorPicker, sceneColor], 'Light colour'));

    // Placement: translate (m, from where the scene put it) and the turn about the vertical.
    b.translate = [0, 1, 2].map((k) => numberInput({
      step: 0.05,
      width: '58px',
      testid: `emitter-translate-${'xyz'[k]}-${i}`,
      title: `Move along ${'xyz'[k]}, m from where the scene put it`,
      onChange: (v) => this._edit(name, (e) => {
        const t = [...(e.translate ?? [0, 0, 0])];
        t[k] = v;
        if (t.every((x) => x === 0)) delete e.translate;
        else e.translate = t;
      }),
    }));
    details.append(row('Move', [...b.translate, el('span', { class: 'unit', text: 'm' })], 'translate x, y, z in metres (dragging the marker changes x and z)'));
    b.rotate = numberInput({
      step: 5,
      unit: '°',
      testid: `emitter-rotate-${i}`,
      title: 'Turn about the vertical through the centre of its bounding box, degrees, counter-clockwise seen from above',
      onChange: (v) => this._edit(name, (e) => (v === 0 ? delete e.rotate_deg : (e.rotate_deg = v))),
    });
    b.where = el('span', { class: 'hint' });
    details.append(row('Turn', [b.rotate, b.where], 'rotate_deg'));
    this.container.append(details);
    return b;
  }

  refresh() {
    if (!this.hello) return;
    for (const b of this.blocks) {
      const eff = effectiveEmitter(b.em, this.entry(b.em.name));
      setIfIdle(b.on, eff.on, 'checked');
      b.luminance.set(eff.luminance);
      const hex = linearToHex(eff.color, true);
      if (document.activeElement !== b.colorPicker) b.colorPicker.value = hex;
      b.swatch.style.background = hex;
      b.swatch.style.opacity = eff.on ? 1 : 0.25;
      b.summaryInfo.textContent = eff.on ? `${Number(eff.luminance.toPrecision(4))} cd/m²` : 'off';
      b.translate.forEach((input, k) => {
        if (document.activeElement !== input) input.value = String(round4(eff.translate[k]));
      });
      if (document.activeElement !== b.rotate.input) b.rotate.input.value = String(eff.rotate);
      b.where.textContent = `at (${eff.position.map((x) => x.toFixed(2)).join(', ')}) m`;
    }
  }
}

export class EmitterMarkers {
  // stage: the element holding the viewport canvas (pointer events are taken there, in the
  // capture phase, before the camera controls and the click handling see them).
  constructor(viewer, store, stage) {
    this.viewer = viewer;
    this.store = store;
    this.group = new THREE.Group();
    viewer.addOverlay(this.group);
    this.visible = true;
    this.items = [];
    this.drag = null;
    this._v = new THREE.Vector3();
    store.onChange(() => this.update());
    this._installDrag(stage);
  }

  setScene(hello) {
    this.hello = hello;
    this.drag = null;
    clearGroup(this.group);
    this._key = null;
    const small = Math.max(0.02, sceneDiagonal(hello) * 0.009);
    this.items = (hello.emitters || []).map((em) => {
      const radius = Math.min(Math.max(small, 0.3 * em.size), 3 * small);
      const sphere = new THREE.Mesh(new THREE.SphereGeometry(radius, 20, 10), new THREE.MeshBasicMaterial({ toneMapped: false, transparent: true }));
      const ringPoints = [];
      for (let k = 0; k <= 48; k++) {
        const a = (2 * Math.PI * k) / 48;
        ringPoints.push(new THREE.Vector3(Math.cos(a) * em.size, 0, Math.sin(a) * em.size));
      }
      const ring = new THREE.Line(new THREE.BufferGeometry().setFromPoints(ringPoints), new THREE.LineBasicMaterial({ toneMapped: false, transparent: true }));
      const group = new THREE.Group();
      group.add(sphere, ring);
      this.group.add(group);
      return { em, group, sphere, ring, radius };
    });
    this.viewer.addOverlay(this.group); // sets the overlay layer on the new objects
    this.update();
  }

  effective(i) {
    const em = this.items[i].em;
    return effectiveEmitter(em, this.store.doc.emitters?.[em.name]);
  }

  update() {
    if (!this.hello) return;
    const key = JSON.stringify([this.visible, this.drag?.i, this.items.map((_, i) => {
      const e = this.effective(i);
      return [e.on, e.color, e.position];
    })]);
    if (key === this._key) return;
    this._key = key;
    this.group.visible = this.visible;
    this.items.forEach((it, i) => {
      const eff = this.effective(i);
      it.eff = eff;
      it.group.position.set(...eff.position);
      const c = new THREE.Color(linearToHex(eff.color, true));
      it.sphere.material.color.copy(c);
      it.sphere.material.opacity = eff.on ? 1 : 0.3;
      it.sphere.scale.setScalar(this.drag?.i === i ? 1.3 : 1);
      it.ring.material.color.copy(c);
      it.ring.material.opacity = eff.on ? 0.8 : 0.3;
    });
    this.viewer.requestRender();
  }

  drawLabels(layer) {
    if (!this.visible) return;
    for (const it of this.items) {
      if (!it.eff) continue;
      layer.label(it.eff.position, it.em.name + (it.eff.on ? '' : ' (off)'), { dy: 8, force: true, color: '#9fe8ff' });
    }
  }

  // Where emitter i's marker is on the canvas (CSS px from its top left), null off screen.
  screenPosition(i) {
    const it = this.items[i];
    if (!it) return null;
    const v = this._v.set(...this.effective(i).position).project(this.viewer.camera);
    if (v.z < -1 || v.z > 1) return null;
    return { x: ((v.x + 1) / 2) * this.viewer.width, y: ((1 - v.y) / 2) * this.viewer.height };
  }

  // The marker under canvas point (x, y): the nearest within its drawn radius (at least 10 px).
  _hit(x, y) {
    if (!this.visible || !this.hello) return -1;
    const cam = this.viewer.camera;
    const pxPerRad = this.viewer.height / (2 * Math.tan(THREE.MathUtils.degToRad(cam.fov) / 2));
    let best = -1, bestD = Infinity;
    this.items.forEach((it, i) => {
      const s = this.screenPosition(i);
      if (!s) return;
      const dist = cam.position.distanceTo(this._v.set(...this.effective(i).position));
      const r = Math.max(10, (it.radius / Math.max(dist, 1e-6)) * pxPerRad + 4);
      const d = Math.hypot(s.x - x, s.y - y);
      if (d <= r && d < bestD) {
        best = i;
        bestD = d;
      }
    });
    return best;
  }

  _installDrag(stage) {
    const canvas = this.viewer.canvas;
    const local = (e) => this.viewer.canvasPoint(e);
    stage.addEventListener('pointerdown', (e) => {
      if (e.button !== 0 || e.target !== canvas || this.drag) return;
      const [x, y] = local(e);
      const i = this._hit(x, y);
      if (i < 0) return;
      const eff = this.effective(i);
      const grab = this.viewer.onPlane(x, y, eff.position[1]);
      if (!grab) return;
      e.stopPropagation();
      e.preventDefault();
      stage.setPointerCapture(e.pointerId);
      this.drag = { i, pointerId: e.pointerId, offset: [grab[0] - eff.position[0], grab[1] - eff.position[2]] };
      stage.classList.add('dragging-emitter');
      this.update();
    }, true);
    stage.addEventListener('pointermove', (e) => {
      if (!this.drag) {
        if (e.target === canvas && e.buttons === 0) {
          const [x, y] = local(e);
          canvas.classList.toggle('over-emitter', this._hit(x, y) >= 0);
        }
        return;
      }
      if (e.pointerId !== this.drag.pointerId) return;
      e.stopPropagation();
      this._moveTo(...local(e));
    }, true);
    const end = (e) => {
      if (!this.drag || e.pointerId !== this.drag.pointerId) return;
      e.stopPropagation();
      if (e.type === 'pointerup') this._moveTo(...local(e));
      this.drag = null;
      stage.classList.remove('dragging-emitter');
      if (stage.hasPointerCapture(e.pointerId)) stage.releasePointerCapture(e.pointerId);
      this.update();
    };
    stage.addEventListener('pointerup', end, true);
    stage.addEventListener('pointercancel', end, true);
  }

  // Moves the dragged emitter so that its grabbed point follows canvas point (x, y), within
  // the scene's bounds widened by the emitter's size.
  _moveTo(x, y) {
    const d = this.drag;
    const it = this.items[d.i];
    const eff = this.effective(d.i);
    const at = this.viewer.onPlane(x, y, eff.position[1]);
    if (!at) return;
    const b = this.hello.bounds;
    const clamp = (v, k) => (b ? Math.min(Math.max(v, b.min[k] - it.em.size), b.max[k] + it.em.size) : v);
    const px = clamp(at[0] - d.offset[0], 0), pz = clamp(at[1] - d.offset[1], 2);
    const translate = [round4(px - it.em.pivot[0]), round4(eff.translate[1]), round4(pz - it.em.pivot[2])];
    this.store.edit(() => {
      const e = this.store.emitter(it.em.name);
      if (translate.every((v) => v === 0)) delete e.translate;
      else e.translate = translate;
    });
  }
}
