// Browser test of the lenslab web page: starts `lenslab serve` on a free loopback port, then in
// headless Chromium drives it as a user would: uploads (file picker, drag-and-drop, a bad table, a
// busy service),
// the f-number keys and input, renders of the shared telephoto scene shown at the report's exposure,
// the exposure control (no new request), the compare view, history after a reload, accessibility
// at 1280x800 and on a 390-wide phone, the report build, and deleting a render.
// Screenshots go to tests/browser/artifacts/.
// usage: node page.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdtempSync, mkdirSync, copyFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { closeAll, launchBrowser, startServer, waitForUpload } from "./serve.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node page.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const here = dirname(fileURLToPath(import.meta.url));
const artifacts = join(here, "artifacts");
mkdirSync(artifacts, { recursive: true });
const work = mkdtempSync(join(tmpdir(), "lenslab-browser-"));

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// Mean sRGB value (0-255) over the colour channels of the canvas matched by `selector`.
const canvasMean = (page, selector) => page.$eval(selector, (canvas) => {
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  let sum = 0;
  for (let i = 0; i < data.length; i += 4) sum += data[i] + data[i + 1] + data[i + 2];
  return sum / (data.length / 4 * 3);
});

const fstopShown = async (page) => Number(await page.inputValue("#fstop-input"));

// Fills the render form with a small render of the shared telephoto scene.
async function smallRenderSettings(page) {
  await page.selectOption("#scene", "shared-telephoto");
  await page.fill("#width", "96");
  await page.fill("#height", "72");
  await page.fill("#spp", "4");
}

