// The Luminaires panel: one block per luminaire of the layout (the scene's in hello order, then
// those the state adds; index i in that order) with on/off
// (data-testid on-i), a dimmer in % (dimmer-i: a slider 0..100 % and a number box that also
// takes more), colour as the scene's, an RGB chromaticity (colour picker) or a colour
// temperature (a logarithmic slider 1800..10000 K; the box takes the state's 1667..25000 K),
// the distribution type and its parameters
// (isotropic, cosine_power, curve, ies, ldt; scene format), and aiming: "Aim at a point"
// (aim-i) makes the next click in the view pick a surface point, which becomes the
// luminaire's "target" (the lighting-design paper §4.2, Fig. 5). Every change edits the
// state document (state.js), which sends the whole document.
import { cctToRgb, hexToLinear, linearToHex } from './colors.js';
import { effectiveLuminaire, layoutLuminaires, peakCandela, sampleCurve } from './luminaire_model.js';
import { el, numberInput, onValue, row, select, setIfIdle, sliderNumber } from './ui.js';

// The colour temperature slider's range (the lamps a designer chooses among), and what a
// lighting state takes (docs/lighting-state.md), which the number box allows.
const CCT_SLIDER_K = [1800, 10000];
const CCT_STATE_K = [1667, 25000];

const DIST_TYPES = [
  ['isotropic', 'isotropic'],
  ['cosine_power', 'cosine power'],
  ['curve', 'curve (points)'],
  ['ies', 'IES file'],
  ['ldt', 'EULUMDAT file'],
];

export class LuminairePanel {
  // callbacks: {aim(index), editCurve(index)}; distributions: Map name → last distribution message
  constructor(container, store, distributions, callbacks) {
    this.container = container;
    this.store = store;
    this.distributions = distributions;
    this.callbacks = callbacks;
    this.blocks = [];
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this._names = null;
    this.refresh();
  }

  // The blocks anew when the layout's names change (a luminaire added or deleted).
  _rebuild(list) {
    this.container.innerHTML = '';
    this.blocks = list.map((lum, i) => this._block(lum, i));
    if (!this.blocks.length) this.container.append(el('p', { class: 'hint', text: 'No luminaires: drag one from the catalogue onto a ceiling or a wall.' }));
  }

  entry(name) {
    return this.store.doc.luminaires?.[name] || {};
  }

  _edit(name, fn) {
    this.store.edit(() => fn(this.store.luminaire(name)));
  }

