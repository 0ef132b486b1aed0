// The lens panel: the lens list and uploads, the selected lens's data and diagram, and its controls
// driven like the course's lens viewer (↑/↓ f-number by 0.1, Shift+↑/↓ a full stop, m the diagram
// mode, ←/→ the focus). Out-of-range f-numbers are refused with the lens's range, never clamped.
import { $, api, authorizedFetch, clearMessage, fixed, showMessage, uploadFile } from "./api.js";
import { analysisChoices, setUpAnalysis, showStoredAnalysis } from "./analysis.js";
import { showGhosts } from "./ghosts.js";
import { isGlassCatalogFile, uploadGlassCatalog } from "./glass-catalogs.js";

const state = {
  lenses: [],
  lensId: null,
  fstop: 2,
  fstopMin: 1, fstopMax: 32,
  updateTimer: 0,
  dataRequest: 0,  // sequence number: answers to older requests are dropped
};

const MODES = ["exact", "thick", "overlay"];
const FOCUS_STEP = 25;  // of the focus slider's 1000 (logarithmic) steps

// ---- lens list and upload --------------------------------------------------------------------

// The live editor (editor.js, which builds on this module) attaches how it follows the chosen lens
// and shows an edited one; until it does, a lens is shown as stored.
let editor = { hasEdits: () => false, loadPrescription: async () => {}, requestPreview: () => {} };
export function attachEditor(hooks) { editor = hooks; }

// notice: what to say once the lens is selected (in place of the last message), before its view
// loads: said after the view, it would overwrite whatever a click meanwhile said.
export async function loadLenses(selectId, notice = "") {
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
    button.append(displayName(lens));
    const detail = document.createElement("small");
    detail.textContent = `EFL ${fixed(lens.efl, 1)} mm, f/${fixed(lens.fstop_min, 2)}` + (lens.bundled ? "" : ` · uploaded (${lens.id})`);
    button.append(detail);
    button.addEventListener("click", () => selectLens(lens.id));
    item.append(button);
    list.append(item);
  }
  const wanted = selectId || state.lensId || (state.lenses.find((l) => l.id === "dgauss.50mm") || state.lenses[0] || {}).id;
  if (wanted) await selectLens(wanted, notice);
}

// A lens file, or a glass catalog (glass-catalogs.js) dropped or chosen in the same place.
// The last upload's message goes at once, before the file is read: a message still on the page
// while the next file is on its way would be taken for that file's answer.
async function uploadChosenFile(file) {
  if (!file) return;
  clearMessage();
  if (await isGlassCatalogFile(file)) await uploadGlassCatalog(file);
  else await uploadLens(file);
}

async function uploadLens(file) {
  try {
    const lens = await uploadFile("/api/lenses", file, "lens tables");
    await loadLenses(lens.id, `Uploaded "${lens.name}" as ${lens.id}.`);
  } catch (e) {
    showMessage(`The lens table "${file.name}" was not accepted: ${e.message}`);
  }
}

function setUpUpload() {
  const input = $("lens-file");
  input.addEventListener("change", () => { uploadChosenFile(input.files[0]); input.value = ""; });
  const zone = $("drop-zone");
  for (const name of ["dragenter", "dragover"]) zone.addEventListener(name, (e) => { e.preventDefault(); zone.classList.add("dragging"); });
  for (const name of ["dragleave", "drop"]) zone.addEventListener(name, (e) => { e.preventDefault(); zone.classList.remove("dragging"); });
  zone.addEventListener("drop", (e) => uploadChosenFile(e.dataTransfer.files[0]));
}

// ---- the f-number ------------------------------------------------------------------------------

const shown = (n) => String(Math.round(n * 100) / 100);

// A range's ends rounded inward: an f-number read off it is one the lens takes (f/6.71 for 6.70196).
const rangeEnds = (min, max) => `f/${shown(Math.ceil(min * 100) / 100)} to f/${shown(Math.floor(max * 100) / 100)}`;

function rangeText() { return rangeEnds(state.fstopMin, state.fstopMax); }

