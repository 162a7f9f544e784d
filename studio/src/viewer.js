// The 3D view: a three.js scene holding the room as one indexed mesh (RLGE) whose vertex
// attribute `lighting` (half floats: radiance RGB, illuminance) is replaced by each RLFR
// frame, drawn with display_shader.js. Renders on demand only (after a frame, a camera
// move or a display change), never in a continuous loop. Before each picture that needs
// it, a small metering pass renders (Y, E) into a float target and reads it back: the
// log-average luminance gives the automatic exposure and the 1st/99th percentiles the
// automatic false-colour range, the same statistics `relight render` takes over its pixels.
// Overlays (luminaire markers, sensor points) live on layer 1, which metering ignores. The
// movable objects (objects.js) are surfaces like the room: their meshes go into `objects`
// (layer 0), drawn with the room's opaque material, so exposure, false colour and metering
// treat them as the room. Window glass (group 1) shows the windows' views (RLWV) per pixel.
import * as THREE from 'three';
import { createDisplayMaterial } from './display_shader.js';
import { autoExposureEv100, exposureScale, resolveScale } from './false_color.js';

const MODE_CODES = { tonemapped: 0, 'false-lux': 1, 'false-luminance': 2 };
const QUANTITY = { 'false-lux': 'lux', 'false-luminance': 'luminance' };
const OVERLAY_LAYER = 1;
const METER_WIDTH = 160;

