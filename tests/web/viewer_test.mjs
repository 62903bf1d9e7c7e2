// The viewer in a real browser: records a task-allocation run in env4 (60 robots), writes its page
// with `swarmpath view`, opens it from disk in headless Chromium and checks that it loads without
// console errors, that the canvas shows every isolated robot in its recorded LED colour at a
// known tick (positions and colours from `view --frame-json`, a second reader of the file), that
// the timeline seeks, that a click on a robot shows its id and state, that hovering names it,
// that play and the heat-map key work. Screenshots of each step go to --out.
//   node viewer_test.mjs --swarmpath build/release/swarmpath --source . --out build/release/web-tests
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { Browser, Checks, findChromium, options, probeRobots, SKIP, sleep, swarmpath, wrongColours } from './browser.mjs';

const o = options(process.argv.slice(2));
const chromium = findChromium();
if (!chromium) {
  console.log('SKIPPED: chromium is not installed (scripts/install-deps.sh installs it), so the viewer was not tested in a browser');
  process.exit(SKIP);
}
const out = join(o.out, 'viewer');
mkdirSync(out, { recursive: true });
const recording = join(out, 'env4-ta.swrec');
const page = join(out, 'env4-ta.html');
swarmpath(o.swarmpath, ['simulate', '--scenario', join(o.source, 'configs/scenarios/paper/env4.toml'), '--robots', '60',
  '--mode', 'ta', '--params', join(o.source, 'genomes/default.toml'), '--seed', '3', '--record', recording]);
swarmpath(o.swarmpath, ['view', recording, '--out', page]);

