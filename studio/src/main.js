// The studio's entry point: connects to `relight serve` (docs/studio-protocol.md), builds
// the view and the panels from `hello`, the mesh from RLGE and the movable objects' meshes
// from RLOB, uploads every RLFR, routes state / pick / distribution / annual / optimized /
// error / pong messages, handles clicks in the view (probe a point, or aim a luminaire at it;
// a press on an emitter's marker drags the emitter, emitters.js; a press on an object drags
// it, objects.js), keeps the status line, and exposes window.relightStudio for the browser
// tests.
import { AnnualPanel } from './annual.js';
import { CameraRig } from './cameras.js';
import { CataloguePanel } from './catalogue.js';
import { Connection } from './connection.js';
import { DistributionEditor } from './distribution_editor.js';
import { EmitterMarkers, EmitterPanel } from './emitters.js';
import { formatValue } from './false_color.js';
import { LabelLayer } from './labels.js';
import { LayoutTools } from './layout.js';
import { Legend } from './legend.js';
import { layoutLuminaires } from './luminaire_model.js';
import { LuminairePanel } from './luminaires.js';
import { Markers } from './markers.js';
import { MaterialPanel } from './materials.js';
import { ModelOpener } from './open_model.js';
import { ObjectPanel, ObjectsView } from './objects.js';
import { OptimizePanel } from './optimize.js';
import { decodeFrame, decodeGeometry, decodeGlossyView, decodeObjects, decodeWindowViews, halfToFloat, messages, splitGlossyView } from './protocol.js';
import { Sensors } from './sensors.js';
import { StateStore, canonical } from './state.js';
import { notice } from './ui.js';
import { ViewPanel } from './view_panel.js';
import { Viewer } from './viewer.js';
import { SitePanel } from './site.js';
import { WeatherDay } from './weather_day.js';
import { WindowsPanel } from './windows.js';

const $ = (id) => document.getElementById(id);

let resolveReady;
const api = {
  ready: new Promise((r) => (resolveReady = r)),
  frames: 0, // frames drawn
  framesReceived: 0, // RLFR messages decoded
  lastFrameNumber: null,
  errors: [], // the server's error messages
  clientErrors: [], // what this client could not decode or apply
  pongs: 0,
  latencies: [],
  lastState: null, // {seq, frame} of the last `state` message: the frame that shows it
  annual: null, // the last `annual` result, with the annual_progress messages before it
  annualProgress: 0,
  optimized: null, // the last `optimized` result of this client's optimise panel
  glossyViews: 0, // RLGV messages applied
  lastGlossyView: null, // {frame, count, eye, serverMs, vertices} of the last one
  catalogue: null, // the last `catalogue` message
  uploads: [], // entries of this client's accepted uploads
  exports: 0, // `scene` replies (Export scene)
};
window.relightStudio = api;

let viewer;
try {
  viewer = new Viewer($('viewport'));
} catch (e) {
  $('overlay-message').textContent = `WebGL is not available: ${e.message}`;
  throw e;
}
api.camera = viewer.camera;
api.portalAt = (x, y) => viewer.portalAt(x, y);

