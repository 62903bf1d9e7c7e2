// swarmpath viewer: plays recorded runs (.swrec, sim/recording.hpp) on a canvas. Self-contained:
// the recordings sit in the page as base64 <script type="application/x-swrec"> elements and every
// element with class "swp-viewer" becomes a player of them. No network, no server.
'use strict';

(() => {
  // ---------------------------------------------------------------- the format (sim/recording.hpp)
  const MAGIC = [0x53, 0x57, 0x52, 0x45, 0x43, 0x0d, 0x0a, 0x1a];
  const FORMAT_VERSION = 1;
  const NEST = -1; // kNestEmitter
  const GOAL = -2; // kGoalEmitter

  function fromBase64(text) {
    const bin = atob(text.replace(/\s+/g, ''));
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) out[i] = bin.charCodeAt(i);
    return out;
  }

  async function inflate(bytes) {
    if (typeof DecompressionStream === 'undefined') {
      throw new Error('this browser cannot inflate the recording (no DecompressionStream): use a current Chromium, Firefox or Safari');
    }
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }

  async function decodeRecording(bytes) {
    for (let i = 0; i < MAGIC.length; ++i) {
      if (bytes[i] !== MAGIC[i]) throw new Error('not a swarmpath recording (.swrec)');
    }
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const version = dv.getUint32(8, true);
    if (version !== FORMAT_VERSION) throw new Error(`recording format version ${version}; this viewer reads ${FORMAT_VERSION}`);
    const headerLength = dv.getUint32(12, true);
    const meta = JSON.parse(new TextDecoder().decode(bytes.subarray(16, 16 + headerLength)));
    const at = 16 + headerLength;
    const packed = dv.getUint32(at, true);
    const rawLength = dv.getUint32(at + 4, true);
    const body = await inflate(bytes.subarray(at + 8, at + 8 + packed));
    if (body.length !== rawLength) throw new Error('corrupt recording body');

    const N = meta.robots;
    const F = meta.frames;
    const E = meta.changes;
    const rec = {
      meta, N, F, E,
      ticks: new Int32Array(F),
      x: new Float32Array(F * N), y: new Float32Array(F * N),
      heading: new Uint8Array(F * N), led: new Uint8Array(F * N), state: new Uint8Array(F * N),
      parent: new Int32Array(F * N), child: new Int32Array(F * N),
      change: {
        tick: new Int32Array(E), robot: new Int32Array(E), from: new Uint8Array(E), to: new Uint8Array(E),
        pfRow: new Uint8Array(E), taRow: new Uint8Array(E),
      },
    };
    const bv = new DataView(body.buffer, body.byteOffset, body.byteLength);
    const qx = new Uint16Array(N);
    const qy = new Uint16Array(N);
    const [ox, oy] = meta.origin;
    const q = meta.quantum;
    let o = 0;
    for (let f = 0; f < F; ++f) {
      const k0 = f * N;
      rec.ticks[f] = bv.getInt32(o, true); o += 4;
      for (let i = 0; i < N; ++i, o += 2) { qx[i] = (qx[i] + bv.getUint16(o, true)) & 0xffff; rec.x[k0 + i] = ox + q * qx[i]; }
      for (let i = 0; i < N; ++i, o += 2) { qy[i] = (qy[i] + bv.getUint16(o, true)) & 0xffff; rec.y[k0 + i] = oy + q * qy[i]; }
      rec.heading.set(body.subarray(o, o + N), k0); o += N;
      rec.led.set(body.subarray(o, o + N), k0); o += N;
      rec.state.set(body.subarray(o, o + N), k0); o += N;
      for (let i = 0; i < N; ++i, o += 4) rec.parent[k0 + i] = bv.getInt32(o, true);
      for (let i = 0; i < N; ++i, o += 4) rec.child[k0 + i] = bv.getInt32(o, true);
    }
    const c = rec.change;
    for (let e = 0; e < E; ++e) {
      c.tick[e] = bv.getInt32(o, true); c.robot[e] = bv.getInt32(o + 4, true);
      c.from[e] = body[o + 8]; c.to[e] = body[o + 9]; c.pfRow[e] = body[o + 10]; c.taRow[e] = body[o + 11];
      o += 12;
    }
    rec.stateNames = new Map(meta.states.map((s) => [s.code, s.name]));
    rec.ledCss = meta.leds.map((l) => `rgb(${l.rgb[0]},${l.rgb[1]},${l.rgb[2]})`);
    rec.ledDark = meta.leds.map((l) => 0.299 * l.rgb[0] + 0.587 * l.rgb[1] + 0.114 * l.rgb[2] < 110);
    return rec;
  }

  // ---------------------------------------------------------------- small functions
  const PATH_COLOURS = { astar: '#e00000', subgoal: '#1f4fff', opt1: '#9b30d0', final: '#00a651' };
  const MILESTONE_COLOURS = { goal: '#c9a000', alloc: '#00a0a0', chain: '#1f4fff', opt1: '#9b30d0', form: '#00a651' };
  const SPEEDS = [0.25, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

  function el(tag, attrs = {}, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
      if (k === 'class') e.className = v;
      else if (k === 'text') e.textContent = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v);
    }
    for (const c of children) e.append(c);
    return e;
  }

  function emitterName(id) {
    if (id === NEST) return 'nest';
    if (id === GOAL) return 'goal';
    if (id < 0) return '—';
    return `robot ${id}`;
  }

  // heat colours as app/svg.cpp draws them: pale yellow, orange, dark red
  function heatRgb(t) {
    const stops = [[255, 255, 204], [253, 141, 60], [128, 0, 38]];
    const s = Math.min(1, Math.max(0, t)) * 2;
    const i = Math.min(1, Math.floor(s));
    const a = s - i;
    return stops[i].map((v, k) => Math.round(v + a * (stops[i + 1][k] - v)));
  }

  // ---------------------------------------------------------------- the player
  class Viewer {
    constructor(root, sources) {
      this.root = root;
      this.sources = sources; // [{title, bytes}]
      this.rec = null;
      this.pos = 0; // fractional frame index
      this.playing = false;
      this.speed = 20;
      this.show = { links: true, paths: true, heat: false, ids: false };
      this.selected = -1;
      this.hover = -1;
      this.view = { scale: 40, cx: 0, cy: 0 };
      this.heat = null;
      this.lastTime = null;
      this.dirty = true;
      this.ready = false;
      this.buildDom();
      this.bindInput();
      this.frameLoop = this.frameLoop.bind(this);
    }

    // the page: top bar, stage, side panel, timeline, controls
    buildDom() {
      const r = this.root;
      r.classList.add('swp');
      r.tabIndex = 0;
      this.titleEl = el('h1');
      this.summaryEl = el('span', { class: 'swp-summary' });
      const top = el('div', { class: 'swp-top' }, this.titleEl);
      if (this.sources.length > 1) {
        this.picker = el('select', { 'aria-label': 'recording', class: 'swp-picker' });
        this.sources.forEach((s, i) => this.picker.append(el('option', { value: String(i), text: s.title })));
        this.picker.addEventListener('change', () => this.load(Number(this.picker.value)));
        top.append(this.picker);
      }
      top.append(this.summaryEl);
      this.canvas = el('canvas', { class: 'swp-canvas', 'aria-label': 'arena' });
      this.tip = el('div', { class: 'swp-tip' });
      this.tip.hidden = true;
      this.stage = el('div', { class: 'swp-stage' }, this.canvas, this.tip);
      this.timeline = el('canvas', { class: 'swp-timeline', 'aria-label': 'timeline', tabindex: '0' });

      const button = (text, title, fn) => el('button', { type: 'button', title, text, onclick: fn });
      this.playButton = button('play', 'play / pause (space)', () => this.toggle());
      this.speedSelect = el('select', { 'aria-label': 'speed', title: 'playback speed ([ and ])' });
      for (const s of SPEEDS) this.speedSelect.append(el('option', { value: String(s), text: `${s}×` }));
      this.speedSelect.addEventListener('change', () => { this.speed = Number(this.speedSelect.value); });
      this.clock = el('span', { class: 'swp-clock' });
      const toggle = (key, text, title) => {
        const box = el('input', { type: 'checkbox' });
        box.checked = this.show[key];
        box.addEventListener('change', () => { this.show[key] = box.checked; this.dirty = true; });
        this[`${key}Box`] = box;
        return el('label', { title }, box, text);
      };
      const controls = el('div', { class: 'swp-controls' },
        button('start', 'to the start (Home)', () => this.seekFrame(0)),
        button('◀', 'one frame back (←)', () => this.step(-1)),
        this.playButton,
        button('▶', 'one frame on (→)', () => this.step(1)),
        button('end', 'to the end (End)', () => this.seekFrame(this.rec ? this.rec.F - 1 : 0)),
        this.speedSelect, this.clock,
        toggle('links', 'links', 'chain links: parent solid, child dashed (l)'),
        toggle('paths', 'paths', 'A*, subgoal, optimisation-1 and final paths (p)'),
        toggle('heat', 'heat map', 'where the robots have been so far (h)'),
        toggle('ids', 'ids', 'robot ids (i)'),
        button('fit', 'fit the arena (f)', () => this.fit()));

      this.robotPanel = el('section', { class: 'swp-robot' });
      this.legendPanel = el('section', { class: 'swp-legend' });
      this.eventsPanel = el('section', { class: 'swp-events' });
      this.helpPanel = el('section', { class: 'swp-help' });
      this.helpPanel.innerHTML = '<h2>Keys</h2><table>' + [
        ['space', 'play / pause'], ['← →', 'one frame back / on'], ['shift ← →', 'ten frames'],
        ['home end', 'start / end'], ['[ ]', 'slower / faster'], ['n N', 'next / previous milestone'],
        ['+ −', 'zoom (or the wheel; drag to pan)'], ['f', 'fit the arena'], ['l p h i', 'links, paths, heat map, ids'],
        ['esc', 'deselect'],
      ].map(([k, v]) => `<tr><td>${k.split(' ').map((x) => `<kbd>${x}</kbd>`).join(' ')}</td><td>${v}</td></tr>`).join('') + '</table>';
      const side = el('div', { class: 'swp-side' }, this.robotPanel, this.eventsPanel, this.legendPanel, this.helpPanel);
      r.replaceChildren(top, this.stage, side, this.timeline, controls);
    }

    async load(index) {
      const src = this.sources[index];
      this.playing = false;
      this.ready = false;
      try {
        this.rec = await decodeRecording(src.bytes);
      } catch (e) {
        console.error(`swarmpath viewer: ${src.title}: ${e.message}`);
        this.root.replaceChildren(el('div', { class: 'swp-error', text: `Cannot show ${src.title}: ${e.message}` }));
        throw e;
      }
      const m = this.rec.meta;
      this.titleEl.textContent = src.title;
      const res = m.result;
      this.summaryEl.textContent = `${m.scenario.name} (${m.scenario.env_class}), ${m.robots} robots, mode ${m.mode}, ` +
        `seed ${m.seed}: ${res.success ? `path complete at tick ${m.milestones.find((x) => x.name === 'form')?.tick ?? res.ticks}` : 'no complete path'}` +
        `; ${res.ticks} ticks, a frame every ${m.every} ticks`;
      const seconds = res.ticks / m.ticks_per_second;
      this.speed = SPEEDS.find((s) => s >= seconds / 60) ?? SPEEDS[SPEEDS.length - 1];
      this.speedSelect.value = String(this.speed);
      this.selected = -1;
      this.hover = -1;
      this.heat = null;
      this.pos = 0;
      this.buildLegend();
      this.fit();
      this.ready = true;
      this.dirty = true;
      this.updatePanels(true);
    }

    start() {
      requestAnimationFrame(this.frameLoop);
    }

    // ------------------------------------------------------------ time
    frameIndex() { return Math.min(this.rec.F - 1, Math.floor(this.pos + 1e-9)); }

    tick() {
      const f = this.frameIndex();
      const t = this.rec.ticks;
      if (f + 1 >= this.rec.F) return t[f];
      return Math.round(t[f] + (this.pos - f) * (t[f + 1] - t[f]));
    }

    seekFrame(f) {
      if (!this.rec) return;
      this.pos = Math.min(this.rec.F - 1, Math.max(0, f));
      this.dirty = true;
      this.updatePanels(true);
    }

    seekTick(tick) {
      const t = this.rec.ticks;
      let lo = 0;
      let hi = this.rec.F - 1;
      if (tick >= t[hi]) return this.seekFrame(hi);
      while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (t[mid] <= tick) lo = mid; else hi = mid;
      }
      this.seekFrame(lo + Math.max(0, (tick - t[lo]) / (t[hi] - t[lo])));
    }

    step(frames) {
      this.playing = false;
      this.seekFrame(Math.round(this.pos) + frames);
    }

    toggle() {
      if (!this.rec) return;
      if (!this.playing && this.pos >= this.rec.F - 1) this.pos = 0;
      this.playing = !this.playing;
      this.lastTime = null;
      this.dirty = true;
    }

    frameLoop(now) {
      if (this.rec && this.playing) {
        if (this.lastTime !== null) {
          const m = this.rec.meta;
          const framesPerSecond = (this.speed * m.ticks_per_second) / m.every;
          this.pos += Math.min(0.25, (now - this.lastTime) / 1000) * framesPerSecond;
          if (this.pos >= this.rec.F - 1) { this.pos = this.rec.F - 1; this.playing = false; }
          this.updatePanels(false);
        }
        this.lastTime = now;
        this.dirty = true;
      }
      if (this.dirty && this.rec) {
        this.render();
        this.dirty = false;
      }
      requestAnimationFrame(this.frameLoop);
    }

    // ------------------------------------------------------------ view transform (y up)
    resize() {
      const dpr = window.devicePixelRatio || 1;
      for (const c of [this.canvas, this.timeline]) {
        const w = Math.max(1, Math.round(c.clientWidth * dpr));
        const h = Math.max(1, Math.round(c.clientHeight * dpr));
        if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
      }
      this.dpr = dpr;
    }

    fit() {
      if (!this.rec) return;
      this.resize();
      const [w, h] = this.rec.meta.scenario.arena_size;
      const cw = this.canvas.width / this.dpr;
      const ch = this.canvas.height / this.dpr;
      this.view.scale = Math.max(1e-3, Math.min(cw / (w * 1.04), ch / (h * 1.04)));
      this.view.cx = 0;
      this.view.cy = 0;
      this.dirty = true;
    }

    // canvas CSS pixels
    worldToScreen(x, y) {
      const cw = this.canvas.width / this.dpr;
      const ch = this.canvas.height / this.dpr;
      return [cw / 2 + (x - this.view.cx) * this.view.scale, ch / 2 - (y - this.view.cy) * this.view.scale];
    }

    screenToWorld(sx, sy) {
      const cw = this.canvas.width / this.dpr;
      const ch = this.canvas.height / this.dpr;
      return [this.view.cx + (sx - cw / 2) / this.view.scale, this.view.cy - (sy - ch / 2) / this.view.scale];
    }

    zoomAt(factor, sx, sy) {
      const [wx, wy] = this.screenToWorld(sx, sy);
      this.view.scale = Math.min(5000, Math.max(0.5, this.view.scale * factor));
      const [nx, ny] = this.screenToWorld(sx, sy);
      this.view.cx += wx - nx;
      this.view.cy += wy - ny;
      this.dirty = true;
    }

    // a robot's interpolated pose at the current position: [x, y, heading rad]
    pose(i) {
      const r = this.rec;
      const f = this.frameIndex();
      const a = this.pos - f;
      const k = f * r.N + i;
      if (a <= 0 || f + 1 >= r.F) return [r.x[k], r.y[k], (r.heading[k] * Math.PI) / 128];
      const k1 = k + r.N;
      const dh = ((r.heading[k1] - r.heading[k] + 384) % 256) - 128;
      return [r.x[k] + a * (r.x[k1] - r.x[k]), r.y[k] + a * (r.y[k1] - r.y[k]), ((r.heading[k] + a * dh) * Math.PI) / 128];
    }

    robotRadiusPx() { return Math.max(2.5, this.rec.meta.robot_radius * this.view.scale); }

    // the robot under a canvas point (CSS pixels), or -1
    robotAt(sx, sy) {
      if (!this.rec) return -1;
      const reach = this.robotRadiusPx() + 3;
      let best = -1;
      let bestD = reach * reach;
      for (let i = 0; i < this.rec.N; ++i) {
        const [x, y] = this.pose(i);
        const [px, py] = this.worldToScreen(x, y);
        const d = (px - sx) ** 2 + (py - sy) ** 2;
        if (d <= bestD) { bestD = d; best = i; }
      }
      return best;
    }

    // ------------------------------------------------------------ drawing
    render() {
      this.resize();
      const ctx = this.canvas.getContext('2d');
      const r = this.rec;
      const m = r.meta;
      const s = this.view.scale;
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      const cw = this.canvas.width / this.dpr;
      const ch = this.canvas.height / this.dpr;
      ctx.fillStyle = '#e6e6e0';
      ctx.fillRect(0, 0, cw, ch);
      // world transform: metres, y up
      ctx.save();
      ctx.translate(cw / 2 - this.view.cx * s, ch / 2 + this.view.cy * s);
      ctx.scale(s, -s);
      const [aw, ah] = m.scenario.arena_size;
      ctx.fillStyle = '#fbfbf8';
      ctx.fillRect(-aw / 2, -ah / 2, aw, ah);
      if (this.show.heat) this.drawHeat(ctx);
      const px = 1 / s; // one CSS pixel in metres
      const d = m.scenario.deployment;
      ctx.setLineDash([4 * px, 3 * px]);
      ctx.strokeStyle = '#9a9a90';
      ctx.lineWidth = px;
      ctx.strokeRect(d.center[0] - d.size[0] / 2, d.center[1] - d.size[1] / 2, d.size[0], d.size[1]);
      ctx.setLineDash([]);
      ctx.fillStyle = '#6b6b66';
      ctx.beginPath();
      for (const o of m.scenario.obstacles) {
        if (o.kind === 'circle') {
          ctx.moveTo(o.center[0] + o.radius, o.center[1]);
          ctx.arc(o.center[0], o.center[1], o.radius, 0, 2 * Math.PI);
        } else {
          const [hx, hy] = o.half;
          const corners = [[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]];
          corners.forEach(([u, v], j) => {
            const x = o.center[0] + o.c * u - o.s * v;
            const y = o.center[1] + o.s * u + o.c * v;
            if (j === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
          });
          ctx.closePath();
        }
      }
      ctx.fill();
      this.drawBeacon(ctx, m.scenario.nest, '#0000ff', px);
      this.drawBeacon(ctx, m.scenario.goal, '#ffff00', px);
      const tick = this.tick();
      if (this.show.paths) this.drawPaths(ctx, tick, px);
      const poses = new Float64Array(r.N * 3);
      for (let i = 0; i < r.N; ++i) poses.set(this.pose(i), 3 * i);
      if (this.show.links) this.drawLinks(ctx, poses, px);
      this.drawRobots(ctx, poses, px);
      ctx.restore();
      this.drawLabels(ctx, poses);
      this.drawScaleBar(ctx, ch);
      this.drawTimeline();
    }

    drawBeacon(ctx, p, colour, px) {
      ctx.beginPath();
      ctx.arc(p[0], p[1], Math.max(0.12, 6 * px), 0, 2 * Math.PI);
      ctx.fillStyle = colour;
      ctx.fill();
      ctx.lineWidth = 1.5 * px;
      ctx.strokeStyle = '#222';
      ctx.stroke();
    }

    drawPaths(ctx, tick, px) {
      for (const p of this.rec.meta.paths) {
        if (p.tick > tick || p.points.length < 2) continue;
        ctx.beginPath();
        p.points.forEach(([x, y], j) => (j === 0 ? ctx.moveTo(x, y) : ctx.lineTo(x, y)));
        ctx.strokeStyle = PATH_COLOURS[p.name] || '#444';
        ctx.lineWidth = 2.2 * px;
        ctx.globalAlpha = 0.8;
        ctx.stroke();
        ctx.globalAlpha = 1;
      }
    }

    drawLinks(ctx, poses, px) {
      const r = this.rec;
      const k0 = this.frameIndex() * r.N;
      const [gx, gy] = r.meta.scenario.goal;
      const [nx, ny] = r.meta.scenario.nest;
      const end = (id) => (id === GOAL ? [gx, gy] : id === NEST ? [nx, ny] : id >= 0 && id < r.N ? [poses[3 * id], poses[3 * id + 1]] : null);
      ctx.lineWidth = 1.6 * px;
      ctx.strokeStyle = 'rgba(25, 25, 25, 0.7)';
      ctx.beginPath();
      for (let i = 0; i < r.N; ++i) {
        const to = end(r.parent[k0 + i]);
        if (!to) continue;
        ctx.moveTo(poses[3 * i], poses[3 * i + 1]);
        ctx.lineTo(to[0], to[1]);
      }
      ctx.stroke();
      ctx.setLineDash([3 * px, 3 * px]);
      ctx.strokeStyle = 'rgba(0, 60, 200, 0.65)';
      ctx.beginPath();
      for (let i = 0; i < r.N; ++i) {
        const c = r.child[k0 + i];
        if (c >= 0 && c < r.N && r.parent[k0 + c] === i) continue; // drawn already as c's parent link
        const to = end(c);
        if (!to) continue;
        ctx.moveTo(poses[3 * i], poses[3 * i + 1]);
        ctx.lineTo(to[0], to[1]);
      }
      ctx.stroke();
      ctx.setLineDash([]);
    }

    drawRobots(ctx, poses, px) {
      const r = this.rec;
      const k0 = this.frameIndex() * r.N;
      const rad = this.robotRadiusPx() * px;
      // one path per LED colour: a thousand robots are a dozen fills
      const groups = new Map();
      for (let i = 0; i < r.N; ++i) {
        const led = r.led[k0 + i];
        let g = groups.get(led);
        if (!g) { g = new Path2D(); groups.set(led, g); }
        g.moveTo(poses[3 * i] + rad, poses[3 * i + 1]);
        g.arc(poses[3 * i], poses[3 * i + 1], rad, 0, 2 * Math.PI);
      }
      ctx.lineWidth = Math.min(1, 0.15 * rad / px) * px;
      ctx.strokeStyle = '#1a1a1a';
      for (const [led, g] of groups) {
        ctx.fillStyle = r.ledCss[led] || '#888';
        ctx.fill(g);
        ctx.stroke(g);
      }
      // headings: a line from the centre to the rim
      const dark = new Path2D();
      const light = new Path2D();
      for (let i = 0; i < r.N; ++i) {
        const [x, y, h] = [poses[3 * i], poses[3 * i + 1], poses[3 * i + 2]];
        const p = r.ledDark[r.led[k0 + i]] ? light : dark;
        p.moveTo(x, y);
        p.lineTo(x + rad * Math.cos(h), y + rad * Math.sin(h));
      }
      ctx.lineWidth = Math.max(1, 0.25 * rad / px) * px;
      ctx.strokeStyle = '#111';
      ctx.stroke(dark);
      ctx.strokeStyle = '#f0f0f0';
      ctx.stroke(light);
      for (const [i, colour, w] of [[this.hover, '#444', 1.5], [this.selected, '#e07000', 3]]) {
        if (i < 0) continue;
        ctx.beginPath();
        ctx.arc(poses[3 * i], poses[3 * i + 1], rad + 4 * px, 0, 2 * Math.PI);
        ctx.lineWidth = w * px;
        ctx.strokeStyle = colour;
        ctx.stroke();
      }
    }

    drawLabels(ctx, poses) {
      if (!this.show.ids) return;
      ctx.fillStyle = '#111';
      ctx.font = '10px system-ui, sans-serif';
      const rad = this.robotRadiusPx();
      for (let i = 0; i < this.rec.N; ++i) {
        const [sx, sy] = this.worldToScreen(poses[3 * i], poses[3 * i + 1]);
        ctx.fillText(String(i), sx + rad + 1, sy - rad - 1);
      }
    }

    drawScaleBar(ctx, ch) {
      const s = this.view.scale;
      let metres = 1;
      for (const m of [0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100]) { if (m * s >= 60) { metres = m; break; } metres = m; }
      const x = 12;
      const y = ch - 14;
      ctx.strokeStyle = '#222';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.moveTo(x, y); ctx.lineTo(x + metres * s, y);
      ctx.moveTo(x, y - 4); ctx.lineTo(x, y + 4);
      ctx.moveTo(x + metres * s, y - 4); ctx.lineTo(x + metres * s, y + 4);
      ctx.stroke();
      ctx.fillStyle = '#222';
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillText(`${metres} m`, x + 4, y - 6);
    }

    // where the robots have been up to the current frame, 25 cm cells, on a log scale
    drawHeat(ctx) {
      const r = this.rec;
      const [aw, ah] = r.meta.scenario.arena_size;
      const cell = 0.25;
      if (!this.heat) {
        const nx = Math.max(1, Math.ceil(aw / cell));
        const ny = Math.max(1, Math.ceil(ah / cell));
        const canvas = document.createElement('canvas');
        canvas.width = nx;
        canvas.height = ny;
        this.heat = { nx, ny, counts: new Float64Array(nx * ny), upTo: -1, canvas, drawnAt: -2 };
      }
      const h = this.heat;
      const f = this.frameIndex();
      if (f < h.upTo) { h.counts.fill(0); h.upTo = -1; }
      for (let g = h.upTo + 1; g <= f; ++g) {
        for (let i = 0; i < r.N; ++i) {
          const cx = Math.floor((r.x[g * r.N + i] + aw / 2) / cell);
          const cy = Math.floor((r.y[g * r.N + i] + ah / 2) / cell);
          if (cx >= 0 && cy >= 0 && cx < h.nx && cy < h.ny) h.counts[cy * h.nx + cx] += 1;
        }
      }
      h.upTo = f;
      if (h.drawnAt !== f) {
        let max = 0;
        for (const c of h.counts) max = Math.max(max, c);
        const img = new ImageData(h.nx, h.ny);
        const lo = Math.log10(Math.max(1e-9, max / 100));
        for (let cy = 0; cy < h.ny; ++cy) {
          for (let cx = 0; cx < h.nx; ++cx) {
            const c = h.counts[cy * h.nx + cx];
            if (c <= 0) continue;
            const t = max > 0 ? (Math.log10(c) - lo) / 2 : 0;
            const [R, G, B] = heatRgb(t);
            const o = ((h.ny - 1 - cy) * h.nx + cx) * 4; // image rows run north to south
            img.data[o] = R; img.data[o + 1] = G; img.data[o + 2] = B; img.data[o + 3] = 215;
          }
        }
        h.canvas.getContext('2d').putImageData(img, 0, 0);
        h.drawnAt = f;
      }
      ctx.save();
      ctx.imageSmoothingEnabled = false;
      ctx.translate(-aw / 2, ah / 2);
      ctx.scale(aw / h.nx, -ah / h.ny);
      ctx.drawImage(h.canvas, 0, 0);
      ctx.restore();
    }

    drawTimeline() {
      const c = this.timeline;
      const ctx = c.getContext('2d');
      const w = c.width / this.dpr;
      const h = c.height / this.dpr;
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      ctx.clearRect(0, 0, w, h);
      const r = this.rec;
      const last = Math.max(1, r.ticks[r.F - 1]);
      const pad = 10;
      const xOf = (t) => pad + ((w - 2 * pad) * t) / last;
      const trackY = h - 16;
      ctx.fillStyle = '#e4e4de';
      ctx.fillRect(pad, trackY - 4, w - 2 * pad, 8);
      const tick = this.tick();
      ctx.fillStyle = '#f0a050';
      ctx.fillRect(pad, trackY - 4, xOf(tick) - pad, 8);
      // notes: small grey ticks; milestones: coloured lines with labels
      ctx.fillStyle = '#8a8a84';
      for (const n of r.meta.notes) ctx.fillRect(xOf(n.tick) - 0.5, trackY + 5, 1, 5);
      // milestone labels in three rows, each in the first row where it overlaps no other, to the
      // right of its line (or to the left where the right edge is near)
      ctx.font = '10px system-ui, sans-serif';
      const rowEnds = [-Infinity, -Infinity, -Infinity];
      for (const m of r.meta.milestones) {
        const x = xOf(m.tick);
        const label = m.label.replace(/ \(.*\)$/, '');
        const tw = ctx.measureText(label).width;
        const left = x + 3 + tw > w - 2 ? x - 3 - tw : x + 3;
        let row = rowEnds.findIndex((end) => end < left - 4);
        if (row < 0) row = rowEnds.indexOf(Math.min(...rowEnds));
        rowEnds[row] = left + tw;
        ctx.fillStyle = MILESTONE_COLOURS[m.name] || '#444';
        ctx.fillRect(x - 1, 2 + 11 * row, 2, trackY + 2 - 11 * row);
        ctx.fillText(label, left, 10 + 11 * row);
      }
      const x = xOf(tick);
      ctx.fillStyle = '#1d1d1b';
      ctx.beginPath();
      ctx.moveTo(x - 6, trackY - 10); ctx.lineTo(x + 6, trackY - 10); ctx.lineTo(x, trackY - 2);
      ctx.fill();
      ctx.fillRect(x - 1, trackY - 4, 2, 12);
      this.timelineX = { pad, w, last };
    }

    // ------------------------------------------------------------ panels
    buildLegend() {
      const r = this.rec;
      // which states showed which colour in this run (sampled over every frame)
      const seen = new Map();
      for (let k = 0; k < r.F * r.N; ++k) {
        const key = r.led[k] * 256 + r.state[k];
        seen.set(key, (seen.get(key) || 0) + 1);
      }
      const byLed = new Map();
      for (const key of seen.keys()) {
        const led = Math.floor(key / 256);
        if (!byLed.has(led)) byLed.set(led, new Set());
        byLed.get(led).add(r.stateNames.get(key % 256) ?? `state ${key % 256}`);
      }
      const rows = [...byLed.keys()].sort((a, b) => a - b).map((led) => el('div', {},
        el('span', { class: 'swp-swatch', style: `background:${r.ledCss[led]}` }),
        `${r.meta.leds[led].name} `,
        el('span', { class: 'swp-states', text: [...byLed.get(led)].sort().join(', ') })));
      const paths = r.meta.paths.map((p) => el('div', {},
        el('span', { class: 'swp-swatch', style: `background:${PATH_COLOURS[p.name] || '#444'};border-radius:0` }), p.label));
      this.legendPanel.replaceChildren(el('h2', { text: 'LEDs in this run' }), ...rows,
        el('h2', { text: 'Paths', style: 'margin-top:6px' }), ...(paths.length ? paths : [el('div', { class: 'swp-muted', text: 'none formed' })]));
    }

    updatePanels(full) {
      if (!this.rec) return;
      const r = this.rec;
      const m = r.meta;
      const tick = this.tick();
      const f = this.frameIndex();
      this.clock.textContent = `tick ${tick} / ${r.ticks[r.F - 1]} (${(tick / m.ticks_per_second).toFixed(1)} s) · frame ${f + 1}/${r.F}`;
      this.playButton.textContent = this.playing ? 'pause' : 'play';
      // the events list: milestones and the allocation's notes, past ones grey
      if (full || !this.eventsBuilt || this.eventsTick !== Math.floor(tick / 50)) {
        this.eventsTick = Math.floor(tick / 50);
        const events = [
          ...m.milestones.map((x) => ({ tick: x.tick, text: x.label, robot: -1 })),
          ...m.notes.map((x) => ({ tick: x.tick, text: `robot ${x.robot}: ${x.text}`, robot: x.robot })),
        ].sort((a, b) => a.tick - b.tick);
        const items = events.slice(0, 400).map((e) => el('div', {
          class: e.tick <= tick ? 'swp-past' : '',
          onclick: () => { this.playing = false; this.seekTick(e.tick); if (e.robot >= 0) this.select(e.robot); },
        }, `${e.tick}: ${e.text}`));
        this.eventsPanel.replaceChildren(el('h2', { text: `Events (${events.length})` }),
          ...(items.length ? items : [el('div', { class: 'swp-muted', text: 'no milestones reached' })]));
        this.eventsBuilt = true;
      }
      this.updateRobotPanel(tick, f);
    }

    updateRobotPanel(tick, f) {
      const r = this.rec;
      const i = this.selected;
      if (i < 0) {
        this.robotPanel.replaceChildren(el('h2', { text: 'Robot' }),
          el('div', { class: 'swp-muted', text: 'Click a robot (hover for its id and state).' }));
        return;
      }
      const k = f * r.N + i;
      const [x, y, hd] = this.pose(i);
      const link = (id) => (id >= 0 && id < r.N
        ? el('span', { class: 'swp-link', text: `robot ${id}`, onclick: () => this.select(id) })
        : emitterName(id));
      const row = (name, ...value) => el('tr', {}, el('td', { text: name }), el('td', {}, ...value));
      const led = r.led[k];
      const c = r.change;
      const recent = [];
      for (let e = r.E - 1; e >= 0 && recent.length < 8; --e) {
        if (c.robot[e] !== i || c.tick[e] > tick) continue;
        const rowName = (rows, n) => (n > 0 && rows[n - 1] ? ` ${rows[n - 1].row}${rows[n - 1].label ? ` (${rows[n - 1].label})` : ''}` : '');
        recent.push(el('li', {}, `${c.tick[e]}: ${r.stateNames.get(c.from[e]) ?? c.from[e]} → ${r.stateNames.get(c.to[e]) ?? c.to[e]}` +
          `${rowName(r.meta.pf_rows, c.pfRow[e])}${rowName(r.meta.ta_rows, c.taRow[e])}`));
      }
      this.robotPanel.replaceChildren(el('h2', { class: 'swp-robot-id', text: `robot ${i}` }),
        el('table', {},
          row('state', r.stateNames.get(r.state[k]) ?? `code ${r.state[k]}`),
          row('LED', el('span', { class: 'swp-swatch', style: `background:${r.ledCss[led]}` }), r.meta.leds[led].name),
          row('position', `${x.toFixed(2)}, ${y.toFixed(2)} m`),
          row('heading', `${((hd * 180) / Math.PI % 360).toFixed(0)}°`),
          row('parent', link(r.parent[k])),
          row('child', link(r.child[k]))),
        el('div', { class: 'swp-muted', text: recent.length ? 'recent transitions (tick: from → to, row)' : 'no transitions yet' }),
        el('ol', { class: 'swp-transitions', reversed: '' }, ...recent));
    }

    select(i) {
      this.selected = i;
      this.dirty = true;
      this.updatePanels(false);
    }

    // ------------------------------------------------------------ input
    bindInput() {
      const stage = this.stage;
      let drag = null;
      const local = (e) => {
        const b = this.canvas.getBoundingClientRect();
        return [e.clientX - b.left, e.clientY - b.top];
      };
      stage.addEventListener('pointerdown', (e) => {
        const [sx, sy] = local(e);
        drag = { sx, sy, cx: this.view.cx, cy: this.view.cy, moved: false };
        stage.setPointerCapture(e.pointerId);
      });
      stage.addEventListener('pointermove', (e) => {
        if (!this.rec) return;
        const [sx, sy] = local(e);
        if (drag) {
          const dx = sx - drag.sx;
          const dy = sy - drag.sy;
          if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
          if (drag.moved) {
            stage.classList.add('swp-dragging');
            this.view.cx = drag.cx - dx / this.view.scale;
            this.view.cy = drag.cy + dy / this.view.scale;
            this.dirty = true;
            return;
          }
        }
        const i = this.robotAt(sx, sy);
        if (i !== this.hover) { this.hover = i; this.dirty = true; }
        if (i >= 0) {
          const k = this.frameIndex() * this.rec.N + i;
          this.tip.textContent = `robot ${i} · ${this.rec.stateNames.get(this.rec.state[k]) ?? this.rec.state[k]} · ${this.rec.meta.leds[this.rec.led[k]].name}`;
          this.tip.style.left = `${sx + 12}px`;
          this.tip.style.top = `${sy + 12}px`;
          this.tip.hidden = false;
        } else {
          this.tip.hidden = true;
        }
      });
      stage.addEventListener('pointerup', (e) => {
        stage.classList.remove('swp-dragging');
        if (drag && !drag.moved) {
          const [sx, sy] = local(e);
          this.select(this.robotAt(sx, sy));
        }
        drag = null;
      });
      stage.addEventListener('pointerleave', () => { this.tip.hidden = true; if (this.hover >= 0) { this.hover = -1; this.dirty = true; } });
      stage.addEventListener('wheel', (e) => {
        e.preventDefault();
        const [sx, sy] = local(e);
        this.zoomAt(Math.exp(-e.deltaY * 0.0015), sx, sy);
      }, { passive: false });
      stage.addEventListener('dblclick', () => this.fit());

      // the timeline: press and drag to scrub
      let scrubbing = false;
      const scrub = (e) => {
        if (!this.rec || !this.timelineX) return;
        const b = this.timeline.getBoundingClientRect();
        const { pad, w, last } = this.timelineX;
        const t = ((e.clientX - b.left - pad) / (w - 2 * pad)) * last;
        this.seekTick(Math.max(0, Math.min(last, t)));
      };
      this.timeline.addEventListener('pointerdown', (e) => {
        scrubbing = true;
        this.playing = false;
        this.timeline.setPointerCapture(e.pointerId);
        scrub(e);
      });
      this.timeline.addEventListener('pointermove', (e) => { if (scrubbing) scrub(e); });
      this.timeline.addEventListener('pointerup', () => { scrubbing = false; });

      document.addEventListener('keydown', (e) => this.onKey(e));
      new ResizeObserver(() => { this.dirty = true; }).observe(this.stage);
    }

    onKey(e) {
      if (!this.rec || e.ctrlKey || e.metaKey || e.altKey) return;
      if (e.target instanceof HTMLElement && /^(INPUT|SELECT|TEXTAREA)$/.test(e.target.tagName) && e.target.type !== 'checkbox') return;
      if (this.root.offsetParent === null && getComputedStyle(this.root).position !== 'fixed') return; // hidden
      const speedIndex = SPEEDS.indexOf(this.speed);
      const flip = (key) => { this.show[key] = !this.show[key]; this[`${key}Box`].checked = this.show[key]; this.dirty = true; };
      const cw = this.canvas.width / this.dpr;
      const ch = this.canvas.height / this.dpr;
      const milestone = (dir) => {
        const tick = this.tick();
        const ticks = this.rec.meta.milestones.map((m) => m.tick).sort((a, b) => a - b);
        const t = dir > 0 ? ticks.find((x) => x > tick) : ticks.reverse().find((x) => x < tick);
        if (t !== undefined) { this.playing = false; this.seekTick(t); }
      };
      const actions = {
        ' ': () => this.toggle(),
        ArrowRight: () => this.step(e.shiftKey ? 10 : 1),
        ArrowLeft: () => this.step(e.shiftKey ? -10 : -1),
        Home: () => this.seekFrame(0),
        End: () => this.seekFrame(this.rec.F - 1),
        ']': () => { this.speed = SPEEDS[Math.min(SPEEDS.length - 1, speedIndex + 1)]; this.speedSelect.value = String(this.speed); },
        '[': () => { this.speed = SPEEDS[Math.max(0, speedIndex - 1)]; this.speedSelect.value = String(this.speed); },
        '+': () => this.zoomAt(1.25, cw / 2, ch / 2),
        '=': () => this.zoomAt(1.25, cw / 2, ch / 2),
        '-': () => this.zoomAt(0.8, cw / 2, ch / 2),
        f: () => this.fit(),
        l: () => flip('links'),
        p: () => flip('paths'),
        h: () => flip('heat'),
        i: () => flip('ids'),
        n: () => milestone(1),
        N: () => milestone(-1),
        Escape: () => this.select(-1),
      };
      const act = actions[e.key];
      if (!act) return;
      e.preventDefault();
      act();
      this.updatePanels(false);
    }
  }

  // ---------------------------------------------------------------- start
  async function main() {
    const sources = [...document.querySelectorAll('script[type="application/x-swrec"]')].map((s) => ({
      title: s.dataset.title || 'recording',
      bytes: fromBase64(s.textContent),
    }));
    const viewers = [];
    for (const root of document.querySelectorAll('.swp-viewer')) {
      const v = new Viewer(root, sources);
      viewers.push(v);
      if (sources.length === 0) {
        root.replaceChildren(el('div', { class: 'swp-error', text: 'This page holds no recording.' }));
        continue;
      }
      await v.load(0);
      v.start();
    }
    window.swarmpathViewers = viewers;
    document.documentElement.dataset.swpReady = 'true';
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', () => { main(); });
  else main();
})();
