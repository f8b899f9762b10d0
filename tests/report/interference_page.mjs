// The interference page (mtcs interfere A B --report) in headless chromium, puppeteer-core from
// web/node_modules: it loads without console errors, the 3-D canvas is not blank, it lists the
// expected number of intersecting triangle pairs (the certified count of
// tests/data/mesh_interference.csv) in its header, its pair table and its groups by solid and face.
// Usage: node interference_page.mjs PAGE.html EXPECTED_PAIRS
// Exit 0: passed; 1: failed; 77: skipped (no chromium on this machine).
import fs from 'node:fs';
import path from 'node:path';
import { launchBrowser } from '../support/browser.mjs';

const [pagePath, expectedText] = process.argv.slice(2);
const expected = Number(expectedText);
if (!fs.existsSync(pagePath) || !(expected > 0)) {
  console.error(`FAILED: usage: interference_page.mjs PAGE.html EXPECTED_PAIRS (got ${pagePath}, ${expectedText})`);
  process.exit(1);
}
const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };
const browser = await launchBrowser('the interference page');
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1366, height: 768 });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`file://${path.resolve(pagePath)}`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.body.dataset.ready === '1', { timeout: 30000 });
  const seen = await page.evaluate(() => ({
    count: Number(document.getElementById('pair-count').textContent),
    rows: document.querySelectorAll('#pairs-table tr').length - 1,
    grouped: [...document.querySelectorAll('#groups-table tr')].slice(1).reduce((s, tr) => s + Number(tr.children[4].textContent), 0),
    verdict: document.getElementById('verdict').textContent,
    frames: window.mtcsInterference.frames(),
  }));
  console.log(`page: verdict ${seen.verdict}, ${seen.count} pairs, ${seen.rows} listed, ${seen.grouped} in the groups, ${seen.frames} frames`);
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
  check(seen.count === expected, `the page lists ${expected} intersecting triangle pairs`);
  check(seen.rows === expected, 'the pair table has one row per pair');
  check(seen.grouped === expected, 'the groups by solid and face hold every pair');
  check(seen.verdict === 'INTERFERENCE', 'the verdict is interference');
  const png = await (await page.$('#view3d')).screenshot({ encoding: 'base64' });
  const red = await page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let off = 0, reds = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - 0xee) + Math.abs(d[i + 1] - 0xf1) + Math.abs(d[i + 2] - 0xf6) > 24) off += 1;
      if (d[i] > 150 && d[i] > d[i + 1] + 70 && d[i] > d[i + 2] + 70) reds += 1;
    }
    return { off: off / (d.length / 4), reds };
  }, png);
  console.log(`canvas: ${(100 * red.off).toFixed(1)} % off the background, ${red.reds} red pixels`);
  check(red.off > 0.02, 'the 3-D canvas is not blank');
  // Clicking the first group flies the camera to it: the interfering triangles fill more pixels.
  await page.click('#groups-table tr:nth-child(2)');
  const png2 = await (await page.$('#view3d')).screenshot({ encoding: 'base64' });
  check(png2 !== png, 'clicking a group moves the view to it');
} finally {
  await browser.close();
}
console.log(failures.length ? `${failures.length} check(s) failed` : 'all checks passed');
process.exit(failures.length ? 1 : 0);
