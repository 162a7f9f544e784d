#!/usr/bin/env node
// `make soak [MINUTES=10]`: a studio soak. Starts `relight serve` on a scene (the demo
// room the studio tests use, build/studio-demo/demo-room.rlt, unless an .rlt is given) and
// connects 16 WebSocket clients on loopback for M minutes. Each sends, every 20–100 ms, a mix
// of whole lighting states (its dimmers and colours of the scene's luminaires, from
// hello.luminaires), picks, pings and malformed messages (bad JSON, an unknown type, bad
// values, a zero pick direction, a binary message), as a design review with every participant
// busy at once would.
//
// Timeline: a warm-up (1 minute), then the measured time in two halves: in the first all 16
// clients read; at the start of the second one client stops reading its socket (paused; it
// goes on sending) until the end, so the two halves compare the 15 others' latencies without
// and with a stalled client. Then the clients stop sending, the stalled client reads again
// for 3 s (what it gets is what the server held for it), every client is closed and, 2 s
// later, the server's memory is read again.
//
// Measured and printed (a readable summary, then one JSON line):
//   - no crash: the server still running, a fresh client's ping answered and a state relit at
//     the end, and its exit code on SIGTERM (0);
//   - resident memory (VmRSS) after the warm-up and at the end (after the stalled client was
//     closed), and the most while a client was stalled;
//   - server-side state→frame time: the `ms` of every RLFR header (docs/studio-protocol.md:
//     the milliseconds the server spent on that frame, relight and per-vertex values, encoding
//     excluded), p50/p99, once per frame;
//   - client-side latencies of the reading clients, without and with the stalled client: from
//     sending a state to receiving the frame that carries its seq (states a later one
//     superseded get no frame of their own: counted, not timed), and ping → pong;
//   - messages sent, error replies (one per malformed message expected), frames received.
// Exits 1 when a limit is violated: memory growth over 16 MiB, server-side p99 over 20 ms, a
// crash (or a reading client closed, or a malformed message without its error reply); 2 on a
// usage error or a failure of the soak itself.
//
// Usage: node scripts/studio-soak.mjs [SCENE.rlt] [--minutes M] [--warmup-seconds S]
//        [--clients N] [--binary PATH]
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { monitorEventLoopDelay } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

function parseArgs(argv) {
  const o = { minutes: 10, warmupSeconds: 60, clients: 16, scene: null,
              binary: process.env.RELIGHT_BINARY ?? path.join(root, process.env.BUILD ?? 'build', 'relight') };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const value = () => { if (i + 1 >= argv.length) throw new Error(`${a} needs a value`); return argv[++i]; };
    if (a === '--minutes') o.minutes = Number(value());
    else if (a === '--warmup-seconds') o.warmupSeconds = Number(value());
    else if (a === '--clients') o.clients = Number(value());
    else if (a === '--binary') o.binary = value();
    else if (a === '-h' || a === '--help') { console.log(fs.readFileSync(fileURLToPath(import.meta.url), 'utf8').split('\nimport ')[0]); process.exit(0); }
    else if (!a.startsWith('-') && !o.scene) o.scene = a;
    else throw new Error(`unknown argument ${a}`);
  }
  o.scene ??= process.env.STUDIO_SCENE ?? path.join(root, process.env.BUILD ?? 'build', 'studio-demo', 'demo-room.rlt');
  if (!(o.minutes > 0) || !(o.warmupSeconds >= 0) || o.warmupSeconds >= 60 * o.minutes) {
    throw new Error('--minutes must be positive and longer than the warm-up');
  }
  if (!(o.clients >= 2)) throw new Error('--clients must be at least 2 (one of them stalls)');
  for (const [what, p] of [['relight binary', o.binary], ['scene', o.scene]]) {
    if (!fs.existsSync(p)) throw new Error(`no ${what} at ${p} (make build; the demo room: make soak makes it, or relight demo --no-serve -o build/studio-demo)`);
  }
  return o;
}

let opts;
try {
  opts = parseArgs(process.argv.slice(2));
} catch (e) {
  console.error(`studio-soak: ${e.message}`);
  process.exit(2);
}
process.env.RELIGHT_BINARY = opts.binary;
process.env.STUDIO_SCENE = opts.scene;
const { requireStudio, residentKiB, startServer, stopServer } = await import('../tests/studio/studio_support.mjs');
const WebSocket = requireStudio('ws');

const kMaxGrowthKiB = 16 * 1024;
const kMaxServerP99Ms = 20;
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

