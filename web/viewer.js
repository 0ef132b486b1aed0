// The image viewer: one render, or two compared (side by side with their |difference|, a slider
// over each other, or flicker), all at one exposure (normalised by 4N²/π as the report does, plus
// the user's stops), zoomed and panned together, with the linear RGB under the pointer.
import { $ } from "./api.js";
import { DIFFERENCE_STOPS, difference, exposeInto, exposeSrgbBytes, fetchPixels, normalisation, percentile99, rampInto } from "./hdr.js";

const MAX_ZOOM = 64;

const view = {
  entries: [],      // [{ id, label, fstop, width, height, image (pixels once done) }]
  diff: null,       // difference() of two finished images
  layers: [],       // [{ canvas, kind: "image"|"difference", entry }]
  stages: [],
  zoom: 1, x: 0, y: 0,
  flicker: 0,       // interval id
};

const pixelCache = new Map();  // render id -> pixels promise

function loadPixels(id) {
  if (!pixelCache.has(id)) {
    const loading = fetchPixels(`/api/renders/${id}/pixels`);
    loading.catch(() => pixelCache.delete(id));
    pixelCache.set(id, loading);
  }
  return pixelCache.get(id);
}

export function forgetPixels(id) { pixelCache.delete(id); }

const stops = () => Number($("exposure").value);
const differenceGain = () => Number($("difference-gain").value);
const scaleOf = (entry) => normalisation(entry.fstop) * Math.pow(2, stops());

// ---- drawing -----------------------------------------------------------------------------------

function drawLayer(layer) {
  const { canvas, kind, entry } = layer;
  const image = kind === "difference" ? view.diff && view.diff.image : entry.image;
  const context = canvas.getContext("2d", { willReadFrequently: !image });
  if (!image) {
    if (entry.preview) drawPreview(context, entry);
    return;
  }
  const pixels = context.createImageData(image.width, image.height);
  if (kind === "difference") rampInto(pixels.data, image, Math.pow(2, stops()) * differenceGain());
  else exposeInto(pixels.data, image, scaleOf(entry));
  context.putImageData(pixels, 0, 0);
}

// A render still in progress: its preview PNG (finished tiles, written at exposure 1) re-exposed.
function drawPreview(context, entry) {
  context.drawImage(entry.preview, 0, 0);
  const pixels = context.getImageData(0, 0, entry.width, entry.height);
  exposeSrgbBytes(pixels.data, scaleOf(entry));
  context.putImageData(pixels, 0, 0);
}

// Re-maps every image at the current exposure (no request: the linear pixels are here).
function redraw() {
  const started = performance.now();
  view.layers.forEach(drawLayer);
  const ms = performance.now() - started;
  const value = stops();
  $("exposure-value").textContent = (value > 0 ? "+" : "") + value.toFixed(1);
  const shownImages = view.layers.filter((l) => (l.kind === "difference" ? view.diff : l.entry.image));
  if (shownImages.length) {
    const { width, height } = view.entries[0];
    $("exposure-timing").textContent = `re-mapped ${shownImages.length} × ${width}×${height} in ${ms.toFixed(1)} ms`;
  }
  showDifferenceScale();
}

function showDifferenceScale() {
  const box = $("difference-scale");
  if (!view.diff) { box.hidden = true; return; }
  box.hidden = false;
  const full = 1 / (Math.pow(2, stops()) * differenceGain());
  $("difference-bar").style.background = `linear-gradient(to right, ${DIFFERENCE_STOPS.map((c) => `rgb(${c})`).join(", ")})`;
  $("difference-max").textContent = `≥ ${full.toPrecision(3)}`;
  const { rmse, worst } = view.diff;
  $("difference-stats").textContent =
    `RMSE ${rmse.toPrecision(3)}; worst pixel (${worst.x}, ${worst.y}): mean |Δ| ${worst.value.toPrecision(3)} ` +
    `(scene-normalised linear units, 1 = a white diffuse surface under the scene's light at exposure 0)`;
}

// New tiles of a render in progress arrived: `picture` is its preview PNG.
export function showPreview(id, picture) {
  for (const layer of view.layers) {
    if (layer.kind !== "image" || layer.entry.id !== id || layer.entry.image) continue;
    layer.entry.preview = picture;
    drawLayer(layer);
  }
}

