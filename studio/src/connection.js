// The WebSocket to `relight serve` (ws(s)://<host>/ws, docs/studio-protocol.md): connects,
// reconnects with a growing delay (1 s … 10 s) when the connection drops, numbers the
// client's messages (seq), routes text messages by "type" and binary ones by their 4-byte
// tag, and pings every 10 s to measure the round trip.
import { binaryTag, messages } from './protocol.js';

export class Connection {
  constructor(url, handlers) {
    this.url = url;
    this.handlers = handlers; // {open, close, text(msg), binary(tag, buffer), status(text), clientError(text)}
    this.seq = 0;
    this.ws = null;
    this.retryMs = 1000;
    this.pingSent = new Map();
    this.rttMs = null;
    this.connected = false;
    this.pingTimer = setInterval(() => this.ping(), 10000);
  }

  connect() {
    this.handlers.status?.('connecting');
    const ws = new WebSocket(this.url);
    ws.binaryType = 'arraybuffer';
    this.ws = ws;
    ws.onopen = () => {
      this.connected = true;
      this.retryMs = 1000;
      this.handlers.status?.('connected');
      this.handlers.open?.();
      this.ping();
    };
    ws.onclose = (event) => {
      if (this.ws !== ws) return;
      this.connected = false;
      const why = event.code === 1009 ? ' (message too big)' : event.code === 1007 ? ' (invalid UTF-8)' : '';
      this.handlers.status?.(`disconnected${why}: retrying in ${Math.round(this.retryMs / 1000)} s`);
      this.handlers.close?.(event);
      setTimeout(() => this.connect(), this.retryMs);
      this.retryMs = Math.min(10000, this.retryMs * 2);
    };
    ws.onerror = () => {};
    ws.onmessage = (event) => {
      if (typeof event.data === 'string') {
        let msg;
        try {
          msg = JSON.parse(event.data);
        } catch (e) {
          this.handlers.clientError?.(`server sent malformed JSON: ${e.message}`);
          return;
        }
        if (msg.type === 'pong' && this.pingSent.has(msg.seq)) {
          this.rttMs = performance.now() - this.pingSent.get(msg.seq);
          this.pingSent.delete(msg.seq);
        }
        this.handlers.text?.(msg);
      } else {
        this.handlers.binary?.(binaryTag(event.data), event.data);
      }
    };
  }

  nextSeq() {
    return ++this.seq;
  }

  // JSON-encodes and sends; false when not connected.
  send(obj) {
    return this.sendRaw(JSON.stringify(obj));
  }

  sendRaw(data) {
    if (!this.ws || this.ws.readyState !== WebSocket.OPEN) return false;
    this.ws.send(data);
    return true;
  }

  ping() {
    if (!this.connected) return;
    const seq = this.nextSeq();
    this.pingSent.set(seq, performance.now());
    if (this.pingSent.size > 20) this.pingSent.delete(this.pingSent.keys().next().value);
    this.send(messages.ping(seq));
  }
}
