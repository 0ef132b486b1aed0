// Browser test of a real prescription on the web page: a Zemax file, saved as UTF-16 with a byte
// order mark as Zemax writes it, is uploaded through the file picker; the page shows its glasses,
// conics and aspheric terms, the colour block with the numbers the API gives, and a diagram whose
// colour fans (F, d, C) appear when the box is ticked. A wavelength outside 180-2500 nm is marked in
// its field and never sent. A Code V .seq with a tilted plate uploads, its surface table shows the
// tilts and its colour block the focal lengths at F, d and C; a singlet folded by a 45 degree mirror
// uploads and its diagram is drawn. Screenshots: tests/browser/artifacts/zemax-lens.png,
// codev-tilted-plate.png, codev-fold-mirror.png.
// usage: node zemax.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { closeAll, launchBrowser, startServer, waitForUpload } from "./serve.mjs";
import { TILTED_PLATE_SEQ } from "./tilted-plate.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node zemax.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const artifacts = join(dirname(fileURLToPath(import.meta.url)), "artifacts");
mkdirSync(artifacts, { recursive: true });
const work = mkdtempSync(join(tmpdir(), "lenslab-zemax-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// Pixels of the diagram image close to an RGB colour (the C line's red: 235, 45, 0).
const diagramPixelsNear = (page, rgb) => page.$eval("#diagram", (img, rgb) => {
  const canvas = document.createElement("canvas");
  canvas.width = img.naturalWidth;
  canvas.height = img.naturalHeight;
  const ctx = canvas.getContext("2d");
  ctx.drawImage(img, 0, 0);
  const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
  let count = 0;
  for (let i = 0; i < data.length; i += 4)
    if (Math.abs(data[i] - rgb[0]) < 25 && Math.abs(data[i + 1] - rgb[1]) < 25 && Math.abs(data[i + 2] - rgb[2]) < 25) ++count;
  return count;
}, rgb);

// The Code V plate tilted 10 degrees before a singlet (tilted-plate.mjs), uploaded through the file
// picker: the surface table shows the plate's tilt and frame mode, and the colour block gives the
// singlet's focal lengths at F, d and C (the plate adds no power; thick-lens formula with Schott's
// indices: 48.694, 49.213, 49.447 mm).
async function checkTiltedCodeVUpload(page) {
  const upload = join(work, "tilted-plate.seq");
  writeFileSync(upload, TILTED_PLATE_SEQ);
  await page.setInputFiles("#lens-file", upload);
  await waitForUpload(page);
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "tilted-plate");
  await page.waitForFunction(() => document.querySelectorAll("#lens-surfaces tbody tr").length === 4);
  const surfaces = await page.$$eval("#lens-surfaces tbody tr", (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));
  const tilt = "decentre (0.000, 0.000, 0.000) mm, tilt (10.000, 0.000, 0.000)° (decentre and return, decentre then tilt)";
  check(surfaces[0][12] === tilt && surfaces[1][12] === tilt && surfaces[2][12] === "" && surfaces[3][12] === "",
        `the .seq's tilted plate shows its tilt in the surface table: "${surfaces[0][12]}"`);
  const colour = Object.fromEntries(await page.$$eval("#lens-colour tbody tr", (rows) => rows.map((r) => [r.cells[0].textContent, r.querySelector("td").textContent])));
  const efls = colour["EFL at F, d, C"].split(", ").map(Number);
  check(Math.abs(efls[0] - 48.694) < 0.001 && Math.abs(efls[1] - 49.213) < 0.001 && Math.abs(efls[2] - 49.447) < 0.001,
        `and the singlet's focal lengths at F, d, C: ${colour["EFL at F, d, C"]}`);
  const id = await page.getAttribute("#lens-title", "data-id");
  await page.waitForFunction((id) => document.querySelector("#diagram-status").textContent.includes(id), id);
  await (await page.$("#diagram")).screenshot({ path: join(artifacts, "codev-tilted-plate.png") });
}

// A Code V singlet folded by a flat mirror at 45 degrees (ADE 45, BEN), written here: the page's
// diagram of it is drawn, rays and the mirror (the diagram lays a folded lens out in space:
// tests/diagram/test_folded_pictures.cpp checks where). Screenshot: codev-fold-mirror.png.
const FOLD_MIRROR_SEQ = `RDM
LEN "A singlet folded by a mirror at 45 degrees"
WL 587.5618
EPD 20
SO 0 1e10
S 100 5 1.6,40
STO
S -150 20
S 0 -77 REFL
  ADE 45
  BEN
SI 0 0
GO
`;

async function checkFoldedCodeVUpload(page) {
  const upload = join(work, "fold-mirror.seq");
  writeFileSync(upload, FOLD_MIRROR_SEQ);
  const oldSrc = await page.getAttribute("#diagram", "src");
  await page.setInputFiles("#lens-file", upload);
  await waitForUpload(page);
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "fold-mirror");
  const id = await page.getAttribute("#lens-title", "data-id");
  await page.waitForFunction((id) => document.querySelector("#diagram-status").textContent.includes(id), id);
  await page.waitForFunction((old) => { const img = document.querySelector("#diagram"); return img.src !== old && img.complete && img.naturalWidth > 0; }, oldSrc);
  // Rays in the exact rays' blue or, with the colour fans ticked above, the F, d and C lines' colours.
  let rays = 0;
  for (const rgb of [[25, 95, 215], [0, 150, 190], [185, 150, 0], [235, 45, 0]]) rays += await diagramPixelsNear(page, rgb);
  const mirror = await diagramPixelsNear(page, [70, 70, 80]);
  check(rays > 500 && mirror > 50, `the folded .seq's diagram is drawn: ${rays} ray pixels, ${mirror} mirror pixels`);
  await (await page.$("#diagram")).screenshot({ path: join(artifacts, "codev-fold-mirror.png") });
}

