// The photometry catalogue (`relight serve --photometry DIR`; docs/studio-protocol.md
// "catalogue"): one card per IES/LDT file with its luminaire, maker, lumens, watts, beam angle
// and a polar plot (C0–C180 solid, C90–C270 dashed, γ = 0 down, scaled to the file's peak).
// A card can be dragged onto a ceiling or a wall in the view (HTML drag and drop, data type
// CATALOGUE_TYPE: the entry's id), or clicked to arm it: the next click in the view places it
// (layout.js). "Upload…" sends a local .ies/.ldt file (≤ 5 MB, read as Latin-1 text so that
// every byte reaches the server's parser); the server parses and stores it and sends every
// client the new catalogue.
import { el, notice } from './ui.js';

export const CATALOGUE_TYPE = 'application/x-relight-photometry';
export const MAX_UPLOAD_BYTES = 5 * 1024 * 1024;

const fmt = (x, digits = 0) => (x === null || x === undefined ? '–' : Number(x).toFixed(digits));

// The polar plot of an entry's `polar` ({gamma_deg, c0, c90, c180, c270}) on a canvas.
export function drawPolar(canvas, polar) {
  const ctx = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height, cx = w / 2, cy = h / 2, r = Math.min(w, h) / 2 - 3;
  ctx.clearRect(0, 0, w, h);
  ctx.strokeStyle = '#555';
  ctx.lineWidth = 1;
  for (const f of [0.5, 1]) {
    ctx.beginPath();
    ctx.arc(cx, cy, r * f, 0, 2 * Math.PI);
    ctx.stroke();
  }
  const peak = Math.max(1e-9, ...['c0', 'c90', 'c180', 'c270'].flatMap((k) => polar[k]));
  const curve = (right, left, colour, dash) => {
    ctx.beginPath();
    ctx.setLineDash(dash);
    ctx.strokeStyle = colour;
    const G = polar.gamma_deg;
    const pts = [...G.map((g, k) => [g, polar[right][k], 1]), ...G.map((g, k) => [g, polar[left][k], -1]).reverse()];
    pts.forEach(([g, cd, side], k) => {
      const a = (g * Math.PI) / 180, s = (r * cd) / peak;
      const x = cx + side * s * Math.sin(a), y = cy + s * Math.cos(a);
      if (k === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    });
    ctx.stroke();
    ctx.setLineDash([]);
  };
  curve('c0', 'c180', '#ffcc44', []);
  curve('c90', 'c270', '#66aaff', [3, 2]);
}

export class CataloguePanel {
  // send(message) → seq or null; onArm(entry or null) when a card is armed or disarmed.
  constructor(container, send, onArm) {
    this.container = container;
    this.send = send;
    this.onArm = onArm;
    this.entries = [];
    this.armed = null;
    this.list = el('div', { class: 'catalogue-list', dataset: { testid: 'catalogue' } });
    this.file = el('input', { type: 'file', accept: '.ies,.IES,.ldt,.LDT', hidden: true, dataset: { testid: 'upload-file' } });
    this.file.addEventListener('change', () => {
      const f = this.file.files[0];
      this.file.value = '';
      if (f) this.upload(f);
    });
    const upload = el('label', { class: 'button', title: 'Add an IES LM-63 or EULUMDAT file (at most 5 MB) to the catalogue: the server checks it with its parsers and stores it' }, ['Upload…', this.file]);
    this.hint = el('p', { class: 'hint', text: 'No catalogue: start the server with relight serve SCENE.rlt --photometry DIR.' });
    container.append(el('div', { class: 'row' }, [upload]), this.hint, this.list);
  }

  entry(id) {
    return this.entries.find((e) => e.id === id) ?? null;
  }

  // A `catalogue` message: the list anew (an upload by any client adds to it).
  setCatalogue(msg) {
    this.entries = msg.entries;
    this.hint.hidden = true;
    this.list.innerHTML = '';
    for (const e of msg.entries) this.list.append(this._card(e));
    for (const r of msg.rejected ?? []) {
      this.list.append(el('div', { class: 'hint catalogue-rejected', title: r.message, text: `✗ ${r.id}: not readable` }));
    }
    if (this.armed && !this.entry(this.armed.id)) this.arm(null);
  }

  _card(e) {
    const s = e.summary;
    const polar = el('canvas', { width: 64, height: 64, class: 'polar', title: 'Polar plot: C0–C180 (solid), C90–C270 (dashed), γ = 0 down' });
    drawPolar(polar, e.polar);
    const title = [s.luminaire || e.name, s.manufacturer].filter(Boolean).join(' · ');
    const card = el('div', {
      class: 'catalogue-entry',
      draggable: 'true',
      dataset: { id: e.id, testid: `catalogue-${e.id}` },
      title: `${e.id}${e.uploaded ? ' (uploaded)' : ''}\n${s.format}${s.catalogue ? `, ${s.catalogue}` : ''}\nDrag onto a ceiling or wall, or click and then click in the view`,
    }, [
      polar,
      el('div', { class: 'catalogue-text' }, [
        el('div', { class: 'catalogue-name', text: title }),
        el('div', { class: 'hint', text: `${fmt(s.lumens)} lm · ${s.watts === null ? '– W' : `${fmt(s.watts, 1)} W`} · beam ${fmt(s.beam_angle_deg)}°` }),
        el('div', { class: 'hint', text: e.name }),
      ]),
    ]);
    card.addEventListener('dragstart', (ev) => {
      ev.dataTransfer.setData(CATALOGUE_TYPE, e.id);
      ev.dataTransfer.setData('text/plain', e.id);
      ev.dataTransfer.effectAllowed = 'copy';
    });
    card.addEventListener('click', () => this.arm(this.armed?.id === e.id ? null : e));
    return card;
  }

  arm(entry) {
    this.armed = entry;
    for (const c of this.list.querySelectorAll('.catalogue-entry')) c.classList.toggle('active', c.dataset.id === entry?.id);
    this.onArm(entry);
  }

  async upload(file) {
    if (file.size > MAX_UPLOAD_BYTES) {
      notice(`${file.name}: ${file.size} bytes, over the upload limit of 5 MB`, 'error');
      return;
    }
    const text = new TextDecoder('latin1').decode(await file.arrayBuffer());
    if (this.send({ type: 'upload', name: file.name, text }) === null) notice('Upload: not connected', 'error');
  }
}
