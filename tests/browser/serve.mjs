// Starts `lenslab serve` on a free loopback port with a fresh data folder under `work`, and headless
// Chromium (Debian's /usr/bin/chromium) with a throw-away profile; shared by the browser scripts.
import { spawn } from "node:child_process";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { chromium } from "playwright-core";

// Resolves with { server, base } once the service prints its listening line; `extra`: more flags.
export function startServer(binary, work, extra = []) {
  const server = spawn(binary, ["serve", "--port", "0", "--data", join(work, "data"), "--access-log", join(work, "access.log"),
    ...extra], { stdio: ["ignore", "pipe", "pipe"] });
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

export async function stopServer(server) {
  const exited = new Promise((resolve) => server.once("exit", resolve));
  server.kill("SIGTERM");
  // The fallback timer is cleared: a pending one keeps node alive for its whole 10 s after the test.
  let timer;
  await Promise.race([exited, new Promise((resolve) => { timer = setTimeout(resolve, 10000); })]);
  clearTimeout(timer);
}

// The end of a page test: the browser, the server and the test's scratch folder, all gone.
export async function closeAll(context, server, work) {
  await context.close();
  await stopServer(server);
  rmSync(work, { recursive: true, force: true });
}

// The page of a fresh `lenslab serve` loaded and ready in headless Chromium, its errors logged, waits
// up to 60 s: { server, base, context, page }. On a failure here everything is closed again.
export async function openPage(binary, work, viewport) {
  const { server, base } = await startServer(binary, work);
  const context = await launchBrowser(viewport);
  try {
    const page = context.pages()[0] || await context.newPage();
    page.setDefaultTimeout(60000);
    page.on("pageerror", (e) => console.log("# page error:", e.message));
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");
    return { server, base, context, page };
  } catch (e) {
    await closeAll(context, server, work);
    throw e;
  }
}

// Waits until an uploaded (or saved-as-new) lens is selected. An upload is parsed in the service's
// work pool, behind whatever the page has asked for already, so this waits up to 120 s; a refusal the
// page shows (the upload's message, the editor's "Not saved") fails it at once, in the page's words.
export async function waitForUpload(page) {
  const outcome = await page.waitForFunction(() => {
    const status = document.querySelector("#editor-status");
    if (status && status.classList.contains("bad") && status.textContent.startsWith("Not saved")) return status.textContent;
    const message = document.querySelector("#message");
    if (!message.hidden && message.textContent.includes("was not accepted")) return message.textContent;
    return document.querySelector("#lens-title").dataset.id.startsWith("upload-") ? "selected" : false;
  }, null, { timeout: 120000 });
  const value = await outcome.jsonValue();
  if (value !== "selected") throw new Error("the upload was refused: " + value);
}

export function launchBrowser(viewport) {
  return chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "lenslab-chromium-")), {
    executablePath: "/usr/bin/chromium",
    headless: true,
    viewport,
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync"],
  });
}