const proto = location.protocol === 'https:' ? 'wss:' : 'ws:';
const connection = new Connection(`${proto}//${location.host}/ws`, {
  status: showConnection,
  text: onText,
  binary: onBinary,
  clientError,
  // The server came back after reopening on a model this page saw opened: show it afresh.
  open: () => {
    if (opener.reopening) location.reload();
  },
  close: () => {
    session.hello = null;
    session.geometry = false;
    eyeUpdate.sent = null;
  },
});
const store = new StateStore(connection);
const distributions = new Map();
const labels = new LabelLayer($('labels'), viewer);
const legend = new Legend($('legend'));
const markers = new Markers(viewer, store);
const sendMessage = (message) => {
  const seq = connection.nextSeq();
  return connection.send({ ...message, seq }) ? seq : null;
};
const opener = new ModelOpener($('model-open'), $('model-status'), sendMessage, (bytes) => connection.sendRaw(bytes));
api.modelMessages = opener.messages;
// The catalogue's armed card places a luminaire with the next click in the view.
const catalogue = new CataloguePanel($('catalogue'), sendMessage, (entry) => layout.setMode(entry ? { kind: 'place', entry } : null));
// Takes presses on luminaire markers on #stage in the capture phase, ahead of everything below.
const layout = new LayoutTools($('layout'), $('stage'), {
  viewer,
  store,
  markers,
  catalogue,
  pick: (ray) => sendPick(ray),
  send: sendMessage,
  sceneName: () => (session.hello?.scene_file || 'scene').replace(/\.rlt$/, ''),
});
// Takes presses on its markers on #stage in the capture phase, ahead of the camera controls
// and the click handling below.
const emitterMarkers = new EmitterMarkers(viewer, store, $('stage'));
// Likewise for presses on movable objects (after the markers: a marker in front wins), except
// while a luminaire is being aimed; a click on an object reads the point as any click does.
const objectsView = new ObjectsView(viewer, store, $('stage'), {
  busy: () => session.aimIndex !== null || !!layout.mode,
  click: (x, y) => onViewportClick(x, y),
});
const sensors = new Sensors(viewer, $('sensors'));
const rig = new CameraRig(viewer, () => viewPanel.markFree());
api.orbitCentre = () => rig.controls.target.toArray();
const viewPanel = new ViewPanel(viewer, rig, markers, $('labels'));
viewPanel.onPlan = (on) => sensors.setPlanView(on);
api.isolineSegments = () => sensors.drawnIsolines;
const luminairePanel = new LuminairePanel($('luminaires'), store, distributions, {
  aim: (i) => startAim(i),
  editCurve: (i) => {
    editor.select(i);
    $('section-distribution').open = true;
    $('section-distribution').scrollIntoView({ behavior: 'smooth' });
  },
});
const editor = new DistributionEditor($('distribution'), store, distributions, requestDistribution);
const sitePanel = new SitePanel($('site'), store);
const weatherDay = new WeatherDay(
  $('weather-day'),
  store,
  sendMessage,
  { projectWeather: () => annualPanel.weatherFile(), fileChosen: () => annualPanel.updateRun() },
);
const windowsPanel = new WindowsPanel($('windows'), store);
const emitterPanel = new EmitterPanel($('emitters'), store);
const objectPanel = new ObjectPanel($('objects'), store, objectsView);
objectsView.onSelect = (i) => objectPanel.setSelected(i);
const materialPanel = new MaterialPanel($('material'), store);
const annualPanel = new AnnualPanel($('annual'), sendMessage, sensors, () => weatherDay.weatherFile());
const optimizePanel = new OptimizePanel(
  $('optimize'),
  sendMessage,
  // The result becomes the lighting state as a loaded state file does (sent, panels refreshed).
  { applyState: (doc) => store.replace(doc), stateShown: () => stateShown() },
);
// The luminaire in the distribution editor is drawn larger in the view.
editor.onSelect = (i) => {
  markers.selected = i;
  markers.update();
};

const session = {
  hello: null,
  geometry: false,
  hadView: false,
  pendingLatency: [], // [{seq, t0}] frames uploaded, not drawn yet
  picks: new Map(), // seq → {resolve, reject}
  aimIndex: null,
  probeRay: null,
  lastFrame: null,
};

// ---- messages

