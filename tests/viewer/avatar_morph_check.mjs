// Loads an animated avatar .glb with three.js's GLTFLoader under Node, plays its last animation with an
// AnimationMixer and measures the inner-lip gap with three.js's own CPU morph and skinning
// (SkinnedMesh.getVertexPosition) at the given times:  node avatar_morph_check.mjs OUT.glb T1,T2,...
// The lips: on the head (the mesh whose jawOpen, else viseme_aa, target moves most), near the midline,
// a vertex the target moves down by more than half its largest drop (lower lip) and the nearest one
// above it at rest that it moves by less than a fifth (upper lip). Prints one JSON line.
import './browser_globals.mjs';
import fs from 'node:fs';
const THREE = await import('three');
const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
const [file, timesArg] = process.argv.slice(2);
const b = fs.readFileSync(file);
const gltf = await new Promise((res, rej) => new GLTFLoader().parse(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength), '', res, rej));
const clip = gltf.animations[gltf.animations.length - 1];
const mixer = new THREE.AnimationMixer(gltf.scene);
const action = mixer.clipAction(clip);  // once, held at the end (the last key is not wrapped to the first)
action.setLoop(THREE.LoopOnce, 1);
action.clampWhenFinished = true;
action.play();
// the head: the mesh with a jawOpen (else viseme_aa) target whose target moves vertices most
let head = null, best = 0, key = null;
gltf.scene.traverse(o => { if (!o.isMesh || !o.morphTargetDictionary) return;
  for (const k of ['jawOpen', 'viseme_aa']) { const i = o.morphTargetDictionary[k]; if (i === undefined) continue;
    const t = o.geometry.morphAttributes.position[i]; let m = 0; for (let v = 0; v < t.count; ++v) m = Math.max(m, Math.hypot(t.getX(v), t.getY(v), t.getZ(v)));
    if (m > best) { best = m; head = o; key = k; } } });
// lip pair: near the midline, close together at rest, the lower one moved down by the key target far more than the upper
const pos = head.geometry.attributes.position, tgt = head.geometry.morphAttributes.position[head.morphTargetDictionary[key]];
const box = new THREE.Box3().setFromBufferAttribute(pos); const cx = (box.min.x + box.max.x) / 2;
const mid = []; let maxDown = 0;
for (let v = 0; v < pos.count; ++v) if (Math.abs(pos.getX(v) - cx) < 0.002) { mid.push(v); maxDown = Math.max(maxDown, -tgt.getY(v)); }
const lower = mid.filter(v => -tgt.getY(v) > 0.5 * maxDown), upper = mid.filter(v => Math.abs(tgt.getY(v)) < 0.2 * maxDown);
let pair = null, pairDist = Infinity;
for (const l of lower) for (const u of upper) {
  const dy = pos.getY(u) - pos.getY(l), dz = pos.getZ(u) - pos.getZ(l);
  if (dy < -0.0005 || dy > 0.006 || Math.abs(dz) > 0.004) continue;
  const d = Math.hypot(dy, dz); if (d < pairDist) { pairDist = d; pair = [u, l]; } }
if (!pair) { console.log(JSON.stringify({ error: 'no lip pair found on ' + head.name })); process.exit(1); }
const out = { mesh: head.name, key, tracks: clip.tracks.length, duration: clip.duration, pair, gaps: [] };
const a = new THREE.Vector3(), c = new THREE.Vector3();
for (const t of (timesArg || '0').split(',').map(Number)) {
  mixer.setTime(t); gltf.scene.updateMatrixWorld(true);
  head.getVertexPosition(pair[0], a); head.getVertexPosition(pair[1], c);
  out.gaps.push({ t, gap_m: +(a.y - c.y).toFixed(6), jawOpen: +(head.morphTargetInfluences[head.morphTargetDictionary.jawOpen] ?? 0).toFixed(4) });
}
console.log(JSON.stringify(out));
