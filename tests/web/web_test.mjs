#!/usr/bin/env node
// The web page in a real browser: headless Chromium (Debian's), driven through the DevTools
// protocol (cdp.mjs), loads the page from a local server (python3 -m http.server) and:
//  1. plays tests/web/flight.rec from its URL on each engine, and on the fixed one anti-aliased
//     and in RGB565 with anti-aliasing: the canvas, read back as PNG, equals `noneuclid render
//     --actions` of the same file, pixel for pixel;
//  2. is flown live with key presses, its K slider and projection menu, and touch taps on its
//     buttons; the run's recording holds them, `noneuclid render --actions` of it equals the
//     canvas pixel for pixel, and the same recording without the thrust gives another picture
//     (the comparison can fail). In the game (the asteroids scene) Space starts it and the
//     fire button, held, fires: the same holds, and without the button's shots it differs;
//  3. runs a pasted scene file, whose recording replays on the file, pixel for pixel; and the
//     measure scene, where taps on the picture mark the live triangle and the recording of the
//     marks replays it;
//  4. says one sentence for a bad option, a scene file it cannot load, a bad pasted one and a
//     texture file (a page reads none);
//  5. fits phones held either way and a desktop, and the rest of page_checks.mjs.
// Every page that should work must also leave its console without an error.
//   node web_test.mjs --noneuclid N --png-diff P --page DIR --work DIR [--chromium PATH]
import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {parseArgs} from 'node:util';
import {fileURLToPath} from 'node:url';

import {Browser} from './cdp.mjs';
import {pageChecks} from './page_checks.mjs';
import {serve} from './serve.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const {values: opt} = parseArgs({options: {
  'noneuclid': {type: 'string'}, 'png-diff': {type: 'string'}, 'page': {type: 'string'},
  'work': {type: 'string'}, 'chromium': {type: 'string', default: 'chromium'},
}});
for (const need of ['noneuclid', 'png-diff', 'page', 'work'])
  if (!opt[need]) throw new Error(`web_test: --${need} is missing`);

const work = path.resolve(opt.work);
fs.rmSync(work, {recursive: true, force: true});
const root = path.join(work, 'site');  // what the server serves: the page and the test's files
fs.mkdirSync(root, {recursive: true});
for (const f of fs.readdirSync(opt.page)) fs.copyFileSync(path.join(opt.page, f), path.join(root, f));
fs.copyFileSync(path.join(here, 'flight.rec'), path.join(root, 'flight.rec'));

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
let failures = 0, passes = 0;

// ---- pictures, render, checks ----------------------------------------------------------------
function pngOf(dataUrl, file) {
  fs.writeFileSync(file, Buffer.from(dataUrl.replace(/^data:image\/png;base64,/, ''), 'base64'));
}
// png_diff's verdict: 0 the same, 1 different; its line of figures.
function pngDiff(a, b) {
  try {
    return {status: 0, out: execFileSync(opt['png-diff'], [a, b, '--exact'], {encoding: 'utf8'}).trim()};
  } catch (e) {
    if (e.status === 1) return {status: 1, out: String(e.stdout).trim()};
    throw new Error(`png_diff ${a} ${b}: ${e.stderr || e.message}`);
  }
}
function render(args) {
  execFileSync(opt.noneuclid, ['render', ...args], {encoding: 'utf8', stdio: ['ignore', 'ignore', 'pipe']});
}

async function check(name, fn) {
  try {
    await fn();
    ++passes;
    console.log(`ok - ${name}`);
  } catch (e) {
    ++failures;
    console.log(`not ok - ${name}\n  ${String(e.stack || e).split('\n').join('\n  ')}`);
  }
}
function expect(condition, text) {
  if (!condition) throw new Error(text);
}

