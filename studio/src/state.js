// The client's lighting-state document (docs/lighting-state.md): it starts as hello.state,
// every control edits it, and the WHOLE document is sent as {"type":"state","seq":n,
// "state":doc} (the server applies a state to the scene's own values, so a state names
// everything that differs from the scene). Edits are sent at most once per animation frame
// (the server coalesces anyway: latest state wins). The server's `state` replies are
// matched to what this client sent: an echo of our own latest state changes nothing, an
// echo of an older one of ours is stale and ignored, any other state (another client, or a
// message sent around this store) replaces the document and refreshes the panels. A state
// the server refuses (an error reply to it) is undone: the document returns to the one shown.
// Also: save the document as a JSON download and load one from a file, and undo / redo: every
// local edit is a step (kMaxUndo kept), except that edits under the same gesture key within
// GESTURE_MS of each other (a slider or a drag) make one step.

import { downloadBlob } from './ui.js';

export const clone = (x) => (x === undefined ? undefined : JSON.parse(JSON.stringify(x)));

// JSON with sorted keys, for comparing documents whatever their key order.
export function canonical(x) {
  if (Array.isArray(x)) return `[${x.map(canonical).join(',')}]`;
  if (x && typeof x === 'object') {
    return `{${Object.keys(x).sort().map((k) => `${JSON.stringify(k)}:${canonical(x[k])}`).join(',')}}`;
  }
  return JSON.stringify(x);
}

// Drops empty luminaire/portal/emitter/object/material entries and empty top-level objects.
function prune(doc) {
  for (const key of ['luminaires', 'portals', 'exterior', 'emitters', 'objects', 'materials']) {
    const o = doc[key];
    if (!o || typeof o !== 'object') continue;
    if (key !== 'exterior') {
      for (const name of Object.keys(o)) {
        const entry = o[name];
        if (entry && typeof entry === 'object' && !Array.isArray(entry)) {
          if (entry.exterior && Object.keys(entry.exterior).length === 0) delete entry.exterior;
          if (Object.keys(entry).length === 0) delete o[name];
        }
      }
    }
    if (Object.keys(o).length === 0) delete doc[key];
  }
  return doc;
}

export const MAX_UNDO = 100;
const GESTURE_MS = 600;

export class StateStore {
  constructor(connection) {
    this.connection = connection;
    this.doc = {};
    this.listeners = [];
    this.sent = new Map(); // seq → {canon, time}
    this.latestSeq = null;
    this.lastSentCanon = null;
    this.myClient = null;
    this.foreignSeqs = new Set();
    this.lastRemote = null; // {client, frame, seq}
    this._scheduled = false;
    this.undoStack = [];
    this.redoStack = [];
    this._gesture = null; // {key, time} of the last recorded edit
  }

  // listener(source): source is 'local' (an edit here) or 'remote' (a replaced document).
  onChange(listener) {
    this.listeners.push(listener);
  }

  _notify(source) {
    for (const l of this.listeners) l(source);
  }

  // A new connection: the server's current state; `client` is this connection's number from
  // hello, so that echoes of our own states are told from other clients' by number.
  reset(doc, client = null) {
    this.doc = clone(doc || {});
    this.shown = clone(this.doc);
    this.sent.clear();
    this.latestSeq = null;
    this.lastSentCanon = canonical(this.doc);
    this.myClient = client;
    this.refusedSeq = null;
    this._scheduled = false;
    this.undoStack = [];
    this.redoStack = [];
    this._gesture = null;
    this._notify('remote');
  }

  // Keeps the document before an edit as an undo step, unless the edit continues the gesture
  // (same key, soon after) whose step is already kept. A key of null is always a new step.
  _record(key) {
    const now = performance.now();
    const same = key !== null && this._gesture?.key === key && now - this._gesture.time < GESTURE_MS;
    this._gesture = { key, time: now };
    if (same) return;
    this.undoStack.push(clone(this.doc));
    if (this.undoStack.length > MAX_UNDO) this.undoStack.shift();
    this.redoStack = [];
  }

  canUndo() {
    return this.undoStack.length > 0;
  }
  canRedo() {
    return this.redoStack.length > 0;
  }

  // Back to the document before the last step (sent at once); false when there is none.
  undo() {
    if (!this.undoStack.length) return false;
    this.redoStack.push(clone(this.doc));
    this.doc = this.undoStack.pop();
    this._gesture = null;
    this._notify('local');
    this.sendNow(true);
    return true;
  }

  redo() {
    if (!this.redoStack.length) return false;
    this.undoStack.push(clone(this.doc));
    this.doc = this.redoStack.pop();
    this._gesture = null;
    this._notify('local');
    this.sendNow(true);
    return true;
  }

