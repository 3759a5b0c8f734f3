// The avatar page of `fapcast serve` in headless Chromium (spec/serve.md, "The avatar page"):
// builds a small SYNTHETIC voice, starts the server on port 0, opens the page, speaks a sentence
// through the page's own form, holds the face (the page's test hook) on the longest vowel's most
// open frame and on the bilabials' most closed one, screenshots both and counts the dark pixels
// (the open mouth's cavity) in the mouth's box, projected from the lip landmarks of
// spec/markers.tsv. Asserts the mouth is open at the vowel and closed at the closure, and that the
// page's measured audio/face offset stays within one frame. Chromium is driven over the DevTools
// protocol on a pipe (chromium_pipe.mjs: no port, no npm package).
//
// node avatar_page_test.mjs --fapcast EXE --chromium EXE --markers spec/markers.tsv --out DIR
//                           [--picture FILE]   (also write the vowel's screenshot there)
import {spawn, spawnSync} from 'node:child_process';
import crypto from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import readline from 'node:readline';
import zlib from 'node:zlib';
import {launchChromium} from './chromium_pipe.mjs';

const TEXT = 'Papa may come home, and Bob made a map.';
const VOWELS = new Set(['AA', 'AE', 'AH', 'AO', 'AW', 'AX', 'AY', 'EH', 'ER', 'EY', 'IH', 'IY', 'OW', 'OY', 'UH', 'UW']);
const BILABIALS = new Set(['P', 'B', 'M']);
const DARK_LUMA = 50;  // of 255 (Rec. 601): the cavity, not the lips' or the skin's shading
const DEADLINE_MS = 80000;  // the whole test: about 22 s alone, 45 s beside two more of it on 2 cores
const started = Date.now();

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
for (const a of ['fapcast', 'chromium', 'markers', 'out'])
  if (!args[a]) { console.error(`usage: --${a} is required`); process.exit(2); }
fs.rmSync(args.out, {recursive: true, force: true});
fs.mkdirSync(args.out, {recursive: true});

const children = [];
let stopping = false;  // set when the test stops the server and Chromium itself
const failures = [];
const elapsed = () => ((Date.now() - started) / 1000).toFixed(1) + ' s';
function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  if (!ok) failures.push(what);
}
function finish(code) {
  for (const c of children) if (c.exitCode === null) c.kill('SIGKILL');
  process.exit(code);
}
function abort(why) {
  console.error('avatar page test: ' + why);
  finish(1);
}
setTimeout(() => abort(`not done in ${DEADLINE_MS / 1000} s`), DEADLINE_MS).unref();

// The mouth's box: the inner lip corners (2.4, 2.5) across, the outer upper lip midpoint (8.1)
// down to the chin boss (2.10), where an open mouth's cavity reaches.
const markers = new Map(fs.readFileSync(args.markers, 'utf8').split('\n').filter((l) => l && !l.startsWith('#'))
  .map((l) => l.split('\t')).map(([label, vertex]) => [label, Number(vertex)]));
const mouth = ['2.4', '2.5', '8.1', '2.10'].map((label) => {
  if (!markers.has(label)) abort(`${args.markers}: no feature point ${label}`);
  return markers.get(label);
});

// --- A small voice of the SYNTHETIC reference talker (as tests/cli's), then fapcast serve on port 0:
// its first stdout line is its URL.
for (const command of [['corpus', 'record-reference', '-q', '--count', '40', '--seed', '1', '-o', path.join(args.out, 'corpus')],
                       ['voice', 'build', '-q', path.join(args.out, 'corpus'), '-o', path.join(args.out, 'v.fapv')]]) {
  const r = spawnSync(args.fapcast, command, {encoding: 'utf8', timeout: 30000});
  if (r.status !== 0) abort(`fapcast ${command.join(' ')}: exit ${r.status ?? r.signal}\n${r.stderr}`);
  console.log(`fapcast ${command[0]} ${command[1]}: ${elapsed()}`);
}
const token = crypto.randomBytes(24).toString('base64url');
const tokenFile = path.join(args.out, 'token');
fs.writeFileSync(tokenFile, token + '\n', {mode: 0o600});
const server = spawn(args.fapcast, ['serve', '--listen', '127.0.0.1:0', '--token-file', tokenFile,
                                      '--voice', path.join(args.out, 'v.fapv')],
                     {stdio: ['ignore', 'pipe', 'pipe']});
