// Hostile WebSocket frames (issue 16): a studio message that declares 1 GiB, or the most a
// frame can declare (2^63 − 1, and 2^64 − 1 with the top bit RFC 6455 requires to be 0), must be refused
// from its header, before the server allocates for it, within 1 s, and a message whose
// fragments add up past the server's 8 MiB limit (kMaxClientMessageBytes) must be refused when
// the fragment that crosses it arrives. The frames are written by hand on a raw TCP connection
// (node:net) after a hand-made upgrade, since a WebSocket library would not send them.
//
// What the server does (websocketpp's hybi13 processor, drop_on_protocol_error off): it sends
// a close frame with 1009 ("A message was too large"), stops reading and closes the TCP
// connection at once (1009 is a terminal close code: it does not wait for the client's close).
// Each refusal is timed from the moment the offending header was written; the server's peak
// resident memory (VmHWM, reset through /proc/PID/clear_refs before each case) is compared with
// its memory before; and a client connected before every case still gets its pong, as does a
// client connected after them all.
import test from 'node:test';
import assert from 'node:assert/strict';
import crypto from 'node:crypto';
import fs from 'node:fs';
import net from 'node:net';

import {
  assertMemory, connect, residentKiB, startServer, stopServer,
} from './studio_support.mjs';

const kMiB = 1 << 20;
const kRefuseWithinMs = 1000;
const kMaxGrowthKiB = 64 * 1024;

// The peak resident memory (VmHWM, KiB) since the last resetPeak().
function peakKiB(pid) {
  return Number(fs.readFileSync(`/proc/${pid}/status`, 'utf8').match(/VmHWM:\s+(\d+)/)[1]);
}
// Writing 5 to clear_refs sets VmHWM to the current VmRSS (Linux ≥ 4.0). Returns false where
// that is not allowed (then only VmRSS after the case is compared).
function resetPeak(pid) {
  try { fs.writeFileSync(`/proc/${pid}/clear_refs`, '5'); return true; } catch { return false; }
}

// A client frame header: FIN, opcode, the payload length in the shortest form RFC 6455 allows
// (`length` a BigInt for the 64-bit form), and the masking key (clients must mask).
const kMask = Buffer.from([0x37, 0xfa, 0x21, 0x3d]);
function frameHeader({ fin = true, opcode = 1, length }) {
  const n = BigInt(length);
  const first = (fin ? 0x80 : 0) | opcode;
  let h;
  if (n < 126n) h = Buffer.from([first, 0x80 | Number(n)]);
  else if (n < 65536n) { h = Buffer.alloc(4); h[0] = first; h[1] = 0x80 | 126; h.writeUInt16BE(Number(n), 2); }
  else { h = Buffer.alloc(10); h[0] = first; h[1] = 0x80 | 127; h.writeBigUInt64BE(n, 2); }
  return Buffer.concat([h, kMask]);
}
// The first bytes of a frame's payload, masked: `count` letters "a" as the server unmasks them
// (valid UTF-8: the server validates text as it arrives and would close with 1007 otherwise).
function maskedText(count) {
  const b = Buffer.alloc(count, 0x61);
  for (let i = 0; i < count; ++i) b[i] ^= kMask[i & 3];
  return b;
}