  // Luminaire / portal / emitter / movable object entry of the document, created on demand.
  luminaire(name) {
    this.doc.luminaires ??= {};
    return (this.doc.luminaires[name] ??= {});
  }
  portal(name) {
    this.doc.portals ??= {};
    return (this.doc.portals[name] ??= {});
  }
  emitter(name) {
    this.doc.emitters ??= {};
    return (this.doc.emitters[name] ??= {});
  }
  object(name) {
    this.doc.objects ??= {};
    return (this.doc.objects[name] ??= {});
  }

  // fn(doc) edits the document; it is then sent (throttled). `gesture`: edits with the same
  // key in quick succession are one undo step (default: one key for all continuous edits);
  // null makes this edit a step of its own (placing, deleting, an array).
  edit(fn, gesture = 'edit') {
    this._record(gesture);
    fn(this.doc);
    prune(this.doc);
    this._notify('local');
    this.scheduleSend();
  }

  // Replaces the whole document and sends it at once (load, reset, test hook): an undo step.
  replace(doc) {
    this._record(null);
    this.doc = prune(clone(doc || {}));
    this._notify('local');
    this.sendNow(true);
  }

  scheduleSend() {
    if (this._scheduled) return;
    this._scheduled = true;
    const fire = () => {
      if (!this._scheduled) return;
      this._scheduled = false;
      this.sendNow(false);
    };
    requestAnimationFrame(fire);
    setTimeout(fire, 100); // when animation frames are throttled (hidden page)
  }

  // Sends the document; unless forced, not when it equals the last one sent.
  sendNow(force) {
    this._scheduled = false;
    const canon = canonical(this.doc);
    if (!force && canon === this.lastSentCanon) return null;
    const seq = this.connection.nextSeq();
    if (!this.connection.send({ type: 'state', seq, state: this.doc })) return null;
    this.sent.set(seq, { canon, time: performance.now() });
    if (this.sent.size > 200) this.sent.delete(this.sent.keys().next().value);
    this.latestSeq = seq;
    this.lastSentCanon = canon;
    return seq;
  }

  // Time at which state seq was sent by this store (for latency), if it was.
  sentTime(seq) {
    return this.sent.get(seq)?.time;
  }

  // A `state` message from the server.
  applyRemote(msg) {
    this.shown = clone(msg.state || {});
    const mine = msg.seq != null && this.sent.get(msg.seq);
    const isMine =
      mine && (this.myClient != null ? msg.client === this.myClient : canonical(msg.state) === mine.canon);
    if (isMine) {
      if (this.myClient == null && msg.client != null) this.myClient = msg.client;
      // After a refusal the document went back to the state shown then; an echo of an
      // earlier state of ours that the server applied since is the state shown now.
      const afterRefusal = this.refusedSeq != null && this.latestSeq === this.refusedSeq &&
        msg.seq < this.refusedSeq && !this._scheduled;
      if (afterRefusal) {
        this.doc = clone(msg.state || {});
        this.lastSentCanon = canonical(this.doc);
        this._notify('remote');
        return 'mine';
      }
      if (msg.seq !== this.latestSeq || this._scheduled) return 'stale';
      return 'mine';
    }
    if (msg.seq != null && this.sent.has(msg.seq)) this.foreignSeqs.add(msg.seq);
    this.lastRemote = { client: msg.client, frame: msg.frame, seq: msg.seq };
    this._scheduled = false;
    this.doc = clone(msg.state || {});
    this.lastSentCanon = canonical(this.doc);
    this._notify('remote');
    return 'remote';
  }

  // An error reply: when it refuses the latest state this store sent, the document goes back
  // to the state the server shows (otherwise every later edit would resend the refused
  // value and be refused too). Returns whether it did.
  refused(seq) {
    if (seq == null || seq !== this.latestSeq || !this.sent.has(seq)) return false;
    this._scheduled = false;
    this.refusedSeq = seq;
    this.doc = clone(this.shown ?? {});
    this.lastSentCanon = canonical(this.doc);
    this._notify('remote');
    return true;
  }

  // Download the document as JSON.
  save(filename = 'lighting-state.json') {
    downloadBlob(new Blob([JSON.stringify(this.doc, null, 2) + '\n'], { type: 'application/json' }), filename);
  }

  // Load a state file (File from an <input type=file>) and send it.
  async load(file) {
    const text = await file.text();
    const doc = JSON.parse(text);
    if (!doc || typeof doc !== 'object' || Array.isArray(doc)) throw new Error('a state file is a JSON object');
    this.replace(doc);
  }
}
