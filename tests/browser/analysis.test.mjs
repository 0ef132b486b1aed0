// One number, one value, in every view (issue 28): for every bundled lens, the designer's analysis
// as the web page shows it (headless Chromium), as the report shows it (`lenslab report --quick`)
// and as the command line prints it (`lenslab analyze`, JSON and text) is checked against the API's
// answer for the same settings (GET /api/lenses/{id}/analysis). The page and the report mark every
// number they show with its JSON pointer and exact value (data-json, data-value, data-scale): each
// must equal the API's value there, and its text must be that value rounded. The command line's
// JSON must equal the API's, and its text tables and settings line the page's cell for cell. Then
// the page's own controls (f-number, focus, wavelength, image plane, reference, MTF range) on two
// lenses: what the page shows must be the API's analysis at what the controls say.
// usage: node analysis.test.mjs LENSLAB_BINARY SOURCE_DIR
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { closeAll, openPage } from "./serve.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node analysis.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-analysis-"));
const mtfEnds = [];  // each bundled lens's MTF range at the defaults (lp/mm)

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// RFC 6901, as the views write their pointers.
function at(json, pointer) {
  let node = json;
  for (const part of pointer.split("/").slice(1)) {
    if (node === null || typeof node !== "object" || !(part in node)) return undefined;
    node = node[part];
  }
  return node;
}

// Every marked value inside `root` (the page's analysis section, a report's lens section).
const markedValues = (page, root) => page.$$eval(`${root} [data-json]`, (elements) => elements.map((e) => ({
  pointer: e.dataset.json, value: e.dataset.value, scale: e.dataset.scale === undefined ? 1 : Number(e.dataset.scale),
  text: e.textContent.trim() })));

// Each marked value against the API's analysis: the same value, and a shown number that is it rounded
// (the last number in the text: "f/2.8", "486.1 nm: RMS 12.34 µm"). A text with no number stands for
// null, false, 0 or a word.
function compareMarked(marked, api, where) {
  const problems = [];
  for (const m of marked) {
    const expected = at(api, m.pointer);
    if (expected === undefined) { problems.push(`${m.pointer}: not in the API's answer`); continue; }
    if (typeof expected === "number") {
      if (Number(m.value) !== expected) problems.push(`${m.pointer}: shown ${m.value}, API ${expected}`);
      const numbers = m.text.match(/-?\d+(?:\.\d+)?/g);
      if (!numbers) {
        if (expected !== 0) problems.push(`${m.pointer}: "${m.text}" shows no number for ${expected}`);
        continue;
      }
      const shown = numbers[numbers.length - 1];
      const decimals = shown.includes(".") ? shown.length - shown.indexOf(".") - 1 : 0;
      if (Math.abs(Number(shown) - expected * m.scale) > 0.5 * 10 ** -decimals * (1 + 1e-9) + 1e-12)
        problems.push(`${m.pointer}: "${m.text}" is not ${expected} x ${m.scale} rounded`);
    } else if (String(expected) !== m.value) {
      problems.push(`${m.pointer}: shown ${m.value}, API ${JSON.stringify(expected)}`);
    } else if (/\d/.test(m.text) && typeof expected !== "string") {
      problems.push(`${m.pointer}: "${m.text}" shows a number for ${expected}`);
    }
  }
  check(problems.length === 0, `${where}: ${marked.length} shown values equal the API's` + (problems.length ? `\n  ${problems.slice(0, 12).join("\n  ")}` : ""));
}

