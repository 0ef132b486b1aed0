// Browser test of the page's API token field: `lenslab serve` on loopback with --token-file (which
// makes every write need the token, loopback or not). In headless Chromium an upload without the
// token is refused and the page says so next to the field; with the token typed in, the same
// upload succeeds, the token is kept for the tab (sessionStorage) and not in localStorage.
// A screenshot of the header with the refusal goes to tests/browser/artifacts/token-refused.png.
// usage: node token.test.mjs LENSLAB_BINARY SOURCE_DIR
import { copyFileSync, mkdirSync, mkdtempSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { closeAll, launchBrowser, startServer, waitForUpload } from "./serve.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node token.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const artifacts = join(dirname(fileURLToPath(import.meta.url)), "artifacts");
mkdirSync(artifacts, { recursive: true });
const work = mkdtempSync(join(tmpdir(), "lenslab-token-"));
const token = "0123456789abcdef0123456789abcdef0123456789abcdef";

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

async function main() {
  writeFileSync(join(work, "token"), token + "\n", { mode: 0o600 });
  const table = join(work, "mine.dat");
  copyFileSync(join(sourceDir, "lenses", "wide.dat"), table);
  const { server, base } = await startServer(binary, work, ["--token-file", join(work, "token")]);
  const context = await launchBrowser({ width: 1280, height: 800 });
  const page = context.pages()[0] || await context.newPage();
  const uploads = [];
  try {
    page.setDefaultTimeout(30000);
    page.on("request", (r) => {
      if (r.method() === "POST" && r.url().endsWith("/api/lenses")) uploads.push(r.headers()["authorization"] || "");
    });
    await page.goto(base);
    await page.waitForSelector("body[data-ready]");
    check(await page.isVisible('#lens-list button[data-id="dgauss.50mm"]'), "reads need no token: the lens list loads");

    await page.setInputFiles("#lens-file", table);
    await page.waitForFunction(() => document.querySelector("#token-status").classList.contains("refused"));
    const refused = await page.textContent("#token-status");
    check(refused.startsWith("Refused (401)") && refused.includes("needs the server's API token"),
          `an upload without the token: "${refused}"`);
    check(uploads.length === 1 && uploads[0] === "", "that upload carried no Authorization header");
    check(await page.evaluate(() => document.activeElement.id) === "token-input", "the keyboard goes to the token field");
    check(!(await page.textContent("#lens-list")).includes("upload-"), "and no lens was added");
    await page.locator("header").screenshot({ path: join(artifacts, "token-refused.png") });

    await page.fill("#token-input", "not-the-token-at-all");
    await page.press("#token-input", "Enter");
    await page.setInputFiles("#lens-file", table);
    await page.waitForFunction(() => document.querySelector("#token-status").textContent.includes("not the server's token"));
    // The refusal reaches the upload's message after the token field; the next upload waits for it.
    await page.waitForFunction(() => !document.querySelector("#message").hidden &&
                                     document.querySelector("#message").textContent.includes("was not accepted"));
    check(true, `a wrong token is told apart: "${await page.textContent("#token-status")}"`);

    await page.fill("#token-input", token);
    await page.press("#token-input", "Enter");
    check((await page.textContent("#token-status")) === "Token set for this tab.", "the token is taken");
    await page.setInputFiles("#lens-file", table);
    await waitForUpload(page);
    await page.waitForSelector("#message.info");
    check(uploads.at(-1) === "Bearer " + token, "the upload carried 'Authorization: Bearer TOKEN'");
    check(!(await page.getAttribute("#token-status", "class")).includes("refused"), "and the refusal is gone");
    const stored = await page.evaluate(() => [sessionStorage.getItem("lenslab.apiToken"), localStorage.getItem("lenslab.apiToken")]);
    check(stored[0] === token && stored[1] === null, "the token is kept in sessionStorage only");

    await page.reload();
    await page.waitForSelector("body[data-ready]");
    check((await page.inputValue("#token-input")) === token, "and is still there after a reload of the tab");
  } finally {
    await closeAll(context, server, work);
  }
}

main().then(() => console.log("token test passed"), (e) => { console.error(e); process.exit(1); });