async function checkLensControls(page, work) {
  await page.waitForSelector('#lens-list button[data-id="dgauss.50mm"]');
  check((await page.title()) === "lenslab", "the page loads with the bundled lenses");

  // The service answers the upload 429 (its work pool busy, Retry-After 1 s) eight times: the
  // page waits and asks again until it is taken.
  const upload = join(work, "my-wide.dat");
  copyFileSync(join(sourceDir, "lenses", "wide.dat"), upload);
  let refusals = 0;
  const busy = (route) => (route.request().method() === "POST" && refusals < 8
    ? (++refusals, route.fulfill({ status: 429, headers: { "Retry-After": "1" }, contentType: "application/json",
                                   body: '{"error":"the server is busy with heavy work"}' }))
    : route.continue());
  await page.route(/\/api\/lenses(\?[^/]*)?$/, busy);
  await page.setInputFiles("#lens-file", upload);
  await waitForUpload(page);
  await page.unroute(/\/api\/lenses(\?[^/]*)?$/, busy);
  check(refusals === 8, "an upload refused 8 times as busy (429, Retry-After 1 s) is asked again until it is taken");
  await page.waitForSelector("#message.info");
  const title = await page.textContent("#lens-title");
  const listed = await page.$eval("#lens-list button[aria-current=true]", (b) => b.firstChild.textContent);
  check(title === "my-wide" && listed === "my-wide", `the upload is shown by its file's name: "${title}", listed as "${listed}"`);
  await page.waitForFunction(() => document.querySelector("#editor-name").value === "my-wide-edited");
  check(true, "and the editor's save name follows it: my-wide-edited");
  await page.waitForFunction(() => document.querySelector("#lens-data tbody").textContent.includes("Effective focal length"));
  const efl = await page.$eval("#lens-data tbody tr td", (td) => Number(td.textContent));
  check(Math.abs(efl - 100.11) < 0.05, `the uploaded lens's data table shows EFL ${efl}`);
  await page.waitForFunction(() => {
    const img = document.querySelector("#diagram");
    return img.src.startsWith("blob:") && img.complete && img.naturalWidth > 0;
  });

  await page.click('#lens-list button[data-id="dgauss.50mm"]');
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "dgauss.50mm");
  await page.fill("#fstop-input", "4");
  await page.press("#fstop-input", "Enter");
  await page.press("#fstop-input", "ArrowUp");
  const up = await fstopShown(page);
  check(Math.abs(up - 4.1) < 1e-9, `ArrowUp on the f-number: f/4 -> f/${up}`);
  await page.press("#fstop-input", "Shift+ArrowUp");
  const stop = await fstopShown(page);
  check(Math.abs(stop / 4.1 - Math.SQRT2) < 0.002, `Shift+ArrowUp: f/4.1 -> f/${stop} (a full stop, x${(stop / 4.1).toFixed(4)})`);
  await page.press("#fstop-input", "Shift+ArrowDown");
  await page.press("#fstop-input", "ArrowDown");
  check(Math.abs((await fstopShown(page)) - 4) < 0.011, "Shift+ArrowDown and ArrowDown step back to f/4");
  await page.fill("#fstop-input", "7");
  await page.press("#fstop-input", "ArrowDown");
  check(Math.abs((await fstopShown(page)) - 6.9) < 1e-9, "ArrowDown starts from a typed f/7 not yet entered: f/6.9");
  await page.fill("#fstop-input", "4");
  await page.press("#fstop-input", "Enter");
  await page.click("#stop-narrower");
  check(Math.abs((await fstopShown(page)) / 4 - Math.SQRT2) < 0.002, "the 'narrower' button is a full stop as well");
  await page.waitForFunction(() => document.querySelector("#lens-data tbody").textContent.includes("5.66"));
  check(true, "the lens data follow the f-number (f/5.66)");

  await page.fill("#fstop-input", "0.9");
  await page.press("#fstop-input", "Enter");
  const note = await page.textContent("#fstop-range");
  check(/outside this lens's range, f\/2\.0\d to f\/64/.test(note), `an out-of-range f-number shows the range: "${note}"`);
  check((await page.getAttribute("#fstop-input", "aria-invalid")) === "true", "and marks the input invalid");
  await page.fill("#fstop-input", "5.6");
  await page.press("#fstop-input", "Enter");
  check((await page.getAttribute("#fstop-input", "aria-invalid")) === "false", "a valid f-number is taken again");

  await page.focus("#diagram-status").catch(() => {});
  await page.locator("#lens-title").click();
  const modeBefore = await page.$eval('input[name="mode"]:checked', (r) => r.value);
  await page.keyboard.press("m");
  const modeAfter = await page.$eval('input[name="mode"]:checked', (r) => r.value);
  check(modeBefore === "exact" && modeAfter === "thick", `'m' toggles the diagram ${modeBefore} -> ${modeAfter}`);
  await page.waitForFunction(() => document.querySelector("#diagram-status").textContent.startsWith("thick"));
  await page.keyboard.press("ArrowLeft");
  check(!(await page.isChecked("#focus-infinity")) && Number(await page.inputValue("#focus-mm")) > 0,
        `ArrowLeft brings the focus in from infinity to ${await page.inputValue("#focus-mm")} mm`);
  await page.check("#focus-infinity");

  await page.evaluate(() => {
    const transfer = new DataTransfer();
    transfer.items.add(new File(["# broken\n50 0 1.5 20\n-50 five 1 20\n"], "broken.dat", { type: "text/plain" }));
    document.querySelector("#drop-zone").dispatchEvent(new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }));
  });
  await page.waitForSelector("#message:not(.info):not([hidden])");
  const problem = await page.textContent("#message");
  check(problem.includes("broken.dat:3"), `a bad upload says why: "${problem}"`);
}

