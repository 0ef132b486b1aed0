// The live prescription editor: the selected lens's surfaces as an editable table. Every accepted
// edit asks POST /api/prescriptions/preview for the edited lens (nothing is stored) and shows its
// first-order and colour data, diagram and analysis (analysis.js) in place of the stored lens's. One
// preview is in flight at a time; edits made meanwhile are sent together when it answers, and an
// answer overtaken by a newer edit is dropped. A cell whose text is not acceptable is marked with
// the reason and the lens is not sent until it is corrected.
import { $, api, authorizedFetch, postJson, showMessage } from "./api.js";
import { COLUMNS, keptFeatures, needsZemax, newRow } from "./prescription-cells.js";
import { loadGlassNames } from "./glass-catalogs.js";
import { UndoHistory } from "./undo-history.js";
import { attachEditor, lensPreviewSettings, loadLenses, selectedLens, selectedLensName, showDiagramPng, showLensData } from "./lens.js";
import { showAnalysis } from "./analysis.js";

const state = {
  lensId: null,
  prescription: null,  // the stored lens's rows and header (GET /api/lenses/{id}/prescription)
  rows: [],            // the rows as edited (every accepted cell applied)
  history: null,
  invalid: new Map(),  // "row:key" -> reason, for cells whose text is not acceptable
  inFlight: false,
  pending: false,      // an edit arrived while a preview was in flight
  editedAt: 0,         // performance.now() of the oldest edit not yet shown
  shown: 0,            // previews shown (the browser test waits on it)
};

const cellId = (i, key) => `${i}:${key}`;
const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

const hasEdits = () => state.prescription !== null && !same(state.rows, state.prescription.rows);

async function loadPrescription(id) {
  const prescription = await api(`/api/lenses/${encodeURIComponent(id)}/prescription`);
  if (selectedLens() !== id) return;
  state.lensId = id;
  state.pending = false;
  state.editedAt = 0;
  state.prescription = prescription;
  state.history = new UndoHistory(prescription.rows);
  setRows(prescription.rows);
  $("editor-name").value = `${selectedLensName()}-edited`;
  $("editor").dataset.lens = id;
  say("");
}

function setRows(rows) {
  state.rows = structuredClone(rows);
  state.invalid.clear();
  drawTable();
  updateButtons();
}

// ---- the table ---------------------------------------------------------------------------------

function drawTable() {
  const body = $("editor-table").tBodies[0];
  body.replaceChildren();
  state.rows.forEach((row, i) => {
    const tr = body.insertRow();
    tr.dataset.row = i;
    const number = tr.insertCell();
    number.className = "surface-number";
    number.textContent = i + 1;
    // What the row keeps besides its cells, marked so that no one wonders why two rows alike differ.
    const kept = keptFeatures(row);
    if (kept.length) {
      number.classList.add("kept");
      number.title = `kept as the file states it: ${kept.join(", ")}`;
      number.dataset.kept = kept.join(", ");
    }
    const stopCell = tr.insertCell();
    const stop = document.createElement("input");
    stop.type = "radio";
    stop.name = "editor-stop";
    stop.checked = row.stop;
    stop.setAttribute("aria-label", `surface ${i + 1} is the aperture stop`);
    stop.addEventListener("change", () => edit(state.rows.map((r, k) => ({ ...r, stop: k === i }))));
    stopCell.append(stop);
    for (const column of COLUMNS) {
      const td = tr.insertCell();
      td.dataset.key = column.key;
      const input = document.createElement("input");
      input.type = "text";
      input.spellcheck = false;
      input.dataset.row = i;
      input.dataset.key = column.key;
      input.setAttribute("aria-label", `surface ${i + 1} ${column.heading}`);
      input.addEventListener("input", () => typed(input));
      input.addEventListener("change", () => committed(input));
      input.addEventListener("focus", () => { if (!state.invalid.has(cellId(i, column.key))) input.value = column.exact(state.rows[i]); input.select(); });
      input.addEventListener("blur", () => showCell(i, column));
      input.addEventListener("keydown", onCellKey);
      const reason = document.createElement("small");
      reason.className = "cell-error";
      td.append(input, reason);
    }
    const actions = tr.insertCell();
    actions.className = "row-actions";
    actions.append(rowButton("+", `insert a surface after surface ${i + 1}`, () => insertRow(i)),
                   rowButton("−", `delete surface ${i + 1}`, () => deleteRow(i)));
    const note = tr.insertCell();
    note.className = "row-note";
    for (const column of COLUMNS) showCell(i, column);
  });
}

function rowButton(text, label, onClick) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.setAttribute("aria-label", label);
  b.title = label;
  b.addEventListener("click", onClick);
  return b;
}

const inputAt = (i, key) => $("editor-table").querySelector(`input[data-row="${i}"][data-key="${key}"]`);

