// The avatar page of `fapcast serve` (spec/serve.md, "The avatar page"): the voice's face from
// /v1/face.glb, driven by the live stream of /v1/live. Each binary frame carries the frame's PCA
// weights and the audio played while it is shown; the audio is scheduled on the AudioContext's
// clock a jitter buffer ahead, and at every animation frame the page shows the frame whose audio
// is playing then. The page measures how far apart the two are (window.fapcastStats).
import * as THREE from '/three/three.module.js';
import {GLTFLoader} from '/three/examples/jsm/loaders/GLTFLoader.js';

const JITTER_FRAMES = 3;  // the audio starts this many frames after the first frame arrives
const query = new URLSearchParams(location.search);
const token = query.get('token') || '';
const channel = query.get('channel') || 'default';
const statusLine = document.getElementById('status');
const statsLine = document.getElementById('stats');

// What the page measured; tests read it (tests/browser/avatar_page_test.mjs).
const stats = window.fapcastStats = {
  state: 'loading', error: null, jitter_frames: JITTER_FRAMES, session: null, sample_rate: 0, fps: 0,
  sentences: [], frames_received: 0, late_frames: 0, sessions_played: 0, animation_frames: 0, morph_ms: 0,
  offset_ms: {count: 0, mean: 0, min: Infinity, max: -Infinity}, offsets: [], held: null,
};
const fail = (what) => { stats.error = String(what); statusLine.textContent = 'error: ' + stats.error; };

// --- The face: one mesh, morphed on the CPU (all K targets, exactly; three.js r111 would use 8).
const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({canvas});
renderer.setClearColor(0x20242a);
const scene = new THREE.Scene();
scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.0));
const key = new THREE.DirectionalLight(0xffffff, 0.8);
key.position.set(0.3, 0.5, 1);
scene.add(key);
const camera = new THREE.PerspectiveCamera(20, 1, 0.01, 10);
let face = null;  // {mesh, base: Float32Array, targets: [Float32Array]}

async function loadFace() {
  const res = await fetch('/v1/face.glb', {headers: {Authorization: 'Bearer ' + token}});
  if (!res.ok) throw new Error('/v1/face.glb: HTTP ' + res.status);
  const bytes = await res.arrayBuffer();
  const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(bytes, '', resolve, reject));
  let mesh = null;
  gltf.scene.traverse((o) => { if (o.isMesh && !mesh) mesh = o; });
  if (!mesh || !mesh.geometry.morphAttributes.position) throw new Error('face.glb: no mesh with morph targets');
  const geometry = mesh.geometry;
  const targets = geometry.morphAttributes.position.map((a) => a.array);
  geometry.morphAttributes = {};  // morphed here, not by the shader
  mesh.material = new THREE.MeshStandardMaterial({roughness: 0.7, side: THREE.DoubleSide, vertexColors: THREE.VertexColors});
  geometry.setAttribute('color', new THREE.BufferAttribute(colours(geometry.attributes.position.count), 3));
  if (geometry.attributes.position.count === ICT_VERTICES) hideOverlays(geometry);
  geometry.computeVertexNormals();
  scene.add(gltf.scene);
  face = {mesh, base: geometry.attributes.position.array.slice(), targets};
  frameTheFace();
}

// The ICT-FaceKit head's parts are vertex ranges (its generic_neutral_mesh.obj's material groups,
// data/ict-facekit); /v1/face.glb has no materials, so the page colours them: skin, then the
// dark mouth socket, gums and tongue, teeth, eyes and lashes (ICTFaceModelMaterial.mtl's colours
// where it has them). Any other mesh is all skin.
const ICT_VERTICES = 26719;
const ICT_PARTS = [  // [first vertex, colour]
  [0, [0.85, 0.62, 0.52]],       // face, head and neck
  [11248, [0.08, 0.01, 0.02]],   // mouth socket
  [13294, [0.85, 0.62, 0.52]],   // eye sockets
  [14062, [0.30, 0.03, 0.06]],   // gums and tongue
  [17039, [0.80, 0.80, 0.80]],   // teeth
  [21451, [0.90, 0.90, 0.88]],   // left sclera
  [22221, [0.20, 0.20, 0.20]],   // left iris
  [23021, [0.90, 0.90, 0.88]],   // right sclera
  [23791, [0.20, 0.20, 0.20]],   // right iris
  [24591, [0.85, 0.62, 0.52]],   // lacrimal fluid, eye blend and occlusion (hidden)
  [25351, [0.10, 0.07, 0.05]],   // eyelashes
];
function colours(count) {
  const c = new Float32Array(3 * count);
  const parts = count === ICT_VERTICES ? ICT_PARTS : ICT_PARTS.slice(0, 1);
  parts.forEach(([first, rgb], i) => {
    const end = i + 1 < parts.length ? parts[i + 1][0] : count;
    for (let v = first; v < end; ++v) c.set(rgb, 3 * v);
  });
  return c;
}