children.push(server);
const serverLog = fs.createWriteStream(path.join(args.out, 'serve.log'));
server.stderr.pipe(serverLog);
server.on('exit', (code, signal) => { if (!stopping) abort(`fapcast serve exited (${code ?? signal}): see ${args.out}/serve.log`); });
const base = await new Promise((resolve) => {
  readline.createInterface({input: server.stdout}).once('line', (line) => resolve(line.trim()));
});
console.log(`server up: ${elapsed()}`);
if (!/^http:\/\/127\.0\.0\.1:\d+\/?$/.test(base)) abort(`fapcast serve's first line is not its URL: ${base}`);

// --- Chromium over the DevTools protocol (chromium_pipe.mjs).
const browser = launchChromium({
  executable: args.chromium, profile: path.join(args.out, 'profile'), log: path.join(args.out, 'chromium.log'),
  flags: ['--autoplay-policy=no-user-gesture-required'],
  onExit: (status) => { if (!stopping) abort(`chromium exited (${status}): see ${args.out}/chromium.log`); },
});
children.push(browser.process);
const pageLog = browser.pageLog;
const {call: page, evaluate} = await browser.openPage();

async function waitFor(expression, what, ms = 20000) {
  for (const until = Date.now() + ms; Date.now() < until;) {
    const v = await evaluate(expression);
    if (v) return v;
    const error = await evaluate('window.fapcastStats && window.fapcastStats.error');
    if (error) abort(`the page failed while waiting for ${what}: ${error}\n${pageLog.join('\n')}`);
    await new Promise((r) => setTimeout(r, 40));
  }
  abort(`no ${what} within ${ms / 1000} s; page log:\n${pageLog.join('\n')}\nstats: ` +
        JSON.stringify(await evaluate('window.fapcastStats')));
}

await page('Emulation.setDeviceMetricsOverride', {width: 480, height: 480, deviceScaleFactor: 1, mobile: false});
await page('Page.navigate', {url: `${base.replace(/\/$/, '')}/?channel=browser-test&token=${token}`});
await waitFor(`window.fapcastStats && fapcastStats.state === 'ready'`, 'face loaded and live stream open');

console.log(`page ready: ${elapsed()}`);
// --- Speak through the page's own form (POST /v1/say), then freeze at a vowel and a closure.
await evaluate(`document.getElementById('text').value = ${JSON.stringify(TEXT)};
                document.getElementById('speak').click(); true`);
