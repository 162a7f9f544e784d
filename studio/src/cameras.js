// Camera control: the scene's cameras as presets (eye, target, up, vertical fov_deg,
// applied exactly), orbiting with three.js OrbitControls, and a first-person walkthrough
// (the lighting-design paper §4.3: "the user can walk through the scene with an arbitrary
// view point or view reference point"). Every camera change asks the viewer for one render;
// walking animates only while a key is held.
//
// Orbit turns about the room's centre, or about the point last double-clicked: a drag starts
// by moving the orbit's centre along the line of sight to that point's depth, so the view does
// not jump and the eye stays within the room instead of swinging out through a wall; a
// double-click turns the view to the point clicked and orbits about it exactly.
// The plan view looks straight down with the ceilings cut away, an elevation level at a wall
// with the room's near half cut away (showSection).
// Walk keeps the eye at an eye height (1.6 m, editable) above the floor under it, and stops at
// walls: W/A/S/D or the arrow keys move, Q/E lower or raise the eye height, Shift runs,
// dragging looks around. A floor more than a step higher is a wall; one lower is walked down to.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const WALK_SPEED = 1.4; // m/s
const LOOK_SPEED = 0.004; // rad per pixel
export const EYE_HEIGHT = 1.6; // m above the floor (EN 12464-1's standing observer's eye)
const BODY_RADIUS = 0.25; // m kept between the walker's eye or knee and a wall
const KNEE = 0.45; // m above the floor: the lower of the two heights tested against walls
const STEP = 0.35; // m: a floor at most this much higher is walked up onto

export class CameraRig {
  constructor(viewer, onUserMove) {
    this.viewer = viewer;
    this.camera = viewer.camera;
    this.dom = viewer.canvas;
    this.onUserMove = onUserMove; // the user moved the camera away from a preset
    this.mode = 'orbit';
    this.keys = new Set();
    this.controls = null;
    this.eyeHeight = EYE_HEIGHT;
    this.onEyeHeight = null; // called with the eye height when Q/E change it
    this.room = null; // {centre, min, max} from the scene's bounds
    this.pivot = null; // the point last double-clicked, else null: the room's centre
    this.plan = null; // in a plan or elevation: {cut, dir, near, far} (near, far: the perspective's own)
    this._ray = new THREE.Raycaster();
    this._makeControls();
    this._walkLoop = null;
    this._installWalk();
    this._installPivot();
  }

  // The scene's bounds (hello.bounds): the default centre of orbit, and the floor where no
  // surface is under the walker.
  setRoom(bounds) {
    this.pivot = null;
    if (!bounds) {
      this.room = null;
      return;
    }
    const min = new THREE.Vector3(...bounds.min), max = new THREE.Vector3(...bounds.max);
    this.room = { min, max, centre: min.clone().add(max).multiplyScalar(0.5) };
  }

  // The room's surfaces along a ray, nearest first (the room's mesh, as drawn: either side).
  _hits(origin, direction, far = Infinity) {
    const mesh = this.viewer.mesh;
    if (!mesh) return [];
    this._ray.set(origin, direction);
    this._ray.far = far;
    return this._ray.intersectObject(mesh, false);
  }

  _hit(origin, direction, far = Infinity) {
    return this._hits(origin, direction, far)[0] ?? null;
  }

  _within(p, margin) {
    const { min, max } = this.room;
    return p.x > min.x + margin && p.x < max.x - margin && p.y > min.y + margin &&
           p.y < max.y - margin && p.z > min.z + margin && p.z < max.z - margin;
  }

