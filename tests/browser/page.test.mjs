// Browser test of the lenslab web page: starts `lenslab serve` on a free loopback port, then in
// headless Chromium uploads a lens (file picker and drag-and-drop), checks its data and diagram,
// changes the aperture, sees a bad upload explained, requests a small render and watches it finish.
// Screenshots go to tests/browser/artifacts/.
// usage: node page.test.mjs LENSLAB_BINARY SOURCE_DIR
import { spawn } from "node:child_process";
import { mkdtempSync, mkdirSync, rmSync, copyFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

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

// Starts the service and resolves with its base URL once it prints the listening line.
function startServer() {
  const server = spawn(binary, ["serve", "--port", "0", "--data", join(work, "data"), "--access-log", join(work, "access.log")],
    { stdio: ["ignore", "pipe", "pipe"] });
  return new Promise((resolve, reject) => {
    let output = "";
    const timer = setTimeout(() => reject(new Error("server did not start:\n" + output)), 30000);
    const onData = (chunk) => {
      output += chunk;
      const m = output.match(/listening on (http:\/\/[^/\s]+\/)/);
      if (m) { clearTimeout(timer); resolve({ server, base: m[1] }); }
    };
    server.stdout.on("data", onData);
    server.stderr.on("data", onData);
    server.on("exit", (code) => reject(new Error(`server exited (${code}):\n${output}`)));
  });
}

async function main() {
  const { server, base } = await startServer();
  const context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "lenslab-chromium-")), {
    executablePath: "/usr/bin/chromium",
    headless: true,
    viewport: { width: 1366, height: 900 },
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync"],
  });
  const pageErrors = [];
  const externalRequests = [];
  const page = context.pages()[0] || await context.newPage();
  try {
    page.on("pageerror", (e) => pageErrors.push(e.message));
    page.on("request", (r) => { if (!r.url().startsWith(base) && !r.url().startsWith("blob:") && !r.url().startsWith("data:")) externalRequests.push(r.url()); });
    page.setDefaultTimeout(30000);

    await page.goto(base);
    await page.waitForSelector('#lens-list button[data-id="dgauss.50mm"]');
    check((await page.title()) === "lenslab", "the page loads with the bundled lenses");

    // Upload through the file picker.
    const upload = join(work, "my-wide.dat");
    copyFileSync(join(sourceDir, "lenses", "wide.dat"), upload);
    await page.setInputFiles("#lens-file", upload);
    await page.waitForFunction(() => document.querySelector("#lens-title").textContent.startsWith("upload-"));
    await page.waitForSelector("#message.info");
    const uploadedId = (await page.textContent("#lens-title")).trim();
    check(uploadedId.startsWith("upload-"), `the upload is selected as ${uploadedId}`);
    await page.waitForFunction(() => document.querySelector("#lens-data tbody").textContent.includes("Effective focal length"));
    const efl = await page.$eval("#lens-data tbody tr td", (td) => Number(td.textContent));
    check(Math.abs(efl - 100.11) < 0.05, `its data table shows EFL ${efl}`);
    await page.waitForFunction(() => {
      const img = document.querySelector("#diagram");
      return img.src.startsWith("blob:") && img.complete && img.naturalWidth > 0;
    });
    check(true, "its diagram is drawn");

    // Change the aperture by two stops and the mode: the diagram and the table follow.
    const before = await page.textContent("#fstop-value");
    await page.$eval("#fstop-slider", (s) => { s.value = 2; s.dispatchEvent(new Event("input", { bubbles: true })); });
    await page.check('input[name="mode"][value="overlay"]');
    await page.waitForFunction(() => document.querySelector("#diagram-status").textContent.startsWith("overlay"));
    const after = await page.textContent("#fstop-value");
    check(Math.abs(Number(after) / Number(before) - 2) < 0.01, `f/${before} -> f/${after} after two stops`);

    // A broken table dropped on the drop zone is explained in words.
    await page.evaluate(() => {
      const transfer = new DataTransfer();
      transfer.items.add(new File(["# broken\n50 0 1.5 20\n-50 five 1 20\n"], "broken.dat", { type: "text/plain" }));
      document.querySelector("#drop-zone").dispatchEvent(new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }));
    });
    await page.waitForSelector("#message:not(.info):not([hidden])");
    const problem = await page.textContent("#message");
    check(problem.includes("broken.dat:3"), `a bad upload says why: "${problem}"`);

    // A small render of the bundled double Gauss, watched to completion.
    await page.click('#lens-list button[data-id="dgauss.50mm"]');
    await page.waitForFunction(() => document.querySelector("#lens-title").textContent === "dgauss.50mm");
    await page.fill("#width", "64");
    await page.fill("#height", "48");
    await page.fill("#spp", "4");
    await page.click("#render-button");
    await page.waitForSelector('.render-card[data-state="done"]', { timeout: 120000 });
    const card = page.locator('.render-card[data-state="done"]').first();
    check((await card.locator("progress").evaluate((p) => p.value)) === 1, "the render's progress bar is full");
    check(await card.locator('a[href$="image.exr"]').isVisible(), "PNG and EXR downloads are offered");
    const status = await card.locator(".status").textContent();
    check(status.startsWith("Done"), `the render reports "${status}"`);

    // The report is built as a job from the header; cancelled here (a full build takes minutes).
    await page.click("#report-build");
    await page.waitForFunction(() => document.querySelector("#report-status").textContent.startsWith("building the report"));
    check(await page.locator("#report-build").isDisabled(), "the report button waits while a build runs");
    const cancelled = await page.request.delete(new URL("/api/report", base).href);
    check(cancelled.status() === 202, `cancelling the report build answers ${cancelled.status()}`);
    await page.waitForFunction(() => document.querySelector("#report-status").textContent.includes("cancelled"), null, { timeout: 60000 });

    await page.screenshot({ path: join(artifacts, "page.png"), fullPage: true });
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.screenshot({ path: join(artifacts, "page-top.png") });
    check(pageErrors.length === 0, "no script errors" + (pageErrors.length ? ": " + pageErrors.join("; ") : ""));
    check(externalRequests.length === 0, "no request leaves the service" + (externalRequests.length ? ": " + externalRequests.join(", ") : ""));
  } catch (e) {
    await page.screenshot({ path: join(artifacts, "failure.png"), fullPage: true }).catch(() => {});
    console.error("page errors:", pageErrors.join("; ") || "none");
    throw e;
  } finally {
    await context.close();
    const exited = new Promise((resolve) => server.once("exit", resolve));
    server.kill("SIGTERM");
    await Promise.race([exited, new Promise((resolve) => setTimeout(resolve, 10000))]);
    rmSync(work, { recursive: true, force: true });
  }
}

main().then(() => console.log("browser test passed"), (e) => { console.error(e); process.exit(1); });