const sentence = await waitFor(`fapcastStats.sentences.length > 0 && fapcastStats.sentences[0]`, 'sentence message');
// The frames of the longest vowel and of every bilabial, from the phones; among them, by the inner
// lip midpoints' distance in the page's own morph, the vowel's most open and the bilabials' most
// closed frame (as tests/cli/rig_cli_test.cpp picks them).
await waitFor(`fapcastStats.frames_received >= ${sentence.frames}`, 'all frames of the sentence');
const distances = await evaluate(`fapcastTest.distances(${markers.get('2.2')}, ${markers.get('2.3')})`);
console.log("inner-lip distance per frame, mm: " + distances.map((f) => (1000 * f.distance).toFixed(1)).join(" "));
const framesOf = (phones) => distances.filter((f) => phones.some(([, start, end]) => start <= f.sample && f.sample < end));
const phoneOf = (f) => sentence.phones.find(([, start, end]) => start <= f.sample && f.sample < end);
const isVowel = ([p]) => VOWELS.has(p.replace(/[0-9]/g, ''));
const longestVowel = sentence.phones.filter(isVowel).reduce((best, p) => (!best || p[2] - p[1] > best[2] - best[1] ? p : best), null);
const vowelFrames = longestVowel ? framesOf([longestVowel]) : [];
const closureFrames = framesOf(sentence.phones.filter(([p]) => BILABIALS.has(p)));
if (!vowelFrames.length || !closureFrames.length) abort(`"${TEXT}" gave no vowel or no bilabial frame: ${JSON.stringify(sentence.phones)}`);
const pick = (frames, better) => frames.reduce((best, f) => (better(f.distance, best.distance) ? f : best));
const shots = [{name: 'vowel', ...pick(vowelFrames, (a, b) => a > b)}, {name: 'closure', ...pick(closureFrames, (a, b) => a < b)}]
  .map((s) => ({...s, phone: phoneOf(s)[0]})).sort((a, b) => a.sample - b.sample);
await evaluate(`fapcastTest.hold(${JSON.stringify(shots.map((s) => s.sample))}); true`);
for (const shot of shots) {
  const held = await waitFor(`fapcastStats.held && fapcastStats.held.sample === ${shot.sample} && fapcastStats.held`,
                             `hold at the ${shot.name}`);
  const box = await evaluate(`fapcastTest.box(${JSON.stringify(mouth)}, true)`);
  const png = Buffer.from((await page('Page.captureScreenshot', {format: 'png'})).data, 'base64');
  fs.writeFileSync(path.join(args.out, shot.name + '.png'), png);
  const clip = {x: box.x0 - 10, y: box.y0 - 10, width: box.x1 - box.x0 + 20, height: box.y1 - box.y0 + 20, scale: 4};
  fs.writeFileSync(path.join(args.out, shot.name + '-mouth.png'),  // for people: the mouth, 4 x
                   Buffer.from((await page('Page.captureScreenshot', {format: 'png', clip})).data, 'base64'));
  if (held.frame !== shot.index) abort(`held frame ${held.frame}, not ${shot.index}`);
  Object.assign(shot, {box, ...darkPixels(decodePng(png), box)});
  await evaluate('fapcastTest.release(); true');
}
await waitFor('fapcastStats.sessions_played > 0', 'the end of the session played');
// Two more at once: the second is queued by the server and must follow the first, whole.
await evaluate(`document.getElementById('text').value = 'Hello there.';
                document.getElementById('speak').click(); document.getElementById('speak').click(); true`);
await waitFor('fapcastStats.sessions_played >= 3', 'two more sessions played');
const stats = await evaluate('fapcastStats');

// --- The checks.
const [v, c] = ['vowel', 'closure'].map((n) => shots.find((s) => s.name === n));
for (const s of [v, c])
  console.log(`${s.name}: frame ${s.index} (sample ${s.sample}, /${s.phone}/), inner lips ${(1000 * s.distance).toFixed(1)} mm ` +
              `apart; mouth box ${s.width} x ${s.height} px, ${s.dark} dark pixels (${(100 * s.dark / s.pixels).toFixed(1)} %)`);
const o = stats.offset_ms, ms = (x) => (x === null ? 'none' : x.toFixed(1));  // JSON has no Infinity
const magnitudes = stats.offsets.map(Math.abs).sort((a, b) => a - b);
const p95 = magnitudes.length ? magnitudes[Math.min(magnitudes.length - 1, Math.floor(0.95 * magnitudes.length))] : null;
console.log(`offset (face shown - audio played): mean ${ms(o.mean)} ms, 95th percentile of its size ${ms(p95)} ms, ` +
            `range ${ms(o.min)}..${ms(o.max)} over ${o.count} displays; frames received ${stats.frames_received}, ` +
            `late ${stats.late_frames}, jitter buffer ${stats.jitter_frames} frames`);