// A raw WebSocket connection: upgrades by hand, then parses the server's frames. Resolves
// once the first RLFR has arrived (hello, RLGE and the frame sent: the server's send queue is
// empty, so what it does next is the answer to what we send), or with `atUpgrade` as soon as
// the 101 has.
function rawConnection(port, { atUpgrade = false } = {}) {
  return new Promise((resolve, reject) => {
    const socket = net.connect(port, '127.0.0.1');
    const c = { socket, frames: [], closeFrame: null, closedAt: null, errors: [], unparsed: 0 };
    c.done = new Promise((r) => socket.on('close', () => { c.closedAt = performance.now(); r(); }));
    let buf = Buffer.alloc(0), upgraded = false, ready = false;
    socket.on('error', (e) => c.errors.push(e.code));
    socket.on('end', () => { c.unparsed = buf.length; });  // bytes of a frame cut off
    socket.on('data', (d) => {
      buf = Buffer.concat([buf, d]);
      if (!upgraded) {
        const end = buf.indexOf('\r\n\r\n');
        if (end < 0) return;
        const status = buf.subarray(0, end).toString('latin1').split('\r\n')[0];
        if (!status.startsWith('HTTP/1.1 101')) { reject(new Error(`upgrade refused: ${status}`)); return; }
        buf = buf.subarray(end + 4);
        upgraded = true;
        if (atUpgrade) { ready = true; resolve(c); }
      }
      while (buf.length >= 2) {
        let len = buf[1] & 0x7f, at = 2;
        if (len === 126) { if (buf.length < 4) break; len = buf.readUInt16BE(2); at = 4; }
        else if (len === 127) { if (buf.length < 10) break; len = Number(buf.readBigUInt64BE(2)); at = 10; }
        if (buf.length < at + len) break;
        const opcode = buf[0] & 0x0f, payload = buf.subarray(at, at + len);
        buf = buf.subarray(at + len);
        const frame = { opcode, at: performance.now(), tag: opcode === 2 ? payload.subarray(0, 4).toString('latin1') : null };
        if (opcode === 8) {
          c.closeFrame = { code: payload.length >= 2 ? payload.readUInt16BE(0) : null,
                           reason: payload.subarray(2).toString(), at: frame.at };
        }
        c.frames.push(frame);
        if (!ready && frame.tag === 'RLFR') { ready = true; resolve(c); }
      }
    });
    socket.once('close', () => { if (!ready) reject(new Error(`closed before the first frame: ${c.errors}`)); });
    socket.write(`GET /ws HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\nUpgrade: websocket\r\n` +
                 `Connection: Upgrade\r\nSec-WebSocket-Key: ${crypto.randomBytes(16).toString('base64')}\r\n` +
                 'Sec-WebSocket-Version: 13\r\n\r\n');
  });
}

let server, witness, pings = 0;
test.before(async () => {
  server = await startServer();
  witness = await connect(server.ws);  // connected before every case, stays open through all
  await witness.nextJson('hello');
});
test.after(async () => {
  witness.close();
  assert.equal(await stopServer(server), 0, server.stderr());
});

async function assertStillServing(client) {
  const seq = ++pings;
  const t0 = performance.now();
  client.send({ type: 'ping', seq });
  const pong = await client.next((m) => !m.binary && m.json.type === 'pong' && m.json.seq === seq, 5000);
  return pong.at - t0;
}

// Connects, lets `attack(socket)` write, and returns what the server did: when it closed the
// connection after the offending header (written at `sentAt`, set by attack), its close frame,
// and its memory.
async function refuse(attack, options) {
  const pid = server.proc.pid;
  const c = await rawConnection(server.port, options);
  const before = residentKiB(pid);
  const peakTracked = resetPeak(pid);
  const timer = setTimeout(() => c.socket.destroy(), 10000);
  const sentAt = await attack(c.socket);
  await c.done;
  clearTimeout(timer);
  const after = residentKiB(pid);
  const peak = peakTracked ? peakKiB(pid) : after;
  return { ...c, refusedMs: c.closedAt - sentAt, before, after, peak };
}

function report(name, r, pongMs) {
  console.log(`${name}: ${r.closeFrame ? `close frame ${r.closeFrame.code} "${r.closeFrame.reason}"` : 'no close frame'}, ` +
              `TCP closed ${r.refusedMs.toFixed(1)} ms after the header; server VmRSS ${r.before} → ${r.after} KiB, ` +
              `peak ${r.peak} KiB (+${r.peak - r.before} KiB); client errors [${r.errors}]; ` +
              `the other client's ping answered in ${pongMs.toFixed(1)} ms`);
}

function assertRefused(r) {
  assert.ok(r.closeFrame, 'the server sends a close frame before closing');
  assert.equal(r.closeFrame.code, 1009);
  assert.equal(r.closeFrame.reason, 'A message was too large');
  assert.ok(r.closedAt !== null);
  assert.ok(r.refusedMs <= kRefuseWithinMs, `closed ${r.refusedMs} ms after the header`);
  assertMemory(r.peak - r.before <= kMaxGrowthKiB, `peak grew ${r.peak - r.before} KiB`);
  assertMemory(r.after - r.before <= kMaxGrowthKiB, `grew ${r.after - r.before} KiB`);
}

// One text frame header declaring `length`, then a few KB of its payload; the client keeps the
// connection open (it would send the rest) until the server closes it.
const declaring = (length) => async (socket) => {
  socket.write(frameHeader({ length }));
  const sentAt = performance.now();
  socket.write(maskedText(4096));
  return sentAt;
};

