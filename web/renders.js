// Renders: submitting them with the lens panel's settings, the history of the user's renders
// (settings, thumbnail, live progress with ETA, re-opening, deleting) and what the viewer shows.
import { $, api, clearMessage, etaText, follow, postJson, showMessage } from "./api.js";
import { exposeSrgbBytes, normalisation } from "./hdr.js";
import { currentFocus, fstopParameter, selectedLens } from "./lens.js";
import { forgetPixels, renderFinished, showPreview, showRenders, shownIds } from "./viewer.js";

const HISTORY_LENGTH = 24;
const THUMB_WIDTH = 112;
const VIEWED_KEY = "lenslab.viewer";  // the renders last open in the viewer, for a reload

const items = new Map();  // render id -> { job, element, parts }

const isOver = (state) => ["done", "failed", "cancelled"].includes(state);
// Jobs from before the lens model's one vocabulary say accurate / approximate.
const modeLabel = (mode) => ({ accurate: "exact", approximate: "thick" }[mode] || mode);

function renderRequest(mode) {
  const request = {
    scene: $("scene").value,
    lens: selectedLens(),
    fstop: fstopParameter(),
    mode,
    spp: Number($("spp").value),
    width: Number($("width").value),
    height: Number($("height").value),
  };
  if (currentFocus() !== "inf") request.focaldistance = currentFocus();
  if ($("film-diagonal").value) request.filmdiagonal = Number($("film-diagonal").value);
  if ($("render-spectral").value) request.spectral = $("render-spectral").value === "on";
  if ($("render-ghosts").value !== "off") {
    request.ghosts = $("render-ghosts").value;
    request.ghost_model = $("render-ghost-model").value;
  }
  if ($("render-tilt").value) request.tilt = Number($("render-tilt").value);
  if ($("render-swing").value) request.swing = Number($("render-swing").value);
  if ($("render-sensor-iso").value || $("render-sensor-pitch").value) {
    request.sensor = {};
    if ($("render-sensor-iso").value) request.sensor.iso = Number($("render-sensor-iso").value);
    if ($("render-sensor-pitch").value) request.sensor.pitch = Number($("render-sensor-pitch").value);
  }
  // "x,y" as typed; anything else goes to the service as written, which refuses it by name.
  const shift = $("render-shift").value.trim();
  if (shift) request.shift = shift.split(",").map((v) => (v.trim() === "" || isNaN(Number(v)) ? v.trim() : Number(v)));
  return request;
}

function describeRequest(r) {
  const fstop = r.fstop ? `f/${Number(r.fstop).toFixed(1)}` : "scene f-number";
  const focus = r.focaldistance ? `focus ${Math.round(r.focaldistance)} mm` : "scene focus";
  const film = r.spectral === true ? " · spectral" : r.spectral === false ? " · RGB" : "";
  const ghosts = r.ghosts && r.ghosts !== "off" ? ` · ghosts ${r.ghosts} (${r.ghost_model})` : "";
  const turns = [r.tilt ? `tilt ${r.tilt}°` : "", r.swing ? `swing ${r.swing}°` : "", r.shift ? `shift ${r.shift.join(", ")} mm` : ""];
  const mount = turns.filter(Boolean).map((t) => ` · ${t}`).join("");
  const sensor = r.sensor ? ` · sensor${r.sensor.iso ? ` ISO ${r.sensor.iso}` : ""}${r.sensor.pitch ? ` ${r.sensor.pitch} µm` : ""}` : "";
  return `${r.lens} · ${r.scene} · ${fstop} · ${focus} · ${r.width}×${r.height} · ${r.spp} spp${film}${ghosts}${mount}${sensor}`;
}

// ---- the viewer's renders ------------------------------------------------------------------------

function viewerEntry(id) {
  const { job } = items.get(id);
  const r = job.request;
  return { id, label: modeLabel(r.mode), fstop: r.fstop || 0, width: r.width, height: r.height, done: job.state === "done" };
}

function openInViewer(ids) {
  const known = ids.filter((id) => items.has(id));
  if (!known.length) return;
  localStorage.setItem(VIEWED_KEY, JSON.stringify(known));
  for (const [id, item] of items) item.element.classList.toggle("shown", known.includes(id));
  showRenders(known.map(viewerEntry));
}

