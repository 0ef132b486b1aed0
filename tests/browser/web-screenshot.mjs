// Screenshots of the web page for docs/: the shared telephoto scene through telephoto.250mm at f/5.6,
// exact and thick compared side by side, at 1280x800 (the viewer in view) and on a
// 390-wide phone; and the lens panel at the top of the page.
// usage: node web-screenshot.mjs LENSLAB_BINARY OUT_DIR
//        (writes web-page.png, web-page-phone.png, web-page-lens.png)
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { launchBrowser, startServer, stopServer } from "./serve.mjs";

const [binary, outDir] = process.argv.slice(2);
if (!binary || !outDir) {
  console.error("usage: node web-screenshot.mjs LENSLAB_BINARY OUT_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-screenshot-"));

async function main() {
  const { server, base } = await startServer(binary, work);
  const context = await launchBrowser({ width: 1280, height: 800 });
  try {
    const page = context.pages()[0] || await context.newPage();
    page.setDefaultTimeout(300000);
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");
    await page.click('#lens-list button[data-id="telephoto.250mm"]');
    await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "telephoto.250mm");
    await page.fill("#fstop-input", "5.6");
    await page.press("#fstop-input", "Enter");
    await page.waitForFunction(() => document.querySelector("#diagram-status").textContent.includes("f/5.6"));
    await page.screenshot({ path: join(outDir, "web-page-lens.png") });
    await page.selectOption("#scene", "shared-telephoto");
    await page.fill("#width", "240");
    await page.fill("#height", "180");
    await page.fill("#spp", "32");
    await page.click("#compare-button");
    await page.waitForFunction(() => !document.querySelector("#difference-scale").hidden);
    await page.evaluate(() => document.querySelector("#viewer").scrollIntoView());
    const box = await (await page.$("#viewer-panes canvas")).boundingBox();
    await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.4);
    await page.screenshot({ path: join(outDir, "web-page.png") });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.evaluate(() => document.querySelector("#viewer").scrollIntoView());
    await page.screenshot({ path: join(outDir, "web-page-phone.png") });
  } finally {
    await context.close();
    await stopServer(server);
    rmSync(work, { recursive: true, force: true });
  }
}

main().catch((e) => { console.error(e); process.exit(1); });
