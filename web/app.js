// lenslab web page: lenses (upload, data, diagram), renders (submit, progressive tiles, compare).
// Plain JavaScript against the service's REST API (docs/api.md); no external resources.
"use strict";

const $ = (id) => document.getElementById(id);

const state = {
  lenses: [],
  lens: null,        // the selected lens's detail (GET /api/lenses/{id})
  lensId: null,
  fstopMin: 1, fstopMax: 32,
  updateTimer: 0,
  dataRequest: 0,    // sequence number: answers to older requests are dropped
};

// ---- messages and requests -------------------------------------------------------------------

function showMessage(text, kind = "error") {
  const box = $("message");
  box.textContent = text;
  box.className = kind === "error" ? "message" : "message info";
  box.hidden = false;
}

function clearMessage() { $("message").hidden = true; }

// Fetches JSON; throws an Error carrying the service's {"error"} text or a plain description.
async function api(path, options = {}) {
  let response;
  try {
    response = await fetch(path, options);
  } catch (e) {
    throw new Error("The lenslab service cannot be reached (" + e.message + "). Is it still running?");
  }
  const text = await response.text();
  let body = null;
  try { body = text ? JSON.parse(text) : null; } catch (e) { body = null; }
  if (!response.ok) {
    const reason = body && body.error ? body.error : response.status + " " + response.statusText;
    const error = new Error(reason);
    error.status = response.status;
    throw error;
  }
  return body;
}

const mm = (v, digits = 3) => (v === null || v === undefined || !isFinite(v)) ? "–" : Number(v).toFixed(digits);

// ---- lens list and upload --------------------------------------------------------------------

async function loadLenses(selectId) {
  const body = await api("/api/lenses");
  state.lenses = body.lenses;
  const list = $("lens-list");
  list.replaceChildren();
  for (const lens of state.lenses) {
    const item = document.createElement("li");
    const button = document.createElement("button");
    button.type = "button";
    button.dataset.id = lens.id;
    // Bundled lenses go by their id; an upload by the name it was uploaded under (its id is random).
    button.append(lens.bundled ? lens.id : lens.name);
    const detail = document.createElement("small");
    detail.textContent = `EFL ${mm(lens.efl, 1)} mm, f/${mm(lens.fstop_min, 2)}` + (lens.bundled ? "" : ` · uploaded (${lens.id})`);
    button.append(detail);
    button.addEventListener("click", () => selectLens(lens.id));
    item.append(button);
    list.append(item);
  }
  const wanted = selectId || state.lensId || (state.lenses.find((l) => l.id === "dgauss.50mm") || state.lenses[0] || {}).id;
  if (wanted) await selectLens(wanted);
}

async function uploadLens(file) {
  clearMessage();
  if (!file) return;
  if (file.size > 1024 * 1024) {
    showMessage(`"${file.name}" is ${Math.round(file.size / 1024)} KiB; lens tables are at most 1 MiB.`);
    return;
  }
  const form = new FormData();
  form.append("file", file, file.name);
  try {
    const lens = await api("/api/lenses", { method: "POST", body: form });
    await loadLenses(lens.id);
    showMessage(`Uploaded "${lens.name}" as ${lens.id}.`, "info");
  } catch (e) {
    showMessage(`The lens table "${file.name}" was not accepted: ${e.message}`);
  }
}

function setUpUpload() {
  const input = $("lens-file");
  input.addEventListener("change", () => { uploadLens(input.files[0]); input.value = ""; });
  const zone = $("drop-zone");
  for (const name of ["dragenter", "dragover"]) {
    zone.addEventListener(name, (e) => { e.preventDefault(); zone.classList.add("dragging"); });
  }
  for (const name of ["dragleave", "drop"]) {
    zone.addEventListener(name, (e) => { e.preventDefault(); zone.classList.remove("dragging"); });
  }
  zone.addEventListener("drop", (e) => uploadLens(e.dataTransfer.files[0]));
}

// ---- the selected lens: controls, data, diagram ----------------------------------------------