function onText(msg) {
  switch (msg.type) {
    case 'hello':
      return onHello(msg);
    case 'state': {
      api.lastState = { seq: msg.seq ?? null, frame: msg.frame ?? null, final: msg.final ?? true };
      // A material edit's first frame is its light reflected once, a moved or added luminaire's
      // has a stored luminaire's interreflection; the converged frame follows.
      $('frame-quality').textContent = msg.final === false ? 'approximate: converging' : '';
      const how = store.applyRemote(msg);
      if (how === 'mine') $('state-origin').textContent = `shown: this client's state (frame ${msg.frame ?? '?'})`;
      if (how === 'remote') {
        $('state-origin').textContent = `shown: state from client ${msg.client ?? '?'} (frame ${msg.frame ?? '?'})`;
        if (msg.seq == null || !store.sentTime(msg.seq)) notice(`Lighting changed by client ${msg.client ?? '?'}`);
      }
      return;
    }
    case 'pick': {
      const p = session.picks.get(msg.seq);
      if (p) {
        session.picks.delete(msg.seq);
        p.resolve(msg);
      }
      return;
    }
    case 'distribution':
      distributions.set(msg.luminaire, msg);
      editor.receive(msg);
      luminairePanel.distributionUpdated(msg.luminaire);
      return;
    case 'catalogue':
      api.catalogue = msg;
      return catalogue.setCatalogue(msg);
    case 'uploaded':
      api.uploads.push(msg.entry);
      notice(`Uploaded ${msg.entry.name}: in the catalogue as ${msg.entry.id}`);
      return;
    case 'model':
      return opener.onModel(msg);
    case 'scene':
      api.exports++;
      return layout.onExport(msg);
    case 'annual_progress':
      api.annualProgress++;
      return annualPanel.onProgress(msg);
    case 'annual':
      api.annual = { ...msg, progress_messages: api.annualProgress };
      return annualPanel.onResult(msg);
    case 'weather_day':
      api.weatherDay = msg;
      return weatherDay.onDay(msg);
    case 'optimized':
      api.optimized = msg;
      return optimizePanel.onResult(msg);
    case 'error': {
      api.errors.push(msg.message);
      if (weatherDay.onError(msg)) {
        notice(`Weather: ${msg.message}`, 'error');
        return;
      }
      if (annualPanel.onError(msg)) {
        notice(`Annual: ${msg.message}`, 'error');
        return;
      }
      if (optimizePanel.onError(msg)) {
        notice(`Optimise: ${msg.message}`, 'error');
        return;
      }
      if (opener.onError(msg)) return;
      const undone = store.refused(msg.seq);
      notice(`Server: ${msg.message}${undone ? ' (the change was undone)' : ''}`, 'error');
      const p = session.picks.get(msg.seq);
      if (p) {
        session.picks.delete(msg.seq);
        p.reject(new Error(msg.message));
      }
      return;
    }
    case 'pong':
      api.pongs++;
      $('clients').textContent = `${msg.clients} client${msg.clients === 1 ? '' : 's'}`;
      $('rtt').textContent = `ping ${connection.rttMs !== null ? connection.rttMs.toFixed(0) : '–'} ms`;
      return;
    default:
      console.warn('relight studio: unknown message', msg);
  }
}

function onHello(hello) {
  session.hello = hello;
  session.geometry = false;
  distributions.clear();
  $('scene-name').textContent = hello.scene_file || '';
  $('scene-name').title = `${hello.scene_file}: ${hello.vertices} vertices, ${hello.triangles} triangles, SH order ${hello.sh_order}, direct light ${hello.direct}`;
  $('overlay-message').textContent = 'Loading geometry…';
  if (hello.protocol !== 1) notice(`Server speaks protocol ${hello.protocol}; this client knows 1`, 'error');
  rig.setRoom(hello.bounds);
  // The plan's cut: 1.2 m over the lowest work plane (2 m over a floor), below the ceilings.
  let workPlane = Infinity;
  for (const s of hello.sensors ?? []) for (const p of s.points) workPlane = Math.min(workPlane, p[1]);
  viewPanel.setPlanCut(Number.isFinite(workPlane) ? workPlane + 1.2 : (hello.bounds?.min[1] ?? 0) + 2);
  viewPanel.setCameras(hello.cameras, session.hadView);
  if (!session.hadView && !(hello.cameras || []).length && hello.bounds) rig.frameBounds(hello.bounds);
  session.hadView = true;
  markers.setScene(hello);
  layout.setScene(hello);
  sensors.setScene(hello);
  luminairePanel.setScene(hello);
  sitePanel.setScene(hello);
  weatherDay.setScene(hello);
  windowsPanel.setScene(hello);
  emitterMarkers.setScene(hello);
  emitterPanel.setScene(hello);
  objectsView.setScene(hello);
  objectPanel.setScene(hello);
  materialPanel.setScene(hello);
  annualPanel.setScene(hello);
  optimizePanel.setScene(hello);
  editor.setScene(hello);
  store.reset(hello.state || {}, hello.client ?? null);
  // Every luminaire's distribution (the layout's added ones too): flux for the panels, exact C0
  // samples for the editor.
  for (const l of layoutLuminaires(hello, store.doc)) requestDistribution(l.name);
}

