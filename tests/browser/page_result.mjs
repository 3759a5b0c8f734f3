// Opens a page in headless Chromium and prints what it writes into its element #out, once that is
// not empty: for pages that compute a result and write it there (tests/viewer/avatar_frames.html).
// Waits in real time, so a loaded machine only makes it slower (Chromium's --virtual-time-budget
// can run out before a page's loader calls back, and then dumps the page without its result).
//
// node page_result.mjs --chromium EXE --url URL --out DIR [--window W,H] [--seconds S]
// Exit 0 with the text on standard output; 1 when the page has none within S seconds (default 120)
// or the browser fails; 2 for a missing argument.
import fs from 'node:fs';
import path from 'node:path';
import {launchChromium} from './chromium_pipe.mjs';

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
for (const a of ['chromium', 'url', 'out'])
  if (!args[a]) { console.error(`usage: --${a} is required`); process.exit(2); }
const seconds = Number(args.seconds ?? 120);
fs.mkdirSync(args.out, {recursive: true});

let browser = null;
function fail(why) {
  console.error('page result: ' + why + (browser && browser.pageLog.length ? '\npage log:\n' + browser.pageLog.join('\n') : ''));
  if (browser) browser.close();
  process.exit(1);
}
setTimeout(() => fail(`${args.url}: no result in #out within ${seconds} s`), seconds * 1000).unref();

browser = launchChromium({executable: args.chromium, profile: path.join(args.out, 'profile'),
                          log: path.join(args.out, 'chromium.log'), windowSize: args.window ?? '1600,400',
                          onExit: (status) => fail(`chromium exited (${status}): see ${args.out}/chromium.log`)});
let page = null;
try {
  page = await browser.openPage(args.url);
} catch (e) {
  fail(String(e));
}
// While the page navigates an evaluation may find no context yet: try again until the deadline.
for (let lastError = null; ;) {
  try {
    const text = await page.evaluate(`(document.getElementById('out') || {}).textContent || ''`);
    if (text) {
      process.stdout.write(text + '\n');
      break;
    }
  } catch (e) {
    if (String(e) !== lastError) console.error('page result: ' + (lastError = String(e)) + ' (trying again)');
  }
  await new Promise((r) => setTimeout(r, 100));
}
browser.close();
process.exit(0);