// A render shown here has finished: its linear pixels replace the preview.
export async function renderFinished(id) {
  const entry = view.entries.find((e) => e.id === id);
  if (!entry) return;
  await fillEntry(entry);
  updateDifference();
  redraw();
}

async function fillEntry(entry) {
  try {
    entry.image = await loadPixels(entry.id);
    entry.fstop = entry.image.fstop || entry.fstop;
  } catch (e) {
    entry.image = null;
  }
}

function updateDifference() {
  const [a, b] = view.entries;
  view.diff = a && b && a.image && b.image && a.width === b.width && a.height === b.height
    ? difference(a.image, b.image, normalisation(a.fstop), normalisation(b.fstop)) : null;
}

// ---- layout --------------------------------------------------------------------------------------

function makeCanvas(entry, kind) {
  const canvas = document.createElement("canvas");
  canvas.width = entry.width;
  canvas.height = entry.height;
  canvas.className = "layer";
  canvas.setAttribute("role", "img");
  canvas.setAttribute("aria-label", kind === "difference" ? "difference image" : `${entry.label} image`);
  canvas.dataset.kind = kind;
  if (kind === "image") canvas.dataset.render = entry.id;
  view.layers.push({ canvas, kind, entry });
  return canvas;
}

function makePane(title, canvases, entry) {
  const figure = document.createElement("figure");
  figure.className = "pane";
  const port = document.createElement("div");
  port.className = "viewport";
  port.style.aspectRatio = `${entry.width} / ${entry.height}`;
  const stage = document.createElement("div");
  stage.className = "stage";
  stage.append(...canvases);
  port.append(stage);
  const caption = document.createElement("figcaption");
  caption.textContent = title;
  figure.append(port, caption);
  view.stages.push(stage);
  attachPointer(port, stage);
  return figure;
}

function layout() {
  clearInterval(view.flicker);
  view.layers = [];
  view.stages = [];
  const box = $("viewer-panes");
  box.replaceChildren();
  const [a, b] = view.entries;
  const mode = b ? $("compare-mode").value : "side";
  box.dataset.mode = mode;
  $("compare-mode").disabled = !b;
  if (!a) {
    $("viewer-title").textContent = "Viewer: open a render from the list";
    return;
  }
  $("viewer-title").textContent = b ? `Viewer: ${a.label} and ${b.label}` : `Viewer: ${a.label}`;
  if (mode === "side") {
    box.append(makePane(a.label, [makeCanvas(a, "image")], a));
    if (b) {
      box.append(makePane(b.label, [makeCanvas(b, "image")], b));
      box.append(makePane(`|difference| ×${differenceGain()} (colour scale below)`, [makeCanvas(a, "difference")], a));
    }
  } else {
    const lower = makeCanvas(a, "image"), upper = makeCanvas(b, "image");
    const pane = makePane(`${a.label} | ${b.label}`, [lower, upper], a);
    box.append(pane);
    if (mode === "slider") {
      const split = () => { upper.style.clipPath = `inset(0 0 0 ${$("split").value}%)`; };
      $("split").oninput = split;
      split();
    } else {
      const caption = pane.querySelector("figcaption");
      const show = (second) => { upper.style.visibility = second ? "visible" : "hidden"; caption.textContent = second ? b.label : a.label; };
      let second = false;
      show(second);
      view.flicker = setInterval(() => show((second = !second)), 700);
    }
  }
  $("split-control").hidden = mode !== "slider";
  applyTransform();
  redraw();
}

// Shows renders ([{ id, label, fstop, width, height }], one or two); finished ones at once.
export async function showRenders(entries) {
  view.entries = entries.map((e) => ({ ...e, image: null }));
  view.diff = null;
  view.zoom = 1; view.x = 0; view.y = 0;
  layout();
  await Promise.all(view.entries.filter((e) => e.done).map(fillEntry));
  updateDifference();
  redraw();
}

export function shownIds() { return view.entries.map((e) => e.id); }

// ---- zoom, pan, pixel values ----------------------------------------------------------------------

