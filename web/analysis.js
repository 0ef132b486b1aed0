// The lens designer's analysis of the lens shown, stored or edited: its settings, numbers and plots
// as the report shows them. The service makes all of it (GET /api/lenses/{id}/analysis?views=html,
// or the editor's preview) and the page inlines it, so every plot has one implementation
// (report/AnalysisPlots.cpp). It follows the lens's f-number, focus and wavelength; the image plane,
// the spots' reference point and the MTF's range are chosen here. Every number shown carries its
// place in the analysis JSON and its exact value (data-json, data-value).
import { $, api } from "./api.js";

const state = {
  request: 0,  // sequence number: an answer overtaken by a newer request or an edited lens is dropped
  shown: 0,    // analyses shown (the browser tests wait on it)
};

// The choices of this panel, named as the API's parameters; the MTF's range only when chosen.
export function analysisChoices() {
  const choices = { image_plane: $("analysis-plane").value, reference: $("analysis-reference").value };
  const max = $("analysis-max-frequency").value;
  if (max !== "") choices.max_frequency = Number(max);
  return choices;
}

// The stored lens's analysis at `lensQuery` (its f-number, focus and wavelength as query parameters).
export async function showStoredAnalysis(lensId, lensQuery) {
  const request = ++state.request;
  const choices = new URLSearchParams(Object.entries(analysisChoices())).toString();
  $("analysis-status").textContent = "Analysing…";
  try {
    const analysis = await api(`/api/lenses/${encodeURIComponent(lensId)}/analysis?${lensQuery}&${choices}&views=html`);
    if (request === state.request) showAnalysis(analysis, lensId);
  } catch (e) {
    if (request !== state.request) return;
    $("analysis-status").textContent = `No analysis of ${lensId} at these settings: ${e.message}`;
    $("analysis").dataset.state = "failed";
  }
}

// Parsed as HTML, as the report inlines its own plots; parsing runs no scripts, and the service
// wrote every byte.
function fragment(html) {
  const template = document.createElement("template");
  template.innerHTML = html;
  return template.content;
}

function plotFigure(plot) {
  const figure = document.createElement("figure");
  figure.dataset.plot = plot.name;
  const caption = document.createElement("figcaption");
  caption.textContent = plot.caption;
  figure.append(fragment(plot.svg), caption);
  return figure;
}

// Shows an analysis answered with its views; `label` names the lens analysed.
export function showAnalysis(analysis, label) {
  ++state.request;
  const views = analysis.views;
  $("analysis-settings").replaceChildren(fragment(views.settings_html));
  $("analysis-tables").replaceChildren(fragment(views.tables_html));
  // One field per row (its spot, MTF and fans), then the curves against field and wavelength.
  const rows = new Map();
  for (const plot of views.plots) {
    const field = (plot.name.match(/-field-(\d+)$/) || [])[1] || "curves";
    if (!rows.has(field)) {
      const row = document.createElement("div");
      row.className = "analysis-row";
      row.dataset.field = field;
      rows.set(field, row);
    }
    rows.get(field).append(plotFigure(plot));
  }
  $("analysis-plots").replaceChildren(...rows.values());
  // A bundled table's name is its path: the file's name is enough beside the lens's id.
  const file = (analysis.name || "").split("/").pop();
  const name = file && file !== label ? `${file} (${label})` : label;
  // A field no ray reaches (traced false) has no image height, distortion or illumination: named here too.
  const notImaged = analysis.fields.filter((f) => !f.traced).map((f) => `${f.field_deg.toFixed(2)}°`);
  $("analysis-status").textContent = `${name}: ${analysis.fields.length} field${analysis.fields.length > 1 ? "s" : ""}, ` +
    `wavelengths ${analysis.wavelengths_nm.map((w) => w.toFixed(1)).join(", ")} nm` +
    (notImaged.length ? `; not imaged: ${notImaged.join(", ")}` : "");
  const section = $("analysis");
  section.dataset.state = "shown";
  section.dataset.lens = label;
  section.dataset.shown = ++state.shown;
}

// `onChange`: asks for the analysis again when a choice here changes.
export function setUpAnalysis(onChange) {
  for (const id of ["analysis-plane", "analysis-reference", "analysis-max-frequency"]) $(id).addEventListener("change", onChange);
  $("analysis-controls").addEventListener("submit", (e) => e.preventDefault());
}