const {server, port} = serve(root);
const base = `http://127.0.0.1:${await port}/index.html`;
const browser = new Browser(opt.chromium, path.join(work, 'profile'), ['--window-size=1000,1000']);
const watchdog = setTimeout(() => {
  console.log('not ok - the browser test did not finish within 400 s');
  browser.process.kill('SIGKILL');
  server.kill();
  process.exit(1);
}, 400000);

// A page at index.html?QUERY, started: its Page, and whether its first run started.
async function openPage(query) {
  const page = await browser.newPage();
  await page.open(`${base}?${query}`);
  const started = await page.evaluate('window.noneuclid.ready');
  return {page, started};
}
async function waitFrames(page, n) {
  const target = (await page.evaluate('window.noneuclid.state().frame')) + n;
  for (let t = 0; t < 600; ++t) {
    const s = await page.evaluate('window.noneuclid.state()');
    if (s.frame >= target) return;
    expect(s.running, `the run ended at frame ${s.frame}, before frame ${target}: ${s.message}`);
    await sleep(50);
  }
  throw new Error(`frame ${target} did not come within 30 s`);
}
const canvasPng = (page, file) =>
  page.evaluate("document.getElementById('screen').toDataURL('image/png')").then((url) => pngOf(url, file));

// ---- 1. a scripted flight: the page against render, each engine --------------------------------
const flight = path.join(root, 'flight.rec');
const cases = [
  {name: 'fixed', query: 'engine=fixed', args: ['--engine', 'fixed']},
  {name: 'fixed-aa', query: 'aa=on', args: ['--aa']},
  {name: 'double', query: 'engine=double', args: ['--engine', 'double']},
  {name: 'float', query: 'engine=float', args: ['--engine', 'float']},
  {name: 'paper', query: 'engine=paper', args: ['--engine', 'paper']},
  {name: 'fixed-rgb565-aa', query: 'format=rgb565&aa=on', args: ['--format', 'rgb565', '--aa']},
];
for (const c of cases) {
  await check(`flight.rec, ${c.name}: the page's canvas equals render --actions, pixel for pixel`, async () => {
    const {page, started} = await openPage(`actions=flight.rec&${c.query}`);
    expect(started === true, `the page did not start: ${(await page.evaluate('window.noneuclid.state()')).message}`);
    await page.evaluate('window.noneuclid.ended()');
    const state = await page.evaluate('window.noneuclid.state()');
    expect(state.frame === 150, `the page stopped at frame ${state.frame}, not 150 (flight.rec's frames)`);
    const shot = path.join(work, `flight-${c.name}-page.png`), want = path.join(work, `flight-${c.name}-render.png`);
    await canvasPng(page, shot);
    render(['--actions', flight, ...c.args, '--out', want]);
    const diff = pngDiff(shot, want);
    expect(diff.status === 0, `the page differs from render: ${diff.out} (${shot}, ${want})`);
    expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
    await page.close();
  });
}

