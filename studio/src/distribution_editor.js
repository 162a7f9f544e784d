// The distribution editor, after the lighting-design paper's Fig. 4 (§4.1): a polar plot of
// the luminous intensity I(γ) in the C0–C180 plane (γ = 0 straight down, C0 to the right,
// C180 to the left; optionally C90–C270) of one luminaire, with
//  * the exact distribution the direct light uses,
//  * its projection onto SH bands l < sh_order without a window, and
//  * with the window the relighter applies to the interreflections (Lanczos' sigma
//    factors, paper Eq. 12–13), all three from the server's `distribution` message;
//  * draggable control points: dragging one radially sets its intensity. A distribution
//    that is not a curve becomes one on the first drag (control points sampled from the
//    exact C0 plane every 10° from 0 to 180). Each move sends the whole state (throttled to
//    one per animation frame); the server applies a single-point move incrementally
//    (paper Eq. 21, Simpson weights updated by t_k (I − I_new) f_l Δγ) and answers with a
//    new distribution message whose `incremental_updates` is shown here.
// Double-click adds a control point; right-click (or Alt-click) removes one.
import { analyticIntensity, effectiveLuminaire, round6, sampleCurve } from './luminaire_model.js';
import { el, numberInput, select } from './ui.js';

const STYLE = {
  exact: { color: '#ff5a36', width: 2.2, dash: [] },
  sh: { color: '#48a8ff', width: 1.5, dash: [6, 4] },
  sh_windowed: { color: '#4fd18b', width: 1.8, dash: [2, 3] },
  c90: { color: '#c9a0ff', width: 1.2, dash: [8, 3, 2, 3] },
};
const HIT_PX = 10;

