// Movable objects (hello.objects, RLOB and the frames' object block; the state's `objects`:
// docs/studio-protocol.md): the Objects panel and the objects in the 3D view.
//
// The panel: one block per object (hello order i) with visible (data-testid object-visible-i),
// the turn about the vertical through its pivot (object-rotate-i, a slider −180…180°; its
// number box object-rotate-i-value) and the move x, y, z in metres from where the scene put it
// (object-x-i, object-y-i, object-z-i), and Reset.
//
// The view: one mesh per object from RLOB (its mesh as the scene places it), coloured by each
// frame's object block with the room's display material, so exposure, false colour and
// metering treat it as the room; placed as the state says (math/placement.h: turned by
// rotate_deg about the vertical through its pivot, then moved by translate) and not drawn when
// hidden. Dragging an object with the left mouse button moves it in the horizontal plane at its
// base: the pointer's ray meets the plane y = the object's current bottom and the state's
// translate follows the pointer (sent at most once per animation frame; the server coalesces,
// and its frames keep coming while the drag goes on); it stops at the room's walls and other
// objects. R turns the object under the pointer, or
// else the selected one, by 15° counter-clockwise seen from above, Shift+R clockwise. A press
// on an object is the object's, not the camera's; a click on it without moving selects it and
// reads the point (the server's pick sees the objects as placed).
import * as THREE from 'three';
import { clearGroup } from './overlay.js';
import { el, numberInput, onValue, row, setIfIdle, sliderNumber } from './ui.js';

const round4 = (x) => Number(x.toFixed(4));
export const TURN_STEP_DEG = 15;
const CLICK_PX = 4; // a press that moves less than this is a click, not a drag
const GAP = 0.001; // m: an object may touch a wall
const LIFT = 0.02; // m: nor does the floor it stands on (or a rug on it) stop it

// An angle in degrees brought to (−180, 180].
export function wrapDegrees(d) {
  const w = ((((d + 180) % 360) + 360) % 360) - 180;
  return w === -180 ? 180 : w;
}

// What an object is under the current state: the scene's placement changed by the entry.
export function effectiveObject(scene, entry = {}) {
  const translate = entry.translate ?? [0, 0, 0];
  return {
    name: scene.name,
    visible: entry.visible ?? true,
    translate,
    rotate: entry.rotate_deg ?? 0,
    position: scene.pivot.map((p, k) => p + translate[k]),
  };
}

// The placement as a matrix (math/placement.h, placed_point): p ↦ pivot + R(p − pivot) +
// translate, R the turn by rotateDeg about +y (counter-clockwise seen from above).
export function placementMatrix(pivot, translate, rotateDeg, out = new THREE.Matrix4()) {
  const a = THREE.MathUtils.degToRad(rotateDeg), c = Math.cos(a), s = Math.sin(a);
  const [px, , pz] = pivot;
  out.set(
    c, 0, s, px - c * px - s * pz + translate[0],
    0, 1, 0, translate[1],
    -s, 0, c, pz + s * px - c * pz + translate[2],
    0, 0, 0, 1,
  );
  return out;
}

// Edits object `name`'s entry with fn(entry), then drops what equals the scene's placement.
function editPlacement(store, name, fn) {
  store.edit(() => {
    const e = store.object(name);
    fn(e);
    if (e.translate && e.translate.every((v) => v === 0)) delete e.translate;
    if (e.rotate_deg === 0) delete e.rotate_deg;
    if (e.visible === true) delete e.visible;
  });
}

const isTyping = (e) => {
  const t = e.target;
  return t && (t.tagName === 'INPUT' || t.tagName === 'SELECT' || t.tagName === 'TEXTAREA' || t.isContentEditable);
};

export class ObjectPanel {
  // view: the ObjectsView (a block clicked selects its object there).
  constructor(container, store, view) {
    this.container = container;
    this.store = store;
    this.view = view;
    this.blocks = [];
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    this.blocks = (hello.objects || []).map((o, i) => this._block(o, i));
    if (!this.blocks.length) this.container.append(el('p', { class: 'hint', text: 'This scene has no movable objects.' }));
    else {
      this.container.append(el('p', {
        class: 'hint',
        text: 'Drag an object in the view to move it across the floor; R turns the object under the pointer (or the selected one) by 15°, Shift+R the other way.',
      }));
    }
    this.refresh();
  }

