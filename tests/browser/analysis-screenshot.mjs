// Screenshots of the page's designer's analysis for docs/: the bundled reflex lens at 1280 wide
// (web-analysis-reflex.png) and on a 390-wide phone (web-analysis-phone.png); with a lens file given,
// that lens uploaded through the page as well (web-analysis-STEM.png, after the file's name: the
// catadioptric shared/realworld/prescriptions/HoO-V2C18Ex27.zmx for docs/, the file itself never
// committed).
// usage: node analysis-screenshot.mjs LENSLAB_BINARY OUT_DIR [LENS_FILE]
import { mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { basename, extname, join } from "node:path";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";

const [binary, outDir, upload] = process.argv.slice(2);
if (!binary || !outDir) {
  console.error("usage: node analysis-screenshot.mjs LENSLAB_BINARY OUT_DIR [LENS_FILE]");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-analysis-shot-"));

// Waits for the analysis of the lens titled on the page after `before` analyses were shown.
async function analysisShown(page, before) {
  await page.waitForFunction((n) => {
    const s = document.querySelector("#analysis");
    return Number(s.dataset.shown || 0) > n && s.dataset.lens === document.querySelector("#lens-title").textContent;
  }, before);
}
const shownCount = (page) => page.$eval("#analysis", (s) => Number(s.dataset.shown || 0));

async function main() {
  const { server, context, page } = await openPage(binary, work, { width: 1280, height: 1000 });
  try {
    page.setDefaultTimeout(120000);
    let before = await shownCount(page);
    await page.click('#lens-list button[data-id="us4666259-ex1-reflex-500mm"]');
    await analysisShown(page, before);
    await (await page.$("#analysis")).screenshot({ path: join(outDir, "web-analysis-reflex.png") });
    if (upload) {
      before = await shownCount(page);
      await page.setInputFiles("#lens-file", upload);
      await waitForUpload(page);
      await analysisShown(page, before);
      await (await page.$("#analysis")).screenshot({ path: join(outDir, `web-analysis-${basename(upload, extname(upload))}.png`) });
      before = await shownCount(page);
      await page.click('#lens-list button[data-id="us4666259-ex1-reflex-500mm"]');
      await analysisShown(page, before);
    }
    await page.setViewportSize({ width: 390, height: 844 });
    await page.evaluate(() => document.querySelector('#analysis-plots .analysis-row[data-field="3"]').scrollIntoView());
    await page.screenshot({ path: join(outDir, "web-analysis-phone.png") });
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => { console.error(e); process.exit(1); });
