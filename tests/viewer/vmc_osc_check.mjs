// A real OSC implementation (npm node-osc) receives fapcast's live VMC stream on loopback:
//   node vmc_osc_check.mjs FAPCAST ARGS...   (the args get "--vmc udp://127.0.0.1:PORT" appended)
// It binds port 0, runs fapcast, collects every bundle until fapcast exits (plus 300 ms), and prints
// one JSON line: the bundles in arrival order as {T, ok, names, values, apply, arrival_ms} and fapcast's
// exit code.
import { spawn } from 'node:child_process';
import { Server } from 'node-osc';
const [fapcast, ...args] = process.argv.slice(2);
const server = new Server(0, '127.0.0.1');
await new Promise(r => server.on('listening', r));
const bundles = [];
const t0 = performance.now();
server.on('bundle', b => {
  const out = { T: null, ok: null, names: [], values: [], apply: false, after_apply: 0, arrival_ms: +(performance.now() - t0).toFixed(3) };
  for (const m of b.elements) {
    if (out.apply) ++out.after_apply;
    if (m[0] === '/VMC/Ext/T') out.T = m[1];
    else if (m[0] === '/VMC/Ext/OK') out.ok = m[1];
    else if (m[0] === '/VMC/Ext/Blend/Val') { out.names.push(m[1]); out.values.push(m[2]); }
    else if (m[0] === '/VMC/Ext/Blend/Apply') out.apply = true;
  }
  bundles.push(out);
});
const child = spawn(fapcast, [...args, '--vmc', `udp://127.0.0.1:${server.port}`], { stdio: ['ignore', 'ignore', 'inherit'] });
const code = await new Promise(r => child.on('exit', r));
await new Promise(r => setTimeout(r, 300));
server.close();
console.log(JSON.stringify({ exit: code, port: server.port, bundles }));