// The f-number slider runs in third stops from the widest aperture: N = Nmin * 2^(s/2).
const stopsToFstop = (s) => state.fstopMin * Math.pow(2, s / 2);
const fstopToStops = (n) => 2 * Math.log2(n / state.fstopMin);

function currentFstop() { return stopsToFstop(Number($("fstop-slider").value)); }

// The f-number as sent to the service: rounded up, so the widest setting stays inside the lens's range.
function fstopParameter() { return Math.ceil(currentFstop() * 1e4) / 1e4; }

function setFstop(n) {
  $("fstop-slider").value = fstopToStops(Math.min(Math.max(n, state.fstopMin), state.fstopMax));
  $("fstop-value").textContent = currentFstop().toFixed(2);
}

// Focus slider 0..1000 maps logarithmically onto [4 EFL, 100 m]; its top end is infinity.
function focusRange() {
  const efl = state.lens ? Math.abs(state.lens.efl) : 50;
  return [Math.max(4 * efl, 10), 100000];
}

function currentFocus() {
  if ($("focus-infinity").checked) return "inf";
  const v = Number($("focus-mm").value);
  return isFinite(v) && v > 0 ? v : "inf";
}

function syncFocusFromSlider() {
  const v = Number($("focus-slider").value);
  const infinity = v >= 1000;
  $("focus-infinity").checked = infinity;
  $("focus-mm").disabled = infinity;
  if (!infinity) {
    const [lo, hi] = focusRange();
    $("focus-mm").value = Math.round(lo * Math.pow(hi / lo, v / 1000));
  }
}

function syncSliderFromFocus() {
  const focus = currentFocus();
  $("focus-mm").disabled = $("focus-infinity").checked;
  if (focus === "inf") { $("focus-slider").value = 1000; return; }
  const [lo, hi] = focusRange();
  $("focus-slider").value = Math.max(0, Math.min(999, 1000 * Math.log(focus / lo) / Math.log(hi / lo)));
}

function currentMode() { return document.querySelector('input[name="mode"]:checked').value; }

async function selectLens(id) {
  clearMessage();
  state.lensId = id;
  for (const b of document.querySelectorAll("#lens-list button")) b.setAttribute("aria-current", String(b.dataset.id === id));
  const summary = state.lenses.find((l) => l.id === id);
  if (!summary) return;
  state.fstopMin = summary.fstop_min;
  state.fstopMax = Math.min(summary.fstop_max, 64);
  const slider = $("fstop-slider");
  slider.min = 0;
  slider.max = Math.max(fstopToStops(state.fstopMax), 0.01);
  slider.step = 1 / 3;
  setFstop(state.fstopMin);
  $("lens-title").textContent = summary.id;
  $("lens-description").textContent = summary.description || summary.name;
  $("delete-lens").hidden = summary.bundled;
  await updateLensView();
}

function scheduleUpdate() {
  clearTimeout(state.updateTimer);
  state.updateTimer = setTimeout(updateLensView, 150);
}

function lensQuery() {
  return `fstop=${fstopParameter()}&focus=${currentFocus()}`;
}

async function updateLensView() {
  if (!state.lensId) return;
  const id = encodeURIComponent(state.lensId);
  const request = ++state.dataRequest;
  const diagramUrl = `/api/lenses/${id}/diagram.png?mode=${currentMode()}&${lensQuery()}&size=1000x500`;
  $("diagram-status").textContent = "Drawing the diagram…";
  loadDiagram(diagramUrl, request);
  try {
    const lens = await api(`/api/lenses/${id}?${lensQuery()}`);
    if (request !== state.dataRequest) return;
    state.lens = lens;
    showLensData(lens);
    showFullStops(lens.full_stops || []);
  } catch (e) {
    if (request !== state.dataRequest) return;
    showMessage(`Lens ${state.lensId} cannot be set that way: ${e.message}`);
  }
}

