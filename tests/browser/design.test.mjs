// Browser test of the design panel: the Cooke triplet of docs/design.md with its curvatures 5% off is
// uploaded through the file picker; Optimise shows the merit falling step by step and puts the
// optimised lens into the editor (its radii change, the lens shows as edited); a 20-trial tolerance
// run shows the yield and a histogram per operand holding every valid trial; Undo returns the editor
// to the uploaded lens. Screenshots of the panel at desktop and phone width:
// docs/web-design-desktop.png, docs/web-design-phone.png.
// usage: node design.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";
import { editorHolds, previews } from "./editor-cells.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node design.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-design-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// docs/design.md's starting point: each of the six curvatures 5% off, alternately + and -.
function perturbedCooke() {
  let k = 0;
  return readFileSync(join(sourceDir, "lenses/design/cooke-triplet-50mm.zmx"), "utf8")
    .replace(/CURV (-?[0-9.]+e[-+][0-9]+)/g, (_, c) => `CURV ${Number(c) * (k++ % 2 ? 0.95 : 1.05)}`);
}

const radii = (page) => page.$$eval('#editor-table input[data-key="radius"]', (inputs) => inputs.map((i) => i.value));

async function main() {
  const { server, context, page } = await openPage(binary, work, { width: 1280, height: 900 });
  try {
    const file = join(work, "cooke-perturbed.zmx");
    writeFileSync(file, perturbedCooke());
    await page.setInputFiles("#lens-file", file);
    await waitForUpload(page);
    const lens = await page.$eval("#lens-title", (h) => h.dataset.id);
    await editorHolds(page, lens);
    const uploaded = await radii(page);

    // Every merit list the panel shows, as it shows them.
    await page.evaluate(() => {
      window.meritsShown = [];
      new MutationObserver(() => { const m = document.querySelector("#design").dataset.merits; if (m) window.meritsShown.push(JSON.parse(m)); })
        .observe(document.querySelector("#design"), { attributeFilter: ["data-merits"] });
    });
    const previewsBefore = await previews(page);
    await page.click("#optimise");
    await page.waitForFunction(() => ["done", "failed", "cancelled"].includes(document.querySelector("#optimise-status").dataset.state));
    check(await page.$eval("#optimise-status", (p) => p.dataset.state) === "done", `optimised: ${await page.textContent("#optimise-status")}`);
    const shown = await page.evaluate(() => window.meritsShown);
    const merits = shown[shown.length - 1];
    check(merits.length >= 3 && merits.every((m, i) => i === 0 || m <= merits[i - 1]),
          `the merit falls at every step: ${merits.map((m) => m.toPrecision(3)).join(" → ")} (${shown.length} updates shown)`);
    check(merits[merits.length - 1] < 0.2 * merits[0], "to under a fifth of the start");
    check(await page.$$eval("#merit-plot circle", (c) => c.length) === merits.length, "one point a step in the merit plot");
    await page.waitForFunction((n) => Number(document.querySelector("#editor").dataset.previews || 0) > n, previewsBefore);
    const optimised = await radii(page);
    check(optimised.some((r, i) => r !== uploaded[i]), `the editor holds the optimised radii (${uploaded[0]} → ${optimised[0]})`);
    check(await page.$eval("#editor", (e) => e.classList.contains("edited")), "shown as an edit of the uploaded lens");

    // A small tolerance run: the yield, and per operand a histogram of every valid trial.
    await page.fill("#tolerance-trials", "20");
    await page.fill("#tolerance-seed", "3");
    await page.click("#tolerance-run");
    await page.waitForFunction(() => document.querySelector("#tolerance-status").dataset.state === "done"
                                     && document.querySelectorAll("#tolerance-results figure").length > 0);
    const figures = await page.$$eval("#tolerance-results figure", (fs) => fs.map((f) => ({
      count: Number(f.dataset.count), binned: Number(f.dataset.binsTotal), bars: f.querySelectorAll("rect.bin").length,
      caption: f.querySelector("figcaption").textContent })));
    check(figures.length >= 2, `${figures.length} histograms: the merit and each operand (${figures[1].caption})`);
    check(figures.every((f) => f.count > 15 && f.count <= 20 && f.binned === f.count && f.bars === 20),
          "each holds its valid trials (16 to 20 of 20) in 20 bins");
    check(figures.every((f) => /p50 .* p90 .* p98 /.test(f.caption)), "each says its 50th, 90th and 98th percentiles");
    check(/Yield [0-9.]+% of 20 trials/.test(await page.textContent("#tolerance-status")), `the yield: ${await page.textContent("#tolerance-status")}`);

    await (await page.$("#design")).screenshot({ path: join(sourceDir, "docs", "web-design-desktop.png") });
    await page.setViewportSize({ width: 390, height: 844 });
    await page.evaluate(() => document.querySelector("#design").scrollIntoView());
    await page.screenshot({ path: join(sourceDir, "docs", "web-design-phone.png") });
    const overflow = await page.$eval("#design", (s) => s.scrollWidth - s.clientWidth);
    check(overflow <= 1, `the panel fits a phone's width (overflow ${overflow} px)`);
    await page.setViewportSize({ width: 1280, height: 900 });

    // Undo: the uploaded lens again.
    await page.click("#optimise-undo");
    await page.waitForFunction(() => !document.querySelector("#editor").classList.contains("edited"));
    check(JSON.stringify(await radii(page)) === JSON.stringify(uploaded), "Undo returns the editor to the uploaded radii");
    check(await page.isDisabled("#optimise-undo"), "and is spent");
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => { console.error(e); process.exit(1); });
