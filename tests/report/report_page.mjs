// The report page in a real browser (Debian's chromium, headless, software WebGL), driven by
// puppeteer-core from web/node_modules (scripts/setup.sh installs both):
//   - the page loads without console errors or uncaught exceptions;
//   - the 3-D canvas is not blank: a screenshot of it, decoded again by the browser, has most
//     pixels off the background and the colour of circuit 0's bores among them;
//   - clicking another point of the Pareto front loads that layout: the label and the bore
//     count in the DOM change to the clicked member's; on overlapping points, repeated clicks
//     step through every member of the stack and a list names them;
//   - the drilling-map panel is there, drawn only once asked (not at load), and clicking a bore of
//     the table draws that bore's map: its canvas shows free and blocked cells in the shares the
//     data gives;
//   - the anytime panel (best objective and hypervolume against evaluations and wall time) is
//     empty at load and draws its four curves, one vertex per stored generation, once opened.
//   - the coolant table lists each circuit; with --coolant (a spec with a flow and a temperature
//     objective) the bores can be drawn by their coolant's temperature, with its scale;
//   - with --temperature, the hottest point is marked where the data puts it and "cut through the
//     hottest point" sets the section plane there.
// Usage: node report_page.mjs REPORT.html [--coolant] [--temperature] [--screenshot PAGE.png] [--width W --height H]
// Exit 0: passed; 1: failed; 77: skipped (no chromium on this machine).
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser } from '../support/browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : fallback; };
const reportPath = path.resolve(args[0] ?? '');
const screenshot = option('--screenshot', null);
const width = Number(option('--width', 1366)), height = Number(option('--height', 768));
const expectCoolant = args.includes('--coolant');  // the report's spec has a flow and a temperature objective
const expectBaffles = args.includes('--baffles');  // the shown layout holds baffles or bubblers
const expectTemperature = args.includes('--temperature');  // the report has the shown layout's cavity temperature

if (!fs.existsSync(reportPath)) {
  console.error(`FAILED: no report at ${reportPath}`);
  process.exit(1);
}

const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

const finish = async () => {
  await browser.close();
  console.log(failures.length ? `${failures.length} check(s) failed` : 'all checks passed');
  process.exit(failures.length ? 1 : 0);
};

