// What every browser test starts with: Debian's chromium (or $MTCS_CHROMIUM), headless with
// software WebGL, driven by puppeteer-core from web/node_modules (scripts/setup.sh installs both).
// No chromium: the test says so and exits 77 (ctest: skipped); no puppeteer-core: it fails.
import path from 'node:path';
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

function findChromium() {
  for (const candidate of [process.env.MTCS_CHROMIUM, 'chromium', 'chromium-browser', 'google-chrome']) {
    if (!candidate) continue;
    try {
      return execFileSync('sh', ['-c', `command -v "${candidate}"`], { encoding: 'utf8' }).trim();
    } catch { /* next */ }
  }
  return null;
}

// `what`: the page the test would have opened, for the skip message.
export async function launchBrowser(what) {
  const chromium = findChromium();
  if (!chromium) {
    console.log(`SKIPPED: no chromium on this machine (scripts/setup.sh installs Debian's chromium); ${what} was not tested in a browser`);
    process.exit(77);
  }
  const require = createRequire(path.join(path.dirname(fileURLToPath(import.meta.url)), '../../web/package.json'));
  let puppeteer;
  try {
    puppeteer = require('puppeteer-core');
  } catch {
    console.error('FAILED: puppeteer-core is not installed in web/node_modules: run scripts/setup.sh (npm ci --prefix web)');
    process.exit(1);
  }
  return puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--hide-scrollbars', '--disable-dev-shm-usage'],
  });
}
