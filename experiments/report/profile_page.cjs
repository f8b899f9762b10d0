// Where a report page's load time goes: chromium's sampling profiler (DevTools protocol) from
// navigation to the page's ready flag, self time per function (three.js is minified: its
// functions show as single letters with their column; see README.md for the two that matter).
// Usage (repo root): node experiments/report/profile_page.cjs PAGE.html
const path = require('node:path');
const puppeteer = require(path.join(__dirname, '../../web/node_modules/puppeteer-core'));
(async () => {
  const browser = await puppeteer.launch({ executablePath: process.env.MTCS_CHROMIUM || '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'] });
  const page = await browser.newPage();
  await page.setViewport({ width: 1366, height: 768 });
  const cdp = await page.target().createCDPSession();
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
  await cdp.send('Profiler.start');
  await page.goto(`file://${path.resolve(process.argv[2])}`);
  await page.waitForFunction(() => document.body.dataset.ready === '1', { timeout: 120000 });
  const { profile } = await cdp.send('Profiler.stop');
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  const self = new Map();
  profile.samples.forEach((id, i) => {
    const f = byId.get(id).callFrame;
    const key = `${f.functionName || '(anonymous)'} ${f.url.startsWith('data:') ? 'three.js' : 'page'}:${f.lineNumber}:${f.columnNumber}`;
    self.set(key, (self.get(key) || 0) + (profile.timeDeltas[i] || 0));
  });
  const total = [...self.values()].reduce((a, b) => a + b, 0);
  console.log(`sampled ${(total / 1000).toFixed(0)} ms`);
  for (const [k, v] of [...self.entries()].sort((a, b) => b[1] - a[1]).slice(0, 15)) console.log(`${(v / 1000).toFixed(0).padStart(7)} ms  ${k}`);
  await browser.close();
})();
