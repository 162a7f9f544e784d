// Luminaire markers in the 3D view (the scene's luminaires and those the state adds, where the
// state hangs them): a small sphere at each luminaire's photometric centre in
// its light colour (faint when off), a line along its current aim (to the target when it is
// aimed at a point), its name as a label, and the probed point of the last click. Drawn on
// the overlay layer, so they never enter the exposure or false-colour statistics.
import * as THREE from 'three';
import { srgbToLinear } from './colors.js';
import { linearToHex } from './colors.js';
import { effectiveLuminaire, layoutLuminaires } from './luminaire_model.js';
import { clearGroup, sceneDiagonal } from './overlay.js';

export class Markers {
  constructor(viewer, store) {
    this.viewer = viewer;
    this.store = store;
    this.group = new THREE.Group();
    viewer.addOverlay(this.group);
    this.visible = true;
    this.items = [];
    this.probe = null; // {point, text}
    this.selected = -1;
    store.onChange(() => this.update());
  }

  setScene(hello) {
    this.hello = hello;
    this._names = null;
    this.radius = Math.max(0.02, sceneDiagonal(hello) * 0.006);
    this.update();
  }

  // One sphere and aim line per luminaire of the layout, built anew when the names change (a
  // luminaire added or deleted; a reconnect).
  _rebuild(list) {
    clearGroup(this.group);
    this._key = null;
    this.items = list.map((lum) => {
      const sphere = new THREE.Mesh(new THREE.SphereGeometry(this.radius, 16, 8), new THREE.MeshBasicMaterial({ toneMapped: false, transparent: true }));
      const lineGeom = new THREE.BufferGeometry().setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
      const line = new THREE.Line(lineGeom, new THREE.LineBasicMaterial({ toneMapped: false, transparent: true, opacity: 0.8 }));
      this.group.add(sphere, line);
      return { lum, sphere, line };
    });
    this.viewer.addOverlay(this.group);
  }

  // The luminaire whose marker is under canvas point (x, y) (within 12 px), or null.
  hit(x, y) {
    if (!this.visible) return null;
    let best = null, bestD = 12;
    for (const it of this.items) {
      const s = this.screenPosition(it.lum.name);
      if (!s) continue;
      const d = Math.hypot(s.x - x, s.y - y);
      if (d < bestD) [best, bestD] = [it.lum.name, d];
    }
    return best;
  }

  // Luminaire `name`'s marker on the canvas (CSS px), or null behind the camera.
  screenPosition(name) {
    const it = this.items.find((x) => x.lum.name === name);
    if (!it) return null;
    const p = (it.eff ?? effectiveLuminaire(it.lum, this.store.doc.luminaires?.[name])).position;
    const v = new THREE.Vector3(...p).project(this.viewer.camera);
    if (v.z < -1 || v.z > 1) return null;
    return { x: ((v.x + 1) / 2) * this.viewer.width, y: ((1 - v.y) / 2) * this.viewer.height };
  }

  // Follows the state; asks for a render only when a marker looks different (a state
  // change that only dims a luminaire needs none until its frame arrives).
  update() {
    if (!this.hello) return;
    const list = layoutLuminaires(this.hello, this.store.doc);
    const names = list.map((l) => l.name).join('\n');
    if (names !== this._names) {
      this._names = names;
      this._rebuild(list);
    }
    const key = JSON.stringify([this.visible, this.selected, [...(this.selectedNames ?? [])], this.items.map((it) => {
      const e = effectiveLuminaire(it.lum, this.store.doc.luminaires?.[it.lum.name]);
      return [e.on, e.color, e.aim, e.target, e.position];
    })]);
    if (key === this._key) return;
    this._key = key;
    this.group.visible = this.visible;
    this.items.forEach((it, i) => {
      const eff = effectiveLuminaire(it.lum, this.store.doc.luminaires?.[it.lum.name]);
      const hex = linearToHex(eff.color, true);
      const c = new THREE.Color(hex);
      it.sphere.material.color.copy(c);
      it.sphere.material.opacity = eff.on ? 1 : 0.3;
      const selected = i === this.selected || this.selectedNames?.has(it.lum.name);
      it.sphere.scale.setScalar(selected ? 1.6 : 1);
      const p = new THREE.Vector3(...eff.position);
      it.sphere.position.copy(p);
      const end = eff.target ? new THREE.Vector3(...eff.target) : p.clone().addScaledVector(new THREE.Vector3(...eff.aim), 0.6);
      const a = it.line.geometry.attributes.position;
      a.setXYZ(0, p.x, p.y, p.z);
      a.setXYZ(1, end.x, end.y, end.z);
      a.needsUpdate = true;
      it.line.geometry.computeBoundingSphere();
      it.line.material.color.setRGB(...[1, 0.85, 0.2].map(srgbToLinear));
      it.line.material.opacity = eff.on ? 0.85 : 0.3;
      it.eff = eff;
    });
    this.viewer.requestRender();
  }

  drawLabels(layer) {
    if (this.probe) {
      layer.dot(this.probe.point, '#ff3df2', 4);
      layer.label(this.probe.point, this.probe.text, { force: true, dy: 8, background: 'rgba(40,0,40,0.8)' });
    }
    if (!this.visible) return;
    for (const it of this.items) {
      layer.label(it.eff?.position ?? it.lum.position, it.lum.name + (it.eff?.on === false ? ' (off)' : ''), { dy: 6, force: true, color: '#ffe07a' });
    }
  }
}
