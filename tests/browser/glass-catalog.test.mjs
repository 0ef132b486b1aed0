// Browser test of glass catalog uploads on the web page: a lens naming a glass only our own Zemax
// catalog has is refused (the page says which glass); the catalog (.agf, one Sellmeier glass of the
// test's own numbers) goes up through the same file picker, and a second, named .txt, is told by its
// content when dropped on the drop zone; both are listed with their glass counts. The lens then
// reads, and the page's EFL is the lensmaker's formula's with the index computed here from the
// Sellmeier terms. A malformed catalog is refused with its line; a catalog a lens uses is not
// deleted (the page says which lens), one no lens uses is. Screenshot: artifacts/glass-catalog.png.
// usage: node glass-catalog.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdirSync, mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";

const [binary] = process.argv.slice(2);
if (!binary) {
  console.error("usage: node glass-catalog.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const artifacts = join(dirname(fileURLToPath(import.meta.url)), "artifacts");
mkdirSync(artifacts, { recursive: true });
const work = mkdtempSync(join(tmpdir(), "lenslab-glass-catalog-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// Zemax formula 2 (Sellmeier 1): n^2 - 1 = sum K L^2 / (L^2 - L), L in micrometres.
const K = [1.2, 0.25, 1.0], L = [0.008, 0.03, 95.0];
const CATALOG = `CC our own glass\nNM LLAB-SELL1 2 0 1.5807 47.11 0 0 0\nCD ${K[0]} ${L[0]} ${K[1]} ${L[1]} ${K[2]} ${L[2]} 0 0 0 0\nLD 0.3 2.5\n`;
const nAt = (nm) => {
  const l2 = (nm / 1000) ** 2;
  return Math.sqrt(1 + K.reduce((sum, k, i) => sum + k * l2 / (l2 - L[i]), 0));
};
// R1 50, 5 mm, R2 -50 in air: 1/f = (n-1) [1/R1 - 1/R2 + (n-1) t / (n R1 R2)].
const nd = nAt(587.5618);
const EFL = 1 / ((nd - 1) * (1 / 50 - 1 / -50 + (nd - 1) * 5 / (nd * 50 * -50)));
const SINGLET = "# a singlet in our own glass\n50.0 5.0 1.5807 20.0 LLAB-SELL1\n-50.0 10.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";

const message = (page) => page.$eval("#message", (m) => (m.hidden ? "" : m.textContent));
const waitForMessage = (page, text) =>
  page.waitForFunction((text) => { const m = document.querySelector("#message"); return !m.hidden && m.textContent.includes(text); }, text);
const catalogsListed = (page) => page.$$eval("#glass-catalog-list li", (items) => items.map((i) => i.textContent));

async function dropFile(page, name, text) {
  await page.evaluate(([name, text]) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([text], name, { type: "text/plain" }));
    document.querySelector("#drop-zone").dispatchEvent(new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }));
  }, [name, text]);
}

async function main() {
  const files = Object.fromEntries(["llab.agf", "singlet.dat", "bad.agf"].map((f) => [f, join(work, f)]));
  writeFileSync(files["llab.agf"], CATALOG);
  writeFileSync(files["singlet.dat"], SINGLET);
  writeFileSync(files["bad.agf"], "NM G1 2 0 1.5 60 0 0 0\nCD 1.0 0.01 five\n");
  const { server, context, page } = await openPage(binary, work, { width: 1280, height: 900 });
  try {
    page.on("dialog", (d) => d.accept());
    check(await page.isHidden("#glass-catalogs"), "no catalogs uploaded: the catalog list is hidden");
    await page.setInputFiles("#lens-file", files["singlet.dat"]);
    await waitForMessage(page, "was not accepted");
    check((await message(page)).includes("unknown glass 'LLAB-SELL1'"), `before the catalog the lens is refused: "${(await message(page)).slice(0, 120)}"`);

    await page.setInputFiles("#lens-file", files["bad.agf"]);
    await waitForMessage(page, `The glass catalog "bad.agf" was not accepted`);
    check((await message(page)).includes(`The glass catalog "bad.agf" was not accepted: bad.agf:2: a CD coefficient is not a finite number: 'five'`),
          `a malformed catalog is refused with its line: "${await message(page)}"`);

    await page.setInputFiles("#lens-file", files["llab.agf"]);
    await waitForMessage(page, "Uploaded the glass catalog LLAB (1 glass)");
    await dropFile(page, "other.txt", CATALOG.replace("LLAB-SELL1", "OTHER-1"));
    await waitForMessage(page, "Uploaded the glass catalog OTHER.TXT (1 glass)");
    const listed = await catalogsListed(page);
    check(listed.length === 2 && listed[0].startsWith("LLAB") && listed[0].includes("1 glass") && listed[1].startsWith("OTHER.TXT"),
          `both catalogs are listed, the dropped .txt told by its content: ${JSON.stringify(listed)}`);

    // The uploaded lens's first data request is held back (the view asks again once the f-number
    // is set), so that the delete below is clicked while that request is on its way, as on a busy
    // service: the delete's answer must not be overwritten by the upload's when it arrives.
    let release, held = false;
    const answerWaits = new Promise((resolve) => { release = resolve; });
    await page.route(/\/api\/lenses\/upload-[^/?]+\?/, async (route) => {
      if (!held) { held = true; await answerWaits; }
      await route.continue();
    });
    await page.setInputFiles("#lens-file", files["singlet.dat"]);
    await waitForUpload(page);
    await page.waitForFunction(() => document.querySelector("#lens-surfaces tbody").textContent.includes("LLAB-SELL1"));
    const efl = Number(await page.$eval("#lens-data tbody tr td", (td) => td.textContent));
    check(Math.abs(efl - EFL) < 0.0005, `after the upload the lens reads; the page's EFL ${efl} is the lensmaker's ${EFL.toFixed(4)} (n_d ${nd.toFixed(6)})`);
    const lensId = await page.getAttribute("#lens-title", "data-id");

    await page.click('#glass-catalog-list li:first-child button');
    await waitForMessage(page, "could not be deleted");
    release();
    await page.waitForLoadState("networkidle");
    const refusal = await message(page);
    check(refusal.includes("The glass catalog LLAB could not be deleted") && refusal.includes(lensId), `the catalog the lens uses is not deleted, the page names the lens, still once the view has loaded: "${refusal}"`);
    await page.click('#glass-catalog-list li:nth-child(2) button');
    await page.waitForFunction(() => document.querySelectorAll("#glass-catalog-list li").length === 1);
    check((await catalogsListed(page))[0].startsWith("LLAB"), "the unused catalog is deleted, the used one stays");
    await page.screenshot({ path: join(artifacts, "glass-catalog.png"), fullPage: true });
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
