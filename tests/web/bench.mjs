#!/usr/bin/env node
// The web page's cost against the native build's, side by side in one run (docs/performance.md):
// for each scene, the page in headless Chromium runs `frames` frames back to back
// (window.noneuclid.bench: step, draw and putImageData), then tests/bench/bench_loop.cpp does
// natively (step and draw; its display shows nothing; the faster of two runs of `frames`, the
// first warming up), `reps` times in turn, the fastest of each kept. Also the
// sizes of the page's .wasm and .js, as served and gzip-compressed.
//   node tests/web/bench.mjs --bench-loop build/release/bench_loop --page build/web/page
//        [--work DIR] [--frames 600] [--reps 5] [--chromium chromium]
import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {parseArgs} from 'node:util';
import zlib from 'node:zlib';

import {Browser} from './cdp.mjs';
import {serve} from './serve.mjs';

const {values: opt} = parseArgs({options: {
  'bench-loop': {type: 'string'}, 'page': {type: 'string'}, 'work': {type: 'string'},
  'frames': {type: 'string', default: '600'}, 'reps': {type: 'string', default: '5'},
  'chromium': {type: 'string', default: 'chromium'},
}});
if (!opt['bench-loop'] || !opt.page) throw new Error('bench: --bench-loop and --page are needed');
const frames = Number(opt.frames), reps = Number(opt.reps);
const work = opt.work ? path.resolve(opt.work) : fs.mkdtempSync(path.join(os.tmpdir(), 'noneuclid-bench-'));
fs.rmSync(path.join(work, 'profile'), {recursive: true, force: true});

const {server, port} = serve(path.resolve(opt.page));
const base = `http://127.0.0.1:${await port}/index.html`;
const browser = new Browser(opt.chromium, path.join(work, 'profile'));
const rows = [];
try {
  for (const scene of ['kiosk', 'stress', 'space']) {
    const page = await browser.newPage();
    await page.open(`${base}?scene=${scene}&size=800x480`);  // the page would fit its size to the window
    if (!await page.evaluate('window.noneuclid.ready')) throw new Error(`the page did not start on ${scene}`);
    // The page and the native program take turns, so that a change in the host's load between
    // them reaches both.
    // Each side warmed up first: the browser compiles the module's hot code again, optimised,
    // while it runs, and both fill the shape caches of the first frames.
    await page.evaluate(`window.noneuclid.bench(${frames})`);
    let web = null, native = Infinity;
    for (let r = 0; r < reps; ++r) {
      const b = await page.evaluate(`window.noneuclid.bench(${frames})`);
      if (b.frames !== frames) throw new Error(`the page's run ended after ${b.frames} of ${frames} frames`);
      if (!web || b.ms < web.ms) web = b;
      const n = JSON.parse(execFileSync(opt['bench-loop'], [scene, String(frames), '2'], {encoding: 'utf8'}));
      native = Math.min(native, n.ms);
    }
    await page.close();
    rows.push({scene, web, native});
  }
} finally {
  await browser.close();
  server.kill();
}

console.log(`| scene (800x480, fixed engine, HUD on) | page in Chromium, ms a frame | of which putImageData | native, ms a frame | page / native | page without putImageData / native |`);
console.log('|---|---:|---:|---:|---:|---:|');
for (const {scene, web, native} of rows)
  console.log(`| ${scene} | ${web.ms.toFixed(3)} | ${web.present_ms.toFixed(3)} | ${native.toFixed(3)} | ` +
              `${(web.ms / native).toFixed(2)} | ${((web.ms - web.present_ms) / native).toFixed(2)} |`);
console.log('');
console.log('| file | bytes | gzip -9 |');
console.log('|---|---:|---:|');
let total = 0, totalGz = 0;
for (const f of ['noneuclid.wasm', 'noneuclid.js', 'page.js', 'page_lang.js', 'page_fit.js', 'sound.js', 'index.html', 'page.css']) {
  const bytes = fs.readFileSync(path.join(opt.page, f));
  const gz = zlib.gzipSync(bytes, {level: 9}).length;
  total += bytes.length, totalGz += gz;
  console.log(`| ${f} | ${bytes.length} | ${gz} |`);
}
console.log(`| all | ${total} (${(total / 1024).toFixed(0)} KiB) | ${totalGz} (${(totalGz / 1024).toFixed(0)} KiB) |`);