async function checkRenderAndExposure(page, base, requests) {
  await page.click('#lens-list button[data-id="telephoto.250mm"]');
  await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "telephoto.250mm");
  await page.fill("#fstop-input", "5.6");
  await page.press("#fstop-input", "Enter");
  await smallRenderSettings(page);
  await page.click("#render-button");
  await page.waitForSelector('.history-item[data-state="done"]', { timeout: 120000 });
  await page.waitForFunction(() => document.querySelector("#exposure-timing").textContent.startsWith("re-mapped"));
  const item = page.locator(".history-item").first();
  check((await item.locator("progress").evaluate((p) => p.value)) === 1, "the render's progress bar is full");
  check((await item.locator(".status").textContent()).startsWith("done"), "the history says it is done");
  const mean = await canvasMean(page, "#viewer-panes canvas");
  check(mean > 60 && mean < 200, `telephoto.250mm at f/5.6, exposure 0 (4N²/π): mean sRGB ${mean.toFixed(1)}`);
  const id = await item.getAttribute("data-id");
  const pixels = await page.request.get(new URL(`/api/renders/${id}/pixels`, base).href);
  const h = pixels.headers();
  const floats = new Float32Array(new Uint8Array(await pixels.body()).buffer);
  check(h["x-image-width"] === "96" && h["x-image-height"] === "72" && floats.length === 96 * 72 * 3 && floats.every(Number.isFinite),
        "GET .../pixels gives 96x72 linear RGB floats");
  check(Math.abs(Number(h["x-image-fstop"]) - 5.6) < 1e-3 && Math.abs(Number(h["x-image-exposure"]) - 4 * 5.6 * 5.6 / Math.PI) < 1e-3,
        `with the f-number ${h["x-image-fstop"]} and the report's exposure 4N²/π = ${h["x-image-exposure"]}`);
  const events = await (await page.request.get(new URL(`/api/renders/${id}/events`, base).href)).text();
  const last = JSON.parse(events.trim().split("\n\n").pop().replace(/^data: /, ""));
  check(last.state === "done" && last.id === id, "the events of a finished render end with its final state");
  const thumb = await canvasMean(page, ".history-item .thumb");
  check(thumb > 40, `its thumbnail is exposed the same way (mean ${thumb.toFixed(1)})`);

  check(requests.some((r) => r.startsWith(`GET ${base}api/renders/${id}/events`)), "the page followed the render through server-sent events");
  requests.length = 0;
  await page.$eval("#exposure", (s) => { s.value = "1"; s.dispatchEvent(new Event("input", { bubbles: true })); });
  const brighter = await canvasMean(page, "#viewer-panes canvas");
  check(brighter > mean + 10, `one stop more exposure brightens the picture: ${mean.toFixed(1)} -> ${brighter.toFixed(1)}`);
  await page.waitForTimeout(300);
  check(requests.length === 0, "without any request" + (requests.length ? ": " + requests.join(", ") : ""));
  await page.click("#exposure-fit");
  const fitted = Number(await page.inputValue("#exposure"));
  check(isFinite(fitted) && fitted !== 1, `'fit' exposes for the 99th percentile: ${fitted} stops`);
  await page.click("#exposure-reset");

  const ms = await page.evaluate(async () => {
    const { exposeInto } = await import("/hdr.js");
    const size = 1024;
    const image = { width: size, height: size, rgb: new Float32Array(size * size * 3).map(() => Math.random() * 0.05), fstop: 5.6 };
    const canvas = document.createElement("canvas");
    canvas.width = canvas.height = size;
    const context = canvas.getContext("2d");
    const times = [];
    for (let k = 0; k < 9; k++) {
      const t0 = performance.now();
      const pixels = context.createImageData(size, size);
      exposeInto(pixels.data, image, 10 * Math.pow(2, k / 10));
      context.putImageData(pixels, 0, 0);
      context.getImageData(0, 0, 1, 1);  // waits for the pixels to land
      times.push(performance.now() - t0);
    }
    return times.sort((a, b) => a - b)[4];
  });
  check(ms < 100, `an exposure change re-maps a 1024x1024 image in ${ms.toFixed(1)} ms (median of 9)`);
}

