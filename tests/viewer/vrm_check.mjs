// A VRM loaded by @pixiv/three-vrm and animated by a .vrma through @pixiv/three-vrm-animation under
// Node:  node vrm_check.mjs AVATAR.vrm ANIMATION.vrma
// Prints one JSON line: the VRM's meta version and expressions, the clip's tracks and duration, and at
// every key time of the animation each expression's weight and the driven morph influences.
import './browser_globals.mjs';
import fs from 'node:fs';
const THREE = await import('three');
const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
const { VRMLoaderPlugin } = await import('@pixiv/three-vrm');
const { VRMAnimationLoaderPlugin, createVRMAnimationClip } = await import('@pixiv/three-vrm-animation');
const load = file => { const b = fs.readFileSync(file); const l = new GLTFLoader();
  l.register(p => new VRMLoaderPlugin(p)); l.register(p => new VRMAnimationLoaderPlugin(p));
  return new Promise((res, rej) => l.parse(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength), '', res, rej)); };
const [vrmFile, vrmaFile] = process.argv.slice(2);
const vrm = (await load(vrmFile)).userData.vrm;
if (!vrm) { console.log(JSON.stringify({ error: 'three-vrm found no VRM in ' + vrmFile })); process.exit(1); }
const animations = (await load(vrmaFile)).userData.vrmAnimations;
if (!animations || animations.length !== 1) { console.log(JSON.stringify({ error: 'want one VRM animation in ' + vrmaFile })); process.exit(1); }
const clip = createVRMAnimationClip(animations[0], vrm);
const mixer = new THREE.AnimationMixer(vrm.scene);
// played once and held at the end, so that the last key is evaluated, not wrapped to the first
const action = mixer.clipAction(clip);
action.setLoop(THREE.LoopOnce, 1);
action.clampWhenFinished = true;
action.play();
const names = vrm.expressionManager.expressions.map(e => e.expressionName);
const times = clip.tracks.length ? Array.from(clip.tracks[0].times) : [];
const frames = times.map(t => { mixer.setTime(t); vrm.update(0);
  return names.map(n => +vrm.expressionManager.getValue(n).toFixed(7)); });
console.log(JSON.stringify({ meta: vrm.meta.metaVersion, expressions: names, tracks: clip.tracks.map(t => t.name),
  duration: clip.duration, times, frames }));