  // While a turn that began inside the room goes on: an eye the turn would carry through a
  // wall, the floor or the ceiling is brought in along its line to the centre, to a hand's
  // breadth inside the room's bounds.
  _keepInside() {
    if (!this._inside) return;
    const margin = 0.1;
    const { min, max } = this._inside;
    const t = this.controls.target, p = this.camera.position;
    let s = 1;
    for (const k of ['x', 'y', 'z']) {
      const d = p[k] - t[k];
      if (p[k] > max[k] - margin && d > 0) s = Math.min(s, (max[k] - margin - t[k]) / d);
      if (p[k] < min[k] + margin && d < 0) s = Math.min(s, (min[k] + margin - t[k]) / d);
    }
    if (s < 1 && s > 0) p.sub(t).multiplyScalar(s).add(t);
  }

  _installPivot() {
    // Capture phase: before OrbitControls reads the press and starts turning.
    this.dom.addEventListener('pointerdown', (e) => {
      if (this.mode !== 'orbit' || e.button !== 0 || !this.controls.enabled || this.plan) return;
      const pivot = this.pivot ?? this.room?.centre;
      if (!pivot) return;
      const dir = new THREE.Vector3();
      this.camera.getWorldDirection(dir);
      // An eye inside the room stays inside while it turns (see keepInside).
      this._inside = this.room && this._within(this.camera.position, 0) ? this.room : null;
      const depth = pivot.clone().sub(this.camera.position).dot(dir);
      if (depth < 0.3) return; // behind or at the eye: keep the centre there is
      this.controls.target.copy(this.camera.position).addScaledVector(dir, depth);
    }, { capture: true });
    this.dom.addEventListener('dblclick', (e) => {
      if (this.mode !== 'orbit' || this.plan) return;
      const [x, y] = this.viewer.canvasPoint(e);
      const { origin, direction } = this.viewer.rayAt(x, y);
      const hit = this._hit(new THREE.Vector3(...origin), new THREE.Vector3(...direction));
      if (!hit) return;
      this.pivot = hit.point.clone();
      this.controls.target.copy(this.pivot);
      this.controls.update();
      this.onUserMove?.();
      this.viewer.requestRender();
    });
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
      this._keepInside();
      this._clipPlan();
      this.viewer.requestRender();
    });
    // A press that did not move the camera (a click to probe or aim) keeps the preset.
    this.controls.addEventListener('start', () => (this._startPose = this._pose()));
    this.controls.addEventListener('end', () => {
      this._inside = null;
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

  // A plan or an elevation: the room seen along `direction` ([x, y, z]: straight down for the
  // plan, level towards a wall for an elevation) from far away, nearly orthographic (a 2° field
  // of view), with everything before the plane through `cut` (a point) across the line of sight
  // left out by the near plane — the ceilings over the plan's cut height, the near half of the
  // room before an elevation's wall — which follows the eye as it zooms. `up`: the picture's
  // up (north, −z, for the plan). Turning is off; drags pan and the wheel zooms.
  showSection(direction, up, cut) {
    if (!this.room) return false;
    const { min, max, centre } = this.room;
    if (!this.plan) this.plan = { near: this.camera.near, far: this.camera.far };
    const dir = new THREE.Vector3(...direction).normalize();
    this.plan.cut = new THREE.Vector3(...cut);
    this.plan.dir = dir;
    if (this.mode !== 'orbit') this.setMode('orbit');
    const half = 0.55 * max.clone().sub(min).length() + 0.3;
    const fov = 2;
    const distance = half / Math.tan(THREE.MathUtils.degToRad(fov / 2));
    // The eye on the line through the room's centre, `distance` before the cut plane.
    const along = this.plan.cut.clone().sub(centre).dot(dir);
    const eye = centre.clone().addScaledVector(dir, along - distance);
    this.applyPreset({ eye: eye.toArray(), target: centre.toArray(), up, fov_deg: fov });
    this.controls.enableRotate = false;
    this.controls.mouseButtons.LEFT = THREE.MOUSE.PAN; // a plan is moved, not turned
    this._clipPlan();
    return true;
  }

  leavePlan() {
    if (!this.plan) return;
    this.camera.near = this.plan.near;
    this.camera.far = this.plan.far;
    this.camera.updateProjectionMatrix();
    this.plan = null;
    this.controls.enableRotate = true;
    this.controls.mouseButtons.LEFT = THREE.MOUSE.ROTATE;
  }

  _clipPlan() {
    if (!this.plan) return;
    const before = this.plan.cut.clone().sub(this.camera.position).dot(this.plan.dir);
    this.camera.near = Math.max(0.01, before);
    this.camera.far = before + this.room.max.clone().sub(this.room.min).length() + 10;
    this.camera.updateProjectionMatrix();
  }

  // The walker's eye height (m above the floor); applied at once in walk mode.
  setEyeHeight(h) {
    this.eyeHeight = Math.min(Math.max(h, 0.3), 3);
    if (this.mode === 'walk') this._standOnFloor();
  }

  // The floor under the eye (the first surface facing up that a ray straight down meets: the
  // back of a ceiling seen from above is passed through), or the scene's lowest point; null
  // with neither.
  _floorUnder(position) {
    const up = this.camera.up;
    const hit = this._hits(position, up.clone().negate()).find((h) => h.face && h.face.normal.dot(up) > 0.5);
    if (hit) return position.dot(up) - hit.distance;
    return this.room ? this.room.min.dot(up) : null;
  }

  // Puts the eye at eye height above the floor under it, keeping where it looks.
  _standOnFloor() {
    const up = this.camera.up;
    const floor = this._floorUnder(this.camera.position);
    if (floor === null) return;
    const lift = floor + this.eyeHeight - this.camera.position.dot(up);
    this.camera.position.addScaledVector(up, lift);
    this.controls.target.addScaledVector(up, lift);
    this.camera.updateMatrixWorld();
    this.viewer.requestRender();
  }

  // Whether a horizontal move `move` from the eye is free: nothing within the body's radius
  // beyond it, at eye and at knee height, and no floor more than a step higher beyond it.
  _free(move) {
    const length = move.length();
    if (length === 0) return true;
    const up = this.camera.up;
    const dir = move.clone().divideScalar(length);
    const eye = this.camera.position;
    const floor = eye.dot(up) - this.eyeHeight;
    const knee = eye.clone().addScaledVector(up, floor + KNEE - eye.dot(up));
    for (const from of [eye, knee]) {
      if (this._hit(from, dir, length + BODY_RADIUS)) return false;
    }
    const ahead = eye.clone().add(move);
    const next = this._floorUnder(ahead);
    return next === null || next <= floor + STEP;
  }

  setMode(mode) {
    if (mode === 'walk') this.leavePlan();
    this.mode = mode;
    this.controls.enabled = mode === 'orbit';
    if (mode === 'walk') this._standOnFloor();
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
      if (k.has('ArrowLeft')) this._look(-300 * dt, 0);
      if (k.has('ArrowRight')) this._look(300 * dt, 0);
      const rise = (k.has('KeyE') ? 1 : 0) - (k.has('KeyQ') ? 1 : 0);
      if (rise) {
        this.setEyeHeight(this.eyeHeight + rise * 0.8 * dt);
        this.onEyeHeight?.(this.eyeHeight);
      }
      if (move.lengthSq() > 0) {
        move.normalize().multiplyScalar(WALK_SPEED * (this.run ? 3 : 1) * dt);
        // Along a wall rather than into it: the whole step, else each of its two parts.
        const parts = [move, new THREE.Vector3().copy(fwd).multiplyScalar(move.dot(fwd)),
                       new THREE.Vector3().copy(right).multiplyScalar(move.dot(right))];
        const free = parts.find((m) => m.lengthSq() > 1e-12 && this._free(m));
        if (free) {
          this.camera.position.add(free);
          this.controls.target.add(free);
          this._standOnFloor();
        }
      }
      this._walkLoop = requestAnimationFrame(step);
    };
    this._walkLoop = requestAnimationFrame(step);
  }
}
