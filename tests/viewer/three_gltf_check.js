#!/usr/bin/env node
// Loads a .glb the way a web viewer does: three.js's GLTFLoader (Debian libjs-three, r111) run in
// Node, no browser, no network. Prints what the viewer sees as one JSON line and checks it:
//
//   node three_gltf_check.js FILE.glb [--targets K] [--frames F] [--fps R]
//
// {"meshes", "vertices", "targets", "names", "animations": [{"name", "duration",
//  "tracks": [{"name", "keys", "values"}]}], "influences": [...]}. Exit 0 when it loads and every
// check given holds, 1 otherwise (the reason on stderr).
'use strict';
const fs = require('fs');
const path = require('path');
const vm = require('vm');

const threeDir = process.env.FAPCAST_THREE_DIR || '/usr/share/javascript/three';
const args = process.argv.slice(2);
const file = args[0];
const want = {};
for (let i = 1; i + 1 < args.length; i += 2) want[args[i].replace(/^--/, '')] = Number(args[i + 1]);

function fail(message) {
  process.stderr.write('three_gltf_check: ' + file + ': ' + message + '\n');
  process.exit(1);
}
if (!file) fail('usage: three_gltf_check.js FILE.glb [--targets K] [--frames F] [--fps R]');

// three.js and its example loaders expect a browser's global object; a fresh context with the
// few globals they touch (the UMD build attaches THREE to it) is enough for parsing.
const context = vm.createContext({ console, TextDecoder, setTimeout, clearTimeout });
for (const script of ['build/three.js', 'examples/js/loaders/GLTFLoader.js']) {
  const source = path.join(threeDir, script);
  if (!fs.existsSync(source)) fail('no ' + source + ' (Debian libjs-three; tools/setup.sh installs it)');
  vm.runInContext(fs.readFileSync(source, 'utf8'), context, { filename: source });
}
const THREE = context.THREE;
if (!THREE || !THREE.GLTFLoader) fail('three.js or GLTFLoader did not load from ' + threeDir);

const bytes = fs.readFileSync(file);
const buffer = vm.runInContext('(n) => new ArrayBuffer(n)', context)(bytes.length);
new Uint8Array(buffer).set(bytes);

new THREE.GLTFLoader().parse(buffer, '', (gltf) => {
  const meshes = [];
  gltf.scene.traverse((o) => { if (o.isMesh) meshes.push(o); });
  if (meshes.length !== 1) fail('expected one mesh, found ' + meshes.length);
  const mesh = meshes[0];
  const geometry = mesh.geometry;
  const morphs = geometry.morphAttributes.position || [];
  const names = Object.keys(mesh.morphTargetDictionary || {})
    .sort((a, b) => mesh.morphTargetDictionary[a] - mesh.morphTargetDictionary[b]);
  const report = {
    meshes: meshes.length,
    vertices: geometry.attributes.position.count,
    targets: morphs.length,
    names,
    influences: Array.from(mesh.morphTargetInfluences || []),
    animations: gltf.animations.map((clip) => ({
      name: clip.name,
      duration: clip.duration,
      tracks: clip.tracks.map((t) => ({ name: t.name, keys: t.times.length, values: t.values.length,
                                        times: Array.from(t.times), weights: Array.from(t.values) })),
    })),
  };
  // Each morph target holds one displacement per vertex.
  for (const m of morphs) if (m.count !== report.vertices) fail('a morph target has ' + m.count + ' vertices');
  if ('targets' in want && report.targets !== want.targets) fail(report.targets + ' morph targets, want ' + want.targets);
  if (report.influences.length !== report.targets) fail('morphTargetInfluences has ' + report.influences.length + ' entries');
  if ('frames' in want) {
    if (report.animations.length !== 1) fail(report.animations.length + ' animations, want 1');
    const tracks = report.animations[0].tracks;
    if (tracks.length !== 1 || !tracks[0].name.endsWith('.morphTargetInfluences'))
      fail('want one .morphTargetInfluences track, found ' + tracks.map((t) => t.name).join(', '));
    if (tracks[0].keys !== want.frames) fail(tracks[0].keys + ' keyframes, want ' + want.frames);
    if (tracks[0].values !== want.frames * report.targets) fail(tracks[0].values + ' weights, want frames x targets');
    if ('fps' in want) {
      const duration = (want.frames - 1) / want.fps;
      if (Math.abs(report.animations[0].duration - duration) > 1e-4)
        fail('duration ' + report.animations[0].duration + ' s, want ' + duration);
    }
  }
  process.stdout.write(JSON.stringify(report) + '\n');
}, (error) => fail('GLTFLoader refused it: ' + (error && error.message ? error.message : error)));
