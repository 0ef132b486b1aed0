// The glass catalogs uploaded to the service (Zemax .agf; docs/api.md, "Glass catalogs"): told from
// lens files by extension or content, uploaded through the lens panel's file picker and drop zone,
// listed by name and glass count, deleted. Their glasses join the editor's glass names at once.
import { $, api, showMessage, uploadFile } from "./api.js";
import { setGlassCatalog } from "./prescription-cells.js";

const glassCount = (n) => `${n} glass${n === 1 ? "" : "es"}`;

// The glass names the editor checks cells against, in the service's search order.
export async function loadGlassNames() {
  setGlassCatalog((await api("/api/glasses")).glasses);
}

// The text of a file's start, UTF-16 too (some makers publish their AGF so).
function startText(bytes) {
  if (bytes[0] === 0xff && bytes[1] === 0xfe) return new TextDecoder("utf-16le").decode(bytes);
  if (bytes[0] === 0xfe && bytes[1] === 0xff) return new TextDecoder("utf-16be").decode(bytes);
  return new TextDecoder("utf-8").decode(bytes);
}

// An .agf file, or one whose first word is an AGF record's (CC comment, NM glass): lens tables
// start with numbers or '#', .zmx with VERS or MODE, .seq with RDM or LEN.
export async function isGlassCatalogFile(file) {
  if (/\.agf$/i.test(file.name)) return true;
  const text = startText(new Uint8Array(await file.slice(0, 4096).arrayBuffer())).replace(/^\ufeff/, "");
  const word = (text.trimStart().split(/\s/)[0] || "");
  return word === "CC" || word === "NM";
}

export async function loadGlassCatalogs() {
  const { catalogs } = await api("/api/glass-catalogs");
  const list = $("glass-catalog-list");
  list.replaceChildren();
  for (const catalog of catalogs) {
    const item = document.createElement("li");
    item.dataset.id = catalog.id;
    const name = document.createElement("span");
    name.textContent = catalog.name;
    const detail = document.createElement("small");
    const shadowed = catalog.shadowed_count ? `, ${catalog.shadowed_count} found first in other catalogs` : "";
    detail.textContent = `${glassCount(catalog.glass_count)}${shadowed} · ${catalog.file_name}`;
    const remove = document.createElement("button");
    remove.type = "button";
    remove.textContent = "Delete";
    remove.setAttribute("aria-label", `Delete the glass catalog ${catalog.name}`);
    remove.addEventListener("click", () => deleteGlassCatalog(catalog));
    item.append(name, remove, detail);
    list.append(item);
  }
  $("glass-catalogs").hidden = catalogs.length === 0;
}

export async function uploadGlassCatalog(file) {
  try {
    const catalog = await uploadFile("/api/glass-catalogs", file, "glass catalogs");
    await Promise.all([loadGlassCatalogs(), loadGlassNames()]);
    showMessage(`Uploaded the glass catalog ${catalog.name} (${glassCount(catalog.glass_count)}).`, "info");
  } catch (e) {
    showMessage(`The glass catalog "${file.name}" was not accepted: ${e.message}`);
  }
}

async function deleteGlassCatalog(catalog) {
  if (!confirm(`Delete the glass catalog ${catalog.name}?`)) return;
  try {
    await api(`/api/glass-catalogs/${encodeURIComponent(catalog.id)}`, { method: "DELETE" });
    await Promise.all([loadGlassCatalogs(), loadGlassNames()]);
  } catch (e) {
    showMessage(`The glass catalog ${catalog.name} could not be deleted: ${e.message}`);
  }
}
