// Headless Chromium driven over the DevTools protocol on a pipe: fds 3 (to it) and 4 (from it),
// NUL-separated JSON messages. No port and no npm package. Shared by the browser tests.
import {spawn} from 'node:child_process';
import fs from 'node:fs';

// Software WebGL (SwiftShader), no sandbox (CI runs as root), no background work or throttling.
const FLAGS = [
  '--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-sandbox',
  '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-background-timer-throttling', '--disable-renderer-backgrounding',
];

// Starts Chromium with a fresh profile in `profile` and its standard error in `log`. `onExit` is
// called if the browser exits before close(). Returns
//   call(method, params, sessionId)  one protocol command, resolved with its result;
//   openPage(url)                     a new tab at `url`: {call(method, params), evaluate(expression)};
//   pageLog                           the pages' console lines and uncaught exceptions;
//   close()                           ends the browser.
export function launchChromium({executable, profile, log, windowSize = '480,480', flags = [], onExit = () => {}}) {
  fs.rmSync(profile, {recursive: true, force: true});
  const chrome = spawn(executable, [...FLAGS, ...flags, '--user-data-dir=' + profile, '--window-size=' + windowSize,
                                    '--remote-debugging-pipe', 'about:blank'],
                       {stdio: ['ignore', 'ignore', fs.openSync(log, 'w'), 'pipe', 'pipe']});
  let closing = false, nextId = 0, inbox = Buffer.alloc(0);
  const pending = new Map(), pageLog = [];
  chrome.stdio[4].on('data', (chunk) => {
    inbox = Buffer.concat([inbox, chunk]);
    for (let end; (end = inbox.indexOf(0)) >= 0; inbox = inbox.subarray(end + 1)) {
      const m = JSON.parse(inbox.subarray(0, end).toString('utf8'));
      if (m.id !== undefined && pending.has(m.id)) {
        const {resolve, reject, method} = pending.get(m.id);
        pending.delete(m.id);
        m.error ? reject(new Error(method + ': ' + m.error.message)) : resolve(m.result);
      } else if (m.method === 'Runtime.consoleAPICalled') {
        pageLog.push(m.params.args.map((a) => a.value ?? a.description).join(' '));
      } else if (m.method === 'Runtime.exceptionThrown') {
        pageLog.push('exception: ' + (m.params.exceptionDetails.exception?.description ?? m.params.exceptionDetails.text));
      }
    }
  });
  chrome.on('exit', (code, signal) => { if (!closing) onExit(code ?? signal); });
  const call = (method, params = {}, sessionId = undefined) => new Promise((resolve, reject) => {
    const id = ++nextId;
    pending.set(id, {resolve, reject, method});
    chrome.stdio[3].write(JSON.stringify({id, method, params, sessionId}) + '\0');
  });
  async function openPage(url) {
    const {targetId} = await call('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await call('Target.attachToTarget', {targetId, flatten: true});
    const page = (method, params) => call(method, params, sessionId);
    await page('Runtime.enable');
    if (url) await page('Page.navigate', {url});
    async function evaluate(expression) {
      const r = await page('Runtime.evaluate', {expression, returnByValue: true, awaitPromise: true});
      if (r.exceptionDetails) throw new Error(`${expression}: ${r.exceptionDetails.exception?.description ?? r.exceptionDetails.text}`);
      return r.result.value;
    }
    return {call: page, evaluate};
  }
  function close() {
    closing = true;
    if (chrome.exitCode === null) chrome.kill('SIGKILL');
  }
  return {process: chrome, call, openPage, pageLog, close};
}
