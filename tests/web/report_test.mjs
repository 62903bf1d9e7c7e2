// The report in a real browser: a tiny tuning run (CMA-ES, two parameters, short_chain), its
// evaluate.json, `swarmpath report`, then the page from disk in headless Chromium: no console errors;
// the progress chart, one chart per tuned parameter and the comparison table with intervals are
// there; the embedded replay shows the robots of the reported genome's run at its end in their
// recorded colours (the same run recorded again by `simulate --record`, read by `view --frame-json`);
// the replay picker switches arenas. A full-page screenshot goes to --out.
//   node report_test.mjs --swarmpath build/release/swarmpath --source . --out build/release/web-tests
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { Browser, Checks, findChromium, options, probeRobots, SKIP, swarmpath, wrongColours } from './browser.mjs';

const o = options(process.argv.slice(2));
const chromium = findChromium();
if (!chromium) {
  console.log('SKIPPED: chromium is not installed (scripts/install-deps.sh installs it), so the report was not tested in a browser');
  process.exit(SKIP);
}
const out = join(o.out, 'report');
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const scenario = join(o.source, 'tests/data/short_chain.toml');
const config = join(out, 'tiny.toml');
writeFileSync(config, `name = "tiny"
mode = "pf"
seed = 3
[tune]
T_explore0 = { lo = 200, hi = 3000, step = 50 }
w_rw = {}
[evaluation]
scenarios = ["${scenario}", "${join(o.source, 'configs/scenarios/paper/env1.toml')}"]
robots = [20]
seeds = 1
max_ticks = 6000
[optimizer]
name = "cmaes"
population = 4
[budget]
generations = 3
[reevaluate]
top_k = 2
seeds = 1
`);
const dir = join(out, 'tiny');
swarmpath(o.swarmpath, ['evolve', '--config', config, '--out', dir, '--threads', '2']);
swarmpath(o.swarmpath, ['evaluate', '--params', join(dir, 'best.toml'), '--against', join(o.source, 'genomes/default.toml'),
  '--scenarios', scenario, '--robots', '20', '--seeds', '3', '--seed-base', '1000', '--ticks', '6000', '--threads', '2',
  '--json', join(dir, 'evaluate.json')]);
const page = join(out, 'report.html');
swarmpath(o.swarmpath, ['report', dir, '--out', page, '--config', config, '--threads', '2']);

const t = new Checks('report_test');
const b = await Browser.launch(chromium);
try {
  await b.goto(pathToFileURL(page).href);
  await b.waitFor("document.documentElement.dataset.swpReady === 'true'");
  const figures = await b.eval(`({ progress: document.querySelectorAll('#progress svg').length,
    parameters: document.querySelectorAll('#parameters svg').length,
    rows: [...document.querySelectorAll('#comparison tbody tr')].map((r) => r.textContent),
    trajectory: document.querySelectorAll('#parameters svg polyline').length })`);
  t.ok(figures.progress === 1, 'the fitness chart is in the page');
  t.ok(figures.parameters === 2 && figures.trajectory >= 4, `one chart per tuned parameter (${figures.parameters}), with the lines drawn`);
  t.ok(figures.rows.length === 2 && figures.rows[1].startsWith('overall') && figures.rows[1].includes('±'),
    `the comparison table has its rows and intervals: ${figures.rows.join(' | ').slice(0, 160)}`);

  const V = 'window.swarmpathViewers[0]';
  const titles = await b.eval(`[...document.querySelectorAll('.swp-picker option')].map((x) => x.textContent)`);
  t.ok(titles.length === 2, `one replay per training arena: ${titles.join('; ')}`);
  await b.eval(`document.getElementById('replays').scrollIntoView(), true`);
  await b.eval(`${V}.render(), true`);
  const meta = await b.eval(`({ seed: ${V}.rec.meta.seed, scenario: ${V}.rec.meta.scenario.name, robots: ${V}.rec.N })`);
  t.ok(meta.scenario === 'short_chain' && meta.robots === 20, `the first replay is short_chain with 20 robots (seed ${meta.seed})`);

  // the same run recorded again: the replay's robots at its last tick are where the C++ reader puts them
  const again = join(out, 'again.swrec');
  swarmpath(o.swarmpath, ['simulate', '--scenario', scenario, '--robots', '20', '--ticks', '6000', '--mode', 'pf',
    '--params', join(dir, 'best.toml'), '--seed', String(meta.seed), '--record', again]);
  await b.press('End');
  const last = await b.eval(`${V}.tick()`);
  const frame = JSON.parse(swarmpath(o.swarmpath, ['view', again, '--frame-json', String(last)]));
  const hash = await b.eval(`${V}.rec.meta.result.state_hash`);
  const againHash = JSON.parse(swarmpath(o.swarmpath, ['simulate', '--scenario', scenario, '--robots', '20', '--ticks', '6000',
    '--mode', 'pf', '--params', join(dir, 'best.toml'), '--seed', String(meta.seed), '--json'])).state_hash;
  t.ok(hash === againHash, `the replay is the run simulate gives (state hash ${againHash})`);
  for (let i = 0; i < 4; ++i) await b.press('+');
  await b.eval(`${V}.render(), true`);
  const probes = await probeRobots(b, V, frame);
  const wrong = wrongColours(probes);
  // how many robots stand apart at the run's last tick is the run's, not the viewer's: three or more
  t.ok(probes.length >= 3 && wrong.length === 0,
    `${probes.length} isolated robots of the replay drawn in their colours at tick ${last}${wrong.length ? `; wrong: ${JSON.stringify(wrong)}` : ''}`);

  // the picker switches to the other arena
  await b.eval(`(() => { const s = document.querySelector('.swp-picker'); s.value = '1'; s.dispatchEvent(new Event('change')); })()`);
  await b.waitFor(`${V}.ready && ${V}.rec.meta.scenario.name === 'env1'`);
  t.ok(true, 'the picker loads the env1 replay');
  await b.eval(`window.scrollTo(0, 0), true`);
  await b.screenshot(join(out, 'report.png'), { fullPage: true });
  t.ok(b.errors.length === 0, `no console errors${b.errors.length ? `: ${b.errors.join(' | ')}` : ''}`);
} catch (e) {
  t.ok(false, `the test ran to the end: ${e.stack}`);
} finally {
  await b.close();
}
console.log(`screenshot in ${out}`);
process.exit(t.finish());
