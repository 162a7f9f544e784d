// Materials (issue 13; hello.materials and the state's `materials`: docs/lighting-state.md
// "Materials"): a click on a surface that reads a material (the pick's `material`; not window
// glass, not a movable object) opens its panel — colour (the base colour: the linear albedo,
// shown and picked as sRGB) with its reflectance in % beside it, metallic and roughness
// (data-testid material-color, material-reflectance, material-metallic, material-roughness;
// Reset drops the state's entry) — and every change
// edits the state's materials[NAME] live. The server answers an edit with a first frame that is
// approximate (the edit's light reflected once; #frame-quality says so) and the converged one
// after it.
import { el, row, sliderNumber } from './ui.js';

const round4 = (x) => Number(x.toFixed(4));
const toSrgb = (c) => (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055);
const toLinear = (c) => (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));

// Linear RGB in 0..1 as an sRGB "#rrggbb" (what <input type=color> shows), and back.
export function linearToHex(rgb) {
  const byte = (c) => Math.round(255 * toSrgb(Math.min(Math.max(c, 0), 1))).toString(16).padStart(2, '0');
  return `#${rgb.map(byte).join('')}`;
}
export function hexToLinear(hex) {
  return [1, 3, 5].map((i) => round4(toLinear(parseInt(hex.slice(i, i + 2), 16) / 255)));
}

// The luminance Y of a linear Rec.709 albedo (the photometric reflectance), in % to 0.1.
const luminanceY = (rgb) => 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
export const reflectancePercent = (rgb) => Number((100 * luminanceY(rgb)).toFixed(1));

// `rgb` scaled to reflectance `y` (0..1) with its hue kept; a grey of `y` when it is black.
// Capped where a channel would exceed 1 (a saturated colour cannot reflect as much).
export function withReflectance(rgb, y) {
  const now = luminanceY(rgb);
  if (now <= 0) return [y, y, y].map(round4);
  const k = Math.min(y / now, 1 / Math.max(...rgb));
  return rgb.map((c) => round4(c * k));
}

export class MaterialPanel {
  constructor(container, store) {
    this.container = container;
    this.store = store;
    this.materials = new Map(); // name → the scene's material (hello)
    this.name = null;
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.materials = new Map((hello.materials ?? []).filter((m) => !m.portal).map((m) => [m.name, m]));
    this.show(null);
  }

  // The material as the state has it: the scene's, with the state's entry over it.
  effective(name) {
    const scene = this.materials.get(name);
    const entry = this.store.doc.materials?.[name] ?? {};
    return {
      albedo: entry.albedo ?? scene.albedo,
      metallic: entry.metallic ?? scene.metallic ?? 0,
      roughness: entry.roughness ?? scene.roughness ?? 1,
    };
  }

  edit(fn) {
    const name = this.name;
    this.store.edit((doc) => {
      doc.materials ??= {};
      fn((doc.materials[name] ??= {}));
    });
  }

  // Opens the panel of material `name` (null or an unknown name: the hint).
  show(name) {
    this.container.innerHTML = '';
    this.name = this.materials.has(name) ? name : null;
    if (!this.name) {
      this.container.append(el('p', { class: 'hint', text: 'Click a surface to edit its material.' }));
      return;
    }
    const m = this.effective(this.name);
    this.color = el('input', {
      type: 'color',
      value: linearToHex(m.albedo),
      title: 'Base colour (albedo; a metal\u2019s reflectance)',
      dataset: { testid: 'material-color' },
    });
    this.color.addEventListener('input', () => this.edit((e) => (e.albedo = hexToLinear(this.color.value))));
    // The reflectance a designer specifies: the albedo's luminance Y in %. Typing one scales the
    // colour to it, keeping its hue, as far as no channel exceeds 1.
    this.reflectance = el('input', {
      type: 'number', min: 0, max: 100, step: 0.1, class: 'num',
      value: reflectancePercent(m.albedo),
      title: 'Reflectance: the share of light the surface reflects (luminance Y of the colour), %',
      dataset: { testid: 'material-reflectance' },
    });
    // On `change` (Enter or leaving the box), not per keystroke: scaling to each partial number
    // typed would wear the hue down.
    this.reflectance.addEventListener('change', () => {
      const percent = Number(this.reflectance.value);
      if (this.reflectance.value === '' || !(percent >= 0 && percent <= 100)) return;
      this.edit((e) => (e.albedo = withReflectance(this.effective(this.name).albedo, percent / 100)));
    });
    this.metallic = sliderNumber({
      min: 0, max: 1, step: 0.01, value: m.metallic, testid: 'material-metallic',
      title: 'Metallic: 0 a dielectric (paint, wood, stone), 1 a metal',
      onChange: (v) => this.edit((e) => (e.metallic = round4(v))),
    });
    this.roughness = sliderNumber({
      min: 0, max: 1, step: 0.01, value: m.roughness, testid: 'material-roughness',
      title: 'Roughness: 0 polished, 1 matt (GGX α = roughness²)',
      onChange: (v) => this.edit((e) => (e.roughness = round4(v))),
    });
    const reset = el('button', {
      type: 'button', text: 'Reset', title: 'The scene\u2019s own material',
      dataset: { testid: 'material-reset' },
      onclick: () => this.store.edit((doc) => { if (doc.materials) delete doc.materials[this.name]; }),
    });
    this.container.append(
      el('div', { class: 'row-label', text: this.name, dataset: { testid: 'material-name' } }),
      row('Colour', [this.color, this.reflectance, el('span', { class: 'unit', text: '%' })]),
      row('Metallic', this.metallic.element),
      row('Roughness', this.roughness.element),
      reset,
    );
  }

  refresh() {
    if (!this.name) return;
    const m = this.effective(this.name);
    if (document.activeElement !== this.color) this.color.value = linearToHex(m.albedo);
    if (document.activeElement !== this.reflectance) this.reflectance.value = reflectancePercent(m.albedo);
    this.metallic.set(m.metallic);
    this.roughness.set(m.roughness);
  }
}