  _block(lum, i) {
    const name = lum.name;
    const b = { lum, i };
    b.swatch = el('span', { class: 'swatch' });
    b.summaryInfo = el('span', { class: 'summary-info' });
    const details = el('details', { class: 'luminaire', open: !lum.added, dataset: { luminaire: name, index: String(i) } }, [
      el('summary', { title: `Luminaire "${name}"${lum.added ? ', added to the layout' : ''}` }, [b.swatch, el('span', { class: 'lum-name', text: name }), b.summaryInfo]),
    ]);
    b.details = details;

    // On/off and reset.
    b.on = el('input', { type: 'checkbox', dataset: { testid: `on-${i}` }, title: 'Switch the luminaire on or off (off keeps its other settings)' });
    onValue(b.on, (v) => this._edit(name, (e) => (v ? delete e.on : (e.on = false))), (x) => x.checked);
    const reset = lum.added
      ? el('button', { type: 'button', class: 'small', text: 'Delete', title: 'Remove this luminaire from the layout' })
      : el('button', { type: 'button', class: 'small', text: 'Reset', title: "Back to the scene's settings for this luminaire (remove it from the state)" });
    reset.addEventListener('click', () => this.store.edit((doc) => delete doc.luminaires?.[name], null));
    details.append(el('div', { class: 'row' }, [el('label', { class: 'check' }, [b.on, ' on']), el('span', { class: 'spacer' }), reset]));

    // Dimmer.
    b.dimmer = sliderNumber({
      min: 0,
      max: 100,
      step: 0.1,
      numberMax: 1e8,
      factor: 100,
      unit: '%',
      value: 1,
      testid: `dimmer-${i}`,
      title: 'Dimmer in % of the photometry (0 % dark, 100 % as specified; the number box takes more than 100 %)',
      onChange: (v) => this._edit(name, (e) => (e.dimmer = v)),
    });
    details.append(row('Dimmer', b.dimmer.element, 'The luminous intensity in % of the photometry'));

    // Colour.
    b.colorMode = select(
      [
        ['scene', "scene's colour"],
        ['rgb', 'RGB colour'],
        ['cct', 'colour temperature'],
      ],
      {
        title: 'Light colour: the scene\'s, a chromaticity picked as RGB, or a black body\'s colour temperature. Colour never changes the lumens.',
        onChange: (mode) =>
          this._edit(name, (e) => {
            const eff = effectiveLuminaire(lum, e);
            delete e.color;
            delete e.cct_kelvin;
            if (mode === 'rgb') e.color = eff.color.map((x) => Number(x.toFixed(4)));
            if (mode === 'cct') e.cct_kelvin = eff.cct ?? 3000;
          }),
      },
    );
    b.colorPicker = el('input', { type: 'color', title: 'Light colour (only its chromaticity counts: it is scaled to luminance 1)' });
    onValue(b.colorPicker, (hex) => this._edit(name, (e) => {
      delete e.cct_kelvin;
      e.color = hexToLinear(hex).map((x) => Number(x.toFixed(4)));
    }));
    b.cct = sliderNumber({
      min: CCT_SLIDER_K[0],
      max: CCT_SLIDER_K[1],
      numberMin: CCT_STATE_K[0],
      numberMax: CCT_STATE_K[1],
      log: true,
      step: 1,
      value: 3000,
      unit: 'K',
      testid: `cct-${i}`,
      title: 'Correlated colour temperature: the slider 1800–10000 K on a logarithmic scale (2700 K warm white, 4000 K neutral, 6500 K daylight); the box takes 1667–25000 K',
      onChange: (v) => this._edit(name, (e) => {
        delete e.color;
        e.cct_kelvin = v;
      }),
    });
    b.cct.slider.classList.add('cct-slider');
    details.append(row('Colour', [b.colorMode, b.colorPicker], 'Light colour'));
    b.cctRow = row('Temperature', b.cct.element, 'Colour temperature in kelvin');
    details.append(b.cctRow);

    // Distribution.
    b.distType = select(DIST_TYPES, {
      title: 'Luminous intensity distribution (scene format): isotropic (same in every direction), cosine power (downlight, spot), curve (control points, editable in the Distribution section), or an IES LM-63 / EULUMDAT photometry file',
      onChange: (type) => this._setType(lum, type),
    });
    b.distParams = el('div', { class: 'dist-params' });
    details.append(row('Distribution', b.distType, 'Luminous intensity distribution'), b.distParams);

    // Aim.
    b.aimText = el('span', { class: 'aim-text' });
    const aim = el('button', { type: 'button', dataset: { testid: `aim-${i}` }, text: 'Aim at a point…', title: 'Then click a surface in the view: the luminaire turns so that its axis (γ = 0) points there' });
    aim.addEventListener('click', () => this.callbacks.aim(i));
    b.aimButton = aim;
    const aimReset = el('button', { type: 'button', class: 'small', text: "Scene's aim", title: "Back to the scene's aiming direction" });
    aimReset.addEventListener('click', () => this._edit(name, (e) => {
      delete e.aim;
      delete e.target;
    }));
    details.append(row('Aim', [aim, aimReset], 'Direction of the luminaire\'s axis'), el('div', { class: 'row sub' }, b.aimText));
    this.container.append(details);
    return b;
  }

  _setType(lum, type) {
    const name = lum.name;
    if (this._pendingFileType?.name === name) this._pendingFileType = null;
    this._edit(name, (e) => {
      const eff = effectiveLuminaire(lum, e);
      const old = eff.distribution;
      if (type === old?.type) return;
      const msg = this.distributions.get(name);
      const peak = Number(peakCandela(old, msg?.exact).toPrecision(4));
      if (type === lum.distribution?.type) e.distribution = JSON.parse(JSON.stringify(lum.distribution));
      else if (type === 'isotropic') e.distribution = { type, candela: peak };
      else if (type === 'cosine_power') e.distribution = { type, candela: peak, exponent: 1, cutoff_deg: 90 };
      else if (type === 'curve') e.distribution = sampleCurve(old, msg);
      else {
        // A file type needs a path first; keep the old distribution until one is given.
        this._pendingFileType = { name, type };
        return;
      }
      if (!lum.added && JSON.stringify(e.distribution) === JSON.stringify(lum.distribution)) delete e.distribution;
    });
    this.refresh();
  }