function onBinary(tag, buffer) {
  try {
    if (tag === 'RLGE') {
      const g = decodeGeometry(buffer);
      viewer.setGeometry(g, session.hello?.bounds);
      session.geometry = true;
      $('overlay-message').textContent = 'Waiting for the first frame…';
    } else if (tag === 'RLOB') {
      if (!session.geometry) throw new Error('RLOB before RLGE');
      objectsView.setMeshes(decodeObjects(buffer));
    } else if (tag === 'RLFR') {
      if (!session.geometry) throw new Error('RLFR before RLGE');
      const f = decodeFrame(buffer);
      api.framesReceived++;
      viewer.setFrame(f);
      objectsView.setFrame(f);
      sensors.setReadings(f.sensors);
      session.lastFrame = f;
      $('overlay-message').textContent = '';
      $('server-ms').textContent = `server ${f.serverMs.toFixed(1)} ms`;
      if (f.seq !== null && store.sentTime(f.seq) !== undefined && !store.foreignSeqs.has(f.seq)) {
        session.pendingLatency.push({ seq: f.seq, t0: store.sentTime(f.seq), frame: f.frame });
      }
      session.pendingFrameNumber = f.frame;
      if (session.probeRay) refreshProbe();
    } else if (tag === 'RLGV') {
      if (!session.geometry) throw new Error('RLGV before RLGE');
      const g = decodeGlossyView(buffer);
      const parts = splitGlossyView(g, viewer.geometry.vertexCount);
      viewer.setGlossyView(parts.room);
      objectsView.setGlossyView(parts.objects);
      api.glossyViews++;
      api.lastGlossyView = { frame: g.frame, count: g.count, eye: g.eye, serverMs: g.serverMs, vertices: Array.from(g.vertices) };
    } else if (tag === 'RLWV') {
      if (!session.geometry) throw new Error('RLWV before RLGE');
      const views = decodeWindowViews(buffer);
      viewer.setWindowViews(views);
      api.windowViews = viewer.windowViews;
    } else {
      console.warn(`relight studio: unknown binary message "${tag}"`);
    }
  } catch (e) {
    clientError(e.message);
  }
}

function clientError(message) {
  api.clientErrors.push(message);
  notice(`Client: ${message}`, 'error');
  console.error(`relight studio: ${message}`);
}

// ---- rendering hooks

viewer.beforeRender.push(() => sensors.colour(viewer.used));
viewer.onDisplayChange = () => legend.update(viewer.used);
// The eye for glossy surfaces (RLGV): sent when the camera has moved, at most every 100 ms
// and once more when it stops; again after a reconnect.
const eyeUpdate = { sent: null, timer: null, last: 0 };
function sendEye() {
  eyeUpdate.timer = null;
  if (!session.geometry) return;
  const eye = viewer.camera.position.toArray();
  if (eyeUpdate.sent && eye.every((x, i) => Math.abs(x - eyeUpdate.sent[i]) < 1e-3)) return;
  if (connection.send(messages.view(connection.nextSeq(), eye))) {
    eyeUpdate.sent = eye;
    eyeUpdate.last = performance.now();
  }
}
viewer.afterRender.push(() => {
  if (eyeUpdate.timer !== null) return;
  const wait = Math.max(0, 100 - (performance.now() - eyeUpdate.last));
  eyeUpdate.timer = setTimeout(sendEye, wait);
});

viewer.afterRender.push((info) => {
  legend.update(viewer.used);
  labels.begin();
  sensors.drawLabels(labels);
  markers.drawLabels(labels);
  emitterMarkers.drawLabels(labels);
  objectsView.drawLabels(labels);
  if (info.frameDrawn) {
    // A frame counts as drawn at the first animation frame after the one that drew it,
    // when the browser has composited it: latency runs from the state message's send to
    // then.
    const pending = session.pendingLatency;
    const number = session.pendingFrameNumber;
    session.pendingLatency = [];
    requestAnimationFrame(() => {
      const now = performance.now();
      api.frames++;
      api.lastFrameNumber = number;
      $('frame-number').textContent = `frame ${number}`;
      for (const p of pending) api.latencies.push(now - p.t0);
      if (pending.length) $('latency').textContent = `latency ${(now - pending.at(-1).t0).toFixed(0)} ms`;
      if (session.hello && session.geometry) resolveReady();
    });
  }
});

// ---- status

