// Opens the report page from the file system in headless Chromium and saves a screenshot, failing
// when the page logs an error, asks for anything not local, or an image does not load.
//   node report-screenshot.cjs SITE_DIR OUT.png [--full | SELECTOR]
// --full: the whole page; SELECTOR (e.g. '#renders'): the window scrolled to that element; else the top.
const fs = require('fs');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

async function main() {
  const [siteDir, outPng, mode] = process.argv.slice(2);
  if (!siteDir || !outPng) throw new Error('usage: node report-screenshot.cjs SITE_DIR OUT.png [--full | SELECTOR]');
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'lenslab-report-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
    viewport: { width: 1280, height: 900 },
  });
  const problems = [];
  try {
    const page = await context.newPage();
    page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
    page.on('requestfailed', (r) => problems.push('failed request: ' + r.url()));
    page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) problems.push('non-local request: ' + r.url()); });
    await page.goto('file://' + path.resolve(siteDir, 'index.html'), { waitUntil: 'load' });
    // Lazy images load as they scroll into view: scroll through, then check every one decoded. A busy
    // machine's renderer can miss an image scrolled past in 20 ms, so every one is then made eager.
    await page.evaluate(async () => {
      for (let y = 0; y < document.body.scrollHeight; y += 600) { window.scrollTo(0, y); await new Promise((r) => setTimeout(r, 20)); }
      window.scrollTo(0, 0);
      for (const i of document.images) i.loading = 'eager';
    });
    await page.waitForFunction(() => Array.from(document.images).every((i) => i.complete), null, { timeout: 20000 });
    const broken = await page.evaluate(() => Array.from(document.images).filter((i) => i.naturalWidth === 0).map((i) => i.getAttribute('src')));
    for (const src of broken) problems.push('image did not load: ' + src);
    if (mode && mode !== '--full') {
      await page.evaluate((selector) => document.querySelector(selector).scrollIntoView(), mode);
      await page.waitForTimeout(200);
    }
    await page.screenshot({ path: outPng, fullPage: mode === '--full' });
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
  if (problems.length) throw new Error(problems.join('\n'));
}

main().catch((e) => { console.error(e.message); process.exit(1); });