// ICT's lacrimal fluid, eye blend and eye occlusion are see-through layers over the eyes: not drawn.
function hideOverlays(geometry) {
  const index = geometry.index.array, kept = [];
  for (let t = 0; t < index.length; t += 3)
    if (![0, 1, 2].some((j) => index[t + j] >= 24591 && index[t + j] < 25351)) kept.push(index[t], index[t + 1], index[t + 2]);
  geometry.setIndex(kept);
}

function frameTheFace() {
  const box = new THREE.Box3().setFromBufferAttribute(new THREE.BufferAttribute(face.base, 3));
  const size = box.getSize(new THREE.Vector3()), centre = box.getCenter(new THREE.Vector3());
  const distance = 1.1 * size.y / (2 * Math.tan(camera.fov * Math.PI / 360));
  camera.position.set(centre.x, centre.y, box.max.z + distance);
  camera.lookAt(centre);
}

function applyWeights(weights) {
  if (!face) return;
  const position = face.mesh.geometry.attributes.position, p = position.array;
  p.set(face.base);
  weights.forEach((w, t) => {
    if (w === 0 || t >= face.targets.length) return;
    const d = face.targets[t];
    for (let i = 0; i < p.length; ++i) p[i] += w * d[i];
  });
  position.needsUpdate = true;
  face.mesh.geometry.computeVertexNormals();
}

// --- The live stream: frames scheduled on the audio clock.
const audio = new AudioContext({latencyHint: 'interactive'});
let session = null;  // the latest: {number, rate, fps, components, expression, anchor: {time, sample}, ended}
let frames = [];     // every session's frames, in playing order: {session, index, sample, samples, when, end, weights}

function onText(message) {
  const m = JSON.parse(message);
  if (m.type === 'session') {
    session = {number: m.session, rate: m.sample_rate, fps: m.fps, components: m.components,
               expression: m.expression_weights || [], anchor: null};
    Object.assign(stats, {state: 'speaking', session: m.session, sample_rate: m.sample_rate, fps: m.fps});
    statusLine.textContent = 'speaking (session ' + m.id + ')';
  } else if (m.type === 'sentence' && session && m.session === session.number) {
    stats.sentences.push({index: m.index, text: m.text, sample: m.sample, samples: m.samples, frames: m.frames, phones: m.phones});
  } else if (m.type === 'end' && session && m.session === session.number) {
    const last = frames[frames.length - 1];
    if (last && last.session === m.session) last.final = true;  // the session's sound ends with it
    statusLine.textContent = 'session ' + m.id + ': ' + m.reason;
  }
}

// Frame message layout: spec/serve.md ("The live stream"), little-endian.
function onFrame(bytes) {
  const v = new DataView(bytes);
  if (v.getUint8(0) !== 1 || !session || v.getUint32(4, true) !== session.number) return;
  const k = v.getUint16(2, true), sample = Number(v.getBigInt64(8, true)), n = v.getUint32(16, true);
  const weights = new Float32Array(bytes.slice(24, 24 + 4 * k));
  const pcm = new Int16Array(bytes.slice(24 + 4 * k, 24 + 4 * k + 2 * n));
  ++stats.frames_received;
  const lead = JITTER_FRAMES / session.fps;
  let when = session.anchor && session.anchor.time + (sample - session.anchor.sample) / session.rate;
  if (!session.anchor || when < audio.currentTime + 0.005) {  // first frame, or too late: start again
    if (session.anchor) ++stats.late_frames;
    const previous = frames.length ? frames[frames.length - 1].end : 0;  // after the last session's sound
    session.anchor = {time: Math.max(audio.currentTime + lead, previous), sample};
    when = session.anchor.time;
  }
  if (n > 0) {
    const buffer = audio.createBuffer(1, n, session.rate), channelData = buffer.getChannelData(0);
    for (let i = 0; i < n; ++i) channelData[i] = pcm[i] / 32768;
    const source = audio.createBufferSource();
    source.buffer = buffer;
    source.connect(audio.destination);
    source.start(when);
  }
  frames.push({session: session.number, index: v.getUint32(20, true), sample, samples: n, when,
               end: when + Math.max(n, 1) / session.rate, weights: targetWeights(weights)});
}

