// Browser test of the editor keeping what it does not show: a Code V lens whose plate is tilted 10
// degrees (returning decentres) with a field list and EPD is uploaded; its tilted rows are marked in
// the editor and its automatic diameters show as "auto"; one radius of the singlet behind is edited
// (50 -> 48 mm) and its rear diameter fixed at 12 mm; the .zmx download holds the new curvature and
// diameter, both tilts, the field list and the aperture, and the lens saved as new is a .zmx with the
// tilts (a .dat would have dropped them).
// usage: node editor-tilted.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { closeAll, openPage, waitForUpload } from "./serve.mjs";
import { editCell, editorHolds } from "./editor-cells.mjs";
import { TILTED_PLATE_SEQ } from "./tilted-plate.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node editor-tilted.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-editor-tilted-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// Zemax's lines for the plate's two tilted faces (SCBD 1, order 0, 10 degrees about x), the field
// list (FTYP 0: angles, 2 fields; YFLN 0 and 3 degrees in 12 slots), the aperture and the edited
// radius (CURV 1/48 to long double's digits, which read back as 48 mm).
const KEPT_LINES = ["  SCBD 1 0 0 0 0 10 0 0\n", "\nFTYP 0 0 2 1 0 0 0\n", "\nYFLN 0 3 0 0 0 0 0 0 0 0 0 0\n", "\nENPD 10\n"];
const EDITED_CURVATURE = "  CURV 0.020833333333333333\n";
const count = (text, part) => text.split(part).length - 1;

async function main() {
  const { server, base, context, page } = await openPage(binary, work, { width: 1280, height: 1000 });
  try {
    const upload = join(work, "tilted-plate.seq");
    writeFileSync(upload, TILTED_PLATE_SEQ);
    await page.setInputFiles("#lens-file", upload);
    await waitForUpload(page);
    const id = await page.getAttribute("#lens-title", "data-id");
    await editorHolds(page, id);
    const kept = await page.$$eval("#editor-table tbody tr .surface-number", (cells) => cells.map((c) => c.dataset.kept || ""));
    check(kept.join("|") === "decentre and tilt (decentre and return)|decentre and tilt (decentre and return)||",
          `the tilted rows are marked as kept: ${JSON.stringify(kept)}`);

    const diameters = await page.$$eval('#editor-table input[data-key="diameter"]', (inputs) => inputs.map((i) => i.value));
    check(diameters.every((d) => d === "auto"), `the diameters the file leaves to the program show as ${JSON.stringify(diameters)}`);

    await editCell(page, 2, "radius", "48");
    await editCell(page, 3, "diameter", "12");  // the rear face's clear aperture fixed: DIAM 6
    check(await page.$eval('#editor-table tr[data-row="2"] td[data-key="radius"]', (td) => td.classList.contains("changed")),
          "the edited radius is marked changed");
    const [file] = await Promise.all([page.waitForEvent("download"), page.click("#editor-zmx")]);
    const zmx = readFileSync(await file.path(), "utf8");
    check(zmx.includes(EDITED_CURVATURE), `the .zmx download (${file.suggestedFilename()}) has the edited radius: ${EDITED_CURVATURE.trim()}`);
    check(count(zmx, KEPT_LINES[0]) === 2, `and both tilted faces: ${count(zmx, KEPT_LINES[0])} x ${KEPT_LINES[0].trim()}`);
    for (const line of KEPT_LINES.slice(1)) check(zmx.includes(line), `and ${line.trim()}`);
    check(count(zmx, "  DIAM 0\n") === 3 && count(zmx, "  DIAM 6\n") === 1,
          `the typed diameter is the rear face's (DIAM 6), the others stay automatic (DIAM 0 x ${count(zmx, "  DIAM 0\n")})`);

    // The stored lens's own download is named by its display name.
    const stored = await page.request.get(`${base}api/lenses/${id}/prescription.zmx`);
    check(stored.headers()["content-disposition"].includes('filename="tilted-plate.zmx"'),
          `the stored lens downloads as ${stored.headers()["content-disposition"]}`);

    await page.fill("#editor-name", "tilted-r48");
    await page.click("#editor-save");
    await page.waitForFunction((old) => document.querySelector("#lens-title").dataset.id !== old, id, { timeout: 120000 });
    const savedId = await page.getAttribute("#lens-title", "data-id");
    const saved = await (await page.request.get(`${base}api/lenses/${savedId}/prescription`)).json();
    check(saved.name === "tilted-r48.zmx" && saved.rows[0].frame && saved.rows[0].frame.tilt_degrees[0] === 10 && saved.rows[2].radius === 48 &&
          saved.fields.points.length === 2, `saved as ${saved.name}: tilt ${saved.rows[0].frame && saved.rows[0].frame.tilt_degrees}, radius ${saved.rows[2].radius}, ${saved.fields.points.length} fields`);
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
