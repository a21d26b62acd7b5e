// The page's sound (docs/sound.md): the engine's synthesiser renders each frame's samples
// (nw_sound_* in page_api.cpp), played here with Web Audio, one AudioBuffer a frame queued back
// to back. Off until the sound button or ?sound=on turns it on; a browser lets a page sound only
// after a click or a key, so the AudioContext is resumed on the first one. page.js calls
// attach() after each start of a run, frame() after each tick, and show() once the page's
// language is known.
'use strict';
class NoneuclidSound {
  constructor(button, on) {
    this.button = button;
    this.on = on;
    this.context = null;
    this.at = 0;        // the AudioContext time the next frame's samples start at
    this.played = 0;    // frames of samples queued, for the tests
    this.mod = null;
    button.addEventListener('click', () => this.set(!this.on));
    const wake = () => { if (this.on) this.start(); };
    for (const type of ['pointerdown', 'keydown']) window.addEventListener(type, wake, true);
  }
  start() {
    if (!this.context) this.context = new AudioContext();
    if (this.context.state === 'suspended') this.context.resume().catch(() => {});
  }
  set(on) {
    this.on = on;
    if (on) this.start();
    if (this.mod) this.attach(this.mod);
    this.show();
  }
  // The button's words (page_lang.js: page.js calls this once the page's language is known).
  show() {
    this.button.textContent = window.noneuclidLanguage.t(this.on ? 'page_sound_on' : 'page_sound_off');
    this.button.setAttribute('aria-pressed', String(this.on));
  }
  // A run started: the engine renders sound for it if it is on.
  attach(mod) {
    this.mod = mod;
    if (this.on) this.start();
    mod._nw_sound(this.on ? this.context.sampleRate : 0);
  }
  frame() {
    const mod = this.mod, ctx = this.context;
    if (!this.on || !mod || !ctx || ctx.state !== 'running') return;
    const n = mod._nw_sound_count();
    if (n <= 0) return;
    const pcm = new Int16Array(mod.HEAPU8.buffer, mod._nw_sound_samples(), n);
    const buffer = ctx.createBuffer(1, n, ctx.sampleRate);
    const data = buffer.getChannelData(0);
    for (let i = 0; i < n; ++i) data[i] = pcm[i] / 32768;
    const source = ctx.createBufferSource();
    source.buffer = buffer;
    source.connect(ctx.destination);
    // Back to back, 50 ms ahead; a queue run dry or grown long (frames late, or early) starts again.
    if (this.at < ctx.currentTime + 0.01 || this.at > ctx.currentTime + 0.3) this.at = ctx.currentTime + 0.05;
    source.start(this.at);
    this.at += n / ctx.sampleRate;
    ++this.played;
  }
  state() {
    const mod = this.mod;
    return {on: this.on, context: this.context ? this.context.state : 'none', played: this.played,
            cues: mod ? mod._nw_sound_cues() : 0, muted: mod ? mod._nw_sound_muted() === 1 : false};
  }
}