function connect() {
  const url = (location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host +
              '/v1/live?channel=' + encodeURIComponent(channel);
  const ws = new WebSocket(url, ['fapcast.v1', 'bearer.' + token]);
  ws.binaryType = 'arraybuffer';
  let opened = false;
  ws.onopen = () => { opened = true; stats.state = 'ready'; statusLine.textContent = 'connected to channel ' + channel; };
  ws.onmessage = (e) => (typeof e.data === 'string' ? onText(e.data) : onFrame(e.data));
  ws.onclose = async (e) => {
    stats.state = 'disconnected';
    const why = 'disconnected (' + e.code + (e.reason ? ': ' + e.reason : '') + ')';
    // A refused handshake hides its status from the page: the same request without the upgrade
    // tells it. A wrong token or a forbidden origin will not change by retrying.
    if (!opened) {
      const refusal = await handshakeRefusal();
      if (refusal) {
        stats.state = 'refused';
        statusLine.textContent = 'refused: ' + refusal + '; not retrying (reload the page with the right ?token=)';
        return;
      }
    }
    statusLine.textContent = why + '; reconnecting';
    setTimeout(connect, 1000);
  };
}

// "HTTP 401 token-wrong: ..." when /v1/live refuses this page's token or origin; else null.
async function handshakeRefusal() {
  try {
    const res = await fetch('/v1/live?channel=' + encodeURIComponent(channel), {headers: {Authorization: 'Bearer ' + token}});
    if (res.status !== 401 && res.status !== 403) return null;
    const answer = await res.json().catch(() => ({}));
    return 'HTTP ' + res.status + ' ' + (answer.error || '') + (answer.detail ? ': ' + answer.detail : '');
  } catch (err) {
    return null;  // the server is away: retrying is right
  }
}

// --- Display: at each animation frame, the frame whose audio plays now.
// The audio clock at a performance.now() instant: getOutputTimestamp() pairs the context time of
// the sample leaving the output with the performance time it does so.
function audioTimeAt(performanceMs) {
  const ts = audio.getOutputTimestamp();
  if (!ts.performanceTime) return audio.currentTime - (audio.outputLatency || 0);
  return ts.contextTime + (performanceMs - ts.performanceTime) / 1000;
}

const KEEP_SECONDS = 5;  // frames kept after their audio played (for the test hook's holds)
let holds = [];  // samples to freeze at (test hook)
let holding = null;

function frameAt(sample) {
  return frames.find((f) => f.session === session.number && f.sample <= sample && sample < f.sample + Math.max(f.samples, 1));
}

function render(now) {
  requestAnimationFrame(render);
  resize();
  ++stats.animation_frames;
  let measured = null;
  if (frames.length && !holding) {
    const t = audioTimeAt(now), last = frames[frames.length - 1];
    const held = holds.length && frameAt(holds[0]);
    if (held && held.when <= t) {
      holding = held;
      show(held);
      stats.held = {sample: holds[0], frame: held.index, frame_sample: held.sample};
    } else if (t <= last.end + 0.5 * (last.end - last.when)) {
      while (frames.length > 1 && frames[0].end < t - KEEP_SECONDS) frames.shift();
      let shown = null;  // the frame whose start is nearest: offsets within half a frame when all is well
      for (const f of frames) if (f.when <= t + 0.5 * (f.end - f.when)) shown = f;
      if (shown && t <= shown.end + 0.5 * (shown.end - shown.when)) {
        show(shown);
        if (t < shown.end) measured = shown;  // past its end it is only the last one, kept up
      }
    } else if (last.final && lastShown) {
      rest();  // the frames are kept for the test hook until they are 5 s old
      stats.state = 'ready';
    }
    for (const f of frames) if (f.final && !f.played && t > f.end) f.played = ++stats.sessions_played;
  }
  renderer.render(scene, camera);
  if (measured) record(measured, now);
}

function rest() {
  applyWeights(new Float32Array(face ? face.targets.length : 0));
  lastShown = null;
}

let lastShown = null;
function show(frame) {
  if (frame === lastShown) return;
  lastShown = frame;
  const t0 = performance.now();
  applyWeights(frame.weights);
  stats.morph_ms = performance.now() - t0;
}

// All targets' weights for a frame: its k PCA weights, then the session's expression weights.
function targetWeights(weights) {
  const w = new Float32Array(face ? face.targets.length : 0);
  w.set(weights.subarray(0, Math.min(session.components, w.length)));
  session.expression.forEach((e, i) => { if (session.components + i < w.length) w[session.components + i] = e; });
  return w;
}

// The audio/face offset of a shown frame, measured apart from the choice of the frame: with the
// output timestamp read afresh, the instant of the audio leaving the output at the time the frame
// was drawn for (the animation frame's time), minus the instant of the frame's first sample.
function record(frame, drawnFor) {
  const ts = audio.getOutputTimestamp();
  if (!ts.performanceTime) return;  // no output yet: nothing to measure against
  const ms = 1000 * (ts.contextTime + (drawnFor - ts.performanceTime) / 1000 - frame.when);
  if (stats.offsets.length < 10000) stats.offsets.push(+ms.toFixed(2));
  const o = stats.offset_ms;
  o.mean += (ms - o.mean) / ++o.count;
  o.min = Math.min(o.min, ms);
  o.max = Math.max(o.max, ms);
  statsLine.textContent = `audio/face offset: mean ${o.mean.toFixed(1)} ms, range ${o.min.toFixed(1)}..${o.max.toFixed(1)} ms ` +
    `over ${o.count} displays; jitter buffer ${JITTER_FRAMES} frames; late frames ${stats.late_frames}`;
}

function resize() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width === w && canvas.height === h) return;
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}

