// Camera control: the scene's cameras as presets (eye, target, up, vertical fov_deg,
// applied exactly), orbiting with three.js OrbitControls, and a first-person walkthrough
// (the lighting-design paper §4.3: "the user can walk through the scene with an arbitrary
// view point or view reference point"): W/A/S/D or the arrow keys move, Q/E go down/up,
// Shift runs, dragging with the mouse looks around. Every camera change asks the viewer
// for one render; walking animates only while a key is held.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const WALK_SPEED = 1.4; // m/s
const LOOK_SPEED = 0.004; // rad per pixel

export class CameraRig {
  constructor(viewer, onUserMove) {
    this.viewer = viewer;
    this.camera = viewer.camera;
    this.dom = viewer.canvas;
    this.onUserMove = onUserMove; // the user moved the camera away from a preset
    this.mode = 'orbit';
    this.keys = new Set();
    this.controls = null;
    this._makeControls();
    this._walkLoop = null;
    this._installWalk();
  }

  _makeControls() {
    const target = this.controls ? this.controls.target.clone() : new THREE.Vector3();
    this.controls?.dispose();
    this.controls = new OrbitControls(this.camera, this.dom);
    this.controls.target.copy(target);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.zoomToCursor = true;
    this.controls.enabled = this.mode === 'orbit';
    this.controls.addEventListener('change', () => {
      this.viewer.requestRender();
    });
    // A press that did not move the camera (a click to probe or aim) keeps the preset.
    this.controls.addEventListener('start', () => (this._startPose = this._pose()));
    this.controls.addEventListener('end', () => {
      if (this._startPose && this._startPose !== this._pose()) this.onUserMove?.();
      this._startPose = null;
    });
  }

  _pose() {
    return JSON.stringify([this.camera.position, this.camera.quaternion, this.camera.zoom]);
  }

  // A scene camera {eye, target, up, fov_deg}, exactly.
  applyPreset(cam) {
    const up = new THREE.Vector3(...(cam.up || [0, 1, 0])).normalize();
    const upChanged = !up.equals(this.camera.up);
    this.camera.up.copy(up);
    if (upChanged) this._makeControls();
    this.camera.position.set(...cam.eye);
    this.camera.fov = cam.fov_deg ?? 60;
    this.camera.lookAt(new THREE.Vector3(...cam.target));
    this.camera.updateProjectionMatrix();
    this.camera.updateMatrixWorld();
    this.controls.target.set(...cam.target);
    this.viewer.requestRender();
  }

  // Current camera as a scene-format camera.
  current() {
    const r = (v) => v.toArray().map((x) => Number(x.toFixed(4)));
    return { eye: r(this.camera.position), target: r(this.controls.target), up: r(this.camera.up), fov_deg: this.camera.fov };
  }

  // Frames the scene's bounds from outside the front, for scenes without cameras.
  frameBounds(bounds) {
    const min = new THREE.Vector3(...bounds.min), max = new THREE.Vector3(...bounds.max);
    const centre = min.clone().add(max).multiplyScalar(0.5);
    const size = max.clone().sub(min).length();
    this.applyPreset({ eye: centre.clone().add(new THREE.Vector3(0.2, 0.35, 1).multiplyScalar(size)).toArray(), target: centre.toArray(), fov_deg: 50 });
  }

  setFov(deg) {
    this.camera.fov = deg;
    this.camera.updateProjectionMatrix();
    this.viewer.requestRender();
  }

  setMode(mode) {
    this.mode = mode;
    this.controls.enabled = mode === 'orbit';
    if (mode === 'orbit') {
      // Orbit about a point ahead of the walker.
      const dir = new THREE.Vector3();
      this.camera.getWorldDirection(dir);
      const d = Math.max(0.5, this.camera.position.distanceTo(this.controls.target));
      this.controls.target.copy(this.camera.position).addScaledVector(dir, Math.min(d, 3));
    }
  }

