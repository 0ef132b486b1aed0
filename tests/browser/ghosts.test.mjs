// Browser test of coatings, ghosts and lens flare on the web page: the surface table shows each
// surface's coating and reflectance; the ghost panel lists dgauss.50mm's 45 ghosts brightest first,
// as the API ranks them, and plots them; a coating edited to bare glass and saved raises that
// surface's reflectance and its ghosts' intensity; a render of the sun scene with all ghosts runs
// to the end and its statistics count 45 ghost paths; a tilted, shifted render (the lens moved on its
// mount) runs with its request in the history. Screenshot: tests/browser/artifacts/ghosts.png.
// usage: node ghosts.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdirSync, mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node ghosts.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const artifacts = join(dirname(fileURLToPath(import.meta.url)), "artifacts");
mkdirSync(artifacts, { recursive: true });
const work = mkdtempSync(join(tmpdir(), "lenslab-ghosts-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

const tableRows = (page, selector) => page.$$eval(`${selector} tbody tr`, (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));

async function checkGhostPanel(page, base) {
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "dgauss.50mm");
  await page.click("#ghost-panel summary");
  await page.waitForFunction(() => document.querySelectorAll("#ghost-table tbody tr").length === 45);
  const fstop = await page.inputValue("#fstop-input");
  const api = await (await page.request.get(`${base}api/lenses/dgauss.50mm/ghosts?fstop=${fstop}&focus=inf`)).json();
  const rows = await tableRows(page, "#ghost-table");
  check(rows.length === api.ghosts.length && rows.every((cells, i) => cells[1] === `${api.ghosts[i].surfaces[0]}–${api.ghosts[i].surfaces[1]}`),
        `the ghost table lists the API's ${api.ghosts.length} ghosts in its order (first ${rows[0][1]})`);
  const intensities = rows.map((cells) => Number(cells[7]));
  check(intensities.every((v, i) => i === 0 || v <= intensities[i - 1]), "brightest first");
  check(rows.some((cells) => cells[8] === "focused"), `a focused ghost is marked (${rows.filter((c) => c[8] === "focused").map((c) => c[1]).join(", ")})`);
  check(await page.$$eval("#ghost-plot circle", (c) => c.length) === 45, "the plot shows 45 ghosts");

  const surfaces = await tableRows(page, "#lens-surfaces");
  check(surfaces[0][10] === "MgF2@550 (default)" && Number(surfaces[0][11]) > 0.3 && Number(surfaces[0][11]) < 0.6,
        `surface 1 shows its default coating and R ${surfaces[0][11]} %`);
  check(surfaces[5][10] === "" && surfaces[3][10] === "", "the stop and the cemented surface are bare");
  await page.screenshot({ path: join(artifacts, "ghosts.png"), fullPage: true });
  return rows;
}

// Surface 1 made bare glass in the editor and saved: its reflectance becomes Fresnel's
// ((1.67 - 1) / (1.67 + 1))^2 = 6.297 %, and every ghost reflecting there gets brighter.
const BARE_FRONT_PERCENT = 100 * ((1.67 - 1) / (1.67 + 1)) ** 2;
async function checkEditedCoating(page, base, before) {
  const cell = '#editor-table input[data-row="0"][data-key="coating"]';
  await page.fill(cell, "none");
  await page.press(cell, "Tab");
  await page.fill("#editor-name", "dgauss-bare-front");
  await page.click("#editor-save");
  await waitForUpload(page);
  await page.waitForFunction(() => document.querySelector("#lens-surfaces tbody tr td:nth-child(11)").textContent === "");
  const surfaces = await tableRows(page, "#lens-surfaces");
  check(surfaces[0][10] === "" && Math.abs(Number(surfaces[0][11]) - BARE_FRONT_PERCENT) < 0.001,
        `saved bare front: R ${surfaces[0][11]} % (Fresnel: ${BARE_FRONT_PERCENT.toFixed(4)} %)`);
  const saved = await page.getAttribute("#lens-title", "data-id");
  await page.waitForFunction((id) => document.querySelector("#ghost-table").dataset.lens === id &&
                                     document.querySelectorAll("#ghost-table tbody tr").length === 45, saved);
  const after = await tableRows(page, "#ghost-table");
  const intensity = (rows, pair) => Number(rows.find((cells) => cells[1] === pair)[7]);
  check(intensity(after, "10–1") > 5 * intensity(before, "10–1"), `ghost 10–1 brightens ${intensity(before, "10–1")} -> ${intensity(after, "10–1")}`);
}

async function checkFlareRender(page, base) {
  await page.click('#lens-list button[data-id="dgauss.50mm"]');
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "dgauss.50mm");
  await page.selectOption("#scene", "sun-flare");
  await page.fill("#width", "96");
  await page.fill("#height", "64");
  await page.fill("#spp", "2");
  await page.selectOption("#render-ghosts", "all");
  await page.selectOption("#render-ghost-model", "paraxial");
  await page.click("#render-button");
  await page.waitForSelector('.history-item[data-state="done"]', { timeout: 120000 });
  check((await page.textContent(".history-item")).includes("ghosts all (paraxial)"), "the history names the ghosts asked for");
  const job = (await (await page.request.get(`${base}api/renders`)).json()).renders[0];
  check(job.request.ghosts === "all" && job.request.ghost_model === "paraxial" && job.stats.flare_paths === 45,
        `the render modelled ${job.stats.flare_paths} ghost paths (${job.request.ghost_model})`);
}