function applyTransform() {
  const port = view.stages[0] && view.stages[0].parentElement;
  const entry = view.entries[0];
  if (port) {
    view.x = Math.min(0, Math.max(port.clientWidth * (1 - view.zoom), view.x));
    view.y = Math.min(0, Math.max(port.clientHeight * (1 - view.zoom), view.y));
  }
  for (const stage of view.stages) stage.style.transform = `translate(${view.x}px, ${view.y}px) scale(${view.zoom})`;
  const perPixel = entry && port ? (port.clientWidth * view.zoom) / entry.width : 0;
  $("zoom-value").textContent = perPixel ? `${perPixel.toFixed(perPixel < 10 ? 1 : 0)} screen px per pixel` : "";
}

// Zooms by `factor` keeping the point (px, py) of the viewport where it is.
function zoomAt(factor, px, py) {
  const zoom = Math.min(MAX_ZOOM, Math.max(1, view.zoom * factor));
  view.x = px - ((px - view.x) * zoom) / view.zoom;
  view.y = py - ((py - view.y) * zoom) / view.zoom;
  view.zoom = zoom;
  applyTransform();
}

function zoomCentre(factor) {
  const port = view.stages[0] && view.stages[0].parentElement;
  if (port) zoomAt(factor, port.clientWidth / 2, port.clientHeight / 2);
}

function attachPointer(port, stage) {
  let drag = null;
  port.addEventListener("wheel", (e) => {
    e.preventDefault();
    const r = port.getBoundingClientRect();
    zoomAt(Math.pow(2, -e.deltaY / 300), e.clientX - r.left, e.clientY - r.top);
  }, { passive: false });
  port.addEventListener("pointerdown", (e) => { drag = { x: e.clientX, y: e.clientY }; port.setPointerCapture(e.pointerId); });
  port.addEventListener("pointerup", () => { drag = null; });
  port.addEventListener("pointercancel", () => { drag = null; });
  port.addEventListener("pointermove", (e) => {
    if (drag) {
      view.x += e.clientX - drag.x;
      view.y += e.clientY - drag.y;
      drag = { x: e.clientX, y: e.clientY };
      applyTransform();
    }
    showPixel(stage, e.clientX, e.clientY);
  });
  port.addEventListener("pointerleave", () => { $("pixel-readout").textContent = "Point at an image to read its linear RGB."; });
}

const rgbText = (rgb, i) => [0, 1, 2].map((c) => rgb[3 * i + c].toPrecision(4)).join(", ");

function showPixel(stage, clientX, clientY) {
  const entry = view.entries[0];
  if (!entry) return;
  const r = stage.getBoundingClientRect();
  const x = Math.floor(((clientX - r.left) / r.width) * entry.width);
  const y = Math.floor(((clientY - r.top) / r.height) * entry.height);
  if (x < 0 || y < 0 || x >= entry.width || y >= entry.height) return;
  const i = y * entry.width + x;
  const parts = view.entries.map((e) => `${e.label}: ${e.image ? rgbText(e.image.rgb, i) : "not finished"}`);
  if (view.diff) parts.push(`|difference| (normalised): ${rgbText(view.diff.image.rgb, i)}`);
  $("pixel-readout").textContent = `pixel (${x}, ${y}), linear RGB as stored in the EXR: ` + parts.join(" · ");
}

// ---- controls ------------------------------------------------------------------------------------

function fit() {
  const entry = view.entries.find((e) => e.image);
  if (!entry) return;
  const p = percentile99(entry.image) * normalisation(entry.fstop);
  if (!(p > 0)) return;
  $("exposure").value = Math.max(Number($("exposure").min), Math.min(Number($("exposure").max), -Math.log2(p))).toFixed(1);
  redraw();
}

export function setUpViewer() {
  $("exposure").addEventListener("input", redraw);
  $("exposure-fit").addEventListener("click", fit);
  $("exposure-reset").addEventListener("click", () => { $("exposure").value = 0; redraw(); });
  $("compare-mode").addEventListener("change", layout);
  $("difference-gain").addEventListener("change", layout);
  $("zoom-in").addEventListener("click", () => zoomCentre(2));
  $("zoom-out").addEventListener("click", () => zoomCentre(0.5));
  $("zoom-fit").addEventListener("click", () => { view.zoom = 1; view.x = 0; view.y = 0; applyTransform(); });
  window.addEventListener("resize", applyTransform);
  layout();
}
