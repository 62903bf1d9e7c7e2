// How long the viewer takes to draw a frame: a recording played in headless Chromium, render() timed
// with the drawing flushed (a pixel read back) over many interpolated frames (links and paths, with
// and without the heat map), and the frames drawn in two seconds of real playback. A measurement,
// not a test: it prints and asserts nothing.
//   node tests/web/viewer_speed.mjs --page run.html [--frames 240]   (scripts/viewer_speed.sh makes the page)
import { pathToFileURL } from 'node:url';

import { Browser, findChromium, options, SKIP, sleep } from './browser.mjs';

const o = options(process.argv.slice(2));
const chromium = findChromium();
if (!chromium) {
  console.log('SKIPPED: chromium is not installed');
  process.exit(SKIP);
}
const frames = Number(o.frames ?? 240);
const b = await Browser.launch(chromium, { width: 1600, height: 1000 });
try {
  await b.goto(pathToFileURL(o.page).href);
  await b.waitFor("document.documentElement.dataset.swpReady === 'true'", 60000);
  const V = 'window.swarmpathViewers[0]';
  const robots = await b.eval(`${V}.rec.N`);
  const time = async (heat) => b.eval(`(() => {
    const v = ${V}; v.playing = false; v.show.heat = ${heat}; v.heat = null; v.pos = 0; v.render();
    const ms = [];
    for (let k = 0; k < ${frames}; ++k) {
      v.pos = Math.min(v.rec.F - 1, k * 0.37);
      const t0 = performance.now(); v.render(); v.canvas.getContext('2d').getImageData(0, 0, 1, 1); ms.push(performance.now() - t0);
    }
    ms.sort((a, b) => a - b);
    return { median: ms[ms.length >> 1], p90: ms[Math.floor(ms.length * 0.9)], max: ms[ms.length - 1] };
  })()`);
  const plain = await time(false);
  const heat = await time(true);
  await b.eval(`(() => { const v = ${V}; v.show.heat = false; v.pos = 0; v.count = 0; const draw = v.render.bind(v);
    v.render = () => { v.count += 1; draw(); }; v.speed = 20; v.toggle(); return true; })()`);
  await sleep(2000);
  const played = await b.eval(`(() => { const v = ${V}; v.toggle(); return v.count; })()`);
  const f = (x) => x.toFixed(2);
  console.log(`${robots} robots, canvas ${await b.eval(`${V}.canvas.width + 'x' + ${V}.canvas.height`)}:`);
  console.log(`  render(): median ${f(plain.median)} ms, p90 ${f(plain.p90)} ms, max ${f(plain.max)} ms (links, paths)`);
  console.log(`  with the heat map: median ${f(heat.median)} ms, p90 ${f(heat.p90)} ms, max ${f(heat.max)} ms`);
  console.log(`  playing for 2 s: ${played} frames drawn (${f(played / 2)} a second)`);
} finally {
  await b.close();
}