async function loadDiagram(url, request) {
  try {
    const response = await fetch(url);
    if (!response.ok) {
      const body = await response.json().catch(() => ({}));
      throw new Error(body.error || response.status + " " + response.statusText);
    }
    const blob = await response.blob();
    if (request !== state.dataRequest) return;
    const img = $("diagram");
    const old = img.src;
    img.src = URL.createObjectURL(blob);
    if (old.startsWith("blob:")) URL.revokeObjectURL(old);
    $("diagram-status").textContent = `${currentMode()} diagram at f/${currentFstop().toFixed(2)}, focus ${currentFocus() === "inf" ? "at infinity" : currentFocus() + " mm"}`;
  } catch (e) {
    if (request !== state.dataRequest) return;
    $("diagram-status").textContent = "The diagram could not be drawn: " + e.message;
  }
}

// The engraved name of a full stop (f/22 rather than f/22.6).
function nominalFstop(n) {
  const names = [1, 1.4, 2, 2.8, 4, 5.6, 8, 11, 16, 22, 32, 45, 64];
  const near = names.find((name) => Math.abs(name / n - 1) < 0.06);
  return near !== undefined ? String(near) : n.toFixed(1);
}

function showFullStops(stops) {
  const box = $("full-stops");
  box.replaceChildren();
  for (const n of stops) {
    if (n > state.fstopMax * 1.0001) continue;
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = "f/" + nominalFstop(n);
    b.addEventListener("click", () => { setFstop(n); scheduleUpdate(); });
    box.append(b);
  }
}

function showLensData(lens) {
  const rows = [
    ["Effective focal length", mm(lens.efl)],
    ["Back focal distance", mm(lens.back_focal_distance)],
    ["Front focal distance", mm(lens.front_focal_distance)],
    ["F (front focal point) z", mm(lens.F.z)],
    ["F′ (rear focal point) z", mm(lens.F_prime.z)],
    ["P (front principal plane) z", mm(lens.P.z)],
    ["P′ (rear principal plane) z", mm(lens.P_prime.z)],
    ["f-number", mm(lens.fstop, 2) + `  (range f/${mm(lens.fstop_min, 2)} – f/${mm(lens.fstop_max, 1)})`],
    ["Stop diameter", mm(lens.stop.diameter) + ` at z ${mm(lens.stop.z)}`],
    ["Entrance pupil", `⌀ ${mm(lens.entrance_pupil.diameter)} at z ${mm(lens.entrance_pupil.z)}`],
    ["Exit pupil", `⌀ ${mm(lens.exit_pupil.diameter)} at z ${mm(lens.exit_pupil.z)}`],
    ["Focus", lens.focus.infinity ? "infinity" : mm(lens.focus.distance, 1) + " mm"],
    ["Film (image plane) z, exact", mm(lens.focus.image_z)],
    ["Film z, thick-lens model", mm(lens.focus.image_z_thick)],
    ["Exact − thick", mm(lens.focus.image_z_difference, 4)],
  ];
  const body = $("lens-data").tBodies[0];
  body.replaceChildren();
  for (const [name, value] of rows) {
    const tr = body.insertRow();
    const th = document.createElement("th");
    th.textContent = name;
    tr.append(th);
    tr.insertCell().textContent = value;
  }
  const surfaces = $("lens-surfaces").tBodies[0];
  surfaces.replaceChildren();
  lens.surfaces.forEach((s, i) => {
    const tr = surfaces.insertRow();
    for (const v of [i + (s.is_stop ? " (stop)" : ""), mm(s.z), s.radius === 0 ? "flat" : mm(s.radius), mm(s.n, 4), mm(s.diameter, 2)])
      tr.insertCell().textContent = v;
  });
}

async function deleteLens() {
  const id = state.lensId;
  if (!id || !confirm(`Delete the uploaded lens ${id}?`)) return;
  try {
    await api(`/api/lenses/${encodeURIComponent(id)}`, { method: "DELETE" });
    state.lensId = null;
    await loadLenses();
  } catch (e) {
    showMessage(`Lens ${id} could not be deleted: ${e.message}`);
  }
}