// ---- history items ---------------------------------------------------------------------------------

function button(text, label, onClick) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.setAttribute("aria-label", label);
  b.addEventListener("click", onClick);
  return b;
}

function addItem(job, atTop) {
  const element = document.createElement("li");
  element.className = "history-item";
  element.dataset.id = job.id;
  const thumb = document.createElement("canvas");
  thumb.className = "thumb";
  thumb.width = THUMB_WIDTH;
  thumb.height = Math.max(1, Math.round((THUMB_WIDTH * job.request.height) / job.request.width));
  thumb.setAttribute("role", "img");
  thumb.setAttribute("aria-label", `thumbnail of ${job.id}`);
  const text = document.createElement("div");
  text.className = "history-text";
  const title = document.createElement("strong");
  title.textContent = `${modeLabel(job.request.mode)} · ${new Date(job.created * 1000).toLocaleTimeString()}`;
  const about = document.createElement("span");
  about.className = "muted";
  about.textContent = describeRequest(job.request);
  const progress = document.createElement("progress");
  progress.max = 1;
  progress.value = 0;
  progress.setAttribute("aria-label", `progress of ${job.id}`);
  const status = document.createElement("span");
  status.className = "status";
  // What the finished picture does not show (the lens blocking most rays, a small image circle).
  const warning = document.createElement("span");
  warning.className = "range-note bad";
  warning.hidden = true;
  const actions = document.createElement("div");
  actions.className = "actions";
  const id = job.id;
  actions.append(
    button("Open", `open render ${id}`, () => openInViewer([id])),
    button("Compare with shown", `compare render ${id} with the render shown`, () => {
      const first = shownIds().find((other) => other !== id);
      openInViewer(first ? [first, id] : [id]);
    }),
    button("Delete", `delete render ${id}`, () => deleteRender(id)));
  text.append(title, about, progress, status, warning, actions);
  element.append(thumb, text);
  $("history").insertAdjacentElement(atTop ? "afterbegin" : "beforeend", element);
  const item = { job, element, thumb, progress, status, warning, actions, tilesSeen: 0 };
  items.set(id, item);
  update(item, job);
  if (!isOver(job.state)) followRender(item);
  else if (job.state === "done") drawFinalThumbnail(item);
}

function update(item, job) {
  item.job = { ...item.job, ...job };
  const p = job.progress;
  item.progress.value = p.fraction;
  item.element.dataset.state = job.state;
  item.status.className = "status state-" + job.state;
  const eta = etaText(p.eta_s);
  item.status.textContent = {
    queued: "waiting in the queue…",
    running: `rendering: ${p.tiles_done} of ${p.tiles_total || "?"} tiles, ${p.elapsed_s.toFixed(1)} s${eta ? ", " + eta : ""}`,
    done: `done: ${p.tiles_total} tiles in ${p.elapsed_s.toFixed(1)} s`,
    failed: "failed: " + (job.error || "unknown reason"),
    cancelled: "cancelled",
  }[job.state] || job.state;
  const warnings = job.warnings || [];
  item.warning.hidden = !warnings.length;
  item.warning.textContent = warnings.map((w) => "warning: " + w).join("; ");
  const downloads = item.actions.querySelectorAll("a");
  if (job.state === "done" && !downloads.length) {
    for (const format of ["png", "exr"]) {
      const a = document.createElement("a");
      a.href = job.links[format];
      a.download = `${job.id}.${format}`;
      a.textContent = format.toUpperCase();
      a.setAttribute("aria-label", `download ${job.id} as ${format.toUpperCase()}`);
      item.actions.append(a);
    }
  }
}

function loadPicture(url) {
  return new Promise((resolve) => {
    const picture = new Image();
    picture.onload = () => resolve(picture);
    picture.onerror = () => resolve(null);
    picture.src = url;
  });
}

