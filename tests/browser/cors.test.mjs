// Browser test of --allow-origin (issue 23, finding 8): a page served from a second origin calls
// the API in headless Chromium with its token. Listed, its upload (a preflighted POST with
// Authorization) succeeds and it reads the answer; an origin not listed cannot.
// usage: node cors.test.mjs LENSLAB_BINARY SOURCE_DIR
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { createServer } from "node:http";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { launchBrowser, startServer, stopServer } from "./serve.mjs";

const [binary, sourceDir] = process.argv.slice(2);
if (!binary || !sourceDir) {
  console.error("usage: node cors.test.mjs LENSLAB_BINARY SOURCE_DIR");
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), "lenslab-cors-"));
const token = "0123456789abcdef0123456789abcdef0123456789abcdef";

function check(condition, message) {
  if (!condition) throw new Error("check failed: " + message);
  console.log("ok -", message);
}

// A page on its own loopback port: the second origin.
function servePage() {
  const page = createServer((req, res) => {
    res.writeHead(200, { "Content-Type": "text/html" });
    res.end('<!doctype html><html><head><link rel="icon" href="data:,"></head><body>another site</body></html>');
  });
  return new Promise((resolve) => page.listen(0, "127.0.0.1", () => resolve(page)));
}

// Uploads a lens table from the page with the token; returns the status and id, or the failure.
function uploadFrom(page, api, table) {
  return page.evaluate(async ({ api, table, token }) => {
    try {
      const r = await fetch(api + "api/lenses?name=cors.dat",
                            { method: "POST", body: table, headers: { "Content-Type": "text/plain", Authorization: "Bearer " + token } });
      return { status: r.status, id: (await r.json()).id };
    } catch (e) {
      return { failed: String(e) };
    }
  }, { api, table, token });
}

async function main() {
  writeFileSync(join(work, "token"), token + "\n", { mode: 0o600 });
  const table = readFileSync(join(sourceDir, "lenses", "dgauss.50mm.dat"), "utf8");
  const pageServer = await servePage();
  const origin = `http://127.0.0.1:${pageServer.address().port}`;
  const { server, base } = await startServer(binary, work, ["--token-file", join(work, "token"), "--allow-origin", origin]);
  mkdirSync(join(work, "other"));
  const other = await startServer(binary, join(work, "other"), ["--token-file", join(work, "token")]);
  const context = await launchBrowser({ width: 800, height: 600 });
  const page = context.pages()[0] || await context.newPage();
  try {
    await page.goto(origin + "/");
    const listed = await uploadFrom(page, base, table);
    check(listed.status === 201 && String(listed.id).startsWith("upload-"),
          `a listed origin uploads with its token and reads the answer: ${JSON.stringify(listed)}`);
    const lenses = await page.evaluate(async (api) => (await (await fetch(api + "api/lenses")).json()).lenses.length, base);
    check(lenses > 0, `and reads the lens list (${lenses} lenses)`);
    const unlisted = await uploadFrom(page, other.base, table);
    check(unlisted.failed !== undefined, `an origin not listed cannot: ${JSON.stringify(unlisted)}`);
  } finally {
    await context.close();
    await stopServer(server);
    await stopServer(other.server);
    pageServer.close();
    rmSync(work, { recursive: true, force: true });
  }
}

main().then(() => console.log("cors test passed"), (e) => { console.error(e); process.exit(1); });