  entry(name) {
    return this.store.doc.objects?.[name] || {};
  }

  _edit(name, fn) {
    editPlacement(this.store, name, fn);
  }

  _block(o, i) {
    const name = o.name;
    const b = { o, i };
    b.summaryInfo = el('span', { class: 'summary-info' });
    const details = el('details', { class: 'object', open: true, dataset: { object: name, index: String(i) } }, [
      el('summary', { title: `Object "${name}": centred at (${o.pivot.map((x) => x.toFixed(2)).join(', ')}) m, ${(2 * o.size).toFixed(2)} m across, ${o.vertices} vertices, ${o.triangles} triangles` }, [
        el('span', { class: 'lum-name', text: name }),
        b.summaryInfo,
      ]),
    ]);
    details.addEventListener('pointerdown', () => this.view.select(i));
    b.details = details;

    b.visible = el('input', { type: 'checkbox', dataset: { testid: `object-visible-${i}` }, title: 'Show the object (hidden: it neither shows, blocks nor reflects light)' });
    onValue(b.visible, (v) => this._edit(name, (e) => (v ? delete e.visible : (e.visible = false))), (x) => x.checked);
    const reset = el('button', { type: 'button', class: 'small', text: 'Reset', title: "Back where the scene has it (remove it from the state)" });
    reset.addEventListener('click', () => this.store.edit((doc) => delete doc.objects?.[name]));
    details.append(el('div', { class: 'row' }, [el('label', { class: 'check' }, [b.visible, ' visible']), el('span', { class: 'spacer' }), reset]));

    b.rotate = sliderNumber({
      min: -180,
      max: 180,
      step: 1,
      value: 0,
      unit: '°',
      testid: `object-rotate-${i}`,
      title: 'Turn about the vertical through the centre of its bounding box, degrees, counter-clockwise seen from above (R / Shift+R in the view)',
      onChange: (v) => this._edit(name, (e) => (e.rotate_deg = wrapDegrees(v))),
    });
    details.append(row('Turn', b.rotate.element, 'rotate_deg'));

    b.translate = [0, 1, 2].map((k) => numberInput({
      step: 0.05,
      width: '58px',
      testid: `object-${'xyz'[k]}-${i}`,
      title: `Move along ${'xyz'[k]}, m from where the scene put it`,
      onChange: (v) => this._edit(name, (e) => {
        const t = [...(e.translate ?? [0, 0, 0])];
        t[k] = v;
        e.translate = t;
      }),
    }));
    details.append(row('Move', [...b.translate, el('span', { class: 'unit', text: 'm' })], 'translate x, y, z in metres (dragging the object changes x and z)'));
    b.where = el('p', { class: 'hint' });
    details.append(b.where);
    this.container.append(details);
    return b;
  }

  setSelected(i) {
    for (const b of this.blocks) b.details.classList.toggle('selected', b.i === i);
  }

  refresh() {
    if (!this.hello) return;
    for (const b of this.blocks) {
      const eff = effectiveObject(b.o, this.entry(b.o.name));
      setIfIdle(b.visible, eff.visible, 'checked');
      b.rotate.set(eff.rotate);
      b.translate.forEach((input, k) => {
        if (document.activeElement !== input) input.value = String(round4(eff.translate[k]));
      });
      b.summaryInfo.textContent = eff.visible ? `${eff.rotate}°` : 'hidden';
      b.where.textContent = `centre at (${eff.position.map((x) => x.toFixed(2)).join(', ')}) m`;
    }
  }
}

