// Two users review one mold in headless chromium (puppeteer-core from web/node_modules) against a
// running `mtcs serve`: the designer uploads two meshes through the page and runs the
// interference check on the server; both pages see it finish live; the reviewer creates a review
// item from a finding (with the 3-D view's camera); the designer's page shows the item without
// reloading and its viewpoint restores the same camera; a corrected version re-checked marks the
// item's finding resolved, which the reviewer's page shows live. No console errors, no CSP
// violations, user text never parsed as HTML.
// Usage: node review_page.mjs URL MESH_DIR CORRECTED_GEAR.off TX,TY,TZ EXPECTED_PAIRS
// Exit 0: passed; 1: failed; 77: skipped (no chromium on this machine).
import path from 'node:path';
import { launchBrowser } from '../support/browser.mjs';

const [url, meshes, correctedGear, translate, expectedText] = process.argv.slice(2);
const expected = Number(expectedText);
const browser = await launchBrowser('the review app');
const failures = [];
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures.push(what); };

// The project and its members, set up through the API as a script would.
async function call(cookie, csrf, method, route, body) {
  const r = await fetch(url + route, { method, headers: { 'Content-Type': 'application/json', Cookie: cookie, 'X-MTCS-CSRF': csrf }, body: JSON.stringify(body) });
  return { status: r.status, body: await r.json(), cookie: (r.headers.get('set-cookie') || '').split(';')[0] };
}
const login = await call('', '', 'POST', '/api/v1/login', { name: 'olga', password: 'olga-password' });
const { cookie } = login, { csrf } = login.body;
const project = (await call(cookie, csrf, 'POST', '/api/v1/projects', { name: 'slide <b>1</b>' })).body.id;
for (const [user, role] of [['dora', 'designer'], ['rita', 'reviewer']])
  await call(cookie, csrf, 'PUT', `/api/v1/projects/${project}/members`, { user, role });

const errors = [];
async function open(name) {
  const context = await browser.createBrowserContext();
  const page = await context.newPage();
  await page.setViewport({ width: 1366, height: 900 });
  page.on('console', (m) => { if (m.type() === 'error' && !/401/.test(m.text())) errors.push(`${name}: ${m.text()} (${m.location().url || ''})`); });
  page.on('pageerror', (e) => errors.push(`${name}: ${e}`));
  await page.goto(`${url}/#project-${project}`, { waitUntil: 'load' });
  await page.waitForSelector('#sign-in-panel:not([hidden])');
  await page.type('#name', name);
  await page.type('#password', `${name}-password`);
  await page.click('#sign-in button');
  await page.waitForFunction(() => document.querySelector('#project-panel') && !document.querySelector('#project-panel').hidden);
  return page;
}
const text = (page, sel) => page.$eval(sel, (e) => e.textContent);
const frameReady = (page) => page.waitForFunction(() => {
  const f = document.getElementById('check-page').contentWindow;
  return f && f.mtcsInterference && f.document.body.dataset.ready === '1';
}, { timeout: 60000 });