// Clicks Render and waits for one more finished render in the history: the newest job.
async function renderToTheEnd(page, base) {
  const finished = await page.$$eval('.history-item[data-state="done"]', (items) => items.length);
  await page.click("#render-button");
  await page.waitForFunction((n) => document.querySelectorAll('.history-item[data-state="done"]').length > n, finished,
                             { timeout: 120000 });
  return (await (await page.request.get(`${base}api/renders`)).json()).renders[0];
}

// The render form's tilt and shift reach the job and its history; a shift the service refuses is
// shown with the service's words.
async function checkTiltShiftRender(page, base) {
  await page.selectOption("#render-ghosts", "off");
  await page.selectOption("#scene", "depth-of-field");
  await page.fill("#render-tilt", "4");
  await page.fill("#render-shift", "2,1");
  const job = await renderToTheEnd(page, base);
  check(job.request.tilt === 4 && job.request.swing === null && job.request.shift.join() === "2,1" && job.state === "done",
        `the render was tilted and shifted as asked: ${JSON.stringify([job.request.tilt, job.request.shift, job.state])}`);
  check((await page.textContent(".history-item")).includes("tilt 4° · shift 2, 1 mm"), "the history names the tilt and shift");
  await page.fill("#render-shift", "2");
  await page.click("#render-button");
  await page.waitForSelector("#message:not(.info):not([hidden])");
  const refusal = await page.textContent("#message");
  check(refusal.includes("shift must be two numbers"), `a one-number shift is refused in words: "${refusal}"`);
}

// The sensor fields reach the job, the history names them, and the EXR carries the readout's
// calibration; a film diagonal the pitch contradicts is refused in the service's words.
async function checkSensorRender(page, base) {
  await page.fill("#render-tilt", "");
  await page.fill("#render-shift", "");
  await page.fill("#render-sensor-iso", "6400");
  await page.fill("#render-sensor-pitch", "4.35");
  const job = await renderToTheEnd(page, base);
  check(job.request.sensor.iso === 6400 && job.request.sensor.pitch === 4.35 && job.state === "done",
        `the render was read out by the sensor asked for: ${JSON.stringify(job.request.sensor)}`);
  check((await page.textContent(".history-item")).includes("sensor ISO 6400 4.35 µm"), "the history names the sensor");
  const exr = await (await page.request.get(`${base}api/renders/${job.id}/image.exr`)).body();
  check(exr.includes("ISO 6400, metered exposure"), "the EXR's header carries the sensor's calibration");
  await page.fill("#film-diagonal", "20");
  await page.click("#render-button");
  await page.waitForFunction(() => document.querySelector("#message").textContent.includes("makes a film diagonal of"));
  check(true, `a film diagonal unlike the pitch's is refused in words: "${await page.textContent("#message")}"`);
  await page.fill("#film-diagonal", "");
  await page.fill("#render-sensor-iso", "");
  await page.fill("#render-sensor-pitch", "");
}

async function main() {
  const { server, base, context, page } = await openPage(binary, work, { width: 1280, height: 900 });
  try {
    const before = await checkGhostPanel(page, base);
    await checkEditedCoating(page, base, before);
    await checkFlareRender(page, base);
    await checkTiltShiftRender(page, base);
    await checkSensorRender(page, base);
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