function percentile(values, p) {
  if (!values.length) return null;
  const s = Float64Array.from(values).sort();
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil((p / 100) * s.length) - 1))];
}
const stats = (values) => ({ n: values.length, p50: round(percentile(values, 50)), p99: round(percentile(values, 99)),
                             max: round(values.length ? Math.max(...values) : null) });
const round = (x) => (x === null ? null : Math.round(x * 100) / 100);

// A deterministic generator (xorshift32) per client.
function random(seed) {
  let s = seed >>> 0 || 1;
  const next = () => { s ^= s << 13; s >>>= 0; s ^= s >>> 17; s ^= s << 5; s >>>= 0; return s / 4294967296; };
  return { next, int: (n) => Math.floor(next() * n), pick: (l) => l[Math.floor(next() * l.length)] };
}

let phase = 'warmup';  // 'warmup' | 'without' | 'with' | 'end'
const serverMs = new Map();  // frame number -> ms (RLFR header)

class SoakClient {
  constructor(index, url, hello) {
    this.index = index;
    this.r = random(1000 + 7919 * index);
    this.stalled = false;
    this.closedCode = null;
    this.sent = { state: 0, pick: 0, ping: 0, malformed: 0 };
    this.received = { frames: 0, states: 0, picks: 0, pongs: 0, errors: 0, other: 0, bytes: 0 };
    this.pendingStates = new Map();  // seq -> {t, phase}
    this.pendingPings = new Map();
    this.superseded = { without: 0, with: 0, warmup: 0, end: 0 };
    this.lat = { without: { state: [], ping: [] }, with: { state: [], ping: [] }, warmup: { state: [], ping: [] }, end: { state: [], ping: [] } };
    this.counter = 0;
    this.url = url;
  }
  open() {
    return new Promise((resolve, reject) => {
      this.ws = new WebSocket(this.url);
      this.ws.on('error', (e) => { if (!this.helloSeen) reject(e); });
      this.ws.on('close', (code) => { this.closedCode = code; this.closedAt = phase; });
      this.ws.on('message', (data, isBinary) => {
        const at = performance.now();
        this.received.bytes += data.length;
        if (isBinary) {
          if (data.length >= 24 && data.toString('latin1', 0, 4) === 'RLFR') {
            this.received.frames++;
            const frame = data.readUInt32LE(4), seq = data.readUInt32LE(8);
            if (!serverMs.has(frame)) serverMs.set(frame, { ms: data.readFloatLE(20), phase });
            // Its own state's frame: every pending state before it was superseded.
            const p = this.pendingStates.get(seq);
            if (p) {
              this.lat[p.phase].state.push(at - p.t);
              for (const [s, q] of this.pendingStates) {
                if (s === seq) break;
                this.superseded[q.phase]++;
                this.pendingStates.delete(s);
              }
              this.pendingStates.delete(seq);
            }
          } else this.received.other++;
          return;
        }
        const m = JSON.parse(data.toString());
        if (m.type === 'hello') { this.hello = m; this.helloSeen = true; resolve(this); }
        else if (m.type === 'state') this.received.states++;
        else if (m.type === 'pick') this.received.picks++;
        else if (m.type === 'error') this.received.errors++;
        else if (m.type === 'pong') {
          this.received.pongs++;
          const p = this.pendingPings.get(m.seq);
          if (p) { this.lat[p.phase].ping.push(at - p.t); this.pendingPings.delete(m.seq); }
        } else this.received.other++;
      });
    });
  }
  nextSeq() { this.counter = (this.counter + 1) & 0xffffff; return (this.index << 24) | this.counter; }
  state() {
    const r = this.r;
    const luminaires = {};
    for (const l of this.hello.luminaires) {
      luminaires[l.name] = r.next() < 0.5
        ? { on: true, dimmer: Math.round(r.next() * 1000) / 1000, color: [0.5 + r.next() / 2, 0.5 + r.next() / 2, 0.5 + r.next() / 2] }
        : { on: r.next() < 0.9, dimmer: Math.round(r.next() * 1000) / 1000, cct_kelvin: 2200 + r.int(4300) };
    }
    return { luminaires };
  }
  malformed(seq) {
    const r = this.r, lum = r.pick(this.hello.luminaires).name;
    return r.pick([
      `{"type":"state","seq":${seq},"state":{"luminaires":`,                                   // bad JSON
      JSON.stringify({ type: 'teleport', seq }),                                                // unknown type
      JSON.stringify({ type: 'state', seq, state: { luminaires: { [lum]: { dimmer: -1 } } } }),  // bad value
      JSON.stringify({ type: 'state', seq, state: { luminaires: { [lum]: { color: [0, 0, 0] } } } }),
      JSON.stringify({ type: 'state', seq, state: { luminaires: { 'no such lamp': { dimmer: 1 } } } }),
      JSON.stringify({ type: 'pick', seq, origin: [1, 1, 1], direction: [0, 0, 0] }),            // zero direction
      JSON.stringify({ type: 'state', seq, state: { luminaires: { [lum]: { dimmer: 'bright' } } } }),
      Buffer.from([0x52, 0x4c, 0x58, 0x58, 1, 2, 3]),                                            // binary
    ]);
  }
  tick() {
    if (this.closedCode !== null || phase === 'end') return;
    const r = this.r, kind = r.int(100), now = performance.now();
    const seq = this.nextSeq();
    if (kind < 50) {
      this.ws.send(JSON.stringify({ type: 'state', seq, state: this.state() }));
      if (!this.stalled) this.pendingStates.set(seq, { t: now, phase });
      this.sent.state++;
    } else if (kind < 75) {
      const b = this.hello.bounds;
      const origin = b.min.map((lo, k) => lo + (0.2 + 0.6 * r.next()) * (b.max[k] - lo));
      this.ws.send(JSON.stringify({ type: 'pick', seq, origin, direction: [r.next() - 0.5, r.next() - 0.5, r.next() - 0.5] }));
      this.sent.pick++;
    } else if (kind < 85) {
      this.ws.send(JSON.stringify({ type: 'ping', seq }));
      if (!this.stalled) this.pendingPings.set(seq, { t: now, phase });
      this.sent.ping++;
    } else {
      this.ws.send(this.malformed(seq));
      this.sent.malformed++;
    }
  }
  run() {
    const loop = () => {
      if (this.closedCode !== null || phase === 'end') return;
      this.tick();
      this.timer = setTimeout(loop, 20 + this.r.int(81));
    };
    this.timer = setTimeout(loop, this.r.int(100));
  }
  stall() { this.stalled = true; this.pendingStates.clear(); this.pendingPings.clear(); this.ws.pause(); }
  // Reads again: what arrives next is what the server (and the kernel's socket buffers) held.
  resume() {
    this.backlogFrom = { ...this.received };
    this.ws.resume();
  }
}