// The thumbnail from a PNG the service wrote at exposure 1, normalised like the viewer. (The PNG
// rather than the float pixels: a history of large renders would otherwise load megabytes each.)
function drawThumbnail(item, picture) {
  const context = item.thumb.getContext("2d", { willReadFrequently: true });
  context.drawImage(picture, 0, 0, item.thumb.width, item.thumb.height);
  const pixels = context.getImageData(0, 0, item.thumb.width, item.thumb.height);
  exposeSrgbBytes(pixels.data, normalisation(item.job.request.fstop));
  context.putImageData(pixels, 0, 0);
}

// New tiles: the image so far into the viewer (if it shows this render) and the thumbnail.
async function drawTiles(item) {
  const picture = await loadPicture(`/api/renders/${item.job.id}/preview.png?t=${item.tilesSeen}`);
  if (!picture) return;
  showPreview(item.job.id, picture);
  drawThumbnail(item, picture);
}

async function drawFinalThumbnail(item) {
  const picture = await loadPicture(item.job.links.png);
  if (picture) drawThumbnail(item, picture);
  else item.status.textContent += " (its image is unavailable)";
}

function followRender(item) {
  const id = item.job.id;
  follow(`/api/renders/${id}/events`, () => `/api/renders/${id}?tiles_since=${item.tilesSeen}`, async (job) => {
    if (!items.has(id)) return true;
    if (job.state === "deleted") { removeItem(id); return true; }
    update(item, job);
    if (job.tiles && job.tiles.length) {
      await drawTiles(item);
      item.tilesSeen += job.tiles.length;
    }
    if (!isOver(job.state)) return false;
    if (job.state === "done") {
      await drawFinalThumbnail(item);
      await renderFinished(id);
    }
    return true;
  });
}

function removeItem(id) {
  const item = items.get(id);
  if (!item) return;
  item.element.remove();
  items.delete(id);
  forgetPixels(id);
  if (!shownIds().includes(id)) return;
  const rest = shownIds().filter((other) => items.has(other));
  if (rest.length) openInViewer(rest);
  else { localStorage.removeItem(VIEWED_KEY); showRenders([]); }
}

// DELETE cancels a live render; for a finished one the service removes it. The list follows what
// the service then says about the render.
async function deleteRender(id) {
  clearMessage();
  try {
    await api(`/api/renders/${id}`, { method: "DELETE" });
  } catch (e) {
    if (e.status !== 404) { showMessage(`Render ${id} could not be deleted: ${e.message}`); return; }
  }
  try {
    const job = await api(`/api/renders/${id}`);
    if (items.has(id)) update(items.get(id), job);
  } catch (e) {
    if (e.status === 404) removeItem(id);
  }
}

// ---- submitting --------------------------------------------------------------------------------------

async function submitRenders(modes) {
  clearMessage();
  if (!selectedLens()) { showMessage("Choose a lens first."); return; }
  const ids = [];
  for (const mode of modes) {
    try {
      const job = await postJson("/api/renders", renderRequest(mode));
      addItem(job, true);
      ids.push(job.id);
    } catch (e) {
      showMessage(`The ${mode} render was refused: ${e.message}`);
    }
  }
  if (!ids.length) return;
  openInViewer(ids);
  $("viewer").scrollIntoView({ block: "start" });
}

export async function loadScenes() {
  const body = await api("/api/scenes");
  const select = $("scene");
  select.replaceChildren();
  for (const s of body.scenes) {
    const option = document.createElement("option");
    option.value = s.id;
    option.textContent = s.title ? `${s.id} — ${s.title}` : s.id;
    select.append(option);
  }
  if (!body.scenes.length) showMessage("The service has no scenes to render (its scenes folder is empty).");
}

// The renders the service keeps (across restarts), newest first; the viewer as it was left.
export async function loadHistory() {
  const body = await api("/api/renders");
  for (const job of body.renders.slice(0, HISTORY_LENGTH)) addItem(job, false);
  let viewed = [];
  try { viewed = JSON.parse(localStorage.getItem(VIEWED_KEY) || "[]"); } catch (e) { viewed = []; }
  openInViewer(Array.isArray(viewed) ? viewed : []);
}

export function setUpRenderPanel() {
  $("render-form").addEventListener("submit", (e) => { e.preventDefault(); submitRenders([$("render-mode").value]); });
  $("compare-button").addEventListener("click", () => submitRenders(["exact", "thick"]));
}