// The numbers every view must show for an analysis: each field's polychromatic RMS (or that no ray
// arrives), each wavelength's RMS radius, the settings.
function checkComplete(marked, api, where) {
  const pointers = new Set(marked.map((m) => m.pointer));
  const wanted = ["/fstop", "/focus_distance", "/image_plane", "/image_z", "/reference", "/primary_wavelength_nm", "/largest_field_deg",
                  "/largest_field_source", "/obscuration"];
  api.fields.forEach((f, i) => {
    wanted.push(f.traced ? `/fields/${i}/polychromatic/rms_radius_mm` : `/fields/${i}/traced`, `/fields/${i}/field_deg`);
    f.spots.forEach((s, j) => wanted.push(s.rays_passed ? `/fields/${i}/spots/${j}/rms_radius_mm` : `/fields/${i}/spots/${j}/rays_passed`));
  });
  const missing = wanted.filter((p) => !pointers.has(p));
  check(missing.length === 0, `${where} shows every field's spots and the settings` + (missing.length ? `: missing ${missing.join(", ")}` : ""));
}

// Where each MTF plot's frequency axis ends (lp/mm), read from the drawing: the frame's right edge
// placed on the scale of the first and last tick labels.
const mtfAxisEnds = (page) => page.$$eval('#analysis-plots figure[data-plot^="mtf-"] svg', (svgs) => svgs.map((svg) => {
  const ticks = [...svg.querySelectorAll('text[text-anchor="middle"][fill="#333"]')]
    .map((t) => ({ x: Number(t.getAttribute("x")), v: Number(t.textContent) }));
  const frame = svg.querySelector('rect[fill="none"][stroke="#555"]');
  const right = Number(frame.getAttribute("x")) + Number(frame.getAttribute("width"));
  const [a, b] = [ticks[0], ticks[ticks.length - 1]];
  return a.v + (right - a.x) * (b.v - a.v) / (b.x - a.x);
}));

// Every plot drawn: an SVG per figure with its curves or dots (a blocked field's plots carry their note).
const drawnPlots = (page) => page.$$eval("#analysis-plots figure", (figures) => figures.map((f) => ({
  name: f.dataset.plot, svgs: f.querySelectorAll("svg").length,
  marks: f.querySelectorAll("svg g path, svg g circle").length })));

async function apiAnalysis(request, base, id, query = "") {
  const response = await request.get(`${base}api/lenses/${encodeURIComponent(id)}/analysis?${query}`);
  const body = await response.json();
  if (response.status() !== 200) throw new Error(`analysis of ${id}?${query}: ${response.status()} ${JSON.stringify(body)}`);
  return body;
}

// Waits for the page's next analysis after `before` of the lens labelled `label`.
async function nextAnalysis(page, before, label) {
  await page.waitForFunction(([n, label]) => {
    const s = document.querySelector("#analysis");
    return Number(s.dataset.shown || 0) > n && s.dataset.lens === label;
  }, [before, label]);
}
const shownCount = (page) => page.$eval("#analysis", (s) => Number(s.dataset.shown || 0));

// The page's tables and settings line as text, the way `lenslab analyze` prints them.
const pageTablesText = (page) => page.evaluate(() => {
  const lines = [];
  for (const table of document.querySelectorAll("#analysis-tables table")) {
    lines.push(table.caption.textContent);
    for (const row of table.rows) lines.push([...row.cells].map((c) => c.textContent).filter((t) => t !== "").join("  "));
  }
  const settings = [...document.querySelectorAll("#analysis-settings dl > div")].map((d) =>
    `${d.querySelector("dt").textContent}: ${d.querySelector("dd").textContent}`).join("; ");
  return { lines, settings };
});

function cli(args) { return execFileSync(binary, args, { encoding: "utf8", maxBuffer: 64 << 20 }); }

// The API's analysis without what only the service adds (the lens's id and display name, the
// page's views), its keys in order, as the command line prints them.
function withoutPageFields(api) {
  const copy = structuredClone(api);
  delete copy.id;
  delete copy.views;
  delete copy.name;
  return sortedKeys(copy);
}

function sortedKeys(value) {
  if (Array.isArray(value)) return value.map(sortedKeys);
  if (value === null || typeof value !== "object") return value;
  return Object.fromEntries(Object.keys(value).sort().map((k) => [k, sortedKeys(value[k])]));
}