const browser = await launchBrowser('the report page');
try {
  const page = await browser.newPage();
  await page.setViewport({ width, height });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url().slice(0, 80)}`));
  const external = [];
  page.on('request', (r) => { if (!/^(file|data|blob):/.test(r.url())) external.push(r.url()); });

  const started = Date.now();
  await page.goto(`file://${reportPath}`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.body.dataset.ready === '1', { timeout: 30000 });
  const seconds = (Date.now() - started) / 1000;
  const timing = await page.evaluate(() => ({
    ready: performance.getEntriesByName('mtcs-drawn')[0].startTime,
    start: performance.getEntriesByName('mtcs-start')[0].startTime,
    built: performance.getEntriesByName('mtcs-built')[0].startTime,
    parsed: performance.getEntriesByName('mtcs-data')[0]?.startTime,
    scene: performance.getEntriesByName('mtcs-scene')[0]?.startTime,
    frames: window.mtcsReport.frames(),
    programs: window.mtcsReport.programs ? window.mtcsReport.programs() : null,
  }));
  console.log(`loaded and drawn in ${seconds.toFixed(2)} s (page clock ${(timing.ready / 1000).toFixed(2)} s: ` +
    `scripts parsed at ${(timing.start / 1000).toFixed(2)} s, page built at ${(timing.built / 1000).toFixed(2)} s, ` +
    `first frame ${((timing.ready - timing.built) / 1000).toFixed(2)} s; ${timing.frames} frames` +
    (timing.programs !== null ? `, ${timing.programs} shader programs)` : ')'));
  if (timing.scene !== undefined)
    console.log(`page clock parts: data parsed ${((timing.parsed - timing.start) / 1000).toFixed(3)} s, ` +
      `static scene ${((timing.scene - timing.parsed) / 1000).toFixed(3)} s, layout, front and charts ${((timing.built - timing.scene) / 1000).toFixed(3)} s`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
  check(external.length === 0, `no network requests${external.length ? ': ' + external.join(' ') : ''}`);

  // The coolant circuits: a row per circuit of the shown member (none without a flow in the spec);
  // the bores by coolant temperature only where the solve's heat is known, then one per bore.
  const coolantOf = () => page.evaluate(() => {
    const r = window.mtcsReport;
    const m = r.data.members.find((x) => x.rank === Number(document.body.dataset.shown));
    const box = document.getElementById('layer-coolant');
    return { rows: document.querySelectorAll('#coolant-table tbody tr').length, circuits: m.coolant ? m.coolant.circuits.length : 0,
      bores: m.layout.bores.length, heat: !!(m.coolant && m.coolant.bores.length), disabled: box.disabled, drawn: r.coolantBores(),
      caption: document.getElementById('coolant-caption').textContent, legend: document.getElementById('legend').textContent };
  });
  if (expectBaffles) {
    // Each blind bore: its insert drawn (the blade or the tube) and named in the bores' table.
    const blind = await page.evaluate(() => {
      const r = window.mtcsReport;
      const m = r.data.members.find((x) => x.rank === Number(document.body.dataset.shown));
      const cells = [...document.querySelectorAll('#bores-table tbody tr')].map((tr) => tr.lastChild.textContent);
      return { blind: m.layout.bores.filter((b) => b.insert).length, inserts: r.inserts(),
        named: cells.filter((t) => /^blind, (baffle|bubbler)/.test(t)).length,
        tube: cells.some((t) => /bubbler \(tube ⌀7\/5\.5 mm\)/.test(t)) };
    });
    console.log(`blind bores ${blind.blind}, inserts drawn ${blind.inserts}, named ${blind.named}`);
    check(blind.blind === 2, 'the shown layout keeps its bubbler and its baffle');
    check(blind.inserts === blind.blind && blind.named === blind.blind, 'every blind bore has its insert drawn and named');
    check(blind.tube, "the bubbler's tube is given in mm");
    check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
    await finish();
  }
  // The hottest point: marked where the data puts it, and one click cuts the view through it.
  const hottest = await page.evaluate(() => {
    const t = window.mtcsReport.data.temperature;
    if (!t) return null;
    document.getElementById('section-hottest').click();
    return { mark: window.mtcsReport.hottestMark(), at: t.hottest, axis: document.getElementById('section-axis').value,
      value: document.getElementById('section-value').textContent };
  });
  if (expectTemperature) check(hottest !== null, 'the report has a cavity temperature (--temperature)');
  if (hottest) {
    check(hottest.mark && hottest.mark.every((c, k) => Math.abs(c - hottest.at[k]) < 1e-6), 'the hottest point is marked where the solve puts it');
    const k = Number(hottest.axis);
    const shown = Number(hottest.value.replace(/^[xyz] = /, '').replace(/ mm$/, ''));
    // The slider moves in thousandths of the block: within one step of the point.
    check(hottest.axis !== '' && Math.abs(shown - hottest.at[k]) < 2,
      `"cut through the hottest point" sets the section there (${hottest.value}, hottest at ${hottest.at[k]})`);
    await page.evaluate(() => { document.getElementById('section-axis').value = ''; document.getElementById('section-axis').dispatchEvent(new Event('input')); });
  }
  const coolant = await coolantOf();
  console.log(`coolant ${coolant.caption}: ${coolant.rows} rows, ${coolant.circuits} circuits, heat ${coolant.heat}, layer ${coolant.disabled ? 'off' : 'on'}`);
  check(coolant.rows === coolant.circuits, 'the coolant table has a row per circuit of the shown layout');
  check(coolant.disabled === !coolant.heat, 'bores by coolant temperature offered exactly when the heat per bore is known');
  if (expectCoolant) {
    check(coolant.circuits > 0 && coolant.heat, 'a spec with a flow and a temperature objective: circuits with their heat');
    await page.click('#layer-coolant');
    const on = await coolantOf();
    check(on.drawn === on.bores && /coolant [\d.]+.*°C/.test(on.legend), `the coolant layer draws every bore (${on.drawn}) and its scale in the legend`);
    check(errors.length === 0, `no console errors after drawing the coolant${errors.length ? ': ' + errors.join(' | ') : ''}`);
    await finish();  // the rest needs the physics plate's front and drilling maps
  }

  // The canvas as a screenshot, decoded by the browser itself (no PNG library needed here).
  // The overlays on the view (title, legend, help) are hidden for it: only what WebGL drew counts
  // (a canvas that drew nothing shows the viewer's background, the scene's colour).
  const pixels = async () => {
    const canvas = await page.$('#view3d');
    await page.evaluate(() => { for (const id of ['view-title', 'legend', 'help']) document.getElementById(id).style.visibility = 'hidden'; });
    const png = await canvas.screenshot({ encoding: 'base64' });
    await page.evaluate(() => { for (const id of ['view-title', 'legend', 'help']) document.getElementById(id).style.visibility = ''; });
    return page.evaluate(async (b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      const bg = [0xee, 0xf1, 0xf6];  // the scene's background (report.js)
      let off = 0, circuit0 = 0;
      const colours = new Set();
      for (let i = 0; i < d.length; i += 4) {
        const dist = Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]);
        if (dist > 24) off += 1;
        // Circuit 0's bores are #1f77b4, shaded: blue well above red and green.
        if (d[i + 2] > d[i] + 60 && d[i + 2] > d[i + 1] + 20) circuit0 += 1;
        colours.add((d[i] >> 3) << 10 | (d[i + 1] >> 3) << 5 | (d[i + 2] >> 3));
      }
      const n = d.length / 4;
      return { n, off: off / n, circuit0, colours: colours.size, hash: Array.from(d.filter((_, i) => i % 97 === 0)).join(',') };
    }, png);
  };
  const before = await pixels();
  console.log(`canvas: ${before.n} pixels, ${(100 * before.off).toFixed(1)} % off the background, ${before.colours} colours, ${before.circuit0} circuit-0 pixels`);
  check(before.off > 0.05 && before.colours > 50, 'the 3-D canvas is not blank');
  check(before.circuit0 > 50, 'the bores of circuit 0 are drawn in its colour');

  // Click another front point: prefer one whose layout has another number of bores.
  const state = () => page.evaluate(() => ({
    label: document.getElementById('layout-label').textContent,
    bores: Number(document.getElementById('bore-count').textContent),
    shown: Number(document.body.dataset.shown),
  }));
  const first = await state();
  const target = await page.evaluate((shown) => {
    const members = window.mtcsReport.data.members;
    const bores = (m) => m.layout.bores.length;
    const now = members.find((m) => m.rank === shown);
    const other = members.find((m) => m.rank !== shown && bores(m) !== bores(now)) ?? members.find((m) => m.rank !== shown);
    return other ? { rank: other.rank, bores: bores(other) } : null;
  }, first.shown);
  check(target !== null, 'the front has a second layout to click');
  // Click a member's point until it is shown: on a stack of overlapping points each click steps
  // to the next member. The number of clicks it took, 0: never.
  const clickMember = async (rank) => {
    for (let k = 1; k <= 1 + (await page.evaluate(() => window.mtcsReport.data.members.length)); ++k) {
      await page.click(`#front-plots .point[data-rank="${rank}"]`);
      if ((await state()).shown === rank) return k;
    }
    return 0;
  };
  if (target) {
    check((await clickMember(target.rank)) > 0, `clicking member ${target.rank}'s point shows it`);
    const after = await state();
    console.log(`clicked member ${target.rank}: "${first.label}" (${first.bores} bores) -> "${after.label}" (${after.bores} bores)`);
    check(after.label !== first.label && after.label.includes(`member ${target.rank}`), 'clicking a front point changes the layout label');
    check(after.bores === target.bores, 'the bore count in the DOM is the clicked layout\'s');
    if (target.bores !== first.bores) check((await pixels()).hash !== before.hash, 'the 3-D view changes with the layout');
    check((await clickMember(first.shown)) > 0, 'clicking the first member\'s point shows it again');
  }
  // The two closest points of any scatter (on the physics plate they overlap): a click on each
  // one's centre shows that one, even where the other is drawn over it; within a few pixels they
  // are one stack: clicking again steps to the other, and the list under the plots names both.
  const closest = await page.evaluate(() => {
    let best = null;
    document.querySelectorAll('#front-plots .plot').forEach((plot, k) => {
      const pts = [...plot.querySelectorAll('.point')].map((e) => ({ rank: Number(e.dataset.rank), c: e }));
      for (let i = 0; i < pts.length; ++i)
        for (let j = i + 1; j < pts.length; ++j) {
          const d = Math.hypot(pts[i].c.cx.baseVal.value - pts[j].c.cx.baseVal.value, pts[i].c.cy.baseVal.value - pts[j].c.cy.baseVal.value);
          if (!best || d < best.d) best = { plot: k, a: pts[i].rank, b: pts[j].rank, d };
        }
    });
    if (!best) return null;
    const plot = document.querySelectorAll('#front-plots .plot')[best.plot];
    plot.scrollIntoView({ block: 'center' });
    const centre = (rank) => { const r = plot.querySelector(`.point[data-rank="${rank}"]`).getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; };
    const scale = plot.querySelector('svg').getScreenCTM().a;
    return { ...best, px: best.d * scale, ca: centre(best.a), cb: centre(best.b) };
  });
  check(closest !== null, 'a scatter has two points');
  if (closest) {
    console.log(`closest points: members ${closest.a} and ${closest.b}, ${closest.px.toFixed(1)} px apart (scatter ${closest.plot})`);
    await page.mouse.click(...closest.cb);
    check((await state()).shown === closest.b, `a click on member ${closest.b}'s centre shows it`);
    await page.mouse.click(...closest.ca);
    check((await state()).shown === closest.a, `a click on member ${closest.a}'s centre shows it`);
    if (closest.px <= 7) {
      await page.mouse.click(...closest.ca);
      check((await state()).shown === closest.b, 'clicking the stack again steps to the other member');
      const listed = await page.evaluate(() => [...document.querySelectorAll('#front-pick button')].map((b) => Number(b.dataset.rank)));
      check(listed.includes(closest.a) && listed.includes(closest.b), `the list under the plots names both (${listed.join(', ')})`);
    }
  }
  // The drilling maps: lazy (nothing drawn at load), then a bore row's click draws its map.
  const drilling = await page.evaluate(() => {
    const dm = window.mtcsReport.data.drilling_maps;
    return { present: !!document.getElementById('drilling-panel'), maps: !!dm, drawnAtLoad: 'entry' in document.getElementById('drilling-map').dataset,
      member: dm ? dm.member : null };
  });
  check(drilling.present && drilling.maps, 'the page has a drilling-map panel and maps (the plate\'s cavity box)');
  check(!drilling.drawnAtLoad, 'no drilling map is drawn before it is asked for');
  if (drilling.maps) {
    await page.evaluate((m) => window.mtcsReport.select(m), drilling.member);
    const row = await page.$('#bores-table tbody tr:last-child');
    await row.click();
    const map = await page.evaluate(() => {
      const cv = document.getElementById('drilling-map');
      const dm = window.mtcsReport.data.drilling_maps;
      const k = Number(cv.dataset.entry);
      const d = cv.getContext('2d').getImageData(0, 0, cv.width, cv.height).data;
      let free = 0, blocked = 0;
      const near = (i, c) => Math.abs(d[i] - c[0]) + Math.abs(d[i + 1] - c[1]) + Math.abs(d[i + 2] - c[2]) < 12;
      for (let i = 0; i < d.length; i += 4) { if (near(i, [0xbf, 0xe3, 0xc0])) ++free; else if (near(i, [0xc8, 0x45, 0x3a])) ++blocked; }
      const e = dm.entries[k];
      return { open: document.getElementById('drilling-panel').open, bore: e ? e.bore : null, row: document.querySelector('#bores-table tbody tr:last-child td').textContent,
        free, blocked, n: d.length / 4, share: e ? e.free / (dm.rows * dm.cols) : -1, info: document.getElementById('drilling-info').textContent };
    });
    console.log(`drilling map of ${map.bore}: ${map.free} free and ${map.blocked} blocked pixels of ${map.n} (data: ${(100 * map.share).toFixed(1)} % free); "${map.info}"`);
    check(map.open && map.bore === map.row, 'clicking a bore of the table opens the panel on its drilling map');
    const drawnShare = map.free / Math.max(1, map.free + map.blocked);
    check(map.free + map.blocked > 0.3 * map.n && Math.abs(drawnShare - map.share) < 0.03,
      `the drilling-map canvas is not blank and shows the free share of the data (${(100 * drawnShare).toFixed(1)} % drawn)`);
  }
  // The anytime curves: lazy, then the summary's click draws them from the page's data.
  const anytimeAtLoad = await page.evaluate(() => ({ present: !!document.getElementById('anytime-panel'),
    plots: document.querySelectorAll('#anytime-plots svg').length }));
  check(anytimeAtLoad.present && anytimeAtLoad.plots === 0, 'the anytime panel is there and draws nothing at load');
  await page.click('#anytime-panel summary');
  // The details' toggle event is queued after the click: wait for the drawing (or give up).
  await page.waitForFunction(() => document.querySelector('#anytime-plots').dataset.drawn === '1', { timeout: 5000 }).catch(() => {});
  const anytime = await page.evaluate(() => {
    const a = window.mtcsReport.data.anytime;
    const count = (ys) => ys.filter((v) => v !== null).length;
    const curves = [...document.querySelectorAll('#anytime-plots svg')].map((root) => {
      const p = root.querySelector('path.so-far'), box = p.getBBox();
      return { title: root.getAttribute('aria-label'), vertices: (p.getAttribute('d').match(/[ML]/g) || []).length, width: box.width, height: box.height };
    });
    return { open: document.getElementById('anytime-panel').open, curves, generations: a.evaluations.length,
      best: count(a.best_so_far), hv: count(a.hypervolume_so_far), caption: document.getElementById('anytime-caption').textContent };
  });
  console.log(`anytime ${anytime.caption}: ${anytime.curves.map((c) => `${c.title} (${c.vertices} vertices, ${c.width.toFixed(0)} x ${c.height.toFixed(0)})`).join('; ')}`);
  check(anytime.open && anytime.curves.length === 4, 'opening the anytime panel draws four charts');
  check(anytime.hv === anytime.generations && anytime.best > 0 &&
    anytime.curves.every((c) => c.vertices === (c.title.startsWith('best') ? anytime.best : anytime.hv)),
    `each curve has one vertex per stored generation (${anytime.generations}; with a feasible layout: ${anytime.best})`);
  check(anytime.curves.every((c) => c.width > 100), 'each curve spans its chart across');
  check(errors.length === 0, `still no console errors after the clicks${errors.length ? ': ' + errors.join(' | ') : ''}`);
  if (screenshot) {
    await page.screenshot({ path: screenshot, fullPage: false });
    console.log(`screenshot: ${screenshot}`);
  }
} finally {
  await browser.close();
}
console.log(failures.length ? `${failures.length} check(s) failed` : 'all checks passed');
process.exit(failures.length ? 1 : 0);