// Takes n when the lens can be set to it; otherwise says the lens's range and keeps the f-number.
// A value within display rounding of the widest aperture means the widest aperture.
function trySetFstop(n) {
  const input = $("fstop-input");
  const ok = isFinite(n) && n >= state.fstopMin - 0.005 && n <= state.fstopMax + 1e-9;
  input.setAttribute("aria-invalid", String(!ok));
  $("fstop-range").textContent = ok ? `range ${rangeText()}` : `f/${isFinite(n) ? shown(n) : input.value} is outside this lens's range, ${rangeText()}`;
  $("fstop-range").classList.toggle("bad", !ok);
  if (!ok) return false;
  state.fstop = Math.max(n, state.fstopMin);
  input.value = shown(state.fstop);
  scheduleUpdate();
  return true;
}

// 0.1 steps land on tenths; full stops multiply by √2. A value typed but not yet entered is the
// starting point.
function stepFstop(direction, fullStop) {
  const typed = $("fstop-input").value;
  if (typed !== shown(state.fstop) && !trySetFstop(Number(typed.replace(",", ".")))) return;
  const n = fullStop ? state.fstop * Math.pow(Math.SQRT2, direction) : Math.round((state.fstop + 0.1 * direction) * 100) / 100;
  trySetFstop(n);
}

// The f-number as sent to the service: rounded up, so the widest setting stays inside the range.
export function fstopParameter() { return Math.ceil(state.fstop * 1e4) / 1e4; }

// ---- focus and mode ------------------------------------------------------------------------------

// Focus slider 0..1000 maps logarithmically onto [4 EFL, 100 m]; its top end is infinity.
function focusRange() {
  const lens = state.lenses.find((l) => l.id === state.lensId);
  const efl = lens ? Math.abs(lens.efl) : 50;
  return [Math.max(4 * efl, 10), 100000];
}

