// Optimise and tolerance the selected lens as jobs of the service (docs/api.md, "Optimising and
// tolerancing"), followed by server-sent events: the merit drawn as it falls, the optimised lens put
// into the prescription editor as one edit (with an Undo back to the lens before), and the Monte
// Carlo's yield and each operand's histogram with its 50th, 90th and 98th percentiles.
import { $, api, follow, postJson } from "./api.js";
import { selectedLens } from "./lens.js";
import { editedRows, editorLens, replaceRows } from "./editor.js";
import { svg } from "./svg.js";

const state = {
  job: null,          // the job running now: {id, kind, lens}
  before: null,       // the editor's rows before the last optimisation (Undo), with their lens
};

const number = (v) => (v === null || v === undefined || !isFinite(v)) ? "–" : Number(v).toPrecision(4);

function say(id, text, bad = false) {
  $(id).textContent = text;
  $(id).classList.toggle("bad", bad);
}

function busy(job) {
  state.job = job;
  $("optimise").disabled = $("tolerance-run").disabled = !!job;
  $("design-stop").hidden = !job;
}

// Submits a job and follows it; `onProgress(status)` while it runs, `onDone(result, lens)` at the end.
async function runJob(kind, body, statusId, onProgress, onDone) {
  const lens = selectedLens();
  if (!lens || state.job) return;
  say(statusId, kind === "optimise" ? "Optimising…" : "Tolerancing…");
  let job;
  try {
    job = await postJson(`/api/lenses/${encodeURIComponent(lens)}/${kind}`, body);
  } catch (e) {
    say(statusId, `Not started: ${e.message}`, true);
    return;
  }
  busy({ id: job.id, kind, lens });
  $(statusId).dataset.state = job.state;
  follow(job.links.events, () => job.links.self, async (status) => {
    $(statusId).dataset.state = status.state;
    if (status.state === "queued") say(statusId, "Waiting for the service's heavy-work pool…");
    else if (status.state === "running" && status.progress) onProgress(status);
    const over = ["done", "failed", "cancelled", "deleted"].includes(status.state);
    if (!over) return false;
    busy(null);
    if (status.state === "done") onDone(status.result, lens);
    else if (status.state === "failed") say(statusId, `Failed: ${status.error}`, true);
    else say(statusId, "Stopped.");
    return true;
  });
}

// ---- optimise ----------------------------------------------------------------------------------

const MERIT_PLOT = { width: 480, height: 150, left: 64, right: 12, top: 10, bottom: 30 };

// The merit after each step, on a logarithmic axis.
function meritPlot(merits) {
  const { width, height, left, right, top, bottom } = MERIT_PLOT;
  const logs = merits.map((m) => Math.log10(Math.max(m, 1e-300)));
  let lo = Math.min(...logs), hi = Math.max(...logs);
  if (hi - lo < 1e-6) { lo -= 0.5; hi += 0.5; }
  const w = width - left - right, h = height - top - bottom;
  const px = (i) => left + (merits.length > 1 ? (i / (merits.length - 1)) * w : w / 2);
  const py = (l) => top + h - ((l - lo) / (hi - lo)) * h;
  const root = svg("svg", { viewBox: `0 0 ${width} ${height}`, role: "img", "aria-label": "merit after each step" });
  root.append(svg("rect", { x: left, y: top, width: w, height: h, class: "frame" }));
  root.append(svg("text", { x: left - 4, y: top + 9, "text-anchor": "end" }, number(10 ** hi)));
  root.append(svg("text", { x: left - 4, y: top + h, "text-anchor": "end" }, number(10 ** lo)));
  root.append(svg("text", { x: left + w / 2, y: height - 6, "text-anchor": "middle" }, `merit (log scale) after each of ${merits.length - 1} steps`));
  root.append(svg("polyline", { points: logs.map((l, i) => `${px(i)},${py(l)}`).join(" "), class: "merit-line" }));
  logs.forEach((l, i) => root.append(svg("circle", { cx: px(i), cy: py(l), r: 3, class: "merit-point" })));
  return root;
}

function showMerits(merits) {
  $("design").dataset.merits = JSON.stringify(merits);
  $("merit-plot").replaceChildren(merits.length ? meritPlot(merits) : "");
}

function optimise() {
  runJob("optimise", {}, "optimise-status",
    (status) => {
      const p = status.progress;
      say("optimise-status", `Step ${p.iteration}: merit ${number(p.merit)} (${p.evaluations} evaluations)`);
      showMerits(p.history);
    },
    (result, lens) => {
      const o = result.optimiser;
      showMerits(o.history);
      say("optimise-status", `Merit ${number(o.start.merit)} → ${number(o.end.merit)} in ${o.iterations} steps (${o.stop}); ` +
          `${o.variables.length} variables moved. The optimised lens is in the editor below.`);
      if (editorLens() !== lens || selectedLens() !== lens) return;  // another lens was chosen meanwhile
      state.before = { lens, rows: editedRows() };
      replaceRows(result.prescription.rows);
      $("optimise-undo").disabled = false;
    });
}