async function checkBundledLens(page, base, lens, file) {
  const before = await shownCount(page);
  await page.click(`#lens-list button[data-id="${lens.id}"]`);
  await nextAnalysis(page, before, lens.id);
  const api = await apiAnalysis(page.request, base, lens.id);
  const marked = await markedValues(page, "#analysis");
  compareMarked(marked, api, `page, ${lens.id}`);
  checkComplete(marked, api, `page, ${lens.id}`);
  const plots = await page.$$eval("#analysis-plots figure", (f) => f.map((e) => e.dataset.plot));
  check(plots.filter((p) => p.startsWith("spot-field-")).length === api.fields.length &&
        plots.filter((p) => /^(spot|mtf|fans)-field-/.test(p)).length === 3 * api.fields.length,
        `page, ${lens.id}: a spot, MTF and fan plot for each of its ${api.fields.length} fields`);
  const drawn = await drawnPlots(page);
  const empty = drawn.filter((p, i) => p.svgs !== 1 ||
    (p.marks === 0 && !/-field-(\d+)$/.test(p.name)) ||
    (p.marks === 0 && api.fields[Number(p.name.match(/-field-(\d+)$/)[1]) - 1].traced));
  check(empty.length === 0, `page, ${lens.id}: each of its ${drawn.length} plots is one SVG with its curves drawn` +
        (empty.length ? `: not ${empty.map((p) => p.name).join(", ")}` : ""));
  // The MTF's frequency axis: 0-200 lp/mm by default, or to the diffraction cutoff when that is lower.
  const end = api.fields[0].mtf.frequencies_lpmm.at(-1);
  check(end <= 200 + 1e-9 && (end > 200 - 1e-9 || api.fields.every((f) => f.mtf.diffraction_limit.at(-1) < 1e-3)),
        `API, ${lens.id}: the MTF runs to ${end.toFixed(1)} lp/mm (200, or the cutoff)`);
  const ends = await mtfAxisEnds(page);
  check(ends.length === api.fields.length && ends.every((e) => Math.abs(e - end) < 1e-3 * end),
        `page, ${lens.id}: every MTF axis ends at ${end.toFixed(1)} lp/mm (${ends.map((e) => e.toFixed(1)).join(", ")})`);
  mtfEnds.push(end);

  // The command line at its defaults is the page at its defaults.
  const json = JSON.parse(cli(["analyze", file, "--json"]));
  delete json.name;
  check(JSON.stringify(sortedKeys(json)) === JSON.stringify(withoutPageFields(api)), `lenslab analyze ${lens.id} --json equals the API's answer`);
  const text = cli(["analyze", file]).trimEnd().split("\n");
  const shown = await pageTablesText(page);
  check(text[0] === `${file}: ${shown.settings} (docs/analysis.md defines each number)`,
        `lenslab analyze ${lens.id}: its settings line is the page's ("${text[0].slice(0, 80)}…")`);
  const cliLines = text.slice(1).map((l) => l.split(/ {2,}/).join("  "));
  check(JSON.stringify(cliLines) === JSON.stringify(shown.lines),
        `lenslab analyze ${lens.id}: its ${cliLines.length} table lines are the page's` +
        (JSON.stringify(cliLines) === JSON.stringify(shown.lines) ? "" : `\n  cli:  ${cliLines.join(" | ").slice(0, 400)}\n  page: ${shown.lines.join(" | ").slice(0, 400)}`));
}

// The report at its own settings (each lens's widest, focused at 2 m or 20 focal lengths): every
// lens section's marked values against the API at the focus the report names.
async function checkReport(page, base, ids) {
  const scenes = join(work, "no-scenes");
  mkdirSync(scenes);
  const site = join(work, "site");
  cli(["report", "--quick", "--quiet", "--scene-dir", scenes, "-o", site]);
  await page.goto(pathToFileURL(join(site, "index.html")).href);
  for (const id of ids) {
    const root = `section.analysis[data-lens="${id}"]`;
    const focus = await page.$eval(`${root} [data-json="/focus_distance"]`, (e) => e.dataset.value);
    const api = await apiAnalysis(page.request, base, id, `focus=${focus === "null" ? "inf" : focus}`);
    const marked = await markedValues(page, root);
    compareMarked(marked, api, `report, ${id}`);
    checkComplete(marked, api, `report, ${id}`);
  }
}