export function currentFocus() {
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

function moveFocus(direction) {
  const slider = $("focus-slider");
  slider.value = Math.max(0, Math.min(1000, Number(slider.value) + direction * FOCUS_STEP));
  syncFocusFromSlider();
  scheduleUpdate();
}

function currentMode() { return document.querySelector('input[name="mode"]:checked').value; }

function cycleMode() {
  const next = MODES[(MODES.indexOf(currentMode()) + 1) % MODES.length];
  document.querySelector(`input[name="mode"][value="${next}"]`).checked = true;
  scheduleUpdate();
}

// ---- the selected lens ----------------------------------------------------------------------------

export function selectedLens() { return state.lensId; }

// What people call a lens: a bundled table's id; an upload's own file name without its extension
// (its id is a random one).
function displayName(lens) { return lens.bundled ? lens.id : lens.name.replace(/\.(dat|zmx|seq|txt)$/i, ""); }

export function selectedLensName() {
  const lens = state.lenses.find((l) => l.id === state.lensId);
  return lens ? displayName(lens) : state.lensId;
}

async function selectLens(id, notice = "") {
  if (notice) showMessage(notice, "info");
  else clearMessage();
  state.lensId = id;
  for (const b of document.querySelectorAll("#lens-list button")) b.setAttribute("aria-current", String(b.dataset.id === id));
  const summary = state.lenses.find((l) => l.id === id);
  if (!summary) return;
  state.fstopMin = summary.fstop_min;
  state.fstopMax = summary.fstop_max;  // the service's range: the lens's widest to f/64
  $("lens-title").textContent = displayName(summary);
  $("lens-title").dataset.id = id;
  $("lens-description").textContent = summary.description || summary.name;
  $("delete-lens").hidden = summary.bundled;
  trySetFstop(state.fstopMin);
  // The editor's rows first: until they are this lens's, an edit of the last lens would be shown.
  await editor.loadPrescription(id).catch((e) => showMessage(`The prescription of ${id} cannot be edited: ${e.message}`));
  await updateLensView();
}

function scheduleUpdate() {
  clearTimeout(state.updateTimer);
  state.updateTimer = setTimeout(updateLensView, 150);
}

// A choice of the analysis panel changed: the analysis again, of the lens shown.
function updateAnalysis() {
  if (!state.lensId || wavelengthParameter() === null) return;
  if (editor.hasEdits()) editor.requestPreview();
  else showStoredAnalysis(state.lensId, analysisLensQuery());
}

// The wavelength box: empty is the lens's own primary wavelength; values outside the box's range
// (the service's, 180-2500 nm) are marked and nothing is asked for until they are corrected (null).
function wavelengthParameter() {
  const input = $("wavelength");
  const text = input.value.trim();
  const nm = Number(text);
  const ok = text === "" || (isFinite(nm) && nm >= Number(input.min) && nm <= Number(input.max));
  input.setAttribute("aria-invalid", String(!ok));
  $("wavelength-note").classList.toggle("bad", !ok);
  return !ok ? null : text !== "" ? `&wavelength=${nm}` : "";
}

const lensQuery = () => `fstop=${fstopParameter()}&focus=${currentFocus()}${wavelengthParameter()}`;
const colourParameter = () => ($("colour-fans").checked ? "&colour=1" : "");

// The analysis's lens settings: no f-number at the widest, so that it is the widest aperture's
// exactly (as `lenslab analyze` without --fstop).
const analysisLensQuery = () =>
  (state.fstop > state.fstopMin + 1e-9 ? `fstop=${fstopParameter()}&` : "") + `focus=${currentFocus()}${wavelengthParameter()}`;

// The settings above for the edited lens: no f-number at the widest, which an edit may move.
export function lensPreviewSettings() {
  const settings = { focus: currentFocus(), mode: currentMode(), colour: $("colour-fans").checked, ...analysisChoices() };
  if (state.fstop > state.fstopMin + 1e-9) settings.fstop = fstopParameter();
  const nm = $("wavelength").value.trim();
  if (nm !== "") settings.wavelength = Number(nm);
  return settings;
}

async function updateLensView() {
  if (!state.lensId || wavelengthParameter() === null) return;
  if (editor.hasEdits()) { editor.requestPreview(); return; }  // the edited lens, not the stored one
  const id = encodeURIComponent(state.lensId);
  const request = ++state.dataRequest;
  $("diagram-status").textContent = "Drawing the diagram…";
  loadDiagram(`/api/lenses/${id}/diagram.png?mode=${currentMode()}&${lensQuery()}${colourParameter()}&size=1000x500`, request);
  showStoredAnalysis(state.lensId, analysisLensQuery());
  try {
    const lens = await api(`/api/lenses/${id}?${lensQuery()}`);
    if (request !== state.dataRequest) return;
    showLensData(lens);
    showFullStops(lens.full_stops || []);
    const ghosts = await api(`/api/lenses/${id}/ghosts?${lensQuery()}`);
    if (request === state.dataRequest) showGhosts(ghosts);
  } catch (e) {
    if (request !== state.dataRequest) return;
    showMessage(`Lens ${state.lensId} cannot be set that way: ${e.message}`);
  }
}

async function loadDiagram(url, request) {
  try {
    const response = await authorizedFetch(url);
    if (!response.ok) {
      const body = await response.json().catch(() => ({}));
      throw new Error(body.error || response.status + " " + response.statusText);
    }
    const blob = await response.blob();
    if (request !== state.dataRequest) return;
    await showDiagramPng(URL.createObjectURL(blob), state.lensId);
  } catch (e) {
    if (request !== state.dataRequest) return;
    $("diagram-status").textContent = "The diagram could not be drawn: " + e.message;
  }
}

// Shows a diagram once it is decoded, so that the old one stays until the new one can replace it.
export async function showDiagramPng(url, lensLabel) {
  const next = new Image();
  next.src = url;
  await next.decode().catch(() => {});
  const img = $("diagram");
  const old = img.src;
  img.src = url;
  if (old.startsWith("blob:")) URL.revokeObjectURL(old);
  const focus = currentFocus();
  $("diagram-status").textContent = `${currentMode()} diagram of ${lensLabel} at f/${shown(state.fstop)}, focus ${focus === "inf" ? "at infinity" : focus + " mm"}`;
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
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = "f/" + nominalFstop(n);
    b.setAttribute("aria-label", `set f/${nominalFstop(n)}`);
    b.addEventListener("click", () => trySetFstop(n));
    box.append(b);
  }
}

