// "Open model…" (docs/studio-protocol.md, "open_model"): sends a building model (IFC, glTF,
// OBJ; at most 200 MB) to the server in 1 MB RLMU pieces, one after the server's reply to the
// last (so that the page never queues the whole file), and shows what the server reports to
// every client: the upload, the import's summary, the precompute's phases, or the failure. When
// the model is precomputed the server reopens on it; the page then reloads to show it.
import { el, notice } from './ui.js';

export const MAX_MODEL_BYTES = 200 * 1024 * 1024;
const CHUNK_BYTES = 1024 * 1024;
const TAG = new TextEncoder().encode('RLMU');

const percent = (f) => `${Math.round(100 * f)}%`;

// The import's one-line summary in a designer's words.
function summaryText(s) {
  if (!s) return 'imported';
  const parts = [
    [s.windows, 'window'], [s.portals, 'portal'], [s.spaces, 'space'],
    [s.luminaires, 'luminaire'], [s.triangles, 'triangle'],
  ].filter(([n]) => Number.isFinite(n)).map(([n, w]) => `${n} ${w}${n === 1 ? '' : 's'}`);
  return `imported: ${parts.join(', ')}`;
}

export class ModelOpener {
  // The button goes in `container`, the progress in `statusContainer`; send(message) → seq or
  // null; sendBinary(bytes) → false when not connected.
  constructor(container, statusContainer, send, sendBinary) {
    this.send = send;
    this.sendBinary = sendBinary;
    this.file = null; // the file this client is sending, while it sends it
    this.seq = null;
    this.reopening = false; // the server is reopening on a model: reload when it is back
    this.messages = []; // every `model` message, for tests
    this.input = el('input', { type: 'file', accept: '.ifc,.gltf,.glb,.obj', hidden: true, dataset: { testid: 'model-file' } });
    this.input.addEventListener('change', () => {
      const f = this.input.files[0];
      this.input.value = '';
      if (f) this.open(f);
    });
    const button = el('label', {
      class: 'button',
      title: 'Open a building model (IFC, glTF with embedded buffers, or OBJ; at most 200 MB): the server imports it with relight import, precomputes it, and the studio shows it',
    }, ['Open model…', this.input]);
    this.bar = el('progress', { max: 1, value: 0 });
    this.text = el('span', { class: 'hint', dataset: { testid: 'model-progress' } });
    this.progress = statusContainer;
    this.progress.hidden = true;
    this.progress.append(this.bar, this.text);
    container.append(button);
  }

  open(file) {
    if (file.size > MAX_MODEL_BYTES) {
      notice(`${file.name}: ${(file.size / 1048576).toFixed(0)} MB, over the 200 MB limit of a model`, 'error');
      return;
    }
    const seq = this.send({ type: 'open_model', name: file.name, bytes: file.size });
    if (seq === null) {
      notice('Open model: not connected', 'error');
      return;
    }
    this.file = file;
    this.seq = seq;
    this.show(`sending ${file.name}`, 0);
  }

  show(text, fraction) {
    this.progress.hidden = false;
    this.text.textContent = text;
    if (fraction === null) this.bar.removeAttribute('value');
    else this.bar.value = fraction;
  }

  async sendPiece(from) {
    const end = Math.min(this.file.size, from + CHUNK_BYTES);
    const bytes = new Uint8Array(await this.file.slice(from, end).arrayBuffer());
    const message = new Uint8Array(TAG.length + bytes.length);
    message.set(TAG, 0);
    message.set(bytes, TAG.length);
    if (!this.sendBinary(message)) this.fail('the connection dropped while sending');
  }

  // A `model` message (to every client).
  onModel(msg) {
    this.messages.push(msg);
    const name = msg.name ?? 'the model';
    switch (msg.stage) {
      case 'receiving':
        if (this.file && msg.seq === this.seq && msg.done < msg.total) {
          this.show(`sending ${name}: ${percent(msg.done / msg.total)}`, msg.done / msg.total);
          this.sendPiece(msg.done).catch((e) => this.fail(`cannot read the file: ${e.message}`));
        }
        return;
      case 'importing':
        this.file = null;
        return this.show(`importing ${name}…`, null);
      case 'imported':
        return this.show(`${name} ${summaryText(msg.summary)}; precomputing…`, null);
      case 'precomputing':
        return this.show(`precomputing ${name}: ${msg.phase} ${percent(msg.fraction)}`, msg.fraction);
      case 'opening':
        this.reopening = true;
        for (const w of msg.warnings ?? []) notice(`${name}: ${w}`, 'info');
        return this.show(`opening ${msg.scene}…`, 1);
      case 'failed':
        this.file = null;
        this.show(`${name} could not be opened: ${msg.message}`, 0);
        notice(`Open model: ${msg.message}`, 'error');
        return;
      default:
    }
  }

  // An `error` reply: true when it answers this client's open_model or one of its pieces.
  onError(msg) {
    if (!this.file || !(msg.seq === this.seq || msg.seq === null || msg.seq === undefined)) return false;
    this.fail(msg.message);
    return true;
  }

  fail(message) {
    const name = this.file?.name ?? 'the model';
    this.file = null;
    this.show(`${name} could not be opened: ${message}`, 0);
    notice(`Open model: ${message}`, 'error');
  }
}