// The controls: what the page shows is the API's analysis at what they say.
async function checkControls(page, base, id, fstop) {
  await page.click(`#lens-list button[data-id="${id}"]`);
  await page.waitForFunction((id) => document.querySelector("#analysis").dataset.lens === id, id);
  let before = await shownCount(page);
  await page.fill("#fstop-input", String(fstop));
  await page.press("#fstop-input", "Enter");
  await page.uncheck("#focus-infinity");
  await page.fill("#focus-mm", "5000");
  await page.fill("#wavelength", "550");
  await nextAnalysis(page, before, id);
  for (const [select, value] of [["#analysis-plane", "best"], ["#analysis-reference", "chief"], ["#analysis-max-frequency", "100"]]) {
    before = await shownCount(page);
    await page.selectOption(select, value);
    await nextAnalysis(page, before, id);
  }
  // Answers to older requests are dropped: the one shown was asked for after the last choice.
  const api = await apiAnalysis(page.request, base, id,
    `fstop=${fstop}&focus=5000&wavelength=550&image_plane=best&reference=chief&max_frequency=100`);
  const marked = await markedValues(page, "#analysis");
  compareMarked(marked, api, `page, ${id} at f/${fstop}, 5 m, 550 nm, best plane, chief ray, MTF to 100 lp/mm`);
  const ends = await mtfAxisEnds(page);
  check(ends.length === api.fields.length && ends.every((e) => Math.abs(e - 100) < 0.1), `its MTF axes end at 100 lp/mm: ${ends.map((e) => e.toFixed(1))}`);
  check(api.image_plane === "best" && api.reference === "chief" && api.primary_wavelength_nm === 550 &&
        Math.abs(api.fields[0].mtf.frequencies_lpmm.at(-1) - 100) < 1e-9, "and those are the settings the API was asked for");
  const words = await page.textContent("#analysis-settings");
  check(words.includes("best") && words.includes("the chief ray") && words.includes(`f/${fstop}`) && words.includes("5000.0 mm"),
        `the settings are named beside the plots: "${words.replace(/\s+/g, " ").trim().slice(0, 160)}…"`);
  const titles = await page.$$eval('#analysis-plots figure[data-plot^="spot-"] svg title', (t) => t.map((e) => e.textContent));
  check(titles.every((t) => t.includes("about the chief ray")), `the spot plots name their reference point: "${titles[0]}"`);
  // Back to the defaults for the next lens.
  await page.selectOption("#analysis-plane", "film");
  await page.selectOption("#analysis-reference", "centroid");
  await page.selectOption("#analysis-max-frequency", "");
  await page.fill("#wavelength", "");
  await page.check("#focus-infinity");
}

async function main() {
  const { server, base, context, page } = await openPage(binary, work, { width: 1280, height: 1000 });
  try {
    const lenses = (await (await page.request.get(`${base}api/lenses`)).json()).lenses.filter((l) => l.bundled);
    const files = new Map(readdirSync(join(sourceDir, "lenses")).filter((f) => /\.(dat|zmx)$/.test(f))
      .map((f) => [f.replace(/\.(dat|zmx)$/, ""), join(sourceDir, "lenses", f)]));
    check(lenses.length === files.size && lenses.length >= 10, `the service offers the ${files.size} bundled lenses`);
    for (const lens of lenses) await checkBundledLens(page, base, lens, files.get(lens.id));
    check(mtfEnds.filter((e) => e === 200).length >= lenses.length / 2, `most MTF axes end at 200 lp/mm: ${mtfEnds.join(", ")}`);
    await checkControls(page, base, "dgauss.50mm", 4);
    await checkControls(page, base, "us4666259-ex1-reflex-500mm", 11);
    await checkReport(page, base, lenses.map((l) => l.id));
  } finally {
    await closeAll(context, server, work);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