export function showLensData(lens) {
  const rows = [
    ["Effective focal length", fixed(lens.efl)],
    ["Back focal distance", fixed(lens.back_focal_distance)],
    ["Front focal distance", fixed(lens.front_focal_distance)],
    ["F (front focal point) z", fixed(lens.F.z)],
    ["F′ (rear focal point) z", fixed(lens.F_prime.z)],
    ["P (front principal plane) z", fixed(lens.P.z)],
    ["P′ (rear principal plane) z", fixed(lens.P_prime.z)],
    ["f-number", fixed(lens.fstop, 2) + `  (range ${rangeEnds(lens.fstop_min, lens.fstop_max)})`],
    ["Stop diameter", fixed(lens.stop.diameter) + ` at z ${fixed(lens.stop.z)}`],
    ["Entrance pupil", `⌀ ${fixed(lens.entrance_pupil.diameter)} at z ${fixed(lens.entrance_pupil.z)}`],
    ["Exit pupil", `⌀ ${fixed(lens.exit_pupil.diameter)} at z ${fixed(lens.exit_pupil.z)}`],
    ["Focus", lens.focus.infinity ? "infinity" : fixed(lens.focus.distance, 1) + " mm"],
    ["Film (image plane) z, exact", fixed(lens.focus.image_z)],
    ["Film z, thick-lens model", fixed(lens.focus.image_z_thick)],
    ["Exact − thick", fixed(lens.focus.image_z_difference, 4)],
  ];
  fillRows("lens-data", rows);
  showColour(lens);
  const surfaces = $("lens-surfaces").tBodies[0];
  surfaces.replaceChildren();
  lens.surfaces.forEach((s, i) => {
    const tr = surfaces.insertRow();
    const name = i + (s.is_stop ? " (stop)" : "") + (s.mirror ? " mirror" : "");
    const glass = s.mirror ? "" : s.glass === "air" ? "" : s.glass + (s.catalog ? ` (${s.catalog})` : "");
    const terms = (s.aspheric || []).map((a, k) => (a ? `r${2 * k + 2}: ${a.toExponential(4)}` : "")).filter(Boolean).join(", ");
    const coating = s.coating === "none" ? "" : s.coating + (s.coating_default ? " (default)" : "");
    for (const v of [name, fixed(s.z), s.radius === 0 ? "flat" : fixed(s.radius), fixed(s.n, 5), fixed(s.diameter, 2), glass,
                     s.mirror || s.n === 1 ? "" : fixed(s.nd, 5), s.vd ? fixed(s.vd, 2) : "", s.conic ? fixed(s.conic, 4) : "", terms,
                     coating, s.mirror || s.reflectance === 0 ? "" : fixed(100 * s.reflectance, 3), surfacePeculiarities(s)])
      tr.insertCell().textContent = v;
  });
}

const triple = (v, digits) => `(${v.map((x) => fixed(x, digits)).join(", ")})`;

// A shaped aperture or obscuration: "rectangular 10.000 x 6.000 at (0.000, 1.000)" (full widths, mm).
const apertureText = (a) => `${a.shape} ${fixed(2 * a.half_width_x)} × ${fixed(2 * a.half_width_y)}` +
  (a.centre_x || a.centre_y ? ` at (${fixed(a.centre_x)}, ${fixed(a.centre_y)})` : "");

// What sets a surface apart from a centred, circular even asphere, as the API gives it (docs/api.md):
// its kind and terms, a shaped clear aperture or obscuration, its decentre (mm) and tilt (degrees,
// about x, y, z) with the frame's mode and order; "" for a plain surface.
function surfacePeculiarities(s) {
  const parts = [];
  if (s.kind) parts.push(`${s.kind} ${(s.form_terms || []).map((a) => a.toExponential(4)).join(", ")}`.trim());
  if (s.clear_aperture) parts.push("aperture " + apertureText(s.clear_aperture));
  if (s.obscuration) parts.push("obscuration " + apertureText(s.obscuration));
  if (s.frame) parts.push(`decentre ${triple(s.frame.decentre, 3)} mm, tilt ${triple(s.frame.tilt_degrees, 3)}° (${s.frame.mode}, ${s.frame.order})`);
  return parts.join("; ");
}