for (const [name, length] of [['1 GiB (2^30 bytes)', 2n ** 30n],
                              ['2^63 - 1 bytes (the most RFC 6455 allows)', 2n ** 63n - 1n],
                              ['2^64 - 1 bytes (with the top bit RFC 6455 requires to be 0)', 2n ** 64n - 1n]]) {
  test(`a text frame declaring ${name} is refused from its header (1009) without allocating`, async () => {
    const r = await refuse(declaring(length));
    const pongMs = await assertStillServing(witness);
    report(`declaring ${name}`, r, pongMs);
    assertRefused(r);
  });
}

// Sent at once after the upgrade, while the server is still writing hello, RLGE (364 KB) and
// the first frame: refused as fast, but the 1009 close frame does not always arrive. The
// server closes its socket with the client's unread bytes still in its receive buffer, which
// makes the kernel reset the connection and drop what was still queued to send: measured
// 2026-12-03, in 6 tries of 27 the client saw the connection end part-way through RLGE
// (176,687 bytes of it) and no close frame. Either way the connection is refused and nothing
// is allocated.
test('a frame declaring 1 GiB sent before the server has sent the geometry is refused as fast', async () => {
  const r = await refuse(declaring(2n ** 30n), { atUpgrade: true });
  report('declaring 1 GiB at the upgrade', r, await assertStillServing(witness));
  console.log(`declaring 1 GiB at the upgrade: received [${r.frames.map((f) => f.tag ?? f.opcode)}]` +
              `${r.unparsed ? ` and ${r.unparsed} bytes of a frame cut off` : ''}`);
  if (r.closeFrame) assert.equal(r.closeFrame.code, 1009);
  assert.ok(r.refusedMs <= kRefuseWithinMs, `closed ${r.refusedMs} ms after the header`);
  assertMemory(r.peak - r.before <= kMaxGrowthKiB, `peak grew ${r.peak - r.before} KiB`);
});

test('a binary frame declaring 1 GiB is refused the same way', async () => {
  const r = await refuse(async (socket) => {
    socket.write(frameHeader({ opcode: 2, length: 2n ** 30n }));
    const sentAt = performance.now();
    socket.write(maskedText(4096));
    return sentAt;
  });
  report('binary declaring 1 GiB', r, await assertStillServing(witness));
  assertRefused(r);
});

test('fragments of 3 MiB are refused at the third, whose header takes the message past 8 MiB', async () => {
  const part = maskedText(3 * kMiB);
  // A text frame without FIN and a continuation (6 MiB, under the limit), then the header of a
  // second continuation declaring 3 MiB more (9 MiB > 8 MiB) and a few KB of it. (A client
  // still writing when the server closes gets EPIPE and node drops what it had received, the
  // close frame included: so the client stops after those few KB, as above.)
  const attack = async (socket) => {
    socket.write(Buffer.concat([frameHeader({ fin: false, opcode: 1, length: part.length }), part]));
    socket.write(Buffer.concat([frameHeader({ fin: false, opcode: 0, length: part.length }), part]));
    await new Promise((resolve) => socket.write(Buffer.alloc(0), resolve));  // handed to the kernel
    socket.write(frameHeader({ fin: false, opcode: 0, length: part.length }));
    const sentAt = performance.now();
    socket.write(part.subarray(0, 4096));
    return sentAt;
  };
  const runs = [];
  for (let i = 0; i < 3; ++i) {
    const r = await refuse(attack);
    report(`fragments 3 + 3 + 3 MiB (${i + 1} of 3)`, r, await assertStillServing(witness));
    assertRefused(r);
    // It held the two fragments it accepted (6 MiB, under the limit) and refused the third
    // from its header.
    assertMemory(r.peak - r.before <= 16 * 1024, `peak grew ${r.peak - r.before} KiB`);
    runs.push(r);
  }
  // The first run leaves ~8 MiB resident (glibc keeps the freed buffers); the next ones reuse
  // it: no growth per refused message.
  assertMemory(runs[2].after - runs[0].after <= 2 * 1024,
            `grew ${runs[2].after - runs[0].after} KiB over two more refused messages`);
});

test('the server still serves: a new client gets its hello, a pong and a relit frame', async () => {
  const c = await connect(server.ws);
  const hello = await c.nextJson('hello');
  await assertStillServing(c);
  c.send({ type: 'state', seq: 77, state: { luminaires: { [hello.luminaires[0].name]: { dimmer: 0.5 } } } });
  const f = await c.next((m) => m.binary && m.tag === 'RLFR' && m.data.readUInt32LE(8) === 77);
  assert.equal(f.data.readUInt32LE(12), hello.vertices);
  c.close();
  assert.equal(witness.closed, null, 'the client connected before the hostile frames is still open');
  assert.doesNotMatch(server.stderr(), /internal error/);
});