// ---- 2. flown live: keys and touch, then the recording replayed ---------------------------------
await check('keys and touch taps: the recording of the live run, replayed by render, equals the canvas', async () => {
  const {page, started} = await openPage('scene=kiosk&size=400x300');
  expect(started === true, 'the page did not start');
  await waitFrames(page, 5);
  const key = async (key, code, keyCode, frames = 2) => {
    await page.key('keyDown', key, code, keyCode);
    await waitFrames(page, frames);
    await page.key('keyUp', key, code, keyCode);
    await waitFrames(page, 2);
  };
  await key('ArrowUp', 'ArrowUp', 38, 30);  // thrust, held half a second
  await key('a', 'KeyA', 65);
  await key('a', 'KeyA', 65);
  await key('3', 'Digit3', 51);  // K = +1
  await key('h', 'KeyH', 72);    // the HUD off and on again
  await key('h', 'KeyH', 72);
  // The page's controls: the K slider to 0.5 (it holds curvature down from +1), the projection
  // menu to stereographic (one tap of the projection control).
  await page.evaluate(`(() => {
    const k = document.getElementById('curvature');
    k.value = '0.5';
    k.dispatchEvent(new Event('input'));
  })()`);
  for (let t = 0; ; ++t) {
    const K = (await page.evaluate('window.noneuclid.state()')).K;
    if (Math.abs(K - 0.5) < 0.01) break;
    expect(t < 600, `the K slider did not bring K to 0.5 within 30 s (K = ${K})`);
    await sleep(50);
  }
  await waitFrames(page, 5);
  const K = (await page.evaluate('window.noneuclid.state()')).K;
  expect(Math.abs(K - 0.5) < 0.01, `the K slider let K go on to ${K}`);
  await page.evaluate(`(() => {
    const p = document.getElementById('projection');
    p.value = 'stereographic';
    p.dispatchEvent(new Event('change'));
  })()`);
  await waitFrames(page, 2);
  const centre = (control) => page.evaluate(`(() => {
    const b = document.querySelector('#touch button[data-control=${control}]');
    if (!b) return null;
    const r = b.getBoundingClientRect();
    return {x: r.x + r.width / 2, y: r.y + r.height / 2};
  })()`);
  for (const [control, frames] of [['right', 20], ['preset', 1]]) {
    const at = await centre(control);
    expect(at, `the page has no touch button for ${control}`);
    await page.touch('touchStart', at.x, at.y);
    await waitFrames(page, frames);
    await page.touch('touchEnd', at.x, at.y);
    await waitFrames(page, 2);
  }
  await waitFrames(page, 10);
  await page.evaluate('window.noneuclid.stop()');
  const shot = path.join(work, 'live-page.png'), recording = path.join(work, 'live.rec');
  await canvasPng(page, shot);
  const text = await page.evaluate('window.noneuclid.recording()');
  fs.writeFileSync(recording, text);
  for (const want of ['press thrust', 'release thrust', 'press left', 'release left', 'press spherical', 'tap hud',
                      'press curvature_down', 'release curvature_down', 'tap projection', 'press right',
                      'release right', 'press preset', 'legend keys', 'size 400x300', 'frames '])
    expect(text.includes(want), `the recording has no '${want}':\n${text}`);
  const replay = path.join(work, 'live-render.png');
  render(['--actions', recording, '--out', replay]);
  const diff = pngDiff(shot, replay);
  expect(diff.status === 0, `the page differs from the replay of its recording: ${diff.out}`);
  // The comparison can fail: without the thrust the ship is elsewhere.
  const without = path.join(work, 'live-without-thrust.rec');
  fs.writeFileSync(without, text.replace(/^\S+ (press|release) thrust\n/gm, ''));
  render(['--actions', without, '--out', path.join(work, 'live-without.png')]);
  expect(pngDiff(shot, path.join(work, 'live-without.png')).status === 1,
         'the replay without the thrust should differ from the page, and does not');
  expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
  await page.close();
});