  _params(b, eff) {
    const d = eff.distribution || {};
    const pending = this._pendingFileType?.name === b.lum.name ? this._pendingFileType.type : null;
    const type = pending || d.type;
    const key = JSON.stringify([type, pending ? null : d]);
    if (b.paramsKey === key) return;
    b.paramsKey = key;
    const p = b.distParams;
    p.innerHTML = '';
    const name = b.lum.name;
    const set = (k, v) => this._edit(name, (e) => {
      const cur = JSON.parse(JSON.stringify(effectiveLuminaire(b.lum, e).distribution));
      cur[k] = v;
      e.distribution = cur;
    });
    if (type === 'isotropic' || type === 'cosine_power') {
      p.append(row('Intensity', numberInput({ value: d.candela, min: 0, step: 'any', unit: 'cd', title: 'Luminous intensity (at γ = 0 for cosine power), candela', onChange: (v) => set('candela', v) })));
    }
    if (type === 'cosine_power') {
      p.append(
        row('Exponent', numberInput({ value: d.exponent, min: 0, step: 'any', title: 'I(γ) = I0 · cos^n γ: larger n, narrower beam (n = 1 Lambertian)', onChange: (v) => set('exponent', v) })),
        row('Cut-off', numberInput({ value: d.cutoff_deg ?? 90, min: 0, max: 180, step: 'any', unit: '°', title: 'No light beyond this angle γ from the axis', onChange: (v) => set('cutoff_deg', v) })),
      );
    }
    if (type === 'curve') {
      const edit = el('button', { type: 'button', text: `Edit ${d.gamma_deg?.length ?? 0} control points…`, title: 'Open the distribution editor (polar plot with draggable points)' });
      edit.addEventListener('click', () => this.callbacks.editCurve(b.i));
      p.append(el('div', { class: 'row sub' }, edit));
    }
    if (type === 'ies' || type === 'ldt') {
      const file = el('input', { type: 'text', value: pending ? '' : d.file || '', placeholder: type === 'ies' ? 'photometry/lamp.ies' : 'photometry/lamp.ldt', title: 'Photometry file path; relative paths resolve against the folder of the .rlt (press Enter to apply)' });
      const apply = () => {
        if (!file.value.trim()) return;
        this._pendingFileType = null;
        this._edit(name, (e) => (e.distribution = { type, file: file.value.trim() }));
      };
      file.addEventListener('change', apply);
      file.addEventListener('keydown', (ev) => ev.key === 'Enter' && apply());
      p.append(row('File', file, 'Photometry file'));
    }
    const flux = this.distributions.get(name)?.flux_lm;
    b.fluxLine = null;
    if (flux !== undefined) {
      b.fluxLine = el('div', { class: 'row sub hint', title: 'Luminous flux of the distribution (from the server), and what the luminaire emits at its dimmer setting' });
      b.flux = flux;
      p.append(b.fluxLine);
    }
  }

  refresh() {
    if (!this.hello) return;
    const list = layoutLuminaires(this.hello, this.store.doc);
    const names = list.map((l) => l.name).join('\n');
    if (names !== this._names) {
      this._names = names;
      this._rebuild(list);
    }
    for (const b of this.blocks) {
      const eff = effectiveLuminaire(b.lum, this.entry(b.lum.name));
      setIfIdle(b.on, eff.on, 'checked');
      b.dimmer.set(eff.dimmer);
      setIfIdle(b.colorMode, eff.colorMode);
      const hex = linearToHex(eff.colorMode === 'cct' ? cctToRgb(eff.cct) : eff.color, true);
      if (document.activeElement !== b.colorPicker) b.colorPicker.value = hex;
      b.colorPicker.style.display = eff.colorMode === 'cct' ? 'none' : '';
      b.colorPicker.disabled = eff.colorMode === 'scene';
      b.cctRow.style.display = eff.colorMode === 'cct' ? '' : 'none';
      if (eff.colorMode === 'cct') b.cct.set(eff.cct);
      b.swatch.style.background = hex;
      b.swatch.style.opacity = eff.on ? 1 : 0.25;
      b.summaryInfo.textContent = eff.on ? `${Math.round(eff.dimmer * 100)} %` : 'off';
      const pending = this._pendingFileType?.name === b.lum.name ? this._pendingFileType.type : null;
      setIfIdle(b.distType, pending || eff.distribution?.type);
      this._params(b, eff);
      if (b.fluxLine) b.fluxLine.textContent = `${Math.round(b.flux)} lm; emits ${Math.round(b.flux * (eff.on ? eff.dimmer : 0))} lm`;
      b.aimText.textContent = eff.target
        ? `target (${eff.target.map((x) => x.toFixed(2)).join(', ')}) m`
        : `direction (${eff.aim.map((x) => x.toFixed(2)).join(', ')})${eff.aimChanged ? '' : " — scene's"}`;
    }
  }

  // Aim mode visual state (button pressed while waiting for the click).
  setAiming(index) {
    this.blocks.forEach((b) => b.aimButton.classList.toggle('active', b.i === index));
  }

  // Refresh the flux line after a distribution message.
  distributionUpdated(name) {
    const b = this.blocks.find((x) => x.lum.name === name);
    if (b) {
      b.paramsKey = null;
      this.refresh();
    }
  }
}