// --- Speaking: POST /v1/say.
document.getElementById('say').addEventListener('submit', async (e) => {
  e.preventDefault();
  audio.resume();
  const res = await fetch('/v1/say', {method: 'POST', headers: {Authorization: 'Bearer ' + token,
    'Content-Type': 'application/json'}, body: JSON.stringify({text: document.getElementById('text').value, channel})});
  const answer = await res.json().catch(() => ({}));
  statusLine.textContent = res.ok ? 'session ' + answer.session + ' started' :
    'POST /v1/say: HTTP ' + res.status + ' ' + (answer.error || answer.reason || '') + (answer.detail ? ': ' + answer.detail : '');
});

// Test hooks: freeze the face at the frames holding these samples (in order), read the mouth box.
window.fapcastTest = {
  hold(samples) { holds = samples.slice(); },
  release() {
    holding = null;
    holds.shift();
    stats.held = null;
    const last = frames[frames.length - 1];
    if (last && last.final && audioTimeAt(performance.now()) > last.end) rest();
    lastShown = null;
  },
  // Per frame kept: the distance (m) between two vertices, e.g. the inner lip midpoints.
  distances(a, b) {
    return frames.filter((f) => session && f.session === session.number).map((f) => {
      const w = f.weights, at = (v, c) => w.reduce((sum, x, t) => sum + x * face.targets[t][3 * v + c], face.base[3 * v + c]);
      return {index: f.index, sample: f.sample, distance: Math.hypot(...[0, 1, 2].map((c) => at(a, c) - at(b, c)))};
    });
  },
  // Screen box (CSS pixels) of these vertices at rest (the voice's mean face) or as now shown.
  box(vertices, atRest) {
    const p = atRest ? new THREE.BufferAttribute(face.base, 3) : face.mesh.geometry.attributes.position;
    const r = canvas.getBoundingClientRect(), v = new THREE.Vector3();
    const box = {x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity};
    for (const i of vertices) {
      v.fromBufferAttribute(p, i).applyMatrix4(face.mesh.matrixWorld).project(camera);
      const x = r.left + (v.x + 1) / 2 * r.width, y = r.top + (1 - v.y) / 2 * r.height;
      Object.assign(box, {x0: Math.min(box.x0, x), y0: Math.min(box.y0, y), x1: Math.max(box.x1, x), y1: Math.max(box.y1, y)});
    }
    return box;
  },
};

loadFace().then(() => { connect(); requestAnimationFrame(render); }, fail);