// A cell's shown text and marks: changed from the stored lens, derived from the catalog, invalid.
function showCell(i, column) {
  const input = inputAt(i, column.key);
  if (!input) return;
  const reason = state.invalid.get(cellId(i, column.key));
  const row = state.rows[i];
  if (!reason && document.activeElement !== input) input.value = column.show(row);
  const stored = state.prescription.rows[i];
  const td = input.parentElement;
  td.classList.toggle("changed", !stored || column.show(stored) !== column.show(row));
  td.classList.toggle("derived", !!column.derived && column.derived(row));
  td.classList.toggle("invalid", !!reason);
  input.setAttribute("aria-invalid", String(!!reason));
  input.title = reason || column.title;
  td.querySelector(".cell-error").textContent = reason || "";
}

function showRow(i) { for (const column of COLUMNS) showCell(i, column); }

// Text typed in a cell: checked at once; an acceptable value goes into the rows and is previewed.
function typed(input) {
  const i = Number(input.dataset.row);
  const column = COLUMNS.find((c) => c.key === input.dataset.key);
  const result = column.read(input.value, state.rows[i]);
  if (result.error) state.invalid.set(cellId(i, column.key), result.error);
  else {
    state.invalid.delete(cellId(i, column.key));
    state.rows[i] = column.apply(state.rows[i], result.value);
  }
  showRow(i);
  requestPreview();
}

// A cell left or entered: one step of undo.
function committed(input) {
  if (state.invalid.has(cellId(Number(input.dataset.row), input.dataset.key))) return;
  if (state.history.push(state.rows)) updateButtons();
}

// Enter and Shift+Enter move down and up a column (Tab and Shift+Tab move along the row).
function onCellKey(e) {
  if (e.key !== "Enter") return;
  e.preventDefault();
  const i = Number(e.target.dataset.row) + (e.shiftKey ? -1 : 1);
  committed(e.target);
  const next = inputAt(i, e.target.dataset.key);
  if (next) next.focus();
  else e.target.blur();
}

// A whole-table edit (stop moved, surface added or deleted, undo): redrawn and previewed.
function edit(rows, record = true) {
  setRows(rows);
  if (record) state.history.push(rows);
  updateButtons();
  requestPreview();
}

function insertRow(i) {
  const rows = structuredClone(state.rows);
  rows.splice(i + 1, 0, newRow(rows[i]));
  edit(rows);
  inputAt(i + 1, "radius").focus();
}

function deleteRow(i) {
  if (state.rows[i].stop) { say(`Surface ${i + 1} is the stop: move the stop to another surface first.`, true); return; }
  if (state.rows.length === 1) return;
  edit(state.rows.filter((_, k) => k !== i));
}

// The optimiser's lens (design.js) comes in as one edit: the editor's Undo returns to the lens before.
export const editedRows = () => structuredClone(state.rows);
export const editorLens = () => state.lensId;
export function replaceRows(rows) { edit(rows); }

function undo() { if (state.history.canUndo) edit(state.history.undo(), false); }
function redo() { if (state.history.canRedo) edit(state.history.redo(), false); }

function updateButtons() {
  $("editor-undo").disabled = !state.history || !state.history.canUndo;
  $("editor-redo").disabled = !state.history || !state.history.canRedo;
  $("editor").classList.toggle("edited", hasEdits());
}

// Ctrl+Z / Ctrl+Shift+Z (and Ctrl+Y) undo and redo edits, except in other text fields, and in a
// cell whose text has not been committed yet, where they undo the typing.
function onKey(e) {
  if (!(e.ctrlKey || e.metaKey) || !state.history) return;
  const key = e.key.toLowerCase();
  if (key !== "z" && key !== "y") return;
  const t = e.target;
  const inCell = t.closest && t.closest("#editor-table");
  if (!inCell && (t.tagName === "INPUT" && t.type !== "radio" || t.tagName === "TEXTAREA")) return;
  if (inCell && t.type === "text") {
    const column = COLUMNS.find((c) => c.key === t.dataset.key);
    if (t.value !== column.exact(state.history.current[Number(t.dataset.row)] || {})) committed(t);
  }
  e.preventDefault();
  if (key === "y" || e.shiftKey) redo();
  else undo();
}

// ---- previews ----------------------------------------------------------------------------------

const say = (text, bad = false) => { $("editor-status").textContent = text; $("editor-status").classList.toggle("bad", bad); };

// The edited rows with everything else the stored lens's prescription holds (its fields, aperture,
// wavelengths and weights, object distance, image tilt: docs/api.md), as the service sent them.
const prescriptionBody = (rows) => {
  const { id, rows: stored, ...lens } = state.prescription;
  return { ...lens, rows };
};

function requestPreview() {
  if (!state.editedAt) state.editedAt = performance.now();
  if (state.invalid.size) {
    say(`Not sent: ${state.invalid.size} cell${state.invalid.size > 1 ? "s need" : " needs"} correcting (marked in red).`, true);
    return;
  }
  if (state.inFlight) { state.pending = true; return; }
  sendPreview();
}

