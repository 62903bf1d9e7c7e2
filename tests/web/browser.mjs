// Headless Chromium driven through the DevTools protocol over a pipe (--remote-debugging-pipe: JSON
// messages, NUL-terminated, on file descriptors 3 and 4), with nothing from npm. The browser tests
// (viewer_test.mjs, report_test.mjs) load pages from disk, read the console, click, press keys and
// take screenshots with it.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export const SKIP = 77; // ctest's SKIP_RETURN_CODE

/// The Chromium on PATH (or $CHROMIUM), or null.
export function findChromium() {
  if (process.env.CHROMIUM) return existsSync(process.env.CHROMIUM) ? process.env.CHROMIUM : null;
  for (const name of ['chromium', 'chromium-browser', 'google-chrome']) {
    const r = spawnSync('sh', ['-c', `command -v ${name}`], { encoding: 'utf8' });
    if (r.status === 0 && r.stdout.trim()) return r.stdout.trim();
  }
  return null;
}

export class Browser {
  static async launch(executable, { width = 1400, height = 900 } = {}) {
    const profile = mkdtempSync(join(tmpdir(), 'swarmpath-chromium-'));
    const args = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-extensions', '--mute-audio', `--user-data-dir=${profile}`, `--window-size=${width},${height}`,
      '--remote-debugging-pipe', 'about:blank'];
    const proc = spawn(executable, args, { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
    const b = new Browser(proc, profile);
    proc.stderr.on('data', (d) => { b.stderr += d.toString(); });
    const { targetInfos } = await b.send('Target.getTargets');
    const page = targetInfos.find((t) => t.type === 'page');
    const attached = await b.send('Target.attachToTarget', { targetId: page.targetId, flatten: true });
    b.page = attached.sessionId; // the protocol's name for a connection to one target
    for (const domain of ['Page', 'Runtime', 'Log']) await b.call(`${domain}.enable`);
    await b.call('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor: 1, mobile: false });
    return b;
  }

  constructor(proc, profile) {
    this.proc = proc;
    this.profile = profile;
    this.stderr = '';
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = [];
    this.errors = []; // console errors, uncaught exceptions, error log entries
    let buffer = '';
    proc.stdio[4].on('data', (chunk) => {
      buffer += chunk.toString();
      let end;
      while ((end = buffer.indexOf('\0')) >= 0) {
        const msg = JSON.parse(buffer.slice(0, end));
        buffer = buffer.slice(end + 1);
        this.dispatch(msg);
      }
    });
    proc.on('exit', (code) => {
      for (const { reject } of this.pending.values()) reject(new Error(`chromium exited (${code}): ${this.stderr.slice(-2000)}`));
      this.pending.clear();
    });
  }

  dispatch(msg) {
    if (msg.id !== undefined) {
      const p = this.pending.get(msg.id);
      this.pending.delete(msg.id);
      if (!p) return;
      if (msg.error) p.reject(new Error(`${p.method}: ${msg.error.message}`));
      else p.resolve(msg.result);
      return;
    }
    if (msg.method === 'Runtime.exceptionThrown') {
      const d = msg.params.exceptionDetails;
      this.errors.push(`uncaught: ${d.exception?.description ?? d.text}`);
    } else if (msg.method === 'Runtime.consoleAPICalled' && ['error', 'assert'].includes(msg.params.type)) {
      this.errors.push(`console.${msg.params.type}: ${msg.params.args.map((a) => a.value ?? a.description).join(' ')}`);
    } else if (msg.method === 'Log.entryAdded' && msg.params.entry.level === 'error') {
      this.errors.push(`log: ${msg.params.entry.text} ${msg.params.entry.url ?? ''}`);
    }
    for (const l of this.listeners) l(msg);
  }

  send(method, params = {}, target) {
    const id = this.nextId++;
    const msg = { id, method, params };
    if (target) msg.sessionId = target;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, method });
      this.proc.stdio[3].write(`${JSON.stringify(msg)}\0`);
    });
  }

  /// A command to the page.
  call(method, params = {}) { return this.send(method, params, this.page); }

  async goto(url) {
    const loaded = new Promise((resolve) => {
      const l = (m) => { if (m.method === 'Page.loadEventFired') { this.listeners = this.listeners.filter((x) => x !== l); resolve(); } };
      this.listeners.push(l);
    });
    await this.call('Page.navigate', { url });
    await loaded;
  }

  /// The value of a JavaScript expression in the page (awaited when it is a promise).
  async eval(expression) {
    const r = await this.call('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
    if (r.exceptionDetails) throw new Error(`${expression}: ${r.exceptionDetails.exception?.description ?? r.exceptionDetails.text}`);
    return r.result.value;
  }

  async waitFor(expression, timeoutMs = 15000) {
    const until = Date.now() + timeoutMs;
    while (Date.now() < until) {
      if (await this.eval(expression)) return;
      await sleep(50);
    }
    throw new Error(`timed out waiting for ${expression}`);
  }

  async click(x, y) {
    for (const type of ['mouseMoved', 'mousePressed', 'mouseReleased']) {
      await this.call('Input.dispatchMouseEvent', { type, x, y, button: type === 'mouseMoved' ? 'none' : 'left', clickCount: 1 });
    }
  }

  async hover(x, y) {
    await this.call('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y, button: 'none' });
  }

  async wheel(x, y, deltaY) {
    await this.call('Input.dispatchMouseEvent', { type: 'mouseWheel', x, y, deltaX: 0, deltaY });
  }

  /// A key press: `key` as KeyboardEvent.key names it (' ', 'ArrowRight', 'h', ...).
  async press(key, { shift = false } = {}) {
    const codes = { ' ': ['Space', 32], ArrowRight: ['ArrowRight', 39], ArrowLeft: ['ArrowLeft', 37], Home: ['Home', 36], End: ['End', 35], Escape: ['Escape', 27] };
    const [code, keyCode] = codes[key] ?? [`Key${key.toUpperCase()}`, key.toUpperCase().charCodeAt(0)];
    const text = key.length === 1 ? key : undefined;
    const modifiers = shift ? 8 : 0;
    await this.call('Input.dispatchKeyEvent', { type: 'keyDown', key, code, windowsVirtualKeyCode: keyCode, text, modifiers });
    await this.call('Input.dispatchKeyEvent', { type: 'keyUp', key, code, windowsVirtualKeyCode: keyCode, modifiers });
  }

  async screenshot(path, { fullPage = false } = {}) {
    const params = { format: 'png' };
    if (fullPage) {
      const m = await this.call('Page.getLayoutMetrics');
      params.captureBeyondViewport = true;
      params.clip = { x: 0, y: 0, width: m.cssContentSize.width, height: m.cssContentSize.height, scale: 1 };
    }
    const { data } = await this.call('Page.captureScreenshot', params);
    writeFileSync(path, Buffer.from(data, 'base64'));
  }

  async close() {
    try { await this.send('Browser.close'); } catch { /* already gone */ }
    await new Promise((resolve) => { if (this.proc.exitCode !== null) resolve(); else this.proc.on('exit', resolve); });
    rmSync(this.profile, { recursive: true, force: true });
  }
}

/// The robots of a `view --frame-json` frame that stand clear of the others (four radii), each with
/// the canvas pixel half way to its rim behind its heading mark and the colour the recording gives it:
/// [{ id, led, want, got }], those inside the canvas only. `viewer` is the page's expression for it.
export async function probeRobots(b, viewer, frame) {
  const rad = frame.robot_radius;
  const isolated = frame.robots.filter((r) => frame.robots.every((q) => q.id === r.id || Math.hypot(q.x - r.x, q.y - r.y) > 4 * rad));
  return b.eval(`(() => {
    const v = ${viewer}; const ctx = v.canvas.getContext('2d');
    return ${JSON.stringify(isolated)}.map((r) => {
      const [cx, cy] = v.worldToScreen(r.x, r.y);
      const d = 0.45 * v.robotRadiusPx();
      const x = Math.round(cx - d * Math.cos(r.yaw)); const y = Math.round(cy + d * Math.sin(r.yaw));
      if (x < 2 || y < 2 || x > v.canvas.width - 3 || y > v.canvas.height - 3) return null;
      return { id: r.id, led: r.led, want: r.rgb, got: Array.from(ctx.getImageData(x, y, 1, 1).data.slice(0, 3)) };
    }).filter((p) => p);
  })()`);
}

/// The probes whose pixel is more than `tolerance` off its colour in any channel.
export function wrongColours(probes, tolerance = 12) {
  return probes.filter((p) => p.want.some((c, k) => Math.abs(c - p.got[k]) > tolerance));
}

export function sleep(ms) { return new Promise((resolve) => setTimeout(resolve, ms)); }

/// Runs `swarmpath` with these arguments; returns stdout, throws with stderr on failure.
export function swarmpath(binary, args) {
  const r = spawnSync(binary, args, { encoding: 'utf8', maxBuffer: 256 << 20 });
  if (r.status !== 0) throw new Error(`swarmpath ${args.join(' ')} exited ${r.status}: ${r.stderr}`);
  return r.stdout;
}

/// Checks, counted and reported as "N passed, M failed".
export class Checks {
  constructor(name) { this.name = name; this.passed = 0; this.failed = 0; }

  ok(condition, what) {
    if (condition) { this.passed += 1; console.log(`  ok    ${what}`); } else { this.failed += 1; console.log(`  FAIL  ${what}`); }
    return condition;
  }

  finish() {
    console.log(`${this.name}: ${this.passed} passed, ${this.failed} failed`);
    return this.failed === 0 ? 0 : 1;
  }
}

/// --key value arguments.
export function options(argv) {
  const o = {};
  for (let i = 0; i + 1 < argv.length; i += 2) o[argv[i].replace(/^--/, '')] = argv[i + 1];
  return o;
}