// This process's event-loop delay (ms, past the monitor's 10 ms timer): how late the soak's
// own clients could notice a message, part of every client-side latency.
const loopStats = (h) => ({ p50: round(Math.max(0, h.percentile(50) / 1e6 - 10)),
                            p99: round(Math.max(0, h.percentile(99) / 1e6 - 10)) });

function cpuSeconds(pid) {
  const f = fs.readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
  return (Number(f[11]) + Number(f[12])) / 100;  // utime + stime, in clock ticks (USER_HZ 100)
}

async function main() {
  const t0 = Date.now();
  const load = [os.loadavg()[0]];
  const server = await startServer();
  const pid = server.proc.pid;
  let crashed = null;
  server.proc.on('exit', (code, signal) => { if (phase !== 'end') crashed = `exited ${code ?? signal} during the soak`; });
  const rss = { start: residentKiB(pid) };
  console.log(`soak: relight serve ${path.relative(root, opts.scene)} (pid ${pid}, ${server.ws}); ` +
              `${opts.clients} clients for ${opts.minutes} min (warm-up ${opts.warmupSeconds} s); ` +
              `${os.cpus().length} cores, load ${load[0].toFixed(2)}`);
  const clients = [];
  for (let i = 0; i < opts.clients; ++i) clients.push(await new SoakClient(i, server.ws).open());
  for (const c of clients) c.run();
  const stalled = clients[clients.length - 1];
  const totalMs = opts.minutes * 60000, warmupMs = opts.warmupSeconds * 1000;
  const half = (totalMs - warmupMs) / 2;
  let rssMaxStalled = 0;
  const loopDelay = monitorEventLoopDelay({ resolution: 10 });
  loopDelay.enable();
  const cpu0 = cpuSeconds(pid);
  const sampler = setInterval(() => {
    if (crashed) return;
    try { if (phase === 'with') rssMaxStalled = Math.max(rssMaxStalled, residentKiB(pid)); } catch {}
  }, 1000);
  const progress = setInterval(() => {
    const m = ((Date.now() - t0) / 60000).toFixed(1);
    try { console.log(`soak: ${m} min, phase ${phase}, VmRSS ${residentKiB(pid)} KiB, frames ${serverMs.size}`); } catch {}
  }, 60000);

  await sleep(warmupMs);
  rss.warm = residentKiB(pid);
  phase = 'without';
  await sleep(half);
  rss.midpoint = residentKiB(pid);
  const loopWithout = loopStats(loopDelay);
  loopDelay.reset();
  phase = 'with';
  stalled.stall();
  await sleep(totalMs - warmupMs - half);
  phase = 'end';
  const loopWith = loopStats(loopDelay);
  loopDelay.disable();
  clearInterval(progress);
  clearInterval(sampler);
  const cpu1 = cpuSeconds(pid);
  rss.endStalled = crashed ? null : residentKiB(pid);
  const stalledClosedByServer = stalled.closedCode;
  // Let the replies in flight arrive; the stalled client reads again (what it gets is what was
  // held for it); then close every client.
  if (stalled.closedCode === null) stalled.resume();
  await sleep(3000);
  const backlog = stalled.backlogFrom
    ? Object.fromEntries(Object.entries(stalled.received).map(([k, v]) => [k, v - stalled.backlogFrom[k]]))
    : null;
  for (const c of clients) { clearTimeout(c.timer); c.ws.terminate(); }
  await sleep(2000);
  rss.end = crashed ? null : residentKiB(pid);
  load.push(os.loadavg()[0]);

  // Still serving: a fresh client's ping and a relit state.
  let alive = false;
  if (!crashed) {
    try {
      const probe = await new SoakClient(99, server.ws).open();
      probe.ws.send(JSON.stringify({ type: 'ping', seq: 4242 }));
      probe.ws.send(JSON.stringify({ type: 'state', seq: 4243, state: probe.state() }));
      const deadline = Date.now() + 10000;
      while (Date.now() < deadline && !(probe.received.pongs && probe.received.frames >= 2)) await sleep(20);
      alive = probe.received.pongs === 1 && probe.received.frames >= 2;
      probe.ws.close();
    } catch (e) { crashed = `no answer at the end: ${e.message}`; }
  }
  const exitCode = crashed ? null : await stopServer(server);

  const readers = clients.filter((c) => c !== stalled);
  const all = (ph, what) => readers.flatMap((c) => c.lat[ph][what]);
  const perClient = (ph, what) => readers.map((c) => round(percentile(c.lat[ph][what], 99)));
  const frameMs = (ph) => [...serverMs.values()].filter((f) => !ph || f.phase === ph).map((f) => f.ms);
  const measured = [...serverMs.values()].filter((f) => f.phase !== 'warmup').map((f) => f.ms);
  const sum = (f) => clients.reduce((n, c) => n + f(c), 0);
  const malformedSent = sum((c) => c.sent.malformed);
  const errorsReceived = sum((c) => (c === stalled ? 0 : c.received.errors));
  const malformedByReaders = readers.reduce((n, c) => n + c.sent.malformed, 0);
  const result = {
    date: new Date().toISOString(), scene: path.relative(root, opts.scene), minutes: opts.minutes,
    warmup_s: opts.warmupSeconds, clients: opts.clients, cores: os.cpus().length,
    load1: load.map((l) => round(l)), server_cpu_s: round(cpu1 - cpu0),
    crashed, alive_at_end: alive, exit_code: exitCode,
    rss_kib: { ...rss, max_while_stalled: rssMaxStalled, growth: rss.end === null ? null : rss.end - rss.warm,
               growth_without_stall: rss.midpoint - rss.warm },
    soak_event_loop_delay_ms: { without: loopWithout, with: loopWith },
    server_frame_ms: { measured: stats(measured), without: stats(frameMs('without')), with: stats(frameMs('with')), warmup: stats(frameMs('warmup')) },
    state_to_frame_ms: { without: stats(all('without', 'state')), with: stats(all('with', 'state')),
                         per_client_p99_without: perClient('without', 'state'), per_client_p99_with: perClient('with', 'state') },
    ping_ms: { without: stats(all('without', 'ping')), with: stats(all('with', 'ping')),
               per_client_p99_without: perClient('without', 'ping'), per_client_p99_with: perClient('with', 'ping') },
    superseded_states: { without: sum((c) => c.superseded.without), with: sum((c) => c.superseded.with) },
    sent: { state: sum((c) => c.sent.state), pick: sum((c) => c.sent.pick), ping: sum((c) => c.sent.ping), malformed: malformedSent },
    received_by_readers: { frames: readers.reduce((n, c) => n + c.received.frames, 0), picks: readers.reduce((n, c) => n + c.received.picks, 0),
                           pongs: readers.reduce((n, c) => n + c.received.pongs, 0), errors: errorsReceived, malformed_sent: malformedByReaders,
                           closed: readers.filter((c) => c.closedCode !== null && c.closedAt !== 'end').map((c) => [c.index, c.closedCode]) },
    stalled_client: { closed_by_server: stalledClosedByServer, backlog_read_after_resume: backlog },
    frames_total: serverMs.size,
  };
  const failures = [];
  if (crashed) failures.push(`crash: ${crashed}`);
  if (!alive) failures.push('the server did not answer a ping and a state at the end');
  if (exitCode !== 0) failures.push(`exit code ${exitCode} on SIGTERM`);
  if (result.rss_kib.growth === null || result.rss_kib.growth > kMaxGrowthKiB) failures.push(`memory grew ${result.rss_kib.growth} KiB (limit ${kMaxGrowthKiB})`);
  if (!(result.server_frame_ms.measured.p99 <= kMaxServerP99Ms)) failures.push(`server-side p99 ${result.server_frame_ms.measured.p99} ms (limit ${kMaxServerP99Ms})`);
  if (result.received_by_readers.closed.length) failures.push(`reading clients closed: ${JSON.stringify(result.received_by_readers.closed)}`);
  if (errorsReceived < malformedByReaders) failures.push(`${malformedByReaders} malformed messages, ${errorsReceived} error replies`);
  result.failures = failures;

  const s = (x) => `p50 ${x.p50} ms, p99 ${x.p99} ms, max ${x.max} ms (n ${x.n})`;
  console.log(`
studio soak: ${opts.clients} clients, ${opts.minutes} min (warm-up ${opts.warmupSeconds} s), ${result.scene}
  sent: ${result.sent.state} states, ${result.sent.pick} picks, ${result.sent.ping} pings, ${malformedSent} malformed; ${result.frames_total} frames
  server: ${crashed ? `CRASHED (${crashed})` : 'no crash'}, ${alive ? 'answered a ping and a state at the end' : 'NOT answering at the end'}, exit code ${exitCode} on SIGTERM; ${result.server_cpu_s} s CPU
  memory (VmRSS): ${rss.start} KiB at start, ${rss.warm} after the warm-up, ${rss.midpoint} at the stall (${result.rss_kib.growth_without_stall} KiB growth without a stalled client), most ${rssMaxStalled} while stalled, ${rss.endStalled} at the end, ${rss.end} after closing the clients: growth ${result.rss_kib.growth} KiB (limit ${kMaxGrowthKiB})
  server-side frame time (RLFR ms): measured ${s(result.server_frame_ms.measured)} (limit p99 ${kMaxServerP99Ms} ms)
  state -> own frame, client-side, ${readers.length} reading clients: without a stalled client ${s(result.state_to_frame_ms.without)}; with ${s(result.state_to_frame_ms.with)}
    superseded (no frame of their own, latest state wins): ${result.superseded_states.without} without, ${result.superseded_states.with} with
    per-client p99 without: ${result.state_to_frame_ms.per_client_p99_without.join(' ')}
    per-client p99 with:    ${result.state_to_frame_ms.per_client_p99_with.join(' ')}
  ping -> pong: without ${s(result.ping_ms.without)}; with ${s(result.ping_ms.with)}
  error replies to the reading clients: ${errorsReceived} for ${malformedByReaders} malformed messages
  stalled client: ${stalledClosedByServer === null ? 'still open at the end' : `closed by the server (${stalledClosedByServer})`}${backlog ? `; read again at the end, it got ${backlog.frames} frames, ${backlog.states} state messages, ${backlog.errors} errors, ${backlog.pongs} pongs, ${backlog.picks} picks (${(backlog.bytes / 1048576).toFixed(1)} MiB) held for it` : ''}
  this soak's own event-loop delay (client side): without p50 ${loopWithout.p50} ms, p99 ${loopWithout.p99} ms; with p50 ${loopWith.p50} ms, p99 ${loopWith.p99} ms
  load average ${result.load1.join(' -> ')} on ${result.cores} cores
  ${failures.length ? `FAILED: ${failures.join('; ')}` : 'all limits met'}`);
  console.log(JSON.stringify(result));
  return failures.length ? 1 : 0;
}

main().then((code) => process.exit(code), (e) => { console.error(`studio-soak: ${e.stack ?? e}`); process.exit(2); });
