// The page's own behaviour in the browser (docs/web.md, "The test"): it fits phones held either
// way and a desktop without scrolling, its HUD text is readable on a phone, a key wins over the
// K slider, a bad address is said once, an unknown scene is named, and the fire button and help
// match the scene. Run by web_test.mjs, whose browser, server and helpers it is given.
import fs from 'node:fs';
import path from 'node:path';

const VIEWPORTS = [{width: 844, height: 390, dpr: 3}, {width: 390, height: 844, dpr: 3}, {width: 1280, height: 800, dpr: 1}];

export async function pageChecks({browser, base, work, check, expect, sleep, waitFrames, render, pngDiff, canvasPng}) {
  const open = async (query, viewport = null) => {
    const page = await browser.newPage();
    await page.open(`${base}?${query}`, viewport);
    return {page, started: await page.evaluate('window.noneuclid.ready')};
  };
  const state = (page) => page.evaluate('window.noneuclid.state()');

  for (const v of VIEWPORTS) {
    await check(`${v.width}x${v.height}: the canvas and every touch button lie in the viewport, the page does not scroll`, async () => {
      const {page, started} = await open('scene=asteroids', v);
      expect(started === true, 'the page did not start');
      await waitFrames(page, 3);
      await sleep(200);  // the ResizeObserver's fit
      const m = await page.evaluate(`(() => {
        const box = (e) => { const r = e.getBoundingClientRect(); return {x: r.x, y: r.y, right: r.right, bottom: r.bottom, w: r.width, h: r.height}; };
        const c = document.getElementById('screen');
        return {vw: innerWidth, vh: innerHeight, canvas: box(c), pixels: [c.width, c.height],
                sw: document.documentElement.scrollWidth, sh: document.documentElement.scrollHeight,
                buttons: [...document.querySelectorAll('#touch button')].map((b) => ({name: b.dataset.control, ...box(b)}))};
      })()`);
      const shot = await page.send('Page.captureScreenshot', {format: 'png'});
      fs.writeFileSync(path.join(work, `fit-${v.width}x${v.height}.png`), Buffer.from(shot.data, 'base64'));
      const inside = (r) => r.x >= 0 && r.y >= 0 && r.right <= m.vw + 0.5 && r.bottom <= m.vh + 0.5 && r.w > 0 && r.h > 0;
      expect(m.vw === v.width && m.vh === v.height, `the viewport is ${m.vw}x${m.vh}, not ${v.width}x${v.height}`);
      expect(inside(m.canvas), `the canvas ${JSON.stringify(m.canvas)} is not inside the viewport`);
      expect(m.buttons.length === 7, `${m.buttons.length} touch buttons, not the game's 7`);
      for (const b of m.buttons) expect(inside(b), `the touch button ${b.name} ${JSON.stringify(b)} is not inside the viewport`);
      expect(m.sw <= m.vw && m.sh <= m.vh, `the page is ${m.sw}x${m.sh} CSS px: it scrolls in a ${m.vw}x${m.vh} viewport`);
      // The world's aspect kept within a CSS pixel, and the space used: the canvas spans at least
      // 60% of the viewport's width or 80% of its height (what the buttons and controls leave).
      const aspect = m.pixels[0] / m.pixels[1];
      expect(Math.abs(m.canvas.w / aspect - m.canvas.h) <= 1, `the canvas ${m.canvas.w}x${m.canvas.h} CSS px lost the world's aspect ${aspect}`);
      expect(m.canvas.w >= 0.6 * m.vw || m.canvas.h >= 0.8 * m.vh, `the canvas ${m.canvas.w}x${m.canvas.h} leaves the viewport's space unused`);
      expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
      await page.close();
    });
  }

  await check('390x844: the HUD text is at least 9 CSS px tall', async () => {
    const {page, started} = await open('scene=kiosk', VIEWPORTS[1]);
    expect(started === true, 'the page did not start');
    await waitFrames(page, 3);
    await sleep(200);
    // The page's HUD font is the built-in one (it reads no console fonts), 8 canvas pixels a
    // line (src/render/font.cpp); a canvas pixel is the canvas's CSS height over its pixels.
    const m = await page.evaluate(`(() => {
      const c = document.getElementById('screen');
      return {css: c.getBoundingClientRect().height, pixels: c.height, scale: window.noneuclid.state().hudScale};
    })()`);
    const text = 8 * m.scale * m.css / m.pixels;  // (the page sets --hud-scale from the pixel density)
    expect(text >= 9, `the HUD text is ${text.toFixed(2)} CSS px tall (canvas ${m.pixels} px shown ${m.css} CSS px tall)`);
    await page.close();
  });

  await check('a click on the K slider, then 3: K stays at +1 (the key wins)', async () => {
    const {page, started} = await open('scene=kiosk&size=400x300');
    expect(started === true, 'the page did not start');
    await waitFrames(page, 3);
    const r = await page.evaluate(`(() => { const r = document.getElementById('curvature').getBoundingClientRect();
                                           return {x: r.x + 0.1 * r.width, y: r.y + r.height / 2}; })()`);
    await page.click(r.x, r.y);  // about K = -0.8: the slider holds curvature down
    await waitFrames(page, 3);
    const before = (await state(page)).K;
    expect(before < -0.01, `the click on the slider did not start bending K down (K = ${before})`);
    await page.key('keyDown', '3', 'Digit3', 51);
    await waitFrames(page, 2);
    await page.key('keyUp', '3', 'Digit3', 51);
    await sleep(3000);
    // One frame of the slider's pull moves K by 0.5/60 (the curvature rate): half that fails it.
    const K = (await state(page)).K;
    expect(Math.abs(K - 1) < 0.004, `K is ${K} 3 s after 3, not +1`);
    const shown = Number(await page.evaluate("document.getElementById('curvature').value"));
    expect(Math.abs(shown - 1) < 0.01, `the slider shows ${shown}, not K = +1`);
    await page.close();
  });

  await check('?curvature=7 is said once: a scene chosen from the menu then runs', async () => {
    const {page, started} = await open('curvature=7');
    expect(started === false, '?curvature=7: the page started');
    expect((await state(page)).message.includes('--curvature'), 'no sentence about --curvature');
    await page.evaluate(`(() => { const s = document.getElementById('scene'); s.value = 'asteroids';
                                  s.dispatchEvent(new Event('change')); })()`);
    await waitFrames(page, 5);
    const s = await state(page);
    expect(s.running && s.message === '', `the scene from the menu did not run: '${s.message}'`);
    await page.close();
  });

  await check('?scene=nosuch: one sentence that names the scene and the built-in ones; no "loading"', async () => {
    const {page, started} = await open('scene=nosuch');
    expect(started === false, '?scene=nosuch: the page started');
    const message = (await state(page)).message;
    const builtins = await page.evaluate("[...document.getElementById('scene').options].map((o) => o.value)");
    expect(message.includes("'nosuch'") && builtins.length > 0 && builtins.every((b) => message.includes(b)),
           `the message '${message}' does not name the scene and the built-in ones (${builtins})`);
    expect((message.match(/\.( |$)/g) || []).length === 1, `the message '${message}' is not one sentence`);
    const status = await page.evaluate("document.getElementById('status').textContent");
    expect(!status.includes('loading'), `the status still says '${status}'`);
    await page.close();
  });

  await check('the address follows the scene, K and projection; a copied link opens on them', async () => {
    const {page, started} = await open('scene=kiosk&size=400x300');
    expect(started === true, 'the page did not start');
    await waitFrames(page, 3);
    for (const [key, code, keyCode] of [['1', 'Digit1', 49], ['p', 'KeyP', 80]]) {
      await page.key('keyDown', key, code, keyCode);
      await waitFrames(page, 2);
      await page.key('keyUp', key, code, keyCode);
      await waitFrames(page, 2);
    }
    await sleep(1200);  // the address is rewritten at most twice a second
    const seen = await page.evaluate(`({K: window.noneuclid.state().K, projection: document.getElementById('projection').value,
                                        link: location.href})`);
    expect(Math.abs(seen.K + 1) < 1e-6 && seen.projection !== 'equidistant', `1 and P gave K = ${seen.K}, ${seen.projection}`);
    await page.close();
    const copy = await browser.newPage();
    await copy.open(seen.link);
    expect(await copy.evaluate('window.noneuclid.ready') === true, `the link ${seen.link} did not start`);
    await waitFrames(copy, 2);
    const got = await copy.evaluate(`({K: window.noneuclid.state().K, projection: document.getElementById('projection').value,
                                       scene: document.getElementById('scene').value})`);
    // K as the address writes it: to 1e-3.
    expect(Math.abs(got.K - seen.K) <= 1e-3 && got.projection === seen.projection && got.scene === 'kiosk',
           `the link ${seen.link} opened on ${JSON.stringify(got)}, not ${JSON.stringify(seen)}`);
    await copy.close();
  });

  await check('the fire button and the help\'s "Space fires" show only in a scene with the game, the bumps\' keys only in an uneven world', async () => {
    for (const [query, game, bumps] of [['', false, false], ['scene=kiosk', false, false], ['scene=asteroids', true, false], ['scene=lens', false, true]]) {
      const {page, started} = await open(query);
      expect(started === true, `?${query}: the page did not start`);
      const m = await page.evaluate(`(() => {
        const b = document.querySelector('#touch button[data-control=fire]');
        return {button: !!b && b.getClientRects().length > 0, help: document.querySelector('.help').innerText};
      })()`);
      expect(m.button === game, `?${query}: the fire button is ${m.button ? 'shown' : 'hidden'}`);
      expect(m.help.includes('Space fires') === game, `?${query}: the help says '${m.help}'`);
      expect(m.help.includes('< and > turn the bumps') === bumps, `?${query}: the help says '${m.help}'`);
      await page.close();
    }
  });

  // The page's words and the HUD's in German and French (lang/texts.hpp): the labels come from
  // the catalogue, the canvas equals render of the run's recording (which keeps the language),
  // and the same recording replayed in English differs (so the HUD's words did change).
  for (const [code, stop, help, fire] of [['de', 'anhalten', 'Leertaste', 'Feuer'], ['fr', 'arrêter', 'Espace tire', 'feu']]) {
    await check(`?lang=${code}: the page's words and the HUD in ${code}; the canvas equals render of its recording`, async () => {
      const {page, started} = await open(`lang=${code}&scene=asteroids&size=480x288`);
      expect(started === true, 'the page did not start');
      await waitFrames(page, 10);
      await page.evaluate('window.noneuclid.stop()');
      const m = await page.evaluate(`(() => ({
        lang: document.documentElement.lang, stop: document.getElementById('stop').textContent,
        help: document.getElementById('help').textContent, choice: document.getElementById('language').value,
        fire: document.querySelector('#touch button[data-control=fire]').textContent}))()`);
      expect(m.lang === code && m.choice === code, `the page's language is ${m.lang} (chosen: ${m.choice}), not ${code}`);
      expect(m.stop === stop, `the stop button says '${m.stop}', not '${stop}'`);
      expect(m.help.includes(help), `the help says '${m.help}', without '${help}'`);
      expect(m.fire === fire, `the fire button says '${m.fire}', not '${fire}'`);
      const shot = path.join(work, `lang-${code}-page.png`), rec = path.join(work, `lang-${code}.rec`);
      await canvasPng(page, shot);
      const text = await page.evaluate('window.noneuclid.recording()');
      fs.writeFileSync(rec, text);
      expect(text.includes(`lang ${code}`), `the recording does not keep the language:\n${text.slice(0, 600)}`);
      render(['--actions', rec, '--out', path.join(work, `lang-${code}-render.png`)]);
      const same = pngDiff(shot, path.join(work, `lang-${code}-render.png`));
      expect(same.status === 0, `the page differs from render of its recording: ${same.out}`);
      render(['--actions', rec, '--lang', 'en', '--out', path.join(work, `lang-${code}-en.png`)]);
      expect(pngDiff(shot, path.join(work, `lang-${code}-en.png`)).status === 1,
             'the same recording in English draws the same HUD: the language did not reach it');
      expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
      await page.close();
    });
  }

  // Opens the page at `query`, holds each [key, code, keyCode, frames] for its frames, stops, and
  // checks that the recording holds every pattern of `recorded` and that the canvas equals render
  // of that recording (pictures and recording as NAME-page.png, NAME.rec, NAME-render.png).
  async function keysMatchRender(query, keys, name, recorded) {
    const {page, started} = await open(query);
    expect(started === true, 'the page did not start');
    await waitFrames(page, 3);
    for (const [key, code, keyCode, frames] of keys) {
      await page.key('keyDown', key, code, keyCode);
      await waitFrames(page, frames);
      await page.key('keyUp', key, code, keyCode);
      await waitFrames(page, 2);
    }
    await page.evaluate('window.noneuclid.stop()');
    const shot = path.join(work, `${name}-page.png`), rec = path.join(work, `${name}.rec`);
    await canvasPng(page, shot);
    const text = await page.evaluate('window.noneuclid.recording()');
    fs.writeFileSync(rec, text);
    expect(recorded.every((r) => r.test(text)), `the recording lacks the keys:\n${text.slice(0, 600)}`);
    render(['--actions', rec, '--out', path.join(work, `${name}-render.png`)]);
    const same = pngDiff(shot, path.join(work, `${name}-render.png`));
    expect(same.status === 0, `the page differs from render of its recording: ${same.out}`);
    expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
    await page.close();
  }

  // An uneven world (src/uneven): the lens, its mass turned up with '.', the view switched with P;
  // the canvas equals render of the run's recording, which holds the strength key's presses.
  await check('?scene=lens: the strength key and the inhabitant\'s view; the canvas equals render of its recording', () =>
    keysMatchRender('scene=lens&size=400x300', [['.', 'Period', 190, 30], ['p', 'KeyP', 80, 2]], 'lens',
                    [/press strength_up\n/, /tap projection\n/]));

  // The three-dimensional world (src/space): thrust, a pitch (I) and a roll (E), then P for the map;
  // the canvas equals render of the run's recording.
  await check('?scene=space: thrust, pitch, roll and the map; the canvas equals render of its recording', () =>
    keysMatchRender('scene=space&size=400x300',
                    [['w', 'KeyW', 87, 20], ['i', 'KeyI', 73, 15], ['e', 'KeyE', 69, 15], ['p', 'KeyP', 80, 2]], 'space',
                    [/press pitch_up\n/, /press roll_right\n/, /tap projection\n/]));

  await check('?lang=xx is refused in one sentence; the page stays in English', async () => {
    const {page, started} = await open('lang=xx&scene=kiosk');
    expect(started === false, 'the page started with ?lang=xx');
    const s = await state(page);
    expect(s.message === "--lang takes en, de or fr, not 'xx'.", `the page says '${s.message}'`);
    const stop = await page.evaluate("document.getElementById('stop').textContent");
    expect(stop === 'stop', `the stop button says '${stop}'`);
    await page.close();
  });

  await check('?palette=high-contrast&large-hud: a black disc and the HUD twice as tall; a copied link keeps both', async () => {
    // The share of black pixels (the high-contrast disc's background) and the height of the HUD's first
    // line of text (the rows with a lit pixel in the left sixth, left of the disc, down to the
    // first empty one).
    const measure = (page) => page.evaluate(`(() => {
      const c = document.querySelector('canvas'), x = c.getContext('2d');
      const d = x.getImageData(0, 0, c.width, c.height).data, count = new Map();
      for (let i = 0; i < d.length; i += 4) {
        const k = d[i] << 16 | d[i + 1] << 8 | d[i + 2];
        count.set(k, (count.get(k) || 0) + 1);
      }
      const black = (count.get(0) || 0) / (c.width * c.height);  // the share of pure black pixels
      const bg = d[0] << 16 | d[1] << 8 | d[2];  // (the top-left corner: outside the disc)
      let top = -1, height = 0;
      for (let y = 0; y < c.height / 2; ++y) {
        let lit = false;
        for (let xx = 0; xx < c.width / 6 && !lit; ++xx) lit = (d[(y * c.width + xx) * 4] << 16 | d[(y * c.width + xx) * 4 + 1] << 8 | d[(y * c.width + xx) * 4 + 2]) !== bg;
        if (lit && top < 0) top = y;
        if (!lit && top >= 0) { height = y - top; break; }
      }
      return {black, height, link: location.href};
    })()`);
    const plain = await open('scene=kiosk&hud&size=800x480');
    expect(plain.started === true, 'the plain page did not start');
    await waitFrames(plain.page, 3);
    const a = await measure(plain.page);
    await plain.page.close();
    const big = await open('scene=kiosk&hud&size=800x480&palette=high-contrast&large-hud');
    expect(big.started === true, 'the page with the palette and the large HUD did not start');
    await waitFrames(big.page, 3);
    await sleep(1200);  // (the address is rewritten at most twice a second)
    const b = await measure(big.page);
    await big.page.close();
    // The disc is black in high contrast only: at 800x480 with the large HUD it shrinks to clear the
    // HUD's text (render/layout.hpp), to about 380 px across, 24% of the pixels less its lines.
    expect(a.black < 0.01 && b.black > 0.2, `black pixels: ${a.black.toFixed(3)} plain, ${b.black.toFixed(3)} high-contrast`);
    expect(a.height > 4 && Math.abs(b.height / a.height - 2) < 0.2, `the HUD's first line: ${a.height} px plain, ${b.height} px large`);
    expect(b.link.includes('palette=high-contrast') && b.link.includes('large-hud'), `the link ${b.link} lost a setting`);
  });

  await check('844x390 at 3x: the canvas has the screen\'s own pixels; turned to 390x844 the run follows without restarting', async () => {
    const {page, started} = await open('scene=kiosk', {width: 844, height: 390, dpr: 3});
    expect(started === true, 'the page did not start');
    await waitFrames(page, 3);
    await page.key('keyDown', '1', 'Digit1', 49);
    await waitFrames(page, 2);
    await page.key('keyUp', '1', 'Digit1', 49);
    const look = () => page.evaluate(`(() => {
      const c = document.getElementById('screen'), s = window.noneuclid.state();
      return {css: c.getBoundingClientRect().width, pixels: s.pixels, frame: s.frame, K: s.K};
    })()`);
    const a = await look();
    // Sharp: a canvas pixel per device pixel (the width rounded down to 10 pixels, at most 1600).
    const ratio = (m) => m.pixels[0] / (Math.min(1600, m.css * 3));
    expect(ratio(a) > 0.97 && ratio(a) <= 1.01, `the canvas is ${a.pixels} pixels shown ${a.css.toFixed(1)} CSS px wide at 3x`);
    await page.send('Emulation.setDeviceMetricsOverride', {width: 390, height: 844, deviceScaleFactor: 3, mobile: true});
    await sleep(600);
    await waitFrames(page, 3);
    const b = await look();
    expect(b.pixels[0] !== a.pixels[0] && ratio(b) > 0.97 && ratio(b) <= 1.01,
           `turned: the canvas is ${b.pixels} pixels shown ${b.css.toFixed(1)} CSS px wide (was ${a.pixels})`);
    expect(b.frame > a.frame && Math.abs(b.K + 1) < 1e-6, `the run restarted: frame ${a.frame} -> ${b.frame}, K ${b.K}`);
    await page.close();
  });

  await check('the full-screen button puts the page in full screen and back', async () => {
    const {page, started} = await open('scene=kiosk');
    expect(started === true, 'the page did not start');
    const click = async () => {
      const r = await page.evaluate(`(() => { const b = document.getElementById('fullscreen').getBoundingClientRect();
                                             return {x: b.x + b.width / 2, y: b.y + b.height / 2}; })()`);
      for (const type of ['mousePressed', 'mouseReleased'])
        await page.send('Input.dispatchMouseEvent', {type, x: r.x, y: r.y, button: 'left', clickCount: 1});
      await sleep(300);
      return page.evaluate(`({full: !!document.fullscreenElement, text: document.getElementById('fullscreen').textContent,
                              shown: !document.getElementById('fullscreen').hidden})`);
    };
    const on = await click();
    expect(on.shown && on.full && on.text === 'leave full screen', `after a click: ${JSON.stringify(on)}`);
    const off = await click();
    expect(!off.full && off.text === 'full screen', `after a second click: ${JSON.stringify(off)}`);
    await page.close();
  });

  // A teacher's link to a lesson file beside the page, played to its end on a phone held either
  // way and on a desktop: a timed step, a step that ends when K passes 0.5 (the + key held), and
  // the game's step that ends on fire (the touch button).
  fs.writeFileSync(path.join(work, 'site', 'short.toml'), [
    'title = "A short lesson"', '', '[[step]]', 'caption = "Look."', 'scene = "kiosk"', 'curvature = 0', 'seconds = 0.5', '',
    '[[step]]', 'caption = "Hold K+."', 'curvature = 0', 'done = "curvature above 0.5"', 'seconds = 60', '',
    '[[step]]', 'caption = "Fire."', 'scene = "asteroids"', 'done = "fire"', ''].join('\n'));
  for (const v of VIEWPORTS) {
    await check(`${v.width}x${v.height}: a teacher's lesson file plays to its end (a timed step, K+ held, the fire button)`, async () => {
      const {page, started} = await open('lesson=short.toml', v);
      expect(started === true, 'the lesson did not start');
      const until = async (what, test) => {
        for (let t = 0; t < 300; ++t) {
          const s = await state(page);
          if (test(s)) return s;
          await sleep(50);
        }
        throw new Error(`${what} did not come within 15 s: ${JSON.stringify(await state(page))}`);
      };
      await until('step 2', (s) => s.lessonStep === 2);
      await page.key('keyDown', '+', 'Equal', 187);
      await until('step 3', (s) => s.lessonStep === 3);
      await page.key('keyUp', '+', 'Equal', 187);
      const at = await page.evaluate(`(() => {
        const b = document.querySelector('#touch button[data-control=fire]');
        if (!b || !b.getClientRects().length) return null;
        const r = b.getBoundingClientRect();
        return {x: r.x + r.width / 2, y: r.y + r.height / 2, inside: r.bottom <= innerHeight && r.right <= innerWidth};
      })()`);
      expect(at && at.inside, `the fire button is not on screen in the game's step: ${JSON.stringify(at)}`);
      await page.touch('touchStart', at.x, at.y);
      await sleep(100);
      await page.touch('touchEnd', at.x, at.y);
      await until('the end of the lesson', (s) => !s.running);
      expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
      await page.close();
    });
  }

  await check('?lesson=curvature plays the lesson\'s first step with its caption; an unknown lesson is one sentence', async () => {
    const {page, started} = await open('lesson=curvature&size=400x240');
    expect(started === true, 'the lesson did not start');
    await waitFrames(page, 5);
    const s = await state(page);
    expect(s.lessonStep === 1 && s.K === 0 && s.running, `the lesson's state: ${JSON.stringify(s)}`);
    // The caption: text in the rows above the legend, which a plain run of the scene leaves empty.
    const rows = (p) => p.evaluate(`(() => {
      const c = document.getElementById('screen'), d = c.getContext('2d').getImageData(0, 0, 60, c.height).data;
      const bg = d[0] << 16 | d[1] << 8 | d[2];
      let lit = 0;
      for (let y = c.height - 60; y < c.height - 20; ++y)
        for (let x = 0; x < 60; ++x) lit += (d[(y * 60 + x) * 4] << 16 | d[(y * 60 + x) * 4 + 1] << 8 | d[(y * 60 + x) * 4 + 2]) !== bg;
      return lit;
    })()`);
    const withCaption = await rows(page);
    await page.close();
    const plain = await open('scene=kiosk&size=400x240');
    await waitFrames(plain.page, 5);
    const without = await rows(plain.page);
    await plain.page.close();
    expect(withCaption > without + 20, `lit pixels above the legend: ${withCaption} in the lesson, ${without} without`);
    const bad = await open('lesson=nosuch');
    expect(bad.started === false, '?lesson=nosuch started');
    const message = (await state(bad.page)).message;
    expect(message.includes("'nosuch'") && message.includes('curvature'), `the message: '${message}'`);
    await bad.page.close();
  });

  await check('sound: off by default; the sound button and ?sound=on turn it on; the engine then gets the game\'s cues, and N mutes them', async () => {
    const text = (page) => page.evaluate(`(() => { const b = document.getElementById('sound'); return b.textContent + '|' + b.getAttribute('aria-pressed'); })()`);
    const off = await open('scene=asteroids&size=400x240');
    expect(off.started === true, 'the page did not start');
    await waitFrames(off.page, 3);
    let s = (await state(off.page)).sound;
    expect(s.on === false && s.cues === 0 && s.played === 0, `by default: ${JSON.stringify(s)}`);
    expect(await text(off.page) === 'sound: off|false', `the button says ${await text(off.page)}`);
    await off.page.evaluate(`document.getElementById('sound').click()`);
    await waitFrames(off.page, 2);
    s = (await state(off.page)).sound;
    expect(s.on === true && s.context !== 'none', `after a click: ${JSON.stringify(s)}`);
    expect(await text(off.page) === 'sound: on|true', `the button says ${await text(off.page)}`);
    await off.page.evaluate(`document.getElementById('sound').click()`);
    expect((await state(off.page)).sound.on === false && await text(off.page) === 'sound: off|false', 'a second click did not turn it off');
    await off.page.close();

    const {page, started} = await open('scene=asteroids&size=400x240&sound=on');
    expect(started === true, '?sound=on did not start');
    expect((await state(page)).message === '', `?sound=on said: ${(await state(page)).message}`);
    expect((await state(page)).sound.on === true && await text(page) === 'sound: on|true', '?sound=on is not on');
    const hold = async (key, code, keyCode, frames) => {
      await page.key('keyDown', key, code, keyCode);
      await waitFrames(page, frames);
      await page.key('keyUp', key, code, keyCode);
    };
    await hold(' ', 'Space', 32, 2);  // a new game
    await waitFrames(page, 5);
    await hold(' ', 'Space', 32, 70);  // fire held: a shot every 0.2 s
    s = (await state(page)).sound;
    expect(s.cues >= 4 && s.muted === false, `after 70 frames of fire: ${JSON.stringify(s)}`);
    await hold('n', 'KeyN', 78, 2);
    const before = (await state(page)).sound;
    expect(before.muted === true, `N did not mute: ${JSON.stringify(before)}`);
    await hold(' ', 'Space', 32, 40);
    s = (await state(page)).sound;
    expect(s.cues === before.cues, `muted, yet ${s.cues - before.cues} more cues`);
    expect(page.problems.length === 0, `the console has errors:\n${page.problems.join('\n')}`);
    await page.close();
  });
}