async function checkCompare(page) {
  await page.click("#compare-button");
  await page.waitForFunction(() => document.querySelectorAll('.history-item[data-state="done"]').length >= 3, null, { timeout: 120000 });
  await page.waitForFunction(() => !document.querySelector("#difference-scale").hidden);
  const boxes = await page.$$eval("#viewer-panes canvas", (cs) => cs.map((c) => { const r = c.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; }));
  const [a, b, d] = boxes;
  check(boxes.length === 3 && a[2] > 100 && [b, d].every((x) => Math.abs(x[1] - a[1]) < 1 && Math.abs(x[2] - a[2]) < 1 && Math.abs(x[3] - a[3]) < 1) &&
        a[0] < b[0] && b[0] < d[0], `compare: exact, thick and |difference| in one row, ${a[2].toFixed(0)}x${a[3].toFixed(0)} each`);
  const stats = await page.textContent("#difference-stats");
  check(/RMSE \d/.test(stats) && /worst pixel \(\d+, \d+\)/.test(stats), `the difference has its numbers: "${stats.slice(0, 60)}…"`);
  const [x, y] = [a[0] + a[2] / 2, a[1] + a[3] / 2];
  await page.mouse.move(x, y);
  const readout = await page.textContent("#pixel-readout");
  check(/exact: [\d.e-]+, [\d.e-]+, [\d.e-]+ · thick: [\d.e-]+/.test(readout), `hover shows linear RGB: "${readout.slice(0, 90)}…"`);
  await page.click("#zoom-in");
  const transforms = await page.$$eval("#viewer-panes .stage", (ss) => ss.map((s) => s.style.transform));
  check(transforms.length === 3 && new Set(transforms).size === 1 && transforms[0].includes("scale(2)"), `zoom is shared: ${transforms[0]}`);
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y + 20);
  await page.mouse.up();
  const panned = await page.$$eval("#viewer-panes .stage", (ss) => ss.map((s) => s.style.transform));
  check(new Set(panned).size === 1 && panned[0] !== transforms[0], `pan is shared: ${panned[0]}`);
  await page.selectOption("#compare-mode", "slider");
  check((await page.$$("#viewer-panes canvas")).length === 2 && (await page.$$("#viewer-panes .pane")).length === 1, "slider mode lays the two over each other");
  await page.selectOption("#compare-mode", "flicker");
  const seen = new Set();
  for (let k = 0; k < 8; k++) { seen.add(await page.textContent("#viewer-panes figcaption")); await page.waitForTimeout(200); }
  check(seen.has("exact") && seen.has("thick"), "flicker mode alternates the two");
  await page.selectOption("#compare-mode", "side");
}

async function checkHistoryAfterReload(page) {
  const ids = await page.$$eval(".history-item", (items) => items.map((i) => i.dataset.id));
  await page.reload();
  await page.waitForSelector("body[data-ready]");
  const again = await page.$$eval(".history-item", (items) => items.map((i) => i.dataset.id));
  check(JSON.stringify(again) === JSON.stringify(ids), `after a reload the history lists the ${ids.length} renders`);
  await page.waitForFunction(() => document.querySelectorAll("#viewer-panes canvas").length === 3);
  check(true, "and the viewer shows the comparison again");
  await page.click(`.history-item[data-id="${ids[2]}"] button:text("Open")`);
  await page.waitForFunction(() => document.querySelectorAll("#viewer-panes canvas").length === 1);
  check(true, "an older render re-opens from the history");
}

async function checkAccessibility(page) {
  const unlabelled = await page.$$eval("input, select, textarea, button, progress", (controls) => controls
    .filter((c) => !(c.labels && c.labels.length) && !c.getAttribute("aria-label") && !c.getAttribute("aria-labelledby") &&
                   !(c.tagName === "BUTTON" && c.textContent.trim()))
    .map((c) => c.outerHTML.slice(0, 80)));
  check(unlabelled.length === 0, "every control has a label" + (unlabelled.length ? ": " + unlabelled.join(" | ") : ""));
  await page.evaluate(() => document.activeElement && document.activeElement.blur());
  await page.keyboard.press("Tab");
  await page.keyboard.press("Tab");
  const outline = await page.evaluate(() => {
    const s = getComputedStyle(document.activeElement);
    return { tag: document.activeElement.tagName, style: s.outlineStyle, width: parseFloat(s.outlineWidth) };
  });
  check(outline.style !== "none" && outline.width >= 2, `keyboard focus is visible (${outline.tag}: ${outline.style} ${outline.width}px)`);
  for (const [width, height, name] of [[1280, 800, "page-1280.png"], [390, 844, "page-phone.png"]]) {
    await page.setViewportSize({ width, height });
    await page.waitForTimeout(100);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    check(overflow <= 0, `at ${width}x${height} nothing sticks out sideways (overflow ${overflow}px)`);
    await page.screenshot({ path: join(artifacts, name), fullPage: true });
  }
  await page.setViewportSize({ width: 1280, height: 800 });
}