async function main() {
  const source = readFileSync(join(sourceDir, "lenses", "us2015-0092100-ex1-55mm.zmx"), "utf8");
  const upload = join(work, "sony-55.zmx");
  writeFileSync(upload, Buffer.from("\ufeff" + source, "utf16le"));
  const { server, base } = await startServer(binary, work);
  const context = await launchBrowser({ width: 1280, height: 900 });
  const page = context.pages()[0] || await context.newPage();
  const diagramUrls = [];
  try {
    page.setDefaultTimeout(30000);
    page.on("request", (r) => { if (r.url().includes("/diagram.png")) diagramUrls.push(r.url()); });
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");
    await page.setInputFiles("#lens-file", upload);
    await waitForUpload(page);
    await page.waitForSelector("#message.info");
    // The uploaded lens's own tables (not the previous lens's): its model glasses show.
    await page.waitForFunction(() => document.querySelector("#lens-surfaces tbody").textContent.includes("model 1.58144"));
    const id = await page.getAttribute("#lens-title", "data-id");

    const surfaces = await page.$$eval("#lens-surfaces tbody tr", (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));
    check(surfaces.length === 15, `the UTF-16 .zmx upload reads 15 surfaces (got ${surfaces.length})`);
    const aspheric = surfaces.filter((cells) => cells[9].includes("r4:"));
    check(aspheric.length === 5, `five surfaces list their aspheric terms (got ${aspheric.length})`);
    check(surfaces.some((cells) => cells[5].startsWith("model 1.58144/40.9")), "model glasses are named by nd/Vd");

    const api = await (await page.request.get(`${base}api/lenses/${id}?fstop=${await page.inputValue("#fstop-input")}&focus=inf`)).json();
    if (api.efl === undefined) throw new Error("the lens API answered " + JSON.stringify(api));
    check(Math.abs(api.efl - 53.61) < 0.005, `the API's EFL ${api.efl.toFixed(4)} is the patent's 53.61`);
    const colour = Object.fromEntries(await page.$$eval("#lens-colour tbody tr", (rows) => rows.map((r) => [r.cells[0].textContent, r.querySelector("td").textContent])));
    const longitudinal = Number(colour["Longitudinal colour (C − F)"]);
    check(Math.abs(longitudinal - api.chromatic.longitudinal_colour_mm) < 1e-4 && longitudinal !== 0,
          `the page's longitudinal colour ${longitudinal} mm is the API's`);
    check(colour["EFL at F, d, C"].split(", ").map(Number).every((v, k) => Math.abs(v - [api.chromatic.efl_F, api.chromatic.efl_d, api.chromatic.efl_C][k]) < 1e-3),
          `EFL at F, d, C: ${colour["EFL at F, d, C"]}`);

    await page.waitForFunction(() => { const img = document.querySelector("#diagram"); return img.src.startsWith("blob:") && img.complete && img.naturalWidth > 0; });
    const plainRed = await diagramPixelsNear(page, [235, 45, 0]);
    const before = diagramUrls.length;
    const oldSrc = await page.getAttribute("#diagram", "src");
    const answered = page.waitForResponse((r) => r.url().includes("colour=1"));
    await page.check("#colour-fans");
    await answered;
    await page.waitForFunction((old) => { const img = document.querySelector("#diagram"); return img.src !== old && img.complete && img.naturalWidth > 0; }, oldSrc);
    const colourRed = await diagramPixelsNear(page, [235, 45, 0]);
    check(diagramUrls.slice(before).some((u) => u.includes("colour=1")), "ticking the box asks for the colour fans");
    check(plainRed === 0 && colourRed > 20, `C-line red pixels in the diagram: ${plainRed} plain, ${colourRed} with colour fans`);

    await page.fill("#wavelength", "486.1327");
    await page.waitForFunction(() => document.querySelector("#lens-colour tbody").textContent.includes("486.13 nm"));
    const efl = Number(await page.$eval("#lens-data tbody tr td", (td) => td.textContent));
    check(Math.abs(efl - api.chromatic.efl_F) < 1e-3, `at 486.13 nm the first-order table shows the F line's EFL ${efl}`);
    const sent = diagramUrls.length;
    await page.fill("#wavelength", "3390");
    await page.waitForTimeout(600);
    check(await page.getAttribute("#wavelength", "aria-invalid") === "true", "3390 nm is marked invalid in its field");
    check(diagramUrls.length === sent, "and nothing is asked for while it is invalid");
    check((await page.textContent("#lens-colour tbody")).includes("486.13 nm"), "the data stay those of the last valid wavelength");
    await page.fill("#wavelength", "");

    // The render form's colour control: spectral or RGB through this dispersive lens, sent as asked.
    await page.selectOption("#scene", "shared-telephoto");
    await page.fill("#width", "32");
    await page.fill("#height", "24");
    await page.fill("#spp", "1");
    for (const [choice, expected, label] of [["off", false, "RGB"], ["on", true, "spectral"], ["", null, ""]]) {
      await page.selectOption("#render-spectral", choice);
      const submitted = page.waitForResponse((r) => r.url().endsWith("/api/renders") && r.request().method() === "POST");
      await page.click("#render-button");
      const job = await (await submitted).json();
      check(job.request && job.request.spectral === expected,
            `colour "${choice || "default"}" submits spectral ${JSON.stringify(job.request && job.request.spectral)}`);
      if (label) {
        const text = await page.locator(`.history-item[data-id="${job.id}"]`).textContent();
        check(text.includes(label), `and the history names it: "${text.trim().slice(0, 120)}"`);
      }
    }
    await page.screenshot({ path: join(artifacts, "zemax-lens.png"), fullPage: true });
    await checkTiltedCodeVUpload(page);
    await checkFoldedCodeVUpload(page);
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