check(v.pixels >= 100, `the mouth box is at least 100 pixels (${v.pixels})`);
check(v.dark >= 0.05 * v.pixels, `the mouth is open at the vowel: >= 5 % of its box dark (${v.dark} of ${v.pixels})`);
check(c.dark <= 0.4 * v.dark, `the lips are closed at the closure: <= 40 % of the vowel's dark pixels (${c.dark} vs ${v.dark})`);
const frameMs = 1000 / stats.fps;
check(o.count >= 5, `the face was shown with its audio at least 5 times (${o.count})`);
// within one frame: the mean, and 95 % of the displays (a loaded machine may stall one now and then)
check(o.count > 0 && Math.abs(o.mean) <= frameMs && p95 <= frameMs,
      `the audio/face offset stays within one frame (±${frameMs} ms): mean ${ms(o.mean)}, 95 % within ±${ms(p95)} ms`);
const sent = stats.sentences.reduce((sum, x) => sum + x.frames, 0);
check(stats.sentences.length === 3 && stats.frames_received === sent,
      `every frame of the 3 sessions arrived (${stats.frames_received} of ${sent})`);
check(stats.sessions_played === 3, `the 3 sessions played to their ends (${stats.sessions_played})`);
if (args.picture) fs.copyFileSync(path.join(args.out, 'vowel.png'), args.picture);
fs.writeFileSync(path.join(args.out, 'result.json'), JSON.stringify({shots, stats, sentence}, null, 1));

// --- Clean shutdown: the server exits 0 on SIGTERM.
stopping = true;
browser.process.kill('SIGTERM');
server.kill('SIGTERM');
const status = await new Promise((resolve) => server.exitCode !== null ? resolve(server.exitCode) : server.once('exit', (code) => resolve(code)));
check(status === 0, `fapcast serve exits 0 on SIGTERM (${status})`);
console.log(`${failures.length ? 'FAILED' : 'passed'} in ${elapsed()}`);
finish(failures.length ? 1 : 0);

// --- Pixels: a PNG (8-bit RGB or RGBA, not interlaced: what Chromium writes) and its dark ones.
function decodePng(png) {
  if (png.readUInt32BE(0) !== 0x89504e47) throw new Error('screenshot: not a PNG');
  let width = 0, height = 0, channels = 0;
  const idat = [];
  for (let at = 8; at < png.length;) {
    const length = png.readUInt32BE(at), type = png.toString('latin1', at + 4, at + 8), data = png.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      channels = {2: 3, 6: 4}[data[9]];
      if (data[8] !== 8 || !channels || data[12] !== 0) throw new Error('screenshot: not 8-bit RGB(A), non-interlaced');
    } else if (type === 'IDAT') idat.push(data);
    at += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat)), stride = width * channels, rgb = Buffer.alloc(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? rgb[y * stride + x - channels] : 0, b = y > 0 ? rgb[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? rgb[(y - 1) * stride + x - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      rgb[y * stride + x] = (line[x] + predictor) & 0xff;
    }
  }
  return {width, height, channels, rgb};
}

function darkPixels(image, box) {
  const x0 = Math.max(0, Math.floor(box.x0)), x1 = Math.min(image.width, Math.ceil(box.x1));
  const y0 = Math.max(0, Math.floor(box.y0)), y1 = Math.min(image.height, Math.ceil(box.y1));
  let dark = 0;
  for (let y = y0; y < y1; ++y)
    for (let x = x0; x < x1; ++x) {
      const i = (y * image.width + x) * image.channels;
      if (0.299 * image.rgb[i] + 0.587 * image.rgb[i + 1] + 0.114 * image.rgb[i + 2] < DARK_LUMA) ++dark;
    }
  return {width: x1 - x0, height: y1 - y0, pixels: (x1 - x0) * (y1 - y0), dark};
}
