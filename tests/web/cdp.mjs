// A small client of the Chrome DevTools Protocol over Chromium's --remote-debugging-pipe (no
// port, no dependency): the browser reads commands from file descriptor 3 and writes answers
// and events to descriptor 4, each message JSON ending in a NUL byte.
import {spawn} from 'node:child_process';

// Flags for a headless Chromium that talks to nothing but the page it is given.
export const HEADLESS_FLAGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--remote-debugging-pipe',
];

export class Browser {
  // Starts `executable` with a fresh profile in `profileDir`.
  constructor(executable, profileDir, extraFlags = []) {
    this.process = spawn(executable, [...HEADLESS_FLAGS, ...extraFlags, `--user-data-dir=${profileDir}`, 'about:blank'],
                         {stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe']});
    this.stderr = '';
    this.process.stderr.on('data', (d) => { this.stderr = (this.stderr + d).slice(-20000); });
    this.next = 1;
    this.pending = new Map();
    this.listeners = new Set();
    let buffered = Buffer.alloc(0);
    this.process.stdio[4].on('data', (chunk) => {
      buffered = Buffer.concat([buffered, chunk]);
      for (let end; (end = buffered.indexOf(0)) >= 0; buffered = buffered.subarray(end + 1))
        this.receive(JSON.parse(buffered.subarray(0, end).toString('utf8')));
    });
    this.exited = new Promise((resolve) => this.process.on('exit', resolve));
    this.exited.then(() => {
      for (const {reject, method} of this.pending.values())
        reject(new Error(`chromium exited while ${method} was pending; its last words:\n${this.stderr}`));
      this.pending.clear();
    });
  }

  receive(message) {
    if (message.id !== undefined) {
      const call = this.pending.get(message.id);
      this.pending.delete(message.id);
      if (!call) return;
      if (message.error) call.reject(new Error(`${call.method}: ${message.error.message}`));
      else call.resolve(message.result);
      return;
    }
    for (const listener of this.listeners) listener(message);
  }

  // A command; `sessionId` sends it to an attached page.
  send(method, params = {}, sessionId = undefined) {
    const id = this.next++;
    const message = {id, method, params};
    if (sessionId) message.sessionId = sessionId;
    return new Promise((resolve, reject) => {
      this.pending.set(id, {resolve, reject, method});
      this.process.stdio[3].write(JSON.stringify(message) + '\0');
    });
  }

  // Calls listener(message) for every event.
  on(listener) { this.listeners.add(listener); }

  // A new tab, attached: its Page.
  async newPage() {
    const {targetId} = await this.send('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await this.send('Target.attachToTarget', {targetId, flatten: true});
    return new Page(this, sessionId, targetId);
  }

  async close() {
    try {
      await Promise.race([this.send('Browser.close'), new Promise((r) => setTimeout(r, 5000))]);
    } catch {
      // it has gone already
    }
    const gone = await Promise.race([this.exited.then(() => true), new Promise((r) => setTimeout(() => r(false), 5000))]);
    if (!gone) this.process.kill('SIGKILL');
  }
}

export class Page {
  constructor(browser, sessionId, targetId) {
    this.browser = browser;
    this.sessionId = sessionId;
    this.targetId = targetId;
    this.problems = [];  // console errors, uncaught exceptions, failed loads: one line each
    browser.on((m) => {
      if (m.sessionId !== sessionId) return;
      if (m.method === 'Runtime.consoleAPICalled' && (m.params.type === 'error' || m.params.type === 'assert'))
        this.problems.push('console.' + m.params.type + ': ' + m.params.args.map((a) => a.value ?? a.description).join(' '));
      else if (m.method === 'Runtime.exceptionThrown')
        this.problems.push('exception: ' + (m.params.exceptionDetails.exception?.description ?? m.params.exceptionDetails.text));
      else if (m.method === 'Log.entryAdded' && m.params.entry.level === 'error')
        this.problems.push('log: ' + m.params.entry.text + (m.params.entry.url ? ' (' + m.params.entry.url + ')' : ''));
    });
  }

  send(method, params = {}) { return this.browser.send(method, params, this.sessionId); }

  // Loads url; `viewport` ({width, height, dpr}), if given, is the screen of a phone or tablet
  // (a mobile viewport of that many CSS pixels, at that device pixel ratio).
  async open(url, viewport = null) {
    await this.send('Runtime.enable');
    await this.send('Log.enable');
    await this.send('Page.enable');
    await this.send('Emulation.setTouchEmulationEnabled', {enabled: true, maxTouchPoints: 5});
    if (viewport)
      await this.send('Emulation.setDeviceMetricsOverride', {width: viewport.width, height: viewport.height,
                                                             deviceScaleFactor: viewport.dpr ?? 1, mobile: true});
    const loaded = new Promise((resolve) => this.browser.on((m) => {
      if (m.sessionId === this.sessionId && m.method === 'Page.loadEventFired') resolve();
    }));
    const {errorText} = await this.send('Page.navigate', {url});
    if (errorText) throw new Error(`cannot open ${url}: ${errorText}`);
    await loaded;
  }

  // The value of a JavaScript expression in the page (a promise is waited for).
  async evaluate(expression) {
    const r = await this.send('Runtime.evaluate', {expression, awaitPromise: true, returnByValue: true});
    if (r.exceptionDetails)
      throw new Error(`${expression}: ${r.exceptionDetails.exception?.description ?? r.exceptionDetails.text}`);
    return r.result.value;
  }

  // A key as a keyboard sends it: down (with its text, for a character) or up.
  key(type, key, code, keyCode) {
    const text = type === 'keyDown' && key.length === 1 ? key : undefined;
    return this.send('Input.dispatchKeyEvent', {type, key, code, windowsVirtualKeyCode: keyCode, text});
  }

  touch(type, x, y) {
    return this.send('Input.dispatchTouchEvent', {type, touchPoints: type === 'touchEnd' ? [] : [{x, y, id: 1}]});
  }

  // A left click of the mouse at (x, y), CSS pixels.
  async click(x, y) {
    await this.send('Input.dispatchMouseEvent', {type: 'mouseMoved', x, y});
    await this.send('Input.dispatchMouseEvent', {type: 'mousePressed', x, y, button: 'left', clickCount: 1});
    await this.send('Input.dispatchMouseEvent', {type: 'mouseReleased', x, y, button: 'left', clickCount: 1});
  }

  close() { return this.browser.send('Target.closeTarget', {targetId: this.targetId}); }
}
