// Browser test of the live prescription editor: a radius edited in the table changes the EFL and
// the on-axis RMS spot to what the API gives for the same lens uploaded independently; an invalid
// cell is marked with its reason and nothing is sent; undo restores the EFL; "save as new lens"
// adds a lens to the list; "render through this lens" starts a render that finishes; the .dat and
// .zmx downloads upload again as the same lens. Measures edit-to-update time (numbers and diagram
// shown) on a 22-surface lens and prints it with the load (a timing is reported, not asserted).
// Screenshot: docs/web-editor.png.
// usage: node editor.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdtempSync, readFileSync } from "node:fs";
import { cpus, loadavg, tmpdir } from "node:os";
import { join } from "node:path";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";
import { editCell, editorHolds, previews } from "./editor-cells.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node editor.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-editor-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

const firstOrderEfl = (page) => page.$eval("#lens-data tbody tr td", (td) => Number(td.textContent));
// The on-axis RMS spot at the d line (µm), as the analysis table marks it.
const onAxisRms = (page) => page.$eval('#analysis-tables td[data-json="/fields/0/spots/1/rms_radius_mm"]',
                                       (td) => Number(td.dataset.value) * 1000);

async function lensSelected(page, id) {
  await page.click(`#lens-list button[data-id="${id}"]`);
  await page.waitForFunction((id) => document.querySelector("#lens-title").textContent === id, id);
  await editorHolds(page, id);
}

async function uploadAndAnalyse(request, base, text, name) {
  const upload = await request.post(`${base}api/lenses?name=${name}&layout=gap-after`, { data: text, headers: { "Content-Type": "text/plain" } });
  const lens = await upload.json();
  if (upload.status() !== 201) throw new Error(`upload of ${name}: ${upload.status()} ${JSON.stringify(lens)}`);
  const analysis = await (await request.get(`${base}api/lenses/${lens.id}/analysis`)).json();
  return { lens, analysis };
}

// Edit-to-update time on a 22-surface lens.
async function timing(page) {
    await lensSelected(page, "us2010-0033848-ex1-35mm");
    const surfaces = await page.$$eval("#editor-table tbody tr", (r) => r.length);
    const curved = await page.$$eval('#editor-table input[data-key="radius"]', (inputs) => inputs.findIndex((i, k) => k >= 5 && i.value !== "flat"));
    const radius = Number(await page.inputValue(`#editor-table input[data-row="${curved}"][data-key="radius"]`));
    const times = [];
    for (let k = 0; k < 9; ++k) times.push(await editCell(page, curved, "radius", String(radius * (1 + 0.002 * (k + 1)))));
    times.sort((a, b) => a - b);
    const median = times[Math.floor(times.length / 2)];
    console.log(`edit-to-update on a ${surfaces}-surface lens: median ${median.toFixed(1)} ms, min ${times[0].toFixed(1)}, max ${times[times.length - 1].toFixed(1)} (ms: ${times.map((t) => t.toFixed(0)).join(" ")})`);
    check(surfaces >= 20, `the timing lens has ${surfaces} surfaces`);
    // Wall time measures the machine as much as the editor (the suite runs tests side by side):
    // reported with the load, never asserted; bench/README.md keeps the figures.
    console.log(`# load average ${loadavg()[0].toFixed(1)} on ${cpus().length} cores (the 150 ms goal is checked on a quiet machine)`);

}