function setUpLensControls() {
  $("fstop-slider").addEventListener("input", () => { $("fstop-value").textContent = currentFstop().toFixed(2); scheduleUpdate(); });
  $("focus-slider").addEventListener("input", () => { syncFocusFromSlider(); scheduleUpdate(); });
  $("focus-mm").addEventListener("input", () => { syncSliderFromFocus(); scheduleUpdate(); });
  $("focus-infinity").addEventListener("change", () => {
    if (!$("focus-infinity").checked) { $("focus-slider").value = 700; syncFocusFromSlider(); }
    syncSliderFromFocus();
    scheduleUpdate();
  });
  for (const radio of document.querySelectorAll('input[name="mode"]')) radio.addEventListener("change", scheduleUpdate);
  $("lens-controls").addEventListener("submit", (e) => e.preventDefault());
  $("delete-lens").addEventListener("click", deleteLens);
}

// ---- renders ---------------------------------------------------------------------------------

async function loadScenes() {
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

function renderRequest(mode) {
  const request = {
    scene: $("scene").value,
    lens: state.lensId,
    fstop: fstopParameter(),
    mode,
    spp: Number($("spp").value),
    width: Number($("width").value),
    height: Number($("height").value),
  };
  if (currentFocus() !== "inf") request.focaldistance = currentFocus();
  if ($("film-diagonal").value) request.filmdiagonal = Number($("film-diagonal").value);
  return request;
}

async function submitRenders(modes) {
  clearMessage();
  if (!state.lensId) { showMessage("Choose a lens first."); return; }
  const row = document.createElement("div");
  row.className = "render-row";
  $("renders").prepend(row);
  for (const mode of modes) {
    try {
      const job = await api("/api/renders", {
        method: "POST",
        headers: { "Content-Type": "application/json" },
        body: JSON.stringify(renderRequest(mode)),
      });
      trackRender(job, row);
    } catch (e) {
      showMessage(`The ${mode} render was refused: ${e.message}`);
    }
  }
  if (!row.children.length) row.remove();
}

function describeRequest(r) {
  const fstop = r.fstop ? `f/${Number(r.fstop).toFixed(1)}` : "scene f-number";
  const focus = r.focaldistance ? `focus ${Math.round(r.focaldistance)} mm` : "scene focus";
  return `${r.lens} · ${r.scene} · ${r.mode} · ${fstop} · ${focus} · ${r.width}×${r.height} · ${r.spp} spp`;
}

// A card that follows one job: polls its status, draws finished tiles from the partial image,
// shows the final image and its downloads.
function trackRender(job, row) {
  const card = document.createElement("article");
  card.className = "render-card";
  card.dataset.id = job.id;
  const title = document.createElement("h3");
  title.textContent = job.request.mode === "approximate" ? "Approximate (thick lens)" : "Accurate (exact trace)";
  const about = document.createElement("p");
  about.className = "muted";
  about.textContent = describeRequest(job.request);
  const canvas = document.createElement("canvas");
  canvas.width = job.request.width;
  canvas.height = job.request.height;
  canvas.style.width = Math.max(job.request.width, 320) + "px";
  const progress = document.createElement("progress");
  progress.max = 1;
  progress.value = 0;
  const status = document.createElement("p");
  status.className = "status";
  const actions = document.createElement("div");
  actions.className = "actions";
  const cancel = document.createElement("button");
  cancel.type = "button";
  cancel.textContent = "Cancel";
  actions.append(cancel);
  card.append(title, about, canvas, progress, status, actions);
  row.append(card);

  const context = canvas.getContext("2d");
  let tilesSeen = 0;
  let stopped = false;

  cancel.addEventListener("click", async () => {
    try { await api(`/api/renders/${job.id}`, { method: "DELETE" }); } catch (e) { showMessage(`Cancel failed: ${e.message}`); }
  });

  async function drawTiles(tiles) {
    const image = await loadImage(`/api/renders/${job.id}/preview.png?t=${tilesSeen}`);
    if (!image) return;
    for (const [x0, y0, x1, y1] of tiles) context.drawImage(image, x0, y0, x1 - x0, y1 - y0, x0, y0, x1 - x0, y1 - y0);
  }

  async function finish(info) {
    stopped = true;
    cancel.remove();
    if (info.state === "done") {
      const image = await loadImage(info.links.png);
      if (image) context.drawImage(image, 0, 0);
      for (const format of ["png", "exr"]) {
        const a = document.createElement("a");
        a.href = info.links[format];
        a.download = `${job.id}.${format}`;
        a.textContent = "Download " + format.toUpperCase();
        actions.append(a);
      }
    }
  }

  async function poll() {
    if (stopped) return;
    let info;
    try {
      info = await api(`/api/renders/${job.id}?tiles_since=${tilesSeen}`);
    } catch (e) {
      status.textContent = "Status unavailable: " + e.message;
      setTimeout(poll, 2000);
      return;
    }
    const p = info.progress;
    progress.value = p.fraction;
    const eta = p.eta_s === null ? "" : `, about ${Math.ceil(p.eta_s)} s left`;
    status.className = "status state-" + info.state;
    status.textContent = {
      queued: "Waiting in the queue…",
      running: `Rendering: ${p.tiles_done} of ${p.tiles_total || "?"} tiles, ${p.elapsed_s.toFixed(1)} s${eta}`,
      done: `Done: ${p.tiles_total} tiles in ${p.elapsed_s.toFixed(1)} s`,
      failed: "Failed: " + (info.error || "unknown reason"),
      cancelled: "Cancelled",
    }[info.state];
    card.dataset.state = info.state;
    if (info.tiles.length) {
      await drawTiles(info.tiles);
      tilesSeen += info.tiles.length;
    }
    if (["done", "failed", "cancelled"].includes(info.state)) await finish(info);
    else setTimeout(poll, 300);
  }
  poll();
}

function loadImage(url) {
  return new Promise((resolve) => {
    const image = new Image();
    image.onload = () => resolve(image);
    image.onerror = () => resolve(null);
    image.src = url;
  });
}

// Renders from earlier visits (the service keeps them across restarts).
async function loadRecentRenders() {
  const body = await api("/api/renders");
  for (const job of body.renders.slice(0, 6).reverse()) {
    const row = document.createElement("div");
    row.className = "render-row";
    $("renders").prepend(row);
    trackRender(job, row);
  }
}

// ---- the report --------------------------------------------------------------------------------

function showReportStatus(job) {
  const p = job.progress || {};
  const text = {
    idle: "",
    running: `building the report: ${p.done || 0} of ${p.total || "?"} items`,
    done: job.summary ? `report built: ${job.summary.built} items made, ${job.summary.reused} reused` : "report built",
    failed: "the report failed: " + (job.error || "unknown error"),
    cancelled: "the report build was cancelled",
  }[job.state] || "";
  $("report-status").textContent = text;
  $("report-build").disabled = job.state === "running";
  return job.state === "running";
}

async function followReport() {
  try {
    while (showReportStatus(await api("/api/report"))) await new Promise((r) => setTimeout(r, 1000));
  } catch (e) {
    showMessage("The report's progress could not be read: " + e.message);
  }
}

async function buildReport() {
  try {
    showReportStatus(await api("/api/report", { method: "POST" }));
    followReport();
  } catch (e) {
    showMessage("The report could not be started: " + e.message);
  }
}

function setUpRenderControls() {
  $("render-form").addEventListener("submit", (e) => { e.preventDefault(); submitRenders([$("render-mode").value]); });
  $("compare-button").addEventListener("click", () => submitRenders(["accurate", "approximate"]));
}

// ---- start -----------------------------------------------------------------------------------

async function start() {
  setUpUpload();
  setUpLensControls();
  setUpRenderControls();
  $("report-build").addEventListener("click", buildReport);
  followReport();
  try {
    await Promise.all([loadLenses(), loadScenes()]);
    await loadRecentRenders();
  } catch (e) {
    showMessage("The page could not load its data: " + e.message);
  }
}

start();