function niceCeil(v) {
  if (!(v > 0)) return 1;
  const e = Math.floor(Math.log10(v));
  for (const m of [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * 10 ** e >= v * (1 - 1e-9)) return m * 10 ** e;
  return 10 ** (e + 1);
}

export class DistributionEditor {
  // distributions: Map name → latest distribution message; request(name): asks the server.
  constructor(container, store, distributions, request) {
    this.container = container;
    this.store = store;
    this.distributions = distributions;
    this.request = request;
    this.index = 0;
    this.drag = null;
    this.showC90 = false;
    this.dpr = window.devicePixelRatio || 1;
    store.onChange((source) => {
      if (!this.drag) {
        this._syncPoints();
        this.draw();
      }
    });
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    if (!hello.luminaires.length) {
      this.container.append(el('p', { class: 'hint', text: 'This scene has no luminaires.' }));
      return;
    }
    this.index = Math.min(this.index, hello.luminaires.length - 1);
    this.lumSelect = select(hello.luminaires.map((l, i) => [String(i), l.name]), {
      id: 'dist-luminaire',
      title: 'The luminaire whose distribution is shown and edited',
      onChange: (v) => this.select(Number(v)),
    });
    const c90 = el('input', { type: 'checkbox', title: 'Also draw the C90–C270 plane (differs from C0–C180 for asymmetric IES/EULUMDAT photometry)' });
    c90.addEventListener('change', () => {
      this.showC90 = c90.checked;
      this.draw();
    });
    this.canvas = el('canvas', { id: 'dist-canvas', class: 'dist-canvas', title: 'Drag a control point radially to change its intensity. Double-click: add a point. Right-click or Alt-click: remove one.' });
    this.info = el('div', { class: 'dist-info', id: 'dist-info' });
    const key = el('div', { class: 'dist-key' }, [
      this._key('exact', 'exact'),
      this._key('sh', 'SH, no window'),
      this._key('sh_windowed', 'SH, sigma window (indirect)'),
    ]);
    this.table = el('div', { class: 'dist-table' });
    const toCurve = el('button', { type: 'button', text: 'Convert to curve', title: 'Replace the distribution by a curve sampled from its C0 plane every 10°' });
    toCurve.addEventListener('click', () => this._ensureCurve(true));
    const reset = el('button', { type: 'button', text: "Scene's distribution", title: "Back to the scene's own distribution for this luminaire" });
    reset.addEventListener('click', () => this.store.edit((doc) => delete doc.luminaires?.[this.name]?.distribution));
    this.container.append(
      el('div', { class: 'row' }, [el('span', { class: 'row-label', text: 'Luminaire' }), this.lumSelect]),
      this.canvas,
      key,
      el('div', { class: 'row' }, [el('label', { class: 'check' }, [c90, ' C90–C270 plane'])]),
      el('div', { class: 'row' }, [toCurve, reset]),
      this.info,
      this.table,
    );
    this._installPointer();
    this.resizeObserver?.disconnect();  // a reconnect builds the panel anew
    this.resizeObserver = new ResizeObserver(() => this.draw());
    this.resizeObserver.observe(this.canvas);
    this.select(this.index);
  }

  _key(k, text) {
    const s = STYLE[k];
    const c = el('canvas', { width: 28, height: 8, class: 'key-swatch' });
    const ctx = c.getContext('2d');
    ctx.strokeStyle = s.color;
    ctx.lineWidth = 2;
    ctx.setLineDash(s.dash);
    ctx.beginPath();
    ctx.moveTo(0, 4);
    ctx.lineTo(28, 4);
    ctx.stroke();
    return el('span', { class: 'key' }, [c, ` ${text}`]);
  }

  get lum() {
    return this.hello?.luminaires[this.index];
  }
  get name() {
    return this.lum?.name;
  }

  select(i) {
    this.index = i;
    if (this.lumSelect) this.lumSelect.value = String(i);
    this.drag = null;
    this.request(this.name);
    this.onSelect?.(i);
    this._syncPoints();
    this.draw();
  }

  // A distribution message from the server (asked or not).
  receive(msg) {
    if (msg.luminaire !== this.name) return;
    if (!this.drag) this._syncPoints();
    this.draw();
  }

  _effective() {
    return effectiveLuminaire(this.lum, this.store.doc.luminaires?.[this.name]);
  }

  // Control points: the curve's own, or (virtual, hollow) samples of the exact C0 plane.
  _syncPoints() {
    if (!this.lum) return;
    const d = this._effective().distribution;
    if (d?.type === 'curve') {
      this.points = { gamma: [...d.gamma_deg], candela: [...d.candela], virtual: false };
    } else {
      const c = sampleCurve(d, this.distributions.get(this.name));
      this.points = { gamma: c.gamma_deg, candela: c.candela, virtual: true };
    }
    this._buildTable();
  }

  _ensureCurve(send) {
    if (this.points.virtual || send) {
      this.points.virtual = false;
      this._sendCurve();
    }
  }

  _sendCurve() {
    const curve = { type: 'curve', gamma_deg: this.points.gamma.map(round6), candela: this.points.candela.map((c) => round6(Math.max(0, c))) };
    this.store.edit(() => (this.store.luminaire(this.name).distribution = curve));
  }

  // Geometry of the plot in CSS pixels.
  _frame() {
    const w = this.canvas.clientWidth || 300;
    const h = w;
    return { w, h, cx: w / 2, cy: h / 2, R: w / 2 - 28 };
  }

  _scaleMax(msg) {
    let m = 0;
    const take = (a) => a && a.forEach((v) => (m = Math.max(m, v)));
    if (msg) {
      for (const k of ['exact', 'sh', 'sh_windowed']) {
        take(msg[k]?.c0);
        take(msg[k]?.c180);
        if (this.showC90) {
          take(msg[k]?.c90);
          take(msg[k]?.c270);
        }
      }
    }
    take(this.points?.candela);
    return niceCeil(m * 1.05);
  }

  _xy(f, gammaDeg, cd, side, max) {
    const g = (gammaDeg * Math.PI) / 180;
    const r = (Math.max(0, cd) / max) * f.R;
    return [f.cx + side * r * Math.sin(g), f.cy + r * Math.cos(g)];
  }

  draw() {
    if (!this.canvas || !this.lum) return;
    const f = this._frame();
    const dpr = this.dpr;
    if (this.canvas.width !== Math.round(f.w * dpr)) {
      this.canvas.width = Math.round(f.w * dpr);
      this.canvas.height = Math.round(f.h * dpr);
      this.canvas.style.height = `${f.h}px`;
    }
    const ctx = this.canvas.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, f.w, f.h);
    const msg = this.distributions.get(this.name);
    const max = this.drag ? this.drag.max : this._scaleMax(msg);
    this.max = max;
    // Grid: rings with candela labels, spokes every 30°.
    ctx.strokeStyle = 'rgba(255,255,255,0.14)';
    ctx.fillStyle = 'rgba(255,255,255,0.55)';
    ctx.font = '10px system-ui, sans-serif';
    ctx.lineWidth = 1;
    ctx.setLineDash([]);
    for (let k = 1; k <= 4; k++) {
      ctx.beginPath();
      ctx.arc(f.cx, f.cy, (f.R * k) / 4, 0, 2 * Math.PI);
      ctx.stroke();
      // Ring labels along γ = 105° on the C0 side, where few beams go.
      const a = (105 * Math.PI) / 180;
      ctx.fillText(`${round6((max * k) / 4)}`, f.cx + ((f.R * k) / 4) * Math.sin(a) + 2, f.cy + ((f.R * k) / 4) * Math.cos(a) - 2);
    }
    for (let g = 0; g < 360; g += 30) {
      const a = (g * Math.PI) / 180;
      ctx.beginPath();
      ctx.moveTo(f.cx, f.cy);
      ctx.lineTo(f.cx + f.R * Math.sin(a), f.cy + f.R * Math.cos(a));
      ctx.stroke();
      const gamma = g <= 180 ? g : 360 - g;
      const lx = f.cx + (f.R + 14) * Math.sin(a), ly = f.cy + (f.R + 12) * Math.cos(a);
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillText(`${gamma}°`, lx, ly);
    }
    ctx.textAlign = 'left';
    ctx.textBaseline = 'alphabetic';
    ctx.fillText('C0 →', f.w - 36, 12);
    ctx.fillText('← C180', 4, 12);
    ctx.fillText('I(γ) in cd', 4, f.h - 6);

    const curve = (gammas, values, side, style) => {
      if (!gammas || !values) return;
      ctx.strokeStyle = style.color;
      ctx.lineWidth = style.width;
      ctx.setLineDash(style.dash);
      ctx.beginPath();
      gammas.forEach((g, i) => {
        const [x, y] = this._xy(f, g, values[i], side, max);
        if (i === 0) ctx.moveTo(x, y);
        else ctx.lineTo(x, y);
      });
      ctx.stroke();
    };
    if (msg) {
      for (const k of ['sh', 'sh_windowed']) {
        curve(msg.gamma_deg, msg[k]?.c0, 1, STYLE[k]);
        curve(msg.gamma_deg, msg[k]?.c180, -1, STYLE[k]);
      }
      if (this.showC90) {
        curve(msg.gamma_deg, msg.exact?.c90, 1, STYLE.c90);
        curve(msg.gamma_deg, msg.exact?.c270, -1, STYLE.c90);
      }
    }
    // The exact curve: while dragging the local control points (piecewise linear).
    if (this.drag || !msg) {
      const d = { type: 'curve', gamma_deg: this.points.gamma, candela: this.points.candela };
      const gs = Array.from({ length: 181 }, (_, i) => i);
      const vs = gs.map((g) => analyticIntensity(this.drag || this.points.virtual === false ? d : this._effective().distribution, g) ?? 0);
      curve(gs, vs, 1, STYLE.exact);
      curve(gs, vs, -1, STYLE.exact);
    } else {
      curve(msg.gamma_deg, msg.exact?.c0, 1, STYLE.exact);
      curve(msg.gamma_deg, msg.exact?.c180, -1, STYLE.exact);
    }
    ctx.setLineDash([]);
    // Control points (hollow while they are only samples of a non-curve distribution).
    if (this.points) {
      this.points.gamma.forEach((g, k) => {
        for (const side of [1, -1]) {
          const [x, y] = this._xy(f, g, this.points.candela[k], side, max);
          ctx.beginPath();
          ctx.arc(x, y, side === 1 ? 4.5 : 3, 0, 2 * Math.PI);
          ctx.lineWidth = 1.5;
          ctx.strokeStyle = '#fff';
          ctx.fillStyle = this.drag?.k === k ? '#ffe04a' : '#ff5a36';
          if (!this.points.virtual && side === 1) ctx.fill();
          ctx.stroke();
        }
      });
    }
    this._info(msg);
  }

  _info(msg) {
    const d = this._effective().distribution;
    const parts = [];
    parts.push(`<b>${d?.type ?? '?'}</b>`);
    if (msg) {
      parts.push(`SH l &lt; ${msg.sh_order}`, `window ${msg.window}`);
      if (msg.flux_lm !== undefined) parts.push(`flux ${Math.round(msg.flux_lm)} lm`);
      parts.push(`<span id="incremental-updates" title="State changes that moved one control point and were applied by the paper's incremental update (Eq. 21) instead of a new SH projection">incremental updates: <b>${msg.incremental_updates ?? 0}</b></span>`);
    } else {
      parts.push('waiting for the server…');
    }
    if (this.points?.virtual) parts.push('<i>drag a point to turn it into a curve</i>');
    this.info.innerHTML = parts.join(' · ');
  }

  _buildTable() {
    if (!this.table) return;
    this.table.innerHTML = '';
    if (!this.points || this.points.virtual) return;
    const rows = this.points.gamma.map((g, k) =>
      el('tr', {}, [
        el('td', { class: 'numcell', text: `${round6(g)}°` }),
        el('td', {}, numberInput({
          value: round6(this.points.candela[k]),
          min: 0,
          step: 'any',
          title: `Intensity at γ = ${g}°, candela`,
          onChange: (v) => {
            this.points.candela[k] = v;
            this._sendCurve();
          },
        })),
      ]),
    );
    this.table.append(el('table', { class: 'points-table' }, [el('thead', {}, el('tr', {}, [el('th', { text: 'γ' }), el('th', { text: 'I (cd)' })])), el('tbody', {}, rows)]));
  }

  _hit(e) {
    const f = this._frame();
    const r = this.canvas.getBoundingClientRect();
    const x = e.clientX - r.left, y = e.clientY - r.top;
    let best = null;
    this.points.gamma.forEach((g, k) => {
      for (const side of [1, -1]) {
        const [px, py] = this._xy(f, g, this.points.candela[k], side, this.max);
        const d = Math.hypot(px - x, py - y);
        if (d < HIT_PX && (!best || d < best.d)) best = { k, side, d };
      }
    });
    return { best, x, y, f };
  }

  _installPointer() {
    const c = this.canvas;
    c.addEventListener('pointerdown', (e) => {
      if (!this.points || e.button !== 0) return;
      const { best } = this._hit(e);
      if (!best) return;
      if (e.altKey) return this._remove(best.k);
      e.preventDefault();
      c.setPointerCapture(e.pointerId);
      const wasVirtual = this.points.virtual;
      this.points.virtual = false;
      this.drag = { k: best.k, side: best.side, max: this.max, converted: wasVirtual };
    });
    c.addEventListener('pointermove', (e) => {
      if (!this.drag) {
        if (this.points) c.style.cursor = this._hit(e).best ? 'grab' : 'default';
        return;
      }
      const { x, y, f } = this._hit(e);
      const g = (this.points.gamma[this.drag.k] * Math.PI) / 180;
      // Radial projection of the pointer onto the control point's direction.
      const along = (x - f.cx) * this.drag.side * Math.sin(g) + (y - f.cy) * Math.cos(g);
      let cd = Math.max(0, (along / f.R) * this.drag.max);
      cd = round6(cd);
      this.points.candela[this.drag.k] = cd;
      if (cd > this.drag.max * 0.98) this.drag.max = niceCeil(cd * 1.25);
      this._sendCurve();
      this.draw();
    });
    const end = () => {
      if (!this.drag) return;
      this.drag = null;
      this._buildTable();
      this.draw();
    };
    c.addEventListener('pointerup', end);
    c.addEventListener('pointercancel', end);
    c.addEventListener('contextmenu', (e) => {
      if (!this.points) return;
      const { best } = this._hit(e);
      if (!best) return;
      e.preventDefault();
      this._remove(best.k);
    });
    c.addEventListener('dblclick', (e) => {
      if (!this.points) return;
      const { x, y, f } = this._hit(e);
      const dx = Math.abs(x - f.cx), dy = y - f.cy;
      const gamma = Math.round((Math.atan2(dx, dy) * 180) / Math.PI);
      const cd = round6((Math.hypot(dx, dy) / f.R) * this.max);
      if (this.points.gamma.includes(gamma)) return;
      const k = this.points.gamma.findIndex((g) => g > gamma);
      const at = k < 0 ? this.points.gamma.length : k;
      this.points.gamma.splice(at, 0, gamma);
      this.points.candela.splice(at, 0, cd);
      this.points.virtual = false;
      this._sendCurve();
      this._buildTable();
      this.draw();
    });
  }

  _remove(k) {
    if (this.points.gamma.length <= 2 || this.points.gamma[k] === 0) return;
    this.points.gamma.splice(k, 1);
    this.points.candela.splice(k, 1);
    this.points.virtual = false;
    this._sendCurve();
    this._buildTable();
    this.draw();
  }
}