export class ObjectsView {
  // stage: the element holding the viewport canvas (presses on objects are taken there in the
  // capture phase, before the camera controls and the click handling see them). busy(): while
  // true (aiming a luminaire) presses go to the view as usual. click(x, y): a click on an object.
  constructor(viewer, store, stage, { busy = () => false, click = null } = {}) {
    this.viewer = viewer;
    this.store = store;
    this.busy = busy;
    this.click = click;
    this.items = [];
    this.selected = null;
    this.hovered = null;
    this.drag = null;
    this.onSelect = null;
    this.outlines = new THREE.Group();
    viewer.addOverlay(this.outlines);
    this._raycaster = new THREE.Raycaster();
    this._v = new THREE.Vector3();
    store.onChange(() => this.update());
    this._installPointer(stage);
    this._installKeys();
  }

  setScene(hello) {
    this.hello = hello;
    this._clearMeshes();
    this.items = (hello.objects || []).map((o) => ({ o, mesh: null, lighting: null, box: null, outline: null }));
    this.glossy = null;
    this.lastFrameHalfs = null;
    this.selected = null;
    this.hovered = null;
    this.drag = null;
    this.update();
  }

  _clearMeshes() {
    for (const m of [...this.viewer.objects.children]) {
      this.viewer.objects.remove(m);
      m.geometry.dispose(); // the material is the viewer's
    }
    clearGroup(this.outlines);
  }