  _installWalk() {
    const isTyping = (e) => {
      const t = e.target;
      return t && (t.tagName === 'INPUT' || t.tagName === 'SELECT' || t.tagName === 'TEXTAREA' || t.isContentEditable);
    };
    const KEYS = ['KeyW', 'KeyA', 'KeyS', 'KeyD', 'KeyQ', 'KeyE', 'ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight'];
    window.addEventListener('keydown', (e) => {
      if (this.mode !== 'walk' || isTyping(e) || !KEYS.includes(e.code)) return;
      e.preventDefault();
      this.keys.add(e.code);
      this.run = e.shiftKey;
      this._startWalk();
    });
    window.addEventListener('keyup', (e) => {
      this.keys.delete(e.code);
      this.run = e.shiftKey;
    });
    window.addEventListener('blur', () => this.keys.clear());
    let last = null;
    this.dom.addEventListener('pointerdown', (e) => {
      if (this.mode !== 'walk' || e.button !== 0) return;
      last = [e.clientX, e.clientY];
      this.dom.setPointerCapture(e.pointerId);
    });
    this.dom.addEventListener('pointermove', (e) => {
      if (this.mode !== 'walk' || !last) return;
      const dx = e.clientX - last[0], dy = e.clientY - last[1];
      last = [e.clientX, e.clientY];
      this._look(dx, dy);
    });
    const end = () => {
      if (last && this.mode === 'walk') this.onUserMove?.();
      last = null;
    };
    this.dom.addEventListener('pointerup', end);
    this.dom.addEventListener('pointercancel', end);
    this.dom.addEventListener(
      'wheel',
      (e) => {
        if (this.mode !== 'walk') return;
        e.preventDefault();
        this.setFov(Math.min(120, Math.max(15, this.camera.fov + Math.sign(e.deltaY) * 3)));
      },
      { passive: false },
    );
  }

  // Turns the view: yaw about the camera's up, pitch about its right (kept off the poles).
  _look(dx, dy) {
    const up = this.camera.up;
    const dir = new THREE.Vector3();
    this.camera.getWorldDirection(dir);
    dir.applyAxisAngle(up, -dx * LOOK_SPEED);
    const right = new THREE.Vector3().crossVectors(dir, up).normalize();
    const pitched = dir.clone().applyAxisAngle(right, -dy * LOOK_SPEED);
    if (Math.abs(pitched.dot(up)) < 0.985) dir.copy(pitched);
    this.camera.lookAt(this.camera.position.clone().add(dir));
    this.controls.target.copy(this.camera.position).add(dir);
    this.viewer.requestRender();
  }

  _startWalk() {
    if (this._walkLoop) return;
    let t0 = performance.now();
    const step = (t) => {
      if (this.keys.size === 0 || this.mode !== 'walk') {
        this._walkLoop = null;
        this.onUserMove?.();
        return;
      }
      const dt = Math.min(0.1, (t - t0) / 1000);
      t0 = t;
      const up = this.camera.up;
      const fwd = new THREE.Vector3();
      this.camera.getWorldDirection(fwd);
      fwd.addScaledVector(up, -fwd.dot(up)).normalize();
      const right = new THREE.Vector3().crossVectors(fwd, up).normalize();
      const move = new THREE.Vector3();
      const k = this.keys;
      if (k.has('KeyW') || k.has('ArrowUp')) move.add(fwd);
      if (k.has('KeyS') || k.has('ArrowDown')) move.sub(fwd);
      if (k.has('KeyD')) move.add(right);
      if (k.has('KeyA')) move.sub(right);
      if (k.has('KeyE')) move.add(up);
      if (k.has('KeyQ')) move.sub(up);
      if (k.has('ArrowLeft')) this._look(-300 * dt, 0);
      if (k.has('ArrowRight')) this._look(300 * dt, 0);
      if (move.lengthSq() > 0) {
        move.normalize().multiplyScalar(WALK_SPEED * (this.run ? 3 : 1) * dt);
        this.camera.position.add(move);
        this.controls.target.add(move);
        this.viewer.requestRender();
      }
      this._walkLoop = requestAnimationFrame(step);
    };
    this._walkLoop = requestAnimationFrame(step);
  }
}
