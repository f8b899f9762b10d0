// A screenshot of a report page as it opens (the top of the page), for docs/report.png and to
// compare page code by eye. Headless chromium, software WebGL, as tests/report/report_page.mjs.
// Usage (repo root): node experiments/report/screenshot.mjs PAGE.html OUT.png [WIDTH HEIGHT]
import path from 'node:path';
import { createRequire } from 'node:module';
const require = createRequire(path.resolve('web/package.json'));
const puppeteer = require('puppeteer-core');
const [page_, out, width = 1366, height = 768] = process.argv.slice(2);
const browser = await puppeteer.launch({ executablePath: process.env.MTCS_CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--hide-scrollbars'] });
const page = await browser.newPage();
await page.setViewport({ width: Number(width), height: Number(height) });
await page.goto(`file://${path.resolve(page_)}`);
await page.waitForFunction(() => document.body.dataset.ready === '1', { timeout: 60000 });
await page.screenshot({ path: out });
await browser.close();