// ---- 2b. the game: fire from the keyboard and from the touch button ------------------------------
await check('the game: Space starts it, the fire button fires; the replay of the recording equals the canvas', async () => {
  const {page, started} = await openPage('scene=asteroids&size=400x300');
  expect(started === true, `the page did not start: ${(await page.evaluate('window.noneuclid.state()')).message}`);
  await waitFrames(page, 5);
  await page.key('keyDown', ' ', 'Space', 32);  // "press fire": the game begins
  await waitFrames(page, 2);
  await page.key('keyUp', ' ', 'Space', 32);
  await waitFrames(page, 50);                    // the ship is there
  const at = await page.evaluate(`(() => {
    const b = document.querySelector('#touch button[data-control=fire]');
    if (!b) return null;
    const r = b.getBoundingClientRect();
    return {x: r.x + r.width / 2, y: r.y + r.height / 2};
  })()`);
  expect(at, 'the page has no fire button');
  await page.touch('touchStart', at.x, at.y);    // held: a shot every bullet_cooldown
  await waitFrames(page, 30);
  await page.touch('touchEnd', at.x, at.y);
  await waitFrames(page, 15);
  await page.evaluate('window.noneuclid.stop()');
  const shot = path.join(work, 'game-page.png'), recording = path.join(work, 'game.rec');
  await canvasPng(page, shot);
  const text = await page.evaluate('window.noneuclid.recording()');
  fs.writeFileSync(recording, text);
  const fires = text.match(/^\S+ (press|release) fire\n/gm) || [];
  expect(fires.length === 4, `the recording does not hold the key's and the button's fire:\n${text}`);
  render(['--actions', recording, '--out', path.join(work, 'game-render.png')]);
  const diff = pngDiff(shot, path.join(work, 'game-render.png'));
  expect(diff.status === 0, `the page differs from the replay of its recording: ${diff.out}`);
  // Without the button's shots (the game still begun by the key), the picture differs.
  const without = path.join(work, 'game-without-shots.rec');
  fs.writeFileSync(without, text.replace(fires[2], '').replace(fires[3], ''));
  render(['--actions', without, '--out', path.join(work, 'game-without.png')]);
  expect(pngDiff(shot, path.join(work, 'game-without.png')).status === 1,
         'the replay without the fire button\'s shots should differ from the page, and does not');
  expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
  await page.close();
});

// ---- 3. a pasted scene file ----------------------------------------------------------------------
const lesson = path.join(here, '..', 'files', 'data', 'lesson.toml');
await check('a pasted scene file runs, and its recording replays on the file', async () => {
  // Without the HUD, which names the scene by its path (/pasted.toml in the page).
  const {page, started} = await openPage('scene=kiosk&size=320x240&hud=off');
  expect(started === true, 'the page did not start');
  await page.evaluate(`(() => {
    document.getElementById('scene-text').value = ${JSON.stringify(fs.readFileSync(lesson, 'utf8'))};
    document.getElementById('run-text').click();
  })()`);
  await waitFrames(page, 40);
  await page.evaluate('window.noneuclid.stop()');
  const shot = path.join(work, 'pasted-page.png'), recording = path.join(work, 'pasted.rec');
  await canvasPng(page, shot);
  const text = await page.evaluate('window.noneuclid.recording()');
  expect(text.includes('scene /pasted.toml\n'), `the recording does not name the pasted scene:\n${text}`);
  fs.writeFileSync(recording, text.replace('scene /pasted.toml\n', `scene ${lesson}\n`));
  const replay = path.join(work, 'pasted-render.png');
  render(['--actions', recording, '--out', replay]);
  const diff = pngDiff(shot, replay);
  expect(diff.status === 0, `the page differs from render of the scene file: ${diff.out}`);
  expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
  await page.close();
});

// ---- 3b. filled and textured bodies (the built-in images) -----------------------------------------
await check('the textured scene at K = -1: the canvas equals render of its recording', async () => {
  const {page, started} = await openPage('scene=textured&curvature=-1&size=400x300&hud=off');
  expect(started === true, 'the page did not start');
  await waitFrames(page, 30);
  await page.evaluate('window.noneuclid.stop()');
  const shot = path.join(work, 'textured-page.png'), recording = path.join(work, 'textured.rec');
  await canvasPng(page, shot);
  fs.writeFileSync(recording, await page.evaluate('window.noneuclid.recording()'));
  const replay = path.join(work, 'textured-render.png');
  render(['--actions', recording, '--out', replay]);
  const diff = pngDiff(shot, replay);
  expect(diff.status === 0, `the page differs from render: ${diff.out} (${shot}, ${replay})`);
  expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
  await page.close();
});