const t = new Checks('viewer_test');
const b = await Browser.launch(chromium);
try {
  await b.goto(pathToFileURL(page).href);
  await b.waitFor("document.documentElement.dataset.swpReady === 'true'");
  const V = 'window.swarmpathViewers[0]';
  await b.screenshot(join(out, '1-loaded.png'));
  const meta = await b.eval(`({ frames: ${V}.rec.F, robots: ${V}.rec.N, last: ${V}.rec.ticks[${V}.rec.F - 1], every: ${V}.rec.meta.every, milestones: ${V}.rec.meta.milestones })`);
  t.ok(meta.robots === 60 && meta.frames > 10, `the page decoded the recording: ${meta.robots} robots, ${meta.frames} frames`);
  const form = meta.milestones.find((m) => m.name === 'form');
  t.ok(form !== undefined, 'the timeline carries the path-complete milestone');

  // seek with the timeline: a click at a tick's place (T_chain, between two frames), then one frame
  // on and back (a whole frame)
  const chain = meta.milestones.find((m) => m.name === 'chain');
  const target = chain ? chain.tick : Math.floor(meta.last / 2);
  const tl = await b.eval(`(() => { const r = ${V}.timeline.getBoundingClientRect(); const x = ${V}.timelineX; return { left: r.left, top: r.top, height: r.height, pad: x.pad, w: x.w, last: x.last }; })()`);
  await b.click(tl.left + tl.pad + ((tl.w - 2 * tl.pad) * target) / tl.last, tl.top + tl.height - 16);
  const seeked = await b.eval(`${V}.tick()`);
  const perPixel = tl.last / (tl.w - 2 * tl.pad);
  t.ok(Math.abs(seeked - target) <= perPixel + 1, `a click on the timeline seeks to tick ${seeked} (aimed at ${target}, ${perPixel.toFixed(1)} ticks a pixel)`);
  await b.press('ArrowRight');
  await b.press('ArrowLeft');
  const tick = await b.eval(`${V}.tick()`);
  t.ok(tick % meta.every === 0 || tick === meta.last, `arrow keys step whole frames (tick ${tick})`);
  const clock = await b.eval(`${V}.clock.textContent`);
  t.ok(clock.startsWith(`tick ${tick} `), `the clock shows it: "${clock}"`);

  // zoom in (three '+' presses) so that robots are several pixels wide
  const scale0 = await b.eval(`${V}.view.scale`);
  for (let i = 0; i < 3; ++i) await b.press('+');
  const scale = await b.eval(`${V}.view.scale`);
  t.ok(scale > 1.9 * scale0, `'+' zooms in (${scale0.toFixed(1)} -> ${scale.toFixed(1)} px/m)`);
  await b.hover(1, 1);
  await b.eval(`${V}.render(), true`);
  await b.screenshot(join(out, '2-seeked.png'));

  // the canvas against the recording as the C++ reader sees it
  const frame = JSON.parse(swarmpath(o.swarmpath, ['view', recording, '--frame-json', String(tick)]));
  t.ok(frame.tick === tick, `view --frame-json gives the frame at tick ${tick}`);
  const probes = await probeRobots(b, V, frame);
  const wrong = wrongColours(probes);
  const colours = new Set(probes.map((p) => p.led));
  t.ok(probes.length >= 8 && wrong.length === 0,
    `${probes.length} isolated robots drawn in their recorded LED colours at tick ${tick}` +
    (wrong.length ? `; wrong: ${JSON.stringify(wrong.slice(0, 5))}` : ''));
  t.ok(colours.size >= 2, `... of ${colours.size} colours (${[...colours].join(', ')})`);

  // a click on an isolated robot shows its id and state in the side panel
  const pickId = (probes.find((p) => p.led === 'red') ?? probes[0]).id;
  const pick = frame.robots[pickId];
  const at = await b.eval(`(() => { const [x, y] = ${V}.worldToScreen(${pick.x}, ${pick.y}); const r = ${V}.canvas.getBoundingClientRect(); return [r.left + x, r.top + y]; })()`);
  await b.hover(at[0], at[1]);
  const tip = await b.eval(`${V}.tip.hidden ? '' : ${V}.tip.textContent`);
  t.ok(tip.startsWith(`robot ${pick.id} `), `hovering robot ${pick.id} names it: "${tip}"`);
  await b.click(at[0], at[1]);
  const shown = await b.eval(`document.querySelector('.swp-robot-id')?.textContent`);
  t.ok(shown === `robot ${pick.id}`, `a click on robot ${pick.id} shows "${shown}"`);
  const panel = await b.eval(`document.querySelector('.swp-robot').textContent`);
  t.ok(panel.includes(pick.state), `the panel gives its state, ${pick.state}`);
  await b.screenshot(join(out, '3-robot.png'));

  // play advances the clock; space pauses
  await b.press('Home');
  await b.press(' ');
  await sleep(700);
  await b.press(' ');
  const played = await b.eval(`${V}.tick()`);
  t.ok(played > 0 && !(await b.eval(`${V}.playing`)), `space plays (to tick ${played}) and pauses`);

  // the heat map key draws where the robots have been
  await b.press('End');
  const before = await b.eval(`${V}.render(), Array.from(${V}.canvas.getContext('2d').getImageData(0, 0, ${V}.canvas.width, ${V}.canvas.height).data.filter((_, i) => i % 4 === 0)).join(',')`);
  await b.press('h');
  const after = await b.eval(`${V}.render(), Array.from(${V}.canvas.getContext('2d').getImageData(0, 0, ${V}.canvas.width, ${V}.canvas.height).data.filter((_, i) => i % 4 === 0)).join(',')`);
  const a = before.split(',');
  const changed = after.split(',').filter((v, i) => v !== a[i]).length;
  t.ok(changed > 500, `'h' draws the heat map (${changed} pixels changed)`);
  await b.screenshot(join(out, '4-heat.png'));
  t.ok(b.errors.length === 0, `no console errors${b.errors.length ? `: ${b.errors.join(' | ')}` : ''}`);
} catch (e) {
  t.ok(false, `the test ran to the end: ${e.stack}`);
} finally {
  await b.close();
}
console.log(`screenshots in ${out}`);
process.exit(t.finish());