function showConnection(text) {
  const c = $('conn');
  c.textContent = `${text === 'connected' ? '●' : '○'} ${text}`;
  c.className = `conn ${text === 'connected' ? 'ok' : text === 'connecting' ? '' : 'bad'}`;
  if (text !== 'connected' && text !== 'connecting') $('overlay-message').textContent = session.geometry ? '' : 'Not connected to relight serve…';
}

// ---- pick, probe and aim

function sendPick(ray) {
  return new Promise((resolve, reject) => {
    const seq = connection.nextSeq();
    if (!connection.send(messages.pick(seq, ray.origin, ray.direction))) return reject(new Error('not connected'));
    session.picks.set(seq, { resolve, reject });
    setTimeout(() => {
      if (session.picks.delete(seq)) reject(new Error('pick: no answer'));
    }, 15000);
  });
}

function pickAt(x, y) {
  return sendPick(viewer.rayAt(x, y));
}

function showProbe(reply) {
  const box = $('probe');
  if (!reply.hit) {
    markers.probe = null;
    box.hidden = false;
    box.textContent = 'Nothing there.';
    viewer.requestRender();
    return;
  }
  // (material is null when the .rlt predates per-triangle materials, and on objects)
  const where = reply.object ? `object “${reply.object}”` : reply.portal ? `window “${reply.portal}”` : reply.material ?? `triangle ${reply.triangle}`;
  if (!reply.object && !reply.portal && reply.material) materialPanel.show(reply.material);
  markers.probe = { point: reply.point, text: `${formatValue(reply.illuminance)} lx · ${formatValue(reply.luminance)} cd/m²` };
  box.hidden = false;
  box.innerHTML = '';
  const lines = [
    [`${where}`, 'Surface (material, window or movable object) at the clicked point'],
    [`E = ${formatValue(reply.illuminance)} lx   L = ${formatValue(reply.luminance)} cd/m²`, 'Illuminance and luminance at the point, interpolated from the current frame'],
    [`at (${reply.point.map((v) => v.toFixed(2)).join(', ')}) m, ${reply.distance.toFixed(2)} m away`, 'Position of the point and its distance from the camera'],
  ];
  for (const [t, title] of lines) {
    const d = document.createElement('div');
    d.textContent = t;
    d.title = title;
    box.append(d);
  }
  viewer.requestRender();
}

let probeBusy = false;
function refreshProbe() {
  if (probeBusy || !session.probeRay) return;
  probeBusy = true;
  sendPick(session.probeRay)
    .then(showProbe)
    .catch(() => {})
    .finally(() => (probeBusy = false));
}

function startAim(i) {
  const lum = luminairePanel.blocks[i]?.lum;
  if (!session.hello || !lum) return;
  session.aimIndex = i;
  luminairePanel.setAiming(i);
  $('stage').classList.add('aiming');
  const banner = $('aim-banner');
  banner.hidden = false;
  banner.textContent = `Click a surface to aim “${lum.name}” at it (Esc cancels)`;
}

function stopAim() {
  session.aimIndex = null;
  luminairePanel.setAiming(null);
  $('stage').classList.remove('aiming');
  $('aim-banner').hidden = true;
}

async function onViewportClick(x, y) {
  if (!session.geometry) return;
  if (layout.click(x, y)) return;
  const ray = viewer.rayAt(x, y);
  if (session.aimIndex !== null) {
    const i = session.aimIndex;
    const name = luminairePanel.blocks[i].lum.name;
    stopAim();
    try {
      const reply = await sendPick(ray);
      if (!reply.hit) return notice('Nothing there to aim at.', 'error');
      const target = reply.point.map((v) => Number(v.toFixed(4)));
      store.edit(() => {
        const e = store.luminaire(name);
        delete e.aim;
        e.target = target;
      });
      notice(`“${name}” aimed at (${target.map((v) => v.toFixed(2)).join(', ')})`);
    } catch (e) {
      notice(`Aim: ${e.message}`, 'error');
    }
    return;
  }
  session.probeRay = ray;
  try {
    showProbe(await sendPick(ray));
  } catch (e) {
    notice(`Pick: ${e.message}`, 'error');
  }
}