// ---- 3c. the instruments: taps on the picture mark the live triangle --------------------------------
await check('the measure scene: three taps on the picture mark a triangle; the recording replays it', async () => {
  const {page, started} = await openPage('scene=measure&curvature=-0.5&size=560x360&hud=off');
  expect(started === true, 'the page did not start');
  await waitFrames(page, 5);
  const at = (fx, fy) => page.evaluate(`(() => {
    const r = document.getElementById('screen').getBoundingClientRect();
    return {x: r.x + ${fx} * r.width, y: r.y + ${fy} * r.height};
  })()`);
  for (const [fx, fy] of [[0.4, 0.3], [0.62, 0.45], [0.45, 0.7]]) {
    const p = await at(fx, fy);
    await page.touch('touchStart', p.x, p.y);
    await page.touch('touchEnd', p.x, p.y);
    await waitFrames(page, 3);
  }
  await waitFrames(page, 5);
  await page.evaluate('window.noneuclid.stop()');
  const shot = path.join(work, 'measure-page.png'), recording = path.join(work, 'measure.rec');
  await canvasPng(page, shot);
  const text = await page.evaluate('window.noneuclid.recording()');
  fs.writeFileSync(recording, text);
  expect((text.match(/ mark /g) || []).length === 3, `the recording has not three marks:\n${text}`);
  const replay = path.join(work, 'measure-render.png');
  render(['--actions', recording, '--out', replay]);
  const diff = pngDiff(shot, replay);
  expect(diff.status === 0, `the page differs from the replay of its recording: ${diff.out}`);
  const without = path.join(work, 'measure-without.rec');
  fs.writeFileSync(without, text.replace(/^\S+ mark .*\n/gm, ''));
  render(['--actions', without, '--out', path.join(work, 'measure-without.png')]);
  expect(pngDiff(shot, path.join(work, 'measure-without.png')).status === 1,
         'the replay without the marks should differ from the page, and does not');
  expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
  await page.close();
});

// ---- 4. bad input: one sentence on the page ---------------------------------------------------
await check('a bad option, a missing scene file, a bad pasted scene and a texture file: one sentence each on the page', async () => {
  for (const [query, want] of [['curvature=7', '--curvature'], ['engine=fast', '--engine must be'],
                               ['scene=lesson.toml', 'lesson.toml']]) {
    const {page, started} = await openPage(query);
    expect(started === false, `?${query}: the page started`);
    const message = (await page.evaluate('window.noneuclid.state()')).message;
    expect(message.includes(want), `?${query}: the message '${message}' does not mention '${want}'`);
    await page.close();
  }
  const {page} = await openPage('scene=kiosk');
  await page.evaluate(`(() => {
    document.getElementById('scene-text').value = 'curvature = -1.0\\n[[body]]\\nname = 5\\n';
    document.getElementById('run-text').click();
  })()`);
  const message = (await page.evaluate('window.noneuclid.state()')).message;
  expect(/pasted\.toml:3:\d+: /.test(message), `a bad pasted scene: the message '${message}' names no line and column`);
  // A texture file: the page reads none, and says so and what to do (not how to rebuild it).
  await page.evaluate(`(() => {
    document.getElementById('scene-text').value = '[[body]]\\nclosed = true\\n' +
      'vertices = [[0.3, 0.0], [0.3, 120.0], [0.3, 240.0]]\\ntexture = "rock.png"\\n';
    document.getElementById('run-text').click();
  })()`);
  const textured = (await page.evaluate('window.noneuclid.state()')).message;
  expect(/pasted\.toml:4:\d+: .*reads no image files/.test(textured) && !textured.includes('rebuild'),
         `a pasted scene with a texture file: the message '${textured}' does not say the page reads no image files`);
  await page.close();
});

// ---- 5. the page itself: screens, the slider, bad addresses, the fire button ----------------------
await pageChecks({browser, base, work, check, expect, sleep, waitFrames, render, pngDiff, canvasPng});

clearTimeout(watchdog);
await browser.close();
server.kill();
console.log(`web: ${passes} checks passed, ${failures} failed (pictures and recordings in ${work})`);
process.exit(failures ? 1 : 0);