async function main() {
  const { server, base, context, page } = await openPage(binary, work, { width: 1280, height: 1000 });
  try {
    const previewBodies = [];  // what the page sends for previews, counted from here
    page.on("request", (r) => { if (r.url().endsWith("/api/prescriptions/preview")) previewBodies.push(r.postData()); });
    if (process.env.EDITOR_TIMING_ONLY) { await timing(page); return; }
    await lensSelected(page, "dgauss.50mm");
    const storedEfl = await firstOrderEfl(page);
    check(Math.abs(storedEfl - 50.358) < 0.01, `dgauss.50mm shows EFL ${storedEfl}`);

    // Edit the first radius: the page's EFL and spot RMS are those of the same rows uploaded.
    await editCell(page, 0, "radius", "31");
    const editedEfl = await firstOrderEfl(page);
    check(Math.abs(editedEfl - storedEfl) > 0.05, `the edited radius changes the EFL: ${storedEfl} -> ${editedEfl}`);
    check(await page.$eval('#editor-table td[data-key="radius"]', (td) => td.classList.contains("changed")), "the edited cell is highlighted");
    const rows = (await page.evaluate(() => fetch("/api/lenses/dgauss.50mm/prescription").then((r) => r.json()))).rows;
    rows[0].radius = 31;
    const table = await (await page.request.post(`${base}api/prescriptions/table.dat`, { data: { rows } })).text();
    const independent = await uploadAndAnalyse(page.request, base, table, "independent.dat");
    check(Math.abs(independent.lens.efl - editedEfl) < 1e-3, `the API's EFL for the same lens is ${independent.lens.efl.toFixed(4)}, the page shows ${editedEfl}`);
    const apiRms = independent.analysis.fields[0].spots[1].rms_radius_mm * 1000;
    const pageRms = await onAxisRms(page);
    check(Math.abs(apiRms - pageRms) < 1e-6, `on-axis RMS spot (d): page ${pageRms.toFixed(3)} µm, API ${apiRms.toFixed(3)} µm`);
    check(await page.$eval("#analysis", (s) => s.dataset.lens) === "edited lens", "the analysis shown is the edited lens's");
    check(await page.$$eval("#analysis-plots svg", (s) => s.length) === 10,
          "three spot diagrams, MTF and fan plots and the chromatic focal shift are drawn");

    // An invalid cell is marked with the reason and not sent; the old text puts it right.
    const sent = previewBodies.length;
    const diameter = '#editor-table input[data-row="2"][data-key="diameter"]';
    const diameterText = await page.inputValue(diameter);
    await page.fill(diameter, "-4");
    await page.waitForTimeout(400);
    const reason = await page.$eval('#editor-table tr[data-row="2"] td[data-key="diameter"] .cell-error', (e) => e.textContent);
    check(reason.includes("positive") && await page.getAttribute(diameter, "aria-invalid") === "true", `the negative diameter is marked: "${reason}"`);
    check(previewBodies.length === sent, "and nothing is sent while it is invalid");
    // Put right, and its preview waited for: an edit's preview still on its way when the next cell
    // is checked would be counted as sent for that cell.
    await editCell(page, 2, "diameter", diameterText);
    const airGlass = await page.$$eval("#editor-table tbody tr", (rows) => rows.findIndex((r) => !r.querySelector('[data-key="index"] input').value));
    const glass = `#editor-table input[data-row="${airGlass}"][data-key="glass"]`;
    const sentBeforeGlass = previewBodies.length;
    await page.fill(glass, "NOSUCHGLASS");
    await page.waitForTimeout(400);
    check((await page.$eval(`#editor-table tr[data-row="${airGlass}"] td[data-key="glass"] .cell-error`, (e) => e.textContent)).includes("NOSUCHGLASS"),
          "an unknown glass name is marked");
    check(previewBodies.length === sentBeforeGlass, "and not sent either");
    await editCell(page, airGlass, "glass", "");

    // A server-side problem (a stop on two rows is impossible here; an overlapping thickness is) lands on its row.
    const before = await previews(page);
    await page.fill('#editor-table input[data-row="3"][data-key="gap"]', "-30");
    await page.press('#editor-table input[data-row="3"][data-key="gap"]', "Tab");
    await page.waitForFunction(() => [...document.querySelectorAll("#editor-table .row-note")].some((n) => n.textContent));
    const note = await page.$$eval("#editor-table .row-note", (notes) => notes.map((n) => n.textContent).filter(Boolean).join(" | "));
    check(note.length > 0, `the service's refusal is shown on the row: "${note}"`);
    check(await previews(page) === before, "and the refused lens is not shown");
    await page.click("#editor-undo");
    await page.waitForFunction(() => !document.querySelector("#editor-status").classList.contains("bad"));

    // Undo back to the stored radius: the stored EFL again; Ctrl+Shift+Z redoes.
    while (!(await page.isDisabled("#editor-undo"))) await page.click("#editor-undo");
    await page.waitForFunction((efl) => Math.abs(Number(document.querySelector("#lens-data tbody tr td").textContent) - efl) < 1e-3, storedEfl);
    check(true, `undo restores the stored EFL ${storedEfl}`);
    await page.keyboard.press("Control+Shift+Z");
    await page.waitForFunction((efl) => Math.abs(Number(document.querySelector("#lens-data tbody tr td").textContent) - efl) < 1e-3, editedEfl);
    check(true, `Ctrl+Shift+Z redoes the radius edit (EFL ${editedEfl})`);

    // Downloads parse as the same lens.
    for (const format of ["dat", "zmx"]) {
      const [file] = await Promise.all([page.waitForEvent("download"), page.click(`#editor-${format}`)]);
      const text = readFileSync(await file.path(), "utf8");
      const again = await uploadAndAnalyse(page.request, base, text, `download.${format}`);
      check(Math.abs(again.lens.efl - editedEfl) < 1e-3, `the .${format} download (${file.suggestedFilename()}) uploads again with EFL ${again.lens.efl.toFixed(4)}`);
    }

    // Save as new: a new lens in the list, selected, with the edited EFL.
    await page.fill("#editor-name", "dgauss-r31");
    await page.click("#editor-save");
    await waitForUpload(page);
    await page.waitForFunction(() => [...document.querySelectorAll("#lens-list button")].some((b) => b.textContent.startsWith("dgauss-r31")));
    const savedId = await page.getAttribute("#lens-title", "data-id");
    const saved = await (await page.request.get(`${base}api/lenses/${savedId}`)).json();
    check(Math.abs(saved.efl - editedEfl) < 1e-3, `saved as ${savedId} "${saved.name}" with EFL ${saved.efl.toFixed(4)}`);

    // Render through an edited lens: saved first, then rendered to the end.
    await lensSelected(page, "dgauss.50mm");
    await editCell(page, 0, "radius", "30");
    await page.fill("#width", "64");
    await page.fill("#height", "48");
    await page.fill("#spp", "4");
    const lensesBefore = (await (await page.request.get(`${base}api/lenses`)).json()).lenses.length;
    await page.click("#editor-render");
    await page.waitForFunction(() => document.querySelector("#history .history-item[data-state=done]"), null, { timeout: 120000 });
    const jobs = (await (await page.request.get(`${base}api/renders`)).json());
    const job = jobs.renders[0];
    const lensesAfter = (await (await page.request.get(`${base}api/lenses`)).json()).lenses.length;
    check(lensesAfter === lensesBefore + 1 && job && job.request.lens.startsWith("upload-") && job.state === "done",
          `render through the edited lens: saved as ${job && job.request.lens}, render ${job && job.id} ${job && job.state}`);

    await timing(page);

    await page.fill('#editor-table input[data-row="7"][data-key="diameter"]', "0");
    await page.waitForTimeout(300);
    await (await page.$("#lens-view")).screenshot({ path: join(sourceDir, "docs", "web-editor.png") });
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