// Whether WebGL runs in software (SwiftShader, llvmpipe): there multisampling costs more
// than it is worth (a render of the room takes several times longer), so it is left off
// unless the page is opened with ?antialias=1.
function softwareRenderer() {
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    const ext = gl?.getExtension('WEBGL_debug_renderer_info');
    const name = ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : '';
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    return /swiftshader|llvmpipe|softpipe|software/i.test(name);
  } catch {
    return false;
  }
}

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    // preserveDrawingBuffer: screenshots and tests read the canvas after it was shown.
    this.software = softwareRenderer();
    const param = new URLSearchParams(location.search).get('antialias');
    const antialias = param !== null ? param !== '0' : !this.software;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.toneMapping = THREE.NoToneMapping;
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(60, 1, 0.02, 200);
    this.camera.layers.enable(OVERLAY_LAYER);
    this.overlays = new THREE.Group();
    this.scene.add(this.overlays);
    this.objects = new THREE.Group();
    this.scene.add(this.objects);
    this.materials = [createDisplayMaterial(false), createDisplayMaterial(true)];
    this.mesh = null;
    this.lighting = null; // the half-float attribute
    // What the user asked for.
    this.display = {
      mode: 'tonemapped', // 'tonemapped' | 'false-lux' | 'false-luminance'
      ev100: 8,
      autoExposure: true,
      toneCurve: 'relight', // 'relight' | 'aces'
      range: { min: null, max: null, scale: 'auto' }, // null: automatic
      backFaces: 'black', // 'black' (as the CLI) | 'hidden'
    };
    // What the last picture used.
    this.used = { mode: 'tonemapped', quantity: null, ev100: 8, scale: { min: 0, max: 1, logarithmic: false }, scaleError: null };
    this.beforeRender = [];
    this.afterRender = [];
    this.framePending = false;
    this.meter = null;
    this.meterSupported = null;
    this._resize();
    new ResizeObserver(() => {
      this._resize();
      this.requestRender();
    }).observe(canvas.parentElement);
  }

  _resize() {
    const w = Math.max(1, this.canvas.parentElement.clientWidth);
    const h = Math.max(1, this.canvas.parentElement.clientHeight);
    this.renderer.setSize(w, h, true);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  get width() {
    return this.canvas.clientWidth;
  }
  get height() {
    return this.canvas.clientHeight;
  }

  // Builds the mesh from a decoded RLGE; glass (code > 0) is drawn two-sided.
  setGeometry(geom, bounds) {
    if (this.mesh) {
      this.scene.remove(this.mesh);
      this.mesh.geometry.dispose();
    }
    const T = geom.triangleCount;
    const index = new Uint32Array(3 * T);
    let n = 0;
    for (const glass of [false, true]) {
      for (let t = 0; t < T; t++) {
        if ((geom.triangleCodes[t] > 0) !== glass) continue;
        index.set(geom.indices.subarray(3 * t, 3 * t + 3), 3 * n++);
      }
    }
    const opaqueCount = 3 * geom.triangleCodes.reduce((a, c) => a + (c === 0 ? 1 : 0), 0);
    this.opaqueCount = opaqueCount;
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(geom.positions), 3));
    this.lighting = new THREE.Float16BufferAttribute(new Uint16Array(4 * geom.vertexCount), 4);
    this.lighting.setUsage(THREE.DynamicDrawUsage);
    g.setAttribute('lighting', this.lighting);
    // Each glass vertex's portal, for the window views (a vertex two portals share takes one).
    const portal = new Float32Array(geom.vertexCount).fill(-1);
    for (let t = 0; t < T; t++) {
      const code = geom.triangleCodes[t];
      if (code > 0) for (let k = 0; k < 3; k++) portal[geom.indices[3 * t + k]] = code - 1;
    }
    g.setAttribute('portal', new THREE.BufferAttribute(portal, 1));
    this.materials[1].uniforms.uViews.value = false; // until this scene's RLWV
    g.setIndex(new THREE.BufferAttribute(index, 1));
    g.addGroup(0, opaqueCount, 0);
    g.addGroup(opaqueCount, 3 * T - opaqueCount, 1);
    g.computeBoundingSphere();
    this.mesh = new THREE.Mesh(g, this.materials);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    this.geometry = geom;
    if (bounds) {
      const d = Math.hypot(...bounds.max.map((v, i) => v - bounds.min[i])) || 10;
      this.camera.near = Math.max(0.005, d * 0.002);
      this.camera.far = d * 30;
      this.camera.updateProjectionMatrix();
    }
    this.requestRender();
  }

  // Uploads a decoded RLFR's per-vertex half floats.
  setFrame(frame) {
    if (!this.lighting) throw new Error('frame before geometry');
    if (frame.vertexCount !== this.geometry.vertexCount) {
      throw new Error(`frame has ${frame.vertexCount} vertices, geometry ${this.geometry.vertexCount}`);
    }
    this.lighting.array.set(frame.halfs);
    this.lastFrameHalfs = frame.halfs;
    this._applyGlossyView();
    this.lighting.needsUpdate = true;
    this.framePending = true;
    this.requestRender();
  }

  // Glossy vertices shaded toward the eye (a decoded RLGV): their radiance replaces the frame's
  // now and in the frames that follow, until the next RLGV (one follows every frame).
  setGlossyView(glossy) {
    if (!this.lighting) throw new Error('glossy view before geometry');
    for (const v of glossy.vertices) {
      if (v >= this.geometry.vertexCount) throw new Error(`RLGV: vertex ${v} of ${this.geometry.vertexCount}`);
    }
    // Vertices the last view listed and this one does not go back to the frame's radiance.
    if (this.glossy && this.lastFrameHalfs) {
      for (const v of this.glossy.vertices) {
        for (let c = 0; c < 3; c++) this.lighting.array[4 * v + c] = this.lastFrameHalfs[4 * v + c];
      }
    }
    this.glossy = glossy;
    this._applyGlossyView();
    this.lighting.needsUpdate = true;
    this.requestRender();
  }

  _applyGlossyView() {
    if (!this.glossy) return;
    const a = this.lighting.array;
    const { vertices, halfs } = this.glossy;
    for (let i = 0; i < vertices.length; i++) {
      for (let c = 0; c < 3; c++) a[4 * vertices[i] + c] = halfs[3 * i + c];
    }
  }

  // The portal whose glass canvas point (x, y) shows first, or −1 (not glass, or nothing).
  portalAt(x, y) {
    if (!this.mesh) return -1;
    const { origin, direction } = this.rayAt(x, y);
    const ray = new THREE.Raycaster(new THREE.Vector3(...origin), new THREE.Vector3(...direction));
    const hit = ray.intersectObject(this.mesh, false)[0];
    if (!hit || 3 * hit.faceIndex < this.opaqueCount) return -1;
    return this.mesh.geometry.getAttribute('portal').getX(hit.face.a);
  }

  // What the windows show looking out (a decoded RLWV): the glass draws it per pixel from now on.
  setWindowViews(views) {
    const N = views.faceSize, P = views.portals.length;
    if (!P || !N) return;
    const data = new Uint16Array(4 * 6 * N * N * P);
    const ONE = 0x3c00; // 1.0 as a half float
    for (let p = 0; p < P; p++) {
      for (let face = 0; face < 6; face++) {
        for (let j = 0; j < N; j++) {
          for (let i = 0; i < N; i++) {
            const from = 3 * (((p * 6 + face) * N + j) * N + i);
            const to = 4 * ((p * N + j) * 6 * N + face * N + i);
            data[to] = views.halfs[from];
            data[to + 1] = views.halfs[from + 1];
            data[to + 2] = views.halfs[from + 2];
            data[to + 3] = ONE;
          }
        }
      }
    }
    const maps = new THREE.DataArrayTexture(data, 6 * N, N, P);
    maps.type = THREE.HalfFloatType;
    maps.format = THREE.RGBAFormat;
    maps.minFilter = maps.magFilter = THREE.LinearFilter;
    maps.needsUpdate = true;
    const sunData = new Float32Array(8 * P);
    views.portals.forEach((v, p) => {
      sunData.set([...v.sunDirection, v.sunCos, ...v.sunLuminance, 0], 8 * p);
    });
    const suns = new THREE.DataTexture(sunData, 2, P, THREE.RGBAFormat, THREE.FloatType);
    suns.needsUpdate = true;
    const u = this.materials[1].uniforms;
    u.uViewMaps.value?.dispose();
    u.uViewSuns.value?.dispose();
    u.uViewMaps.value = maps;
    u.uViewSuns.value = suns;
    u.uViewFace.value = N;
    u.uViews.value = true;
    this.windowViews = { frame: views.frame, portals: P, faceSize: N };
    this.requestRender();
  }

  addOverlay(object) {
    object.traverse((o) => o.layers.set(OVERLAY_LAYER));
    this.overlays.add(object);
  }

  setDisplay(changes) {
    Object.assign(this.display, changes);
    // The mode (and with it the legend's unit) shows at once; the scale follows the render.
    this.used.mode = this.display.mode;
    this.used.quantity = QUANTITY[this.display.mode] ?? null;
    this.onDisplayChange?.();
    this.requestRender();
  }

  // Schedules one render at the next animation frame (several requests make one render).
  requestRender() {
    if (this._scheduled) return;
    this._scheduled = true;
    requestAnimationFrame(() => {
      this._scheduled = false;
      this.renderNow();
    });
  }

  // A camera ray through the canvas pixel (x, y) in CSS pixels from the top left.
  // Where the ray through canvas point (x, y) meets the horizontal plane at `height`, as
  // [x, z], or null (parallel, or behind the camera): dragging things along the floor.
  onPlane(x, y, height) {
    const { origin, direction } = this.rayAt(x, y);
    if (Math.abs(direction[1]) < 1e-6) return null;
    const t = (height - origin[1]) / direction[1];
    if (!(t > 0)) return null;
    return [origin[0] + t * direction[0], origin[2] + t * direction[2]];
  }

  // A pointer event's position in canvas pixels.
  canvasPoint(e) {
    const r = this.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  rayAt(x, y) {
    const ndc = new THREE.Vector2((x / this.width) * 2 - 1, -(y / this.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    return { origin: ray.ray.origin.toArray(), direction: ray.ray.direction.toArray() };
  }

  // Statistics of the current view: [log-average Y, lit values for the false-colour scale].
  _meterView(quantity) {
    if (this.meterSupported === null) {
      this.meterSupported = this.renderer.capabilities.isWebGL2 && this.renderer.extensions.has('EXT_color_buffer_float');
    }
    if (!this.meterSupported || !this.mesh) return this._meterVertices(quantity);
    const w = Math.min(METER_WIDTH, Math.max(8, this.width));
    const h = Math.max(4, Math.round((w * this.height) / Math.max(1, this.width)));
    if (!this.meter || this.meter.width !== w || this.meter.height !== h) {
      this.meter?.dispose();
      this.meter = new THREE.WebGLRenderTarget(w, h, { type: THREE.FloatType, depthBuffer: true });
      this.meterPixels = new Float32Array(4 * w * h);
    }
    const layers = this.camera.layers.mask;
    this.camera.layers.set(0);
    this.materials.forEach((m) => (m.uniforms.uMode.value = 3));
    const clear = this.renderer.getClearColor(new THREE.Color());
    const clearAlpha = this.renderer.getClearAlpha();
    this.renderer.setClearColor(0x000000, 0);
    this.renderer.setRenderTarget(this.meter);
    this.renderer.clear();
    this.renderer.render(this.scene, this.camera);
    this.renderer.readRenderTargetPixels(this.meter, 0, 0, w, h, this.meterPixels);
    this.renderer.setRenderTarget(null);
    this.renderer.setClearColor(clear, clearAlpha);
    this.camera.layers.mask = layers;
    const px = this.meterPixels;
    let sum = 0, count = 0;
    const values = [];
    for (let i = 0; i < px.length; i += 4) {
      if (px[i + 3] < 0.5) continue;
      const y = px[i];
      if (Number.isFinite(y) && y > 0) {
        sum += Math.log(y);
        count++;
      }
      if (quantity) values.push(quantity === 'lux' ? px[i + 1] : y);
    }
    return { logAverage: count ? Math.exp(sum / count) : null, values };
  }

  // Fallback without float render targets: the same statistics over the vertices (the room's
  // and the shown objects').
  _meterVertices(quantity) {
    if (!this.lighting) return { logAverage: null, values: [] };
    const arrays = [this.lighting.array];
    for (const o of this.objects.children) {
      const l = o.geometry?.getAttribute('lighting');
      if (o.visible && l) arrays.push(l.array);
    }
    let sum = 0, count = 0;
    const values = [];
    for (const a of arrays) {
      for (let v = 0; v < a.length / 4; v++) {
        const L = [0, 1, 2].map((k) => THREE.DataUtils.fromHalfFloat(a[4 * v + k]));
        const y = 0.2126 * L[0] + 0.7152 * L[1] + 0.0722 * L[2];
        if (y > 0) {
          sum += Math.log(y);
          count++;
        }
        if (quantity) values.push(quantity === 'lux' ? THREE.DataUtils.fromHalfFloat(a[4 * v + 3]) : y);
      }
    }
    return { logAverage: count ? Math.exp(sum / count) : null, values };
  }

  renderNow() {
    for (const f of this.beforeRender) f();
    const d = this.display;
    const falseColour = d.mode !== 'tonemapped';
    const quantity = QUANTITY[d.mode] ?? null;
    const autoRange = falseColour && (d.range.min === null || d.range.max === null);
    const needMeter = this.mesh && ((d.autoExposure && !falseColour) || autoRange);
    const meter = needMeter ? this._meterView(autoRange ? quantity : null) : null;
    if (!falseColour) {
      this.used.ev100 = d.autoExposure ? (meter?.logAverage ? autoExposureEv100(meter.logAverage) : this.used.ev100) : d.ev100;
    } else {
      const s = resolveScale(meter?.values || [], d.range);
      if (s.error) {
        this.used.scaleError = s.error;
      } else {
        this.used.scaleError = null;
        this.used.scale = s;
      }
    }
    this.used.mode = d.mode;
    this.used.quantity = quantity;
    const code = MODE_CODES[d.mode] ?? 0;
    for (const m of this.materials) {
      const u = m.uniforms;
      u.uMode.value = code;
      u.uToneCurve.value = d.toneCurve === 'aces' ? 1 : 0;
      u.uExposureScale.value = exposureScale(this.used.ev100);
      u.uMin.value = this.used.scale.min;
      u.uMax.value = this.used.scale.max;
      u.uLog.value = this.used.scale.logarithmic;
    }
    this.materials[0].side = d.backFaces === 'hidden' ? THREE.FrontSide : THREE.DoubleSide;
    this.renderer.setClearColor(
      falseColour ? new THREE.Color().setRGB(128 / 255, 128 / 255, 128 / 255, THREE.SRGBColorSpace) : 0x000000,
      1,
    );
    this.renderer.render(this.scene, this.camera);
    const info = { frameDrawn: this.framePending };
    this.framePending = false;
    for (const f of this.afterRender) f(info);
  }
}
