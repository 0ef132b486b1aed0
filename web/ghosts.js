// The ghost analysis of the selected lens (GET /api/lenses/{id}/ghosts): every two-reflection path,
// brightest first, as a table and as a plot of its blur on the film against its intensity beside
// the direct image (both logarithmic: the dangerous ghosts sit at the top left).
import { $, fixed } from "./api.js";
import { svg } from "./svg.js";

const PLOT = { width: 480, height: 260, left: 56, right: 12, top: 12, bottom: 40 };

// Decades spanning the values, for a logarithmic axis.
function decades(values) {
  const logs = values.filter((v) => v > 0).map(Math.log10);
  const lo = Math.floor(Math.min(...logs)), hi = Math.ceil(Math.max(...logs));
  return [lo, hi > lo ? hi : lo + 1];
}

function ghostPlot(ghosts) {
  const blur = ghosts.map((g) => Math.max(g.blur_diameter_mm, 1e-4));
  const intensity = ghosts.map((g) => Math.max(g.relative_intensity, 1e-12));
  const [x0, x1] = decades(blur), [y0, y1] = decades(intensity);
  const w = PLOT.width - PLOT.left - PLOT.right, h = PLOT.height - PLOT.top - PLOT.bottom;
  const px = (v) => PLOT.left + ((Math.log10(v) - x0) / (x1 - x0)) * w;
  const py = (v) => PLOT.top + h - ((Math.log10(v) - y0) / (y1 - y0)) * h;
  const root = svg("svg", { viewBox: `0 0 ${PLOT.width} ${PLOT.height}`, role: "img", "aria-label": "ghost blur against intensity" });
  root.append(svg("rect", { x: PLOT.left, y: PLOT.top, width: w, height: h, class: "frame" }));
  for (let d = x0; d <= x1; ++d) root.append(svg("text", { x: px(10 ** d), y: PLOT.top + h + 14, "text-anchor": "middle" }, `1e${d}`));
  for (let d = y0; d <= y1; ++d) root.append(svg("text", { x: PLOT.left - 4, y: py(10 ** d) + 4, "text-anchor": "end" }, `1e${d}`));
  root.append(svg("text", { x: PLOT.left + w / 2, y: PLOT.height - 4, "text-anchor": "middle" }, "blur diameter on the film (mm)"));
  root.append(svg("text", { x: 12, y: PLOT.top + h / 2, transform: `rotate(-90 12 ${PLOT.top + h / 2})`, "text-anchor": "middle" }, "intensity"));
  ghosts.forEach((g, i) => {
    const dot = svg("circle", { cx: px(blur[i]), cy: py(intensity[i]), r: 4, class: g.focused ? "focused" : "defocused" });
    dot.append(svg("title", {}, `${g.surfaces[0]}–${g.surfaces[1]}: blur ${fixed(g.blur_diameter_mm, 3)} mm, intensity ${g.relative_intensity.toExponential(2)}`));
    root.append(dot);
  });
  return root;
}

export function showGhosts(body) {
  const ghosts = body.ghosts;
  const focused = ghosts.filter((g) => g.focused).length;
  $("ghost-summary").textContent = `${body.reflecting_surfaces} reflecting surfaces, ${ghosts.length} ghosts at ${fixed(body.wavelength_nm, 2)} nm, ` +
    `paraxial and on axis; ${focused} focused near the film (blur under ${body.focused_below_mm} mm). Intensity: peak irradiance ` +
    `beside the direct image of a source ${body.source_diameter_deg}° across (the sun).`;
  $("ghost-plot").replaceChildren(ghosts.length ? ghostPlot(ghosts) : "");
  const rows = $("ghost-table").tBodies[0];
  $("ghost-table").dataset.lens = body.id;  // which lens the rows are of
  rows.replaceChildren();
  ghosts.forEach((g, i) => {
    const tr = rows.insertRow();
    tr.classList.toggle("focused", g.focused);
    const focus = g.focus_from_film_mm === null ? "∞" : fixed(g.focus_from_film_mm, 3);
    for (const v of [i + 1, `${g.surfaces[0]}–${g.surfaces[1]}`, fixed(100 * g.reflectance[0], 3), fixed(100 * g.reflectance[1], 3), focus,
                     fixed(g.blur_diameter_mm, 3), g.energy.toExponential(2), g.relative_intensity.toExponential(2), g.focused ? "focused" : ""])
      tr.insertCell().textContent = v;
  });
}