function undoOptimise() {
  if (!state.before || editorLens() !== state.before.lens) return;
  replaceRows(state.before.rows);
  state.before = null;
  $("optimise-undo").disabled = true;
  say("optimise-status", "Back to the lens before the optimisation.");
  showMerits([]);
}

// ---- tolerance ---------------------------------------------------------------------------------

const HISTOGRAM = { width: 260, height: 120, left: 8, right: 8, top: 8, bottom: 28 };

// One distribution's histogram (its bins span min to max), with its 50/90/98th percentiles marked.
function histogramPlot(d, label) {
  const { width, height, left, right, top, bottom } = HISTOGRAM;
  const w = width - left - right, h = height - top - bottom;
  const most = Math.max(1, ...d.histogram);
  const span = d.max - d.min || 1;
  const x = (v) => left + ((v - d.min) / span) * w;
  const root = svg("svg", { viewBox: `0 0 ${width} ${height}`, role: "img", "aria-label": `histogram of ${label}` });
  const bin = w / d.histogram.length;
  d.histogram.forEach((count, i) => {
    const bh = (count / most) * h;
    root.append(svg("rect", { x: left + i * bin + 0.5, y: top + h - bh, width: Math.max(bin - 1, 0.5), height: bh, class: "bin" }, undefined));
  });
  let labelled = -Infinity;  // a label too close to the last one is left out (its line says enough)
  for (const [name, v] of [["p50", d.p50], ["p90", d.p90], ["p98", d.p98]]) {
    root.append(svg("line", { x1: x(v), x2: x(v), y1: top, y2: top + h, class: `percentile ${name}` }));
    if (x(v) - labelled < 16) continue;
    root.append(svg("text", { x: x(v), y: top + h + 11, "text-anchor": "middle", class: name }, name.slice(1)));
    labelled = x(v);
  }
  root.append(svg("text", { x: left, y: height - 3, "text-anchor": "start" }, number(d.min)));
  root.append(svg("text", { x: width - right, y: height - 3, "text-anchor": "end" }, number(d.max)));
  return root;
}

function distributionFigure(d, label, unit) {
  const figure = document.createElement("figure");
  figure.className = "distribution";
  figure.dataset.count = d.count;
  figure.dataset.binsTotal = d.histogram.reduce((a, b) => a + b, 0);
  const caption = document.createElement("figcaption");
  caption.textContent = `${label}: p50 ${number(d.p50)}, p90 ${number(d.p90)}, p98 ${number(d.p98)}${unit ? " " + unit : ""}`;
  figure.append(histogramPlot(d, label), caption);
  return figure;
}

function showTolerance(result) {
  const mc = result.monte_carlo;
  say("tolerance-status", `Yield ${(100 * mc.yield).toFixed(1)}% of ${mc.trials} trials (seed ${result.seed}; ${mc.invalid} could not be built or traced); ` +
      `nominal merit ${number(mc.nominal_merit)}. ${result.sensitivity.length} tolerances; the most sensitive: ` +
      (result.sensitivity[0] ? result.sensitivity[0].tolerance : "none") + ".");
  const figures = [distributionFigure(mc.merit, "merit", "")];
  for (const op of mc.operands) figures.push(distributionFigure(op.distribution, op.description, op.unit));
  $("tolerance-results").replaceChildren(...figures);
  $("tolerance-results").dataset.trials = mc.trials;
}

function tolerance(event) {
  event.preventDefault();
  const body = { trials: Number($("tolerance-trials").value), seed: Number($("tolerance-seed").value) };
  $("tolerance-results").replaceChildren();
  runJob("tolerance", body, "tolerance-status",
    (status) => {
      const p = status.progress;
      say("tolerance-status", p.phase === "sensitivity" ? "Sensitivity: each tolerance alone at its limits…"
                                                        : `Monte Carlo: ${p.trials_done} of ${p.trials} trials`);
    },
    (result) => showTolerance(result));
}

// ---- the panel ---------------------------------------------------------------------------------

// Another lens chosen: what the panel shows was of the last one.
function lensChanged(records) {
  if (state.job || records.every((r) => r.oldValue === $("lens-title").dataset.id)) return;
  for (const id of ["optimise-status", "tolerance-status"]) say(id, "");
  showMerits([]);
  $("tolerance-results").replaceChildren();
  state.before = null;
  $("optimise-undo").disabled = true;
}

export function setUpDesign() {
  $("optimise").addEventListener("click", optimise);
  $("optimise-undo").addEventListener("click", undoOptimise);
  $("tolerance-form").addEventListener("submit", tolerance);
  $("design-stop").addEventListener("click", () => state.job && api(`/api/design-jobs/${state.job.id}`, { method: "DELETE" }).catch(() => {}));
  new MutationObserver(lensChanged).observe($("lens-title"), { attributeFilter: ["data-id"], attributeOldValue: true });
}