function showColour(lens) {
  const c = lens.chromatic;
  const rows = [
    ["Wavelength of the data above", `${fixed(lens.wavelength_nm, 2)} nm` + (lens.dispersive ? "" : " (no dispersion: one index per glass)")],
    ["EFL at F, d, C", `${fixed(c.efl_F)}, ${fixed(c.efl_d)}, ${fixed(c.efl_C)}`],
    ["Image z at F, d, C", `${fixed(c.image_z_F)}, ${fixed(c.image_z_d)}, ${fixed(c.image_z_C)}`],
    ["Longitudinal colour (C − F)", fixed(c.longitudinal_colour_mm, 4)],
    c.lateral_colour_mm === null
      ? ["Lateral colour (F − C)", "none: the lens defines no largest field"]
      : [`Lateral colour (F − C) at ${fixed(c.lateral_colour_field_deg, 1)}°`, fixed(c.lateral_colour_mm, 4)],
    ["Largest field", lens.field_of_view.largest_field_deg === null
      ? lens.field_of_view.source
      : `${fixed(lens.field_of_view.largest_field_deg, 2)}° (${lens.field_of_view.source})`],
  ];
  fillRows("lens-colour", rows);
}

// A two-column table of [name, value] rows.
function fillRows(tableId, rows) {
  const body = $(tableId).tBodies[0];
  body.replaceChildren();
  for (const [name, value] of rows) {
    const tr = body.insertRow();
    const th = document.createElement("th");
    th.textContent = name;
    tr.append(th);
    tr.insertCell().textContent = value;
  }
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

// ---- keys ------------------------------------------------------------------------------------------

// Keys act on the lens unless the user is typing elsewhere (text fields, lists, sliders keep theirs).
function ownsKeys(target) {
  if (target.id === "fstop-input") return true;
  if (target.isContentEditable || ["SELECT", "TEXTAREA"].includes(target.tagName)) return false;
  return !(target.tagName === "INPUT" && !["checkbox", "radio", "button", "submit"].includes(target.type));
}

function onKey(e) {
  if (e.altKey || e.ctrlKey || e.metaKey || !ownsKeys(e.target) || !state.lensId) return;
  const typing = e.target.id === "fstop-input";
  if (e.target.type === "radio" && e.key.startsWith("Arrow")) return;  // arrows choose among radios
  if (e.key === "ArrowUp" || e.key === "ArrowDown") stepFstop(e.key === "ArrowUp" ? 1 : -1, e.shiftKey);
  else if ((e.key === "m" || e.key === "M") && !typing) cycleMode();
  else if ((e.key === "ArrowLeft" || e.key === "ArrowRight") && !typing) moveFocus(e.key === "ArrowRight" ? 1 : -1);
  else return;
  e.preventDefault();
}

export function setUpLensPanel() {
  setUpUpload();
  const input = $("fstop-input");
  input.addEventListener("change", () => trySetFstop(Number(input.value.replace(",", "."))));
  input.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); input.dispatchEvent(new Event("change")); } });
  $("stop-wider").addEventListener("click", () => stepFstop(-1, true));
  $("stop-narrower").addEventListener("click", () => stepFstop(1, true));
  $("focus-slider").addEventListener("input", () => { syncFocusFromSlider(); scheduleUpdate(); });
  $("focus-mm").addEventListener("input", () => { syncSliderFromFocus(); scheduleUpdate(); });
  $("focus-infinity").addEventListener("change", () => {
    if (!$("focus-infinity").checked) { $("focus-slider").value = 700; syncFocusFromSlider(); }
    syncSliderFromFocus();
    scheduleUpdate();
  });
  for (const radio of document.querySelectorAll('input[name="mode"]')) radio.addEventListener("change", scheduleUpdate);
  $("colour-fans").addEventListener("change", scheduleUpdate);
  $("wavelength").addEventListener("input", scheduleUpdate);
  $("lens-controls").addEventListener("submit", (e) => e.preventDefault());
  $("delete-lens").addEventListener("click", deleteLens);
  setUpAnalysis(updateAnalysis);
  document.addEventListener("keydown", onKey);
}
