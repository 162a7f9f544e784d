// The View panel: camera presets (#camera-preset: the scene's cameras by name, "orbit" for a
// free camera, and "plan view": straight down in false colour, with the sensor grids'
// isolines and readings), navigation (orbit or walk; walk's eye height), field of view, the display mode
// (#view-mode: tonemapped, false-lux, false-luminance), exposure in EV100 (#exposure) with
// automatic exposure (#auto-exposure), the tone curve, the false-colour range and scale,
// back faces, luminaire markers, a PNG screenshot and the current camera as scene JSON.
import { screenshot } from './screenshot.js';

const $ = (id) => document.getElementById(id);

// The camera list's entries for the plan view and the elevations, after the scene's cameras:
// an elevation looks at its wall from the room's centre (north is −z, as the site's north_deg
// counts from).
const PLAN = 'plan view';
const ELEVATIONS = {
  'north elevation': [0, 0, -1],
  'east elevation': [1, 0, 0],
  'south elevation': [0, 0, 1],
  'west elevation': [-1, 0, 0],
};

export class ViewPanel {
  constructor(viewer, rig, markers, labelsCanvas) {
    this.viewer = viewer;
    this.rig = rig;
    this.cameras = [];
    const preset = $('camera-preset');
    preset.addEventListener('change', () => this.applyPreset(preset.value));

    $('nav-mode').addEventListener('change', (e) => {
      if (e.target.value === 'walk' && rig.plan) this.applyPreset('orbit');
      rig.setMode(e.target.value);
      $('nav-hint').textContent = e.target.value === 'walk'
        ? 'Walk at eye height: W A S D or arrows move (walls stop you), Q / E lower / raise the eye, Shift runs, drag to look, wheel changes the field of view. Click a surface to read its lux and cd/m²; Esc clears.'
        : 'Orbit about the room\'s centre (double-click a surface to orbit about it): drag to turn, right-drag to pan, wheel to zoom. Click a surface to read its illuminance and luminance; Esc clears.';
      viewer.canvas.focus();
    });
    const eye = $('eye-height');
    eye.addEventListener('change', () => {
      const h = Number(eye.value);
      if (eye.value !== '' && h >= 0.3 && h <= 3) rig.setEyeHeight(h);
    });
    rig.onEyeHeight = (h) => {
      if (document.activeElement !== eye) eye.value = h.toFixed(2);
    };

    const fov = $('fov');
    fov.addEventListener('input', () => {
      rig.setFov(Number(fov.value));
      this.markFree();
    });

    const mode = $('view-mode');
    const onMode = () => {
      viewer.setDisplay({ mode: mode.value });
      this._modeControls();
    };
    mode.addEventListener('change', onMode);
    mode.addEventListener('input', onMode);

    const exposure = $('exposure');
    const auto = $('auto-exposure');
    const onExposure = () => {
      auto.checked = false;
      viewer.setDisplay({ ev100: Number(exposure.value), autoExposure: false });
      this.showExposure(Number(exposure.value));
    };
    exposure.addEventListener('input', onExposure);
    exposure.addEventListener('change', onExposure);
    auto.addEventListener('change', () => {
      viewer.setDisplay({ autoExposure: auto.checked, ev100: Number(exposure.value) });
    });
    $('tone-curve').addEventListener('change', (e) => viewer.setDisplay({ toneCurve: e.target.value }));

    const range = () => {
      const v = (id) => ($(id).value === '' ? null : Number($(id).value));
      viewer.setDisplay({ range: { min: v('fc-min'), max: v('fc-max'), scale: $('fc-scale').value } });
    };
    for (const id of ['fc-min', 'fc-max', 'fc-scale']) $(id).addEventListener('change', range);

    $('back-faces').addEventListener('change', (e) => viewer.setDisplay({ backFaces: e.target.value }));
    $('show-luminaires').addEventListener('change', (e) => {
      markers.visible = e.target.checked;
      markers.update();
    });
    $('screenshot').addEventListener('click', () => {
      const cam = preset.value === 'orbit' ? 'view' : preset.value;
      const name = `relight-${cam.replace(/[^\w.-]+/g, '_')}-${viewer.used.mode}.png`;
      screenshot(viewer, labelsCanvas, name);
    });
    $('copy-camera').addEventListener('click', () => {
      const out = $('camera-json');
      out.hidden = false;
      out.value = JSON.stringify({ name: 'my view', ...rig.current() });
      out.select();
    });
    viewer.afterRender.push(() => this.afterRender());
    this._modeControls();
  }