async function checkReport(page, base) {
  await page.click("#report-build");
  await page.waitForFunction(() => document.querySelector("#report-status").textContent.startsWith("building the report"));
  check(await page.locator("#report-build").isDisabled(), "the report button waits while a build runs");
  const cancelled = await page.request.delete(new URL("/api/report", base).href);
  check(cancelled.status() === 202, `cancelling the report build answers ${cancelled.status()}`);
  await page.waitForFunction(() => document.querySelector("#report-status").textContent.includes("cancelled"), null, { timeout: 60000 });
}

// Without server-sent events the page follows a render by polling.
async function checkPollingFallback(context, base) {
  const page = await context.newPage();
  try {
    await page.addInitScript(() => { delete window.EventSource; });
    const streams = [];
    page.on("request", (r) => { if (r.url().includes("/events")) streams.push(r.url()); });
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");
    const before = await page.$$eval(".history-item", (items) => items.length);
    await smallRenderSettings(page);
    await page.fill("#width", "32");
    await page.fill("#height", "24");
    await page.click("#render-button");
    await page.waitForFunction((n) => document.querySelectorAll(".history-item").length > n, before);
    await page.waitForSelector('.history-item:first-child[data-state="done"]', { timeout: 60000 });
    check(streams.length === 0, "without EventSource a render is followed to the end by polling");
  } finally {
    await page.close();
  }
}

async function checkDeletion(page, base) {
  const id = await page.$eval('.history-item[data-state="done"]', (i) => i.dataset.id);
  await page.click(`.history-item[data-id="${id}"] button:text("Delete")`);
  await page.waitForSelector(`.history-item[data-id="${id}"]`, { state: "detached", timeout: 10000 })
    .catch(async () => { throw new Error(`render ${id} is still listed; the page says: ${await page.textContent("#message")}`); });
  check(true, `the deleted render ${id} left the list`);
  const list = await (await page.request.get(new URL("/api/renders", base).href)).json();
  check(!list.renders.some((r) => r.id === id), "and the service no longer lists it");
}

async function main() {
  const { server, base } = await startServer(binary, work);
  const context = await launchBrowser({ width: 1280, height: 800 });
  const pageErrors = [];
  const externalRequests = [];
  const renderRequests = [];
  const page = context.pages()[0] || await context.newPage();
  try {
    page.on("pageerror", (e) => pageErrors.push(e.message));
    page.on("request", (r) => {
      const url = r.url();
      if (!url.startsWith(base) && !url.startsWith("blob:") && !url.startsWith("data:")) externalRequests.push(url);
      if (url.includes("/api/renders")) renderRequests.push(r.method() + " " + url);
    });
    page.setDefaultTimeout(30000);
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");

    await checkLensControls(page, work);
    await checkRenderAndExposure(page, base, renderRequests);
    await checkCompare(page);
    await page.screenshot({ path: join(artifacts, "page.png"), fullPage: true });
    await checkHistoryAfterReload(page);
    await checkAccessibility(page);
    await checkReport(page, base);
    await checkPollingFallback(context, base);
    check(pageErrors.length === 0, "no script errors" + (pageErrors.length ? ": " + pageErrors.join("; ") : ""));
    check(externalRequests.length === 0, "no request leaves the service" + (externalRequests.length ? ": " + externalRequests.join(", ") : ""));
    await checkDeletion(page, base);
  } catch (e) {
    await page.screenshot({ path: join(artifacts, "failure.png"), fullPage: true }).catch(() => {});
    console.error("page errors:", pageErrors.join("; ") || "none");
    throw e;
  } finally {
    await closeAll(context, server, work);
  }
}

main().then(() => console.log("browser test passed"), (e) => { console.error(e); process.exit(1); });