{
  const canvas = viewer.canvas;
  let down = null;
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button === 0) down = { x: e.clientX, y: e.clientY, t: performance.now() };
    canvas.focus();
  });
  canvas.addEventListener('pointerup', (e) => {
    if (!down || e.button !== 0) return;
    const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
    const quick = performance.now() - down.t < 800;
    down = null;
    if (moved > 4 || !quick) return;
    const r = canvas.getBoundingClientRect();
    onViewportClick(e.clientX - r.left, e.clientY - r.top);
  });
  window.addEventListener('keydown', (e) => {
    if (e.key !== 'Escape') return;
    if (session.aimIndex !== null) stopAim();
    else {
      session.probeRay = null;
      markers.probe = null;
      $('probe').hidden = true;
      viewer.requestRender();
    }
  });
}

// ---- the state shown

// Sends an edit still waiting for its animation frame, so that the server, which reads one
// connection's messages in order, has the state on screen before the optimise panel's run
// (it starts from the last state it received).
function stateShown() {
  store.sendNow(false);
  return Promise.resolve();
}

// ---- distribution requests

function requestDistribution(name) {
  if (!name) return;
  connection.send(messages.distribution(connection.nextSeq(), name));
}

// ---- State section

{
  const json = $('state-json');
  const show = () => {
    // Two-space JSON with arrays of numbers kept on one line.
    const text = JSON.stringify(store.doc, null, 2).replace(/\[[\d\s,.eE+-]*\]/g, (a) => a.replace(/\s+/g, ' ').replace('[ ', '[').replace(' ]', ']'));
    if (document.activeElement !== json) json.value = text;
  };
  store.onChange(show);
  $('state-save').addEventListener('click', () => store.save(`${(session.hello?.scene_file || 'scene').replace(/\.rlt$/, '')}-state.json`));
  $('state-file').addEventListener('change', async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    try {
      await store.load(file);
      notice(`Loaded ${file.name}`);
    } catch (err) {
      notice(`Load: ${err.message}`, 'error');
    }
    e.target.value = '';
  });
  $('state-reset').addEventListener('click', () => store.replace({}));
  $('state-send').addEventListener('click', () => {
    try {
      store.replace(JSON.parse(json.value));
      json.blur();
      show();
    } catch (err) {
      notice(`State JSON: ${err.message}`, 'error');
    }
  });
}

$('show-emitters').addEventListener('change', (e) => {
  emitterMarkers.visible = e.target.checked;
  emitterMarkers.update();
});

$('panel-toggle').addEventListener('click', () => {
  $('app').classList.toggle('collapsed');
});

// ---- test and scripting hooks

Object.assign(api, {
  send: (obj) => connection.send(obj),
  sendRaw: (data) => connection.sendRaw(data),
  state: () => JSON.parse(JSON.stringify(store.doc)),
  setState: (doc) => {
    store.replace(doc);
    return store.latestSeq;
  },
  pick: (x, y) => pickAt(x, y),
  requestRender: () => viewer.requestRender(),
  // The radiance shown at vertex v (cd/m², R G B), glossy views applied.
  shownRadiance: (v) => [0, 1, 2].map((c) => halfToFloat(viewer.lighting.array[4 * v + c])),
  // The radiance shown at object vertex q (hello order), glossy views applied; with
  // `fromFrame`, the last frame's there.
  objectRadiance: (q, fromFrame = false) => {
    const items = objectsView.items;
    let k = 0, first = 0;
    while (k + 1 < items.length && q >= first + items[k].o.vertices) first += items[k++].o.vertices;
    const at = fromFrame ? 4 * q : 4 * (q - first);
    const src = fromFrame ? objectsView.lastFrameHalfs : items[k].lighting.array;
    return [0, 1, 2].map((c) => halfToFloat(src[at + c]));
  },
  // The sensor readings of the frame shown (lx, every set's points back to back).
  sensorReadings: () => Array.from(sensors.values),
  // Emitter i's marker on the canvas (CSS px), object i's base centre, and any world point's.
  emitterOnScreen: (i) => emitterMarkers.screenPosition(i),
  objectOnScreen: (i) => objectsView.screenPosition(i),
  objects: objectsView,
  project: (p) => {
    const s = labels.project(p);
    return s && { x: s[0], y: s[1] };
  },
  viewer,
  store,
  editor,
  rig,
  canonical,
  layout,
  catalogueView: catalogue,
  // Luminaire `name`'s marker on the canvas (CSS px).
  luminaireOnScreen: (name) => markers.screenPosition(name),
});

connection.connect();