  setCameras(cameras, keepView) {
    this.cameras = cameras || [];
    const preset = $('camera-preset');
    preset.innerHTML = '';
    for (const c of this.cameras) {
      const o = document.createElement('option');
      o.value = c.name;
      o.textContent = c.name;
      o.title = `eye (${c.eye.join(', ')}), target (${c.target.join(', ')}), ${c.fov_deg ?? 60}°`;
      preset.append(o);
    }
    const free = document.createElement('option');
    free.value = 'orbit';
    free.textContent = 'orbit (free camera)';
    preset.append(free);
    for (const [value, text, title] of [
      [PLAN, 'plan (from above, false colour, isolines)', 'Straight down, north up, the ceilings left out; illuminance in false colour with each sensor grid\'s isolines and readings'],
      ...Object.keys(ELEVATIONS).map((wall) => [wall, `elevation: ${wall.split(' ')[0]} wall`, 'Level towards that wall, the near half of the room left out; illuminance in false colour']),
    ]) {
      const o = document.createElement('option');
      o.value = value;
      o.textContent = text;
      o.title = title;
      preset.append(o);
    }
    if (keepView) preset.value = 'orbit';
    else if (this.cameras.length) this.applyPreset(this.cameras[0].name);
    else preset.value = 'orbit';
  }

  applyPreset(name) {
    const preset = $('camera-preset');
    preset.value = name;
    const cam = this.cameras.find((c) => c.name === name);
    const mode = $('view-mode');
    const setMode = (value) => {
      mode.value = value;
      mode.dispatchEvent(new Event('change'));
    };
    const section = cam ? null : this.section(name);
    if (section) {
      if (!this.rig.plan) this.modeBeforePlan = mode.value;
      if (this.rig.showSection(...section)) {
        setMode('false-lux');
        this.onPlan?.(name === PLAN);
      }
    } else if (this.rig.plan) {
      this.rig.leavePlan();
      setMode(this.modeBeforePlan ?? 'tonemapped');
      this.onPlan?.(false);
    }
    if (cam) this.rig.applyPreset(cam);
    $('fov').value = String(this.rig.camera.fov);
    $('fov-value').textContent = `${Math.round(this.rig.camera.fov)}°`;
  }

  // The plan view's cut: the ceilings above it are left out (m; see CameraRig.showSection).
  setPlanCut(cut) {
    this.planCut = cut;
  }

  // CameraRig.showSection's arguments for the plan or an elevation entry; null for others.
  section(name) {
    const centre = this.rig.room?.centre;
    if (!centre) return null;
    if (name === PLAN) return [[0, -1, 0], [0, 0, -1], [centre.x, this.planCut, centre.z]];
    const dir = ELEVATIONS[name];
    return dir ? [dir, [0, 1, 0], centre.toArray()] : null;
  }

  // The user moved the camera: no preset any more (the plan stays a plan when panned).
  markFree() {
    if (this.rig.plan) return;
    $('camera-preset').value = 'orbit';
    $('fov-value').textContent = `${Math.round(this.rig.camera.fov)}°`;
  }

  showExposure(ev) {
    $('exposure-value').textContent = `EV ${ev.toFixed(1)}`;
  }

  _modeControls() {
    const tone = this.viewer.display.mode === 'tonemapped';
    $('tonemap-controls').style.display = tone ? '' : 'none';
    $('false-colour-controls').style.display = tone ? 'none' : '';
  }

  afterRender() {
    const used = this.viewer.used;
    if (this.viewer.display.autoExposure && used.mode === 'tonemapped') {
      const ex = $('exposure');
      if (document.activeElement !== ex) ex.value = String(used.ev100.toFixed(1));
      this.showExposure(used.ev100);
    }
    const fov = $('fov');
    if (document.activeElement !== fov && Number(fov.value) !== this.rig.camera.fov) {
      fov.value = String(this.rig.camera.fov);
      $('fov-value').textContent = `${Math.round(this.rig.camera.fov)}°`;
    }
  }
}