try {
  const dora = await open('dora');
  const rita = await open('rita');
  check((await text(dora, '#project-title')) === 'slide <b>1</b>', 'a project name with markup shows as text');
  check(await rita.$eval('#upload', (f) => f.hidden), 'a reviewer gets no upload form');

  // The designer uploads both meshes through the page.
  async function upload(component, file) {
    await dora.$eval('#component-name', (e, v) => { e.value = v; }, component);
    await (await dora.$('#component-file')).uploadFile(file);
    await dora.click('#upload button');
    await dora.waitForFunction((c, n) => [...document.querySelectorAll('#components tr')].some((tr) => tr.children[0].textContent === c && tr.children[1].textContent === n),
      { timeout: 30000 }, component, String(file === correctedGear ? 2 : 1));
  }
  await upload('homer', path.join(meshes, 'homer.off'));
  await upload('gear', path.join(meshes, 'mcad_herringbone_gear.off'));
  check(true, 'the designer uploaded homer and the gear');
  await rita.waitForFunction(() => document.querySelectorAll('#components tr').length === 3, { timeout: 10000 });
  check(true, 'the reviewer sees both components arrive live');

  // The check on the server; both pages see it finish.
  async function runCheck(n) {
    await dora.$eval('#check-a', (e) => { e.value = 'homer'; });
    await dora.$eval('#check-b', (e) => { e.value = 'gear'; });
    await dora.$eval('#check-translate', (e, v) => { e.value = v; }, translate);
    await dora.click('#new-check button');
    for (const page of [dora, rita])
      await page.waitForFunction((n) => {
        const j = window.mtcsReview.jobs();
        return j.length === n && j[n - 1].state === 'succeeded';
      }, { timeout: 60000 }, n);
    return rita.evaluate((n) => window.mtcsReview.jobs()[n - 1], n);
  }
  const first = await runCheck(1);
  check(first.result.pair_count === expected, `the check on the server reports the certified ${expected} pairs (got ${first.result.pair_count})`);
  check(first.result.findings.new === first.result.groups, 'every face group is a new finding');

  // The reviewer opens the check and makes an item from its first finding.
  await rita.click(`#jobs tr[data-key="job-${first.id}"]`);
  await frameReady(rita);
  const pairsInPage = await rita.evaluate(() => document.getElementById('check-page').contentWindow.mtcsInterference.data.check.pair_count);
  check(pairsInPage === expected, 'the check\'s 3-D page shows the same pairs');
  await rita.click('#findings tr:nth-child(2) button');
  await rita.waitForFunction(() => window.mtcsReview.topics().length === 1, { timeout: 10000 });
  const item = await rita.evaluate(() => window.mtcsReview.topics()[0]);
  const saved = item.comments[0].viewpoint;
  check(saved && saved.camera_view_point.length === 3 && saved.job === first.id, 'the item carries the view\'s camera and its check');

  // The designer's page shows it without reloading; its viewpoint restores the camera.
  await dora.waitForFunction(() => document.querySelectorAll('#topics tr').length === 2, { timeout: 10000 });
  check(true, 'the designer sees the new item live');
  await dora.click('#topics tr[data-key="topic-1"]');
  await dora.waitForSelector('#comments button');
  await dora.click('#comments button');
  await frameReady(dora);
  await dora.waitForFunction(() => window.mtcsReview.state.job !== null);
  await dora.click('#comments button');  // the page is loaded now: set the camera
  const restored = await dora.evaluate(() => document.getElementById('check-page').contentWindow.mtcsInterference.viewpoint());
  const far = Math.max(...['camera_view_point', 'camera_direction', 'camera_up_vector'].flatMap((k) => saved[k].map((v, i) => Math.abs(v - restored[k][i]))));
  check(far < 1e-6, `the viewpoint restores the camera (largest difference ${far.toExponential(2)})`);

  // Markup in a comment is text.
  await dora.type('#comment-text', '<img src=x onerror="window.hacked=1">');
  await dora.click('#new-comment button');
  await rita.waitForFunction(() => window.mtcsReview.topics()[0].comments.length === 2, { timeout: 10000 });
  check(!(await rita.evaluate(() => window.hacked)) && (await rita.$$('#comments img')).length === 0, 'a comment with markup is shown as text');

  // A corrected gear, checked again: the item's finding is resolved, the reviewer's page says so live.
  await upload('gear', correctedGear);
  const third = await runCheck(2);
  check(third.result.pair_count === 0 && third.result.findings.resolved === first.result.groups, 'the corrected version: no pairs, every finding resolved');
  await rita.waitForFunction(() => window.mtcsReview.topics()[0].comments.some((c) => c.author === 'mtcs' && /resolved/.test(c.text)), { timeout: 10000 });
  check(true, 'the reviewer\'s page shows mtcs\'s note that the item\'s finding is resolved');
  check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
} catch (e) {
  check(false, `the review ran to its end: ${e.stack || e}`);
} finally {
  await browser.close();
}
if (failures.length) { console.log(`FAILED: ${failures.length} check(s)`); process.exit(1); }
console.log('PASSED');
