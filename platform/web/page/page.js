// The page around the engine (platform/web/page_api.cpp): it hands the URL's options to the
// engine as command-line words, drives the frame loop from requestAnimationFrame, puts each
// frame on the <canvas>, and turns keys, touch buttons and the page's controls into the
// engine's controls, every one of which the engine records. window.noneuclid is for tests and
// for pages that embed this one.
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);
  const canvas = $('screen');
  const context = canvas.getContext('2d');
  const params = new URLSearchParams(location.search);
  const FLAGS = new Set(['aa', 'hud', 'stats', 'large-hud', 'one-button', 'sound']);  // `aa`, `aa=on` or `aa=off`
  // The touch buttons: control, and the label's text (lang/texts.hpp) or the label itself.
  const TOUCH = [['thrust', 'page_thrust'], ['left', 'page_left'], ['right', 'page_right'], ['curvature_down', 'K −'],
                 ['curvature_up', 'K +'], ['preset', 'page_preset'], ['fire', 'page_fire']];
  const language = window.noneuclidLanguage;  // the page's words (page_lang.js)
  const {t, fill} = language;

  let mod = null;           // the engine (createNoneuclid)
  let generation = 0;       // the run the animation frames belong to
  let running = false;
  let image = null;         // an ImageData over the engine's pixels, while they stay put
  let startWords = [];      // the first run's words (the URL's); "start again" uses the last run's
  let lastWords = [];
  let builtins = [];
  let presentMs = 0;        // time spent in putImageData, for bench()
  const tickMs = [];        // the last frames' times, for the status line
  const keysHeld = new Map();  // KeyboardEvent.key -> control, while down
  const waiting = [];       // stop() and ended() callers, told when the run ends
  let control = {};         // control name -> number
  let kTarget = null, kHeld = -1;  // the K slider: the K it steers to, the control held for it
  let linkDue = 0;          // when the address may next be rewritten (linkState)
  let sliderDown = false;   // a pointer holds the K slider: it shows its own value, not K
  const sound = new NoneuclidSound($('sound'), params.has('sound') && params.get('sound') !== 'off');  // (sound.js)
  const K_KEYS = ['hyperbolic', 'flat', 'spherical', 'preset', 'curvature_up', 'curvature_down', 'reset'];

  // ---- the engine's display: frames in, pixels out ------------------------------------------
  function present(pointer, width, height) {
    const t0 = performance.now();
    if (canvas.width !== width || canvas.height !== height) {  // (the run was resized)
      canvas.width = width, canvas.height = height;
      fit();
    }
    const buffer = mod.HEAPU8.buffer;  // a new one when the memory grows
    if (!image || image.buffer !== buffer || image.pointer !== pointer || image.data.width !== width ||
        image.data.height !== height) {
      const bytes = new Uint8ClampedArray(buffer, pointer, width * height * 4);
      image = {buffer, pointer, data: new ImageData(bytes, width, height)};
    }
    context.putImageData(image.data, 0, 0);
    presentMs += performance.now() - t0;
  }
  function readBack(pointer, width, height) {
    const data = context.getImageData(0, 0, width, height).data;
    mod.HEAPU8.set(data, pointer);
    return true;
  }

  // ---- runs ---------------------------------------------------------------------------------
  function say(text) {
    const box = $('message');
    box.textContent = text;
    box.hidden = !text;
    if (text) console.warn('noneuclid: ' + text);
  }
  const call = (name, type, args) => mod.ccall(name, type, args.map((a) => typeof a === 'string' ? 'string' : 'number'), args);

  // A file the URL names, fetched from the page's server into the engine's file system; `missing`
  // says what a 404 means.
  async function put(url, missing) {
    const response = await fetch(url);
    if (response.status === 404 && missing) throw new Error(missing);
    if (!response.ok) throw new Error(`cannot load ${url}: the server answered ${response.status} ${response.statusText}.`);
    const path = '/' + (url.split('/').pop().split('?')[0].replace(/[^\w.-]/g, '_') || 'file');
    mod.FS.writeFile(path, new Uint8Array(await response.arrayBuffer()));
    return path;
  }
  async function wordsOfUrl() {
    const words = [];
    for (const [key, value] of params) {
      if (key === 'scene' && !builtins.includes(value)) {
        words.push('--scene', await put(value, `no built-in scene '${value}' and no file ${value} beside the page: ` +
                                        `the built-in scenes are ${builtins.join(', ')}.`));
      } else if (key === 'lesson' && (value.endsWith('.toml') || value.includes('/'))) {
        words.push('--lesson', await put(value, `no lesson file ${value} beside the page: put it there, or name a built-in lesson.`));
      } else if (key === 'actions') {
        words.push('--actions', await put(value, `no actions file ${value} beside the page: put it there, or give its address.`));
      } else if (FLAGS.has(key)) {
        words.push(value === 'off' ? '--no-' + key : '--' + key);
      } else {
        words.push('--' + key, value);
      }
    }
    return words;
  }
  // The URL's words without what the page's controls choose, for a run they start.
  function wordsWith(scene, engine) {
    const words = [];
    for (let i = 0; i < startWords.length; ++i) {
      const w = startWords[i];
      if (['--scene', '--engine', '--actions', '--frames', '--lesson'].includes(w)) ++i;
      else words.push(w);
    }
    return words.concat('--scene', scene, '--engine', engine);
  }

  function start(words) {
    ++generation;
    running = false;
    kTarget = null, kHeld = -1;
    keysHeld.clear();
    for (const b of document.querySelectorAll('#touch button')) b.classList.remove('held');
    $('download').hidden = true;
    if (call('nw_start', 'number', [words.join('\n')]) !== 0) {
      say(mod.UTF8ToString(mod._nw_message()));
      $('status').textContent = t('page_not_running');
      return false;
    }
    say('');
    lastWords = words;
    canvas.width = mod._nw_width();
    canvas.height = mod._nw_height();
    fit();
    showGame();
    image = null;
    tickMs.length = 0;
    $('engine').value = mod.UTF8ToString(mod._nw_engine());
    const scene = words[words.lastIndexOf('--scene') + 1];
    if (words.includes('--scene') && [...$('scene').options].some((o) => o.value === scene)) $('scene').value = scene;
    running = true;
    sound.attach(mod);
    const mine = generation;
    requestAnimationFrame(() => frame(mine));
    return true;
  }

  // The fire button and the help's "Space fires" only where fire does something: the game; the
  // bumps' keys only in an uneven world (a lesson's step may change the scene, so each frame asks).
  let game = null, bumps = null;
  function showGame() {
    const now = mod._nw_has_game() === 1, uneven = mod._nw_has_bumps() === 1;
    if (now === game && uneven === bumps) return;
    game = now, bumps = uneven;
    const fire = document.querySelector('#touch button[data-control=fire]');
    if (fire) fire.hidden = !game;
    $('help').textContent = t(game ? 'page_help_game' : 'page_help') + (bumps ? ' ' + t('page_help_bumps') : '');
  }

  function frame(mine) {
    if (mine !== generation || !running) return;
    steerCurvature();
    const t0 = performance.now();
    const more = mod._nw_tick();
    sound.frame();
    showGame();
    tickMs.push(performance.now() - t0);
    if (tickMs.length > 60) tickMs.shift();
    showState();
    if (more) requestAnimationFrame(() => frame(mine));
    else ended();
  }

  function ended() {
    running = false;
    releaseAll();
    say(mod.UTF8ToString(mod._nw_message()));
    const link = $('download');
    if (link.href.startsWith('blob:')) URL.revokeObjectURL(link.href);
    link.href = URL.createObjectURL(new Blob([mod.UTF8ToString(mod._nw_recording())], {type: 'text/plain'}));
    link.hidden = false;
    $('status').textContent += ' · ' + t('page_ended');
    while (waiting.length) waiting.shift()();
  }

  function showState() {
    const K = mod._nw_curvature();
    if (kTarget === null && !sliderDown) $('curvature').value = K;
    $('k-value').textContent = K.toFixed(2);
    const projection = mod.UTF8ToString(mod._nw_projection());
    if (document.activeElement !== $('projection')) $('projection').value = projection;
    const ms = tickMs.reduce((a, b) => a + b, 0) / Math.max(tickMs.length, 1);
    linkState(K, projection);
    $('status').textContent = fill('page_status', mod._nw_frame(), K.toFixed(3), projection,
                                   mod.UTF8ToString(mod._nw_engine()), ms.toFixed(2));
  }

  // The address says what is seen (scene, K, projection, engine), so that a copied link shows it:
  // rewritten at most twice a second, and left alone while an actions file plays (the file says
  // it) or for a scene pasted into the page (no address has it).
  // A menu's choices from the program's tables (nw_choices: "value\tlabel" lines).
  function fillMenu(id) {
    const lines = mod.UTF8ToString(mod.ccall('nw_choices', 'number', ['string'], [id])).split('\n').filter(Boolean);
    $(id).replaceChildren(...lines.map((line) => {
      const [value, label] = line.split('\t');
      const o = document.createElement('option');
      o.value = value, o.textContent = label;
      return o;
    }));
  }

  function linkState(K, projection) {
    const now = performance.now();
    if (now < linkDue || lastWords.includes('--actions')) return;
    linkDue = now + 500;
    const scene = lastScene();
    if (!builtins.includes(scene) && scene !== params.get('scene')) return;
    const link = new URLSearchParams(location.search);
    for (const drop of ['actions', 'frames']) link.delete(drop);
    link.set('scene', scene);
    link.set('curvature', String(Math.round(K * 1000) / 1000));
    link.set('projection', projection);
    link.set('engine', mod.UTF8ToString(mod._nw_engine()));
    link.set('lang', language.code());
    const query = '?' + link.toString();
    if (query !== location.search) history.replaceState(null, '', query);
  }

  // ---- input ----------------------------------------------------------------------------------
  function input(c, pressed) {
    if (running && c >= 0) mod._nw_input(c, pressed ? 1 : 0);
  }
  function releaseAll() {
    for (const c of keysHeld.values()) input(c, false);
    keysHeld.clear();
    if (kHeld >= 0) input(kHeld, false);
    kTarget = null, kHeld = -1;
  }

  function onKey(e, pressed) {
    const t = e.target;
    if (t && (t.tagName === 'TEXTAREA' || t.tagName === 'SELECT' || (t.tagName === 'INPUT' && t.type !== 'range'))) return;
    if (!running || e.ctrlKey || e.metaKey || e.altKey) return;
    if (pressed) {
      const c = keysHeld.has(e.key) ? keysHeld.get(e.key) : call('nw_key', 'number', [e.key]);
      if (c < 0) return;
      e.preventDefault();
      if (keysHeld.has(e.key)) return;  // the keyboard's auto-repeat
      keysHeld.set(e.key, c);
      if (kTarget !== null && K_KEYS.some((name) => control[name] === c)) stopSteering();  // the key wins
      input(c, true);
    } else {
      // Released under another name (Shift let go before "+"): the control it was pressed as.
      let c = keysHeld.get(e.key);
      if (c === undefined) c = call('nw_key', 'number', [e.key]);
      if (c < 0) return;
      e.preventDefault();
      keysHeld.delete(e.key);
      for (const [k, held] of keysHeld) if (held === c) keysHeld.delete(k);
      input(c, false);
    }
  }

  function touchButtons() {
    const box = $('touch');
    for (const [name, label] of TOUCH) {
      const c = control[name];
      if (c < 0) continue;  // a control this build has not
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = t(label);
      b.dataset.control = name;
      let down = false;
      const press = (e) => {
        e.preventDefault();
        if (e.pointerId !== undefined) b.setPointerCapture(e.pointerId);
        if (down) return;
        down = true;
        b.classList.add('held');
        input(c, true);
      };
      const release = (e) => {
        e.preventDefault();
        if (!down) return;
        down = false;
        b.classList.remove('held');
        input(c, false);
      };
      b.addEventListener('pointerdown', press);
      for (const type of ['pointerup', 'pointercancel', 'lostpointercapture']) b.addEventListener(type, release);
      b.addEventListener('contextmenu', (e) => e.preventDefault());
      box.appendChild(b);
    }
  }

  function stopSteering() {
    if (kHeld >= 0) input(kHeld, false);
    kTarget = null, kHeld = -1;
  }

  // The canvas, as large as #stage allows with the run's aspect (CSS pixels; the canvas keeps
  // the run's own pixels).
  const fit = () => window.noneuclidFit.fit(canvas, $('stage'));       // (page_fit.js)
  const pageSize = () => window.noneuclidFit.pageSize($('stage'));
  let sizeChosen = false;  // the page chose the run's size (the address gave none): it follows #stage
  function defaultSize() {
    const s = pageSize();
    sizeChosen = true;
    return [`${s.width}x${s.height}`, '--hud-scale', String(s.hudScale)];
  }
  // #stage changed (a turned phone, full screen, a resized window): the run's canvas follows.
  let resizeDue = null;
  function followStage() {
    fit();
    if (!sizeChosen || !running) return;
    clearTimeout(resizeDue);
    resizeDue = setTimeout(() => {
      const s = pageSize();
      if (running && (s.width !== canvas.width || s.height !== canvas.height)) mod._nw_resize(s.width, s.height);
    }, 150);
  }

  // The K slider steers K to its value by holding curvature up or down, as a visitor holding the
  // button would: the recording replays it.
  // (In the earth scene the keys zoom, K within (0, 1]: where K stops moving, the steering stops.)
  let kLast = null, frameLast = null;
  function steerCurvature() {
    if (kTarget === null) return;
    const K = mod._nw_curvature(), frame = mod._nw_frame();
    const want = kTarget > K ? control.curvature_up : kTarget < K ? control.curvature_down : -1;
    const stuck = kHeld >= 0 && K === kLast && frame !== frameLast;  // (a step went by, K did not move)
    kLast = K, frameLast = frame;
    if (kHeld >= 0 && (want !== kHeld || stuck)) {  // reached, passed or as far as it goes: done
      input(kHeld, false);
      kTarget = null, kHeld = -1;
    } else if (kHeld < 0) {
      if (want >= 0) input(want, true);
      kHeld = want;
      if (want < 0) kTarget = null;
    }
  }

  function wireControls() {
    window.addEventListener('keydown', (e) => onKey(e, true));
    window.addEventListener('keyup', (e) => onKey(e, false));
    new ResizeObserver(followStage).observe($('stage'));
    const full = $('fullscreen');
    full.hidden = !document.fullscreenEnabled;
    full.addEventListener('click', () => {
      if (document.fullscreenElement) document.exitFullscreen();
      else document.documentElement.requestFullscreen().catch((e) => say(`full screen was refused: ${e.message}`));
    });
    document.addEventListener('fullscreenchange', () => {
      full.textContent = t(document.fullscreenElement ? 'page_leave_full_screen' : 'page_full_screen');
    });
    window.addEventListener('blur', () => {
      for (const c of keysHeld.values()) input(c, false);
      keysHeld.clear();
    });
    const scene = $('scene');
    for (const name of builtins) scene.add(new Option(name, name));
    scene.addEventListener('change', () => start(wordsWith(scene.value, $('engine').value)) && canvas.focus());
    $('engine').addEventListener('change', () => start(wordsWith(lastScene(), $('engine').value)) && canvas.focus());
    $('projection').addEventListener('change', (e) => {
      const taps = call('nw_projection_taps', 'number', [e.target.value]);
      for (let i = 0; i < taps; ++i) input(control.projection, true), input(control.projection, false);
      canvas.focus();
    });
    $('curvature').addEventListener('pointerdown', () => { sliderDown = true; });
    for (const type of ['pointerup', 'pointercancel', 'lostpointercapture'])
      $('curvature').addEventListener(type, () => { sliderDown = false; });
    $('curvature').addEventListener('input', (e) => {
      if (kHeld >= 0) input(kHeld, false);
      kHeld = -1;
      kTarget = Number(e.target.value);
    });
    $('stop').addEventListener('click', () => mod._nw_stop());
    $('restart').addEventListener('click', () => start(lastWords) && canvas.focus());
    // A tap on the picture drops a mark of the live instrument there (M cycles the instrument).
    canvas.addEventListener('pointerdown', (e) => {
      const box = canvas.getBoundingClientRect();
      mod._nw_mark((e.clientX - box.left) * canvas.width / box.width, (e.clientY - box.top) * canvas.height / box.height);
      canvas.focus();
    });
    $('run-text').addEventListener('click', () => runText('pasted.toml', $('scene-text').value));
    $('scene-file').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      if (file) runText(file.name.replace(/[^\w.-]/g, '_'), await file.text());
    });
  }
  function lastScene() {
    const i = lastWords.lastIndexOf('--scene');
    return i >= 0 ? lastWords[i + 1] : 'kiosk';
  }
  function runText(name, text) {
    mod.FS.writeFile('/' + name, text);
    if (![...$('scene').options].some((o) => o.value === '/' + name)) $('scene').add(new Option(name, '/' + name));
    if (start(wordsWith('/' + name, $('engine').value))) canvas.focus();
  }

  // ---- for tests and embedding pages ------------------------------------------------------------
  let readyResolve;
  const ready = new Promise((resolve) => { readyResolve = resolve; });
  window.noneuclid = {
    ready,  // resolves once the first run has started (true) or could not (false)
    state: () => ({
      running, frame: mod ? mod._nw_frame() : 0, K: mod ? mod._nw_curvature() : 0,
      pixels: [canvas.width, canvas.height], hudScale: sizeChosen ? pageSize().hudScale : 1,
      lessonStep: mod ? mod._nw_lesson_step() : 0,
      message: $('message').hidden ? '' : $('message').textContent,
      sound: sound.state(),
    }),
    // Resolves when the run has ended: stop() ends it after the frame being drawn.
    ended: () => new Promise((resolve) => running ? waiting.push(resolve) : resolve()),
    stop() {
      const done = this.ended();
      if (running) mod._nw_stop();
      return done;
    },
    recording: () => mod ? mod.UTF8ToString(mod._nw_recording()) : '',
    // `frames` frames back to back (not waiting for the screen), timed: milliseconds a frame,
    // and of that the part spent in putImageData.
    bench(frames) {
      let n = 0;
      presentMs = 0;
      const t0 = performance.now();
      while (n < frames && mod._nw_tick()) ++n;
      const ms = performance.now() - t0;
      return {frames: n, ms: ms / Math.max(n, 1), present_ms: presentMs / Math.max(n, 1)};
    },
  };

  createNoneuclid({
    noneuclidPresent: present,
    noneuclidReadBack: readBack,
    print: (text) => console.log(text),
    printErr: (text) => console.warn(text),
  }).then(async (m) => {
    mod = m;
    for (const menu of ['projection', 'engine', 'language']) fillMenu(menu);
    language.load(mod, params);
    sound.show();
    builtins = mod.UTF8ToString(mod._nw_scenes()).split('\n').filter(Boolean);
    for (const name of new Set(TOUCH.map(([name]) => name).concat(['projection'], K_KEYS)))
      control[name] = call('nw_control', 'number', [name]);
    touchButtons();
    wireControls();
    try {
      startWords = await wordsOfUrl();
      if (!params.has('size') && !params.has('actions')) startWords.push('--size', ...defaultSize());
      if (!params.has('lang') && !params.has('actions')) startWords.push('--lang', language.code());
    } catch (e) {
      say(e.message);
      $('status').textContent = t('page_not_running');
      startWords = ['--size', ...defaultSize()];  // said once: the menus start runs without the address
      readyResolve(false);
      return;
    }
    const started = start(startWords);
    // A bad address is said once: the menus then start runs without its words.
    if (!started) startWords = ['--size', ...defaultSize()];
    readyResolve(started);
    canvas.focus();
  });
})();