  // A decoded RLOB: one mesh per object, in hello order.
  setMeshes(decoded) {
    if (!this.hello) throw new Error('RLOB before hello');
    if (decoded.objects.length !== this.items.length) {
      throw new Error(`RLOB has ${decoded.objects.length} objects, hello ${this.items.length}`);
    }
    this._clearMeshes();
    decoded.objects.forEach((g, i) => {
      const it = this.items[i];
      if (g.vertexCount !== it.o.vertices || g.triangleCount !== it.o.triangles) {
        throw new Error(`RLOB object ${i}: ${g.vertexCount} vertices and ${g.triangleCount} triangles, hello ${it.o.vertices} and ${it.o.triangles}`);
      }
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(g.positions), 3));
      it.lighting = new THREE.Float16BufferAttribute(new Uint16Array(4 * g.vertexCount), 4);
      it.lighting.setUsage(THREE.DynamicDrawUsage);
      geometry.setAttribute('lighting', it.lighting);
      geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(g.indices), 1));
      geometry.computeBoundingBox();
      geometry.computeBoundingSphere();
      it.box = geometry.boundingBox.clone();
      it.mesh = new THREE.Mesh(geometry, this.viewer.materials[0]);
      it.mesh.name = it.o.name;
      it.mesh.matrixAutoUpdate = false;
      it.mesh.userData.objectIndex = i;
      this.viewer.objects.add(it.mesh);
      // The selection outline: the object's bounding box as the scene places it, placed with it.
      const size = it.box.getSize(new THREE.Vector3()), centre = it.box.getCenter(new THREE.Vector3());
      const edges = new THREE.EdgesGeometry(new THREE.BoxGeometry(size.x, size.y, size.z)).translate(centre.x, centre.y, centre.z);
      it.outline = new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: 0xffb347, toneMapped: false, transparent: true }));
      it.outline.matrixAutoUpdate = false;
      it.outline.visible = false;
      this.outlines.add(it.outline);
    });
    this.viewer.addOverlay(this.outlines); // the overlay layer for the new outlines
    this.update();
  }

  // The object block of a decoded RLFR (4 half floats per object vertex, hello order).
  setFrame(frame) {
    if (!this.items.length || !this.items[0].lighting) return;
    const total = this.items.reduce((n, it) => n + it.o.vertices, 0);
    if (frame.objectVertexCount !== total) {
      throw new Error(`frame has ${frame.objectVertexCount} object vertices, the objects ${total}`);
    }
    let at = 0;
    for (const it of this.items) {
      const n = 4 * it.o.vertices;
      it.lighting.array.set(frame.objectHalfs.subarray(at, at + n));
      it.lighting.needsUpdate = true;
      at += n;
    }
    this.lastFrameHalfs = frame.objectHalfs;
    this._writeGlossy(false);
  }

  // Glossy object vertices shaded toward the eye (the objects' part of a decoded RLGV, object
  // vertices in hello order): their radiance replaces the frame's now and in the frames that
  // follow, until the next RLGV — as the viewer does for the room's.
  setGlossyView(glossy) {
    const total = this.items.reduce((n, it) => n + it.o.vertices, 0);
    for (const q of glossy.vertices) {
      if (q >= total) throw new Error(`RLGV: object vertex ${q} of ${total}`);
    }
    this._writeGlossy(true); // the last view's vertices go back to the frame's radiance
    this.glossy = glossy;
    this._writeGlossy(false);
    this.viewer.requestRender();
  }

  // Writes the glossy view's radiance into the objects' lighting, or with `restore` the last
  // frame's radiance at the same vertices.
  _writeGlossy(restore) {
    if (!this.glossy || !this.items.length || !this.items[0].lighting) return;
    if (restore && !this.lastFrameHalfs) return;
    const first = [];
    let n = 0;
    for (const it of this.items) {
      first.push(n);
      n += it.o.vertices;
    }
    const { vertices, halfs } = this.glossy;
    let k = 0;
    for (let i = 0; i < vertices.length; i++) {
      const q = vertices[i];
      while (k + 1 < first.length && first[k + 1] <= q) k++; // vertices are ascending
      const it = this.items[k];
      const v = q - first[k];
      for (let c = 0; c < 3; c++) {
        it.lighting.array[4 * v + c] = restore ? this.lastFrameHalfs[4 * q + c] : halfs[3 * i + c];
      }
      it.lighting.needsUpdate = true;
    }
  }

  effective(i) {
    const o = this.items[i].o;
    return effectiveObject(o, this.store.doc.objects?.[o.name]);
  }

  select(i) {
    if (this.selected === i) return;
    this.selected = i;
    this.onSelect?.(i);
    this.update();
  }

  update() {
    if (!this.hello) return;
    const marked = this.drag?.i ?? this.selected;
    this.items.forEach((it, i) => {
      if (!it.mesh) return;
      const eff = this.effective(i);
      placementMatrix(it.o.pivot, eff.translate, eff.rotate, it.mesh.matrix);
      it.mesh.matrixWorldNeedsUpdate = true;
      it.mesh.visible = eff.visible;
      it.mesh.updateMatrixWorld();
      it.outline.matrix.copy(it.mesh.matrix);
      it.outline.matrixWorldNeedsUpdate = true;
      it.outline.visible = i === marked;
      it.outline.material.opacity = eff.visible ? 1 : 0.4;
    });
    this.viewer.requestRender();
  }

  // The object's name (and turn, or "hidden") over the selected or dragged object.
  drawLabels(layer) {
    const i = this.drag?.i ?? this.selected;
    const it = this.items[i];
    if (!it?.box) return;
    const eff = this.effective(i);
    const top = [eff.position[0], it.box.max.y + eff.translate[1], eff.position[2]];
    layer.label(top, `${it.o.name} ${eff.visible ? `${eff.rotate}°` : '(hidden)'}`, { force: true, color: '#ffd9a0' });
  }

  // Where the centre of object i's base (the bottom of its bounding box under its pivot, as
  // placed) is on the canvas (CSS px from its top left); null off screen.
  screenPosition(i) {
    const it = this.items[i];
    if (!it?.box) return null;
    const eff = this.effective(i);
    const v = this._v.set(eff.position[0], it.box.min.y + eff.translate[1], eff.position[2]).project(this.viewer.camera);
    if (v.z < -1 || v.z > 1) return null;
    return { x: ((v.x + 1) / 2) * this.viewer.width, y: ((1 - v.y) / 2) * this.viewer.height };
  }

  // The shown object under canvas point (x, y): {i, distance}, or null. With `room`, null also
  // when a surface of the room is in front of it.
  _hit(x, y, room) {
    const meshes = this.items.filter((it) => it.mesh?.visible).map((it) => it.mesh);
    if (!meshes.length) return null;
    const { origin, direction } = this.viewer.rayAt(x, y);
    this._raycaster.set(new THREE.Vector3(...origin), new THREE.Vector3(...direction));
    const hits = this._raycaster.intersectObjects(meshes, false);
    if (!hits.length) return null;
    const h = hits[0];
    if (room && this.viewer.mesh) {
      const wall = this._raycaster.intersectObject(this.viewer.mesh, false);
      if (wall.length && wall[0].distance < h.distance) return null;
    }
    return { i: h.object.userData.objectIndex, distance: h.distance };
  }

  _installPointer(stage) {
    const canvas = this.viewer.canvas;
    const local = (e) => this.viewer.canvasPoint(e);
    stage.addEventListener('pointerdown', (e) => {
      // (defaultPrevented: an emitter's marker took this press)
      if (e.button !== 0 || e.target !== canvas || this.drag || e.defaultPrevented || this.busy()) return;
      const [x, y] = local(e);
      const hit = this._hit(x, y, true);
      if (!hit) return;
      e.stopPropagation();
      e.preventDefault();
      stage.setPointerCapture(e.pointerId);
      const eff = this.effective(hit.i);
      const bottom = this.items[hit.i].box.min.y + eff.translate[1];
      const grab = this.viewer.onPlane(x, y, bottom);
      this.drag = {
        i: hit.i,
        pointerId: e.pointerId,
        start: [x, y],
        moved: false,
        bottom,
        offset: grab ? [grab[0] - eff.position[0], grab[1] - eff.position[2]] : null,
      };
      canvas.focus();
      stage.classList.add('dragging-object');
      this.select(hit.i);
      this.update();
    }, true);
    stage.addEventListener('pointermove', (e) => {
      if (!this.drag) {
        if (e.target === canvas && e.buttons === 0) {
          const h = this._hit(...local(e), false);
          this.hovered = h ? h.i : null;
          canvas.classList.toggle('over-object', h !== null);
        }
        return;
      }
      if (e.pointerId !== this.drag.pointerId) return;
      e.stopPropagation();
      const [x, y] = local(e);
      if (!this.drag.moved && Math.hypot(x - this.drag.start[0], y - this.drag.start[1]) < CLICK_PX) return;
      this.drag.moved = true;
      this._moveTo(x, y);
    }, true);
    const end = (e) => {
      if (!this.drag || e.pointerId !== this.drag.pointerId) return;
      e.stopPropagation();
      const d = this.drag;
      const [x, y] = local(e);
      if (e.type === 'pointerup' && d.moved) this._moveTo(x, y);
      this.drag = null;
      stage.classList.remove('dragging-object');
      if (stage.hasPointerCapture(e.pointerId)) stage.releasePointerCapture(e.pointerId);
      this.update();
      if (e.type === 'pointerup' && !d.moved) this.click?.(x, y);
    };
    stage.addEventListener('pointerup', end, true);
    stage.addEventListener('pointercancel', end, true);
  }

  _installKeys() {
    window.addEventListener('keydown', (e) => {
      if (isTyping(e) || e.ctrlKey || e.metaKey || e.altKey) return;
      if (e.key === 'Escape') {
        if (!this.drag) this.select(null);
        return;
      }
      if (e.code !== 'KeyR') return;
      const i = this.drag?.i ?? this.hovered ?? this.selected;
      if (i === null || i === undefined || !this.items[i]) return;
      e.preventDefault();
      this.turn(i, e.shiftKey ? -TURN_STEP_DEG : TURN_STEP_DEG);
    });
  }

  // Turns object i by `degrees` (counter-clockwise seen from above) from where it is now.
  turn(i, degrees) {
    const o = this.items[i].o;
    const eff = this.effective(i);
    this.select(i);
    editPlacement(this.store, o.name, (e) => (e.rotate_deg = wrapDegrees(round4(eff.rotate + degrees))));
  }

  // Object i's box at a placement as a world box, lifted LIFT off the floor it stands on and
  // shrunk by GAP on every side, so that standing on the floor or touching a wall is no
  // collision.
  _placedBox(i, translate, rotate) {
    const it = this.items[i];
    const box = it.box.clone().applyMatrix4(placementMatrix(it.o.pivot, translate, rotate, this._m ??= new THREE.Matrix4()));
    box.min.addScalar(GAP);
    box.max.addScalar(-GAP);
    box.min.y += LIFT - GAP;
    return box;
  }

  // Whether object i placed so meets the room's surfaces (window glass included) or another
  // visible object's box. The room's triangles' bounds are kept per geometry.
  _collides(i, translate, rotate) {
    const box = this._placedBox(i, translate, rotate);
    if (box.isEmpty()) return false;
    for (let j = 0; j < this.items.length; j++) {
      if (j === i || !this.items[j].box) continue;
      const e = this.effective(j);
      if (e.visible && box.intersectsBox(this._placedBox(j, e.translate, e.rotate))) return true;
    }
    const g = this.viewer.geometry;
    if (!g) return false;
    if (this._bounds?.geometry !== g) this._bounds = { geometry: g, boxes: triangleBounds(g) };
    const b = this._bounds.boxes, P = g.positions, I = g.indices;
    const tri = (this._tri ??= new THREE.Triangle());
    for (let t = 0; t < g.triangleCount; t++) {
      const k = 6 * t;
      if (b[k] > box.max.x || b[k + 3] < box.min.x || b[k + 1] > box.max.y || b[k + 4] < box.min.y || b[k + 2] > box.max.z || b[k + 5] < box.min.z) continue;
      tri.a.fromArray(P, 3 * I[3 * t]);
      tri.b.fromArray(P, 3 * I[3 * t + 1]);
      tri.c.fromArray(P, 3 * I[3 * t + 2]);
      if (box.intersectsTriangle(tri)) return true;
    }
    return false;
  }

  // Moves the dragged object so that its grabbed point follows canvas point (x, y) in the
  // plane of its base, its centre kept within the scene's bounds. It stops at walls and other
  // objects: when the whole move would collide it goes as far as it can along x, then along z
  // (bisection), so that it slides along a wall; an object already overlapping something moves
  // freely.
  _moveTo(x, y) {
    const d = this.drag;
    if (!d.offset) return;
    const it = this.items[d.i];
    const at = this.viewer.onPlane(x, y, d.bottom);
    if (!at) return;
    const b = this.hello.bounds;
    const clamp = (v, k) => (b ? Math.min(Math.max(v, b.min[k]), b.max[k]) : v);
    const px = clamp(at[0] - d.offset[0], 0), pz = clamp(at[1] - d.offset[1], 2);
    const eff = this.effective(d.i);
    const from = eff.translate;
    const to = [px - it.o.pivot[0], from[1], pz - it.o.pivot[2]];
    const free = (t) => !this._collides(d.i, t, eff.rotate);
    let t = to;
    if (it.box && free(from) && !free(to)) {
      // Along x, then along z, each as far as it is free: a drag into a wall slides along it.
      t = [...from];
      for (const c of [0, 2]) {
        const along = (f) => t.map((v, k) => (k === c ? v + f * (to[c] - v) : v));
        if (free(along(1))) {
          t = along(1);
          continue;
        }
        let lo = 0, hi = 1;
        for (let k = 0; k < 12; k++) {
          const mid = (lo + hi) / 2;
          if (free(along(mid))) lo = mid;
          else hi = mid;
        }
        t = along(lo);
      }
    }
    editPlacement(this.store, it.o.name, (e) => {
      e.translate = t.map(round4);
    });
  }
}

// Per triangle of a decoded RLGE its bounding box (min xyz, max xyz).
function triangleBounds(g) {
  const out = new Float32Array(6 * g.triangleCount);
  const P = g.positions, I = g.indices;
  for (let t = 0; t < g.triangleCount; t++) {
    for (let c = 0; c < 3; c++) {
      const a = P[3 * I[3 * t] + c], b = P[3 * I[3 * t + 1] + c], d = P[3 * I[3 * t + 2] + c];
      out[6 * t + c] = Math.min(a, b, d);
      out[6 * t + 3 + c] = Math.max(a, b, d);
    }
  }
  return out;
}