async function sendPreview() {
  state.inFlight = true;
  state.pending = false;
  const lensId = state.lensId, rows = structuredClone(state.rows);
  for (const note of document.querySelectorAll("#editor-table .row-note")) note.textContent = "";
  try {
    const answer = await postJson("/api/prescriptions/preview", { ...prescriptionBody(rows), ...lensPreviewSettings() });
    if (state.pending || lensId !== state.lensId) return;  // overtaken: the newer edit is sent below
    await showPreview(answer);
  } catch (e) {
    if (!state.pending && lensId === state.lensId) showPreviewError(e);
  } finally {
    state.inFlight = false;
    if (state.pending && lensId === state.lensId) sendPreview();
  }
}

async function showPreview(answer) {
  await showDiagramPng("data:image/png;base64," + answer.diagram_png_base64, "edited lens");
  showLensData(answer.lens);
  showAnalysis(answer.analysis, hasEdits() ? "edited lens" : state.lensId);
  const ms = performance.now() - state.editedAt;
  state.editedAt = 0;
  state.shown++;
  $("editor").dataset.previewMs = ms.toFixed(1);
  $("editor").dataset.previews = state.shown;
  say(`${hasEdits() ? "Edited lens" : "Stored lens"}: EFL ${answer.lens.efl.toFixed(3)} mm, updated in ${Math.round(ms)} ms.`);
}

// A row the service refused is marked on that row; anything else (an f-number this lens cannot
// take) in the status line.
function showPreviewError(e) {
  state.editedAt = 0;
  const row = e.body && e.body.row;
  const note = row && $("editor-table").querySelector(`tr[data-row="${row - 1}"] .row-note`);
  if (note) note.textContent = e.body.problem;
  say(`Not shown: ${e.message}`, true);
}

// ---- saving, downloading, rendering -----------------------------------------------------------------

// The rows written as a file; an Error with the service's reason (and .status: 422 for what the
// format cannot hold, as a .dat cannot hold a conic, a primary wavelength other than the d line or a
// catalog order that picks a glass).
async function prescriptionText(format, body) {
  const response = await authorizedFetch(`/api/prescriptions/${format === "zmx" ? "prescription.zmx" : "table.dat"}`, {
    method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
  const text = await response.text();
  if (!response.ok) throw Object.assign(new Error(JSON.parse(text).error), { status: response.status });
  return text;
}

// The lens as a .dat when a table can hold it, else as a .zmx.
async function savedFile(body) {
  if (!needsZemax(body)) {
    try {
      return { format: "dat", text: await prescriptionText("dat", body) };
    } catch (e) {
      if (e.status !== 422) throw e;
    }
  }
  return { format: "zmx", text: await prescriptionText("zmx", body) };
}

// Uploads the edited rows as a new lens and selects it.
export async function saveAsNewLens() {
  if (state.invalid.size) throw new Error("some cells need correcting first");
  const base = ($("editor-name").value.trim() || `${selectedLensName()}-edited`).replace(/\.(dat|zmx)$/, "");
  const comments = [`${base} (edited from ${selectedLensName()})`, ...(state.prescription.comments || []).slice(1)];
  const file = await savedFile({ ...prescriptionBody(state.rows), comments });
  const name = `${base}.${file.format}`;
  const lens = await api(`/api/lenses?name=${encodeURIComponent(name)}&layout=gap-after`,
                         { method: "POST", headers: { "Content-Type": "text/plain" }, body: file.text });
  await loadLenses(lens.id);
  say(`Saved as ${lens.id} (${name}).`);
  return lens.id;
}

async function download(format) {
  try {
    const text = await prescriptionText(format, prescriptionBody(state.rows));
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
    link.download = `${$("editor-name").value.trim() || selectedLensName()}.${format}`;
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000);
  } catch (e) {
    say(`No .${format}: ${e.message}`, true);
  }
}

async function renderThroughThisLens() {
  try {
    if (hasEdits()) await saveAsNewLens();
    $("render-form").requestSubmit();
    $("render-panel").scrollIntoView({ behavior: "smooth" });
  } catch (e) {
    say(`Not rendered: ${e.message}`, true);
  }
}

export async function setUpEditor() {
  attachEditor({ hasEdits, loadPrescription, requestPreview });
  $("editor-undo").addEventListener("click", undo);
  $("editor-redo").addEventListener("click", redo);
  $("editor-save").addEventListener("click", () => saveAsNewLens().catch((e) => say(`Not saved: ${e.message}`, true)));
  $("editor-dat").addEventListener("click", () => download("dat"));
  $("editor-zmx").addEventListener("click", () => download("zmx"));
  $("editor-render").addEventListener("click", renderThroughThisLens);
  $("editor-revert").addEventListener("click", () => state.prescription && edit(state.prescription.rows));
  document.addEventListener("keydown", onKey);
  try {
    await loadGlassNames();
  } catch (e) {
    showMessage("The glass catalog could not be loaded; glass names are checked by the service only: " + e.message);
  }
}
