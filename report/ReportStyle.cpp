#include "ReportPage.h"

namespace lenslab {

// Readable on a laptop, printable, no web fonts: the system's sans-serif and a single column that
// widens for the image rows.
std::string reportStyleSheet() {
    return R"css(:root {
  --ink: #1d1d1f;
  --muted: #5a5a60;
  --rule: #d9d9de;
  --panel: #f5f5f7;
  --accent: #0072b2;
  --problem: #b00020;
}
* { box-sizing: border-box; }
body {
  margin: 0;
  color: var(--ink);
  background: #fff;
  font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
}
header, main, footer { max-width: 1280px; margin: 0 auto; padding: 0 24px; }
header { padding-top: 24px; border-bottom: 1px solid var(--rule); }
h1 { font-size: 2rem; margin: 0 0 8px; }
h2 { font-size: 1.5rem; margin: 40px 0 12px; padding-top: 8px; border-top: 2px solid var(--ink); }
h3 { font-size: 1.2rem; margin: 28px 0 8px; }
h4 { font-size: 1rem; margin: 20px 0 8px; }
a { color: var(--accent); }
code { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 0.9em; background: var(--panel); padding: 0 3px; border-radius: 3px; }
.lede { max-width: 60em; }
.parameters { color: var(--muted); padding-left: 1.2em; }
nav ol { padding-left: 1.2em; }
nav li { margin: 2px 0; }
nav a { margin-right: 4px; }
section > p, article > p { max-width: 60em; }
.design { color: var(--muted); margin-top: 0; }
.problem { color: var(--problem); font-weight: 600; }
.lens { border-bottom: 1px solid var(--rule); padding-bottom: 16px; }
.lens-layout { display: grid; grid-template-columns: minmax(0, 34em) minmax(0, 1fr); gap: 24px; align-items: start; }
@media (max-width: 1000px) { .lens-layout { grid-template-columns: minmax(0, 1fr); } }
table { border-collapse: collapse; font-size: 0.9rem; }
caption { text-align: left; color: var(--muted); font-size: 0.85rem; padding-bottom: 6px; caption-side: top; }
th, td { padding: 3px 8px; border-bottom: 1px solid var(--rule); text-align: left; vertical-align: top; }
thead th { border-bottom: 2px solid var(--ink); }
td[data-key], .render-stats td, .ghosts td { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.lens-data td:last-child { color: var(--muted); }
figure { margin: 0; }
figcaption { color: var(--muted); font-size: 0.85rem; margin-top: 4px; }
img { max-width: 100%; height: auto; display: block; background: var(--panel); }
.diagrams { display: grid; grid-template-columns: minmax(0, 1fr); gap: 12px; }
.plots { display: grid; grid-template-columns: repeat(auto-fit, minmax(320px, 1fr)); gap: 20px; margin-top: 20px; }
.plots.wide { grid-template-columns: repeat(auto-fit, minmax(480px, 1fr)); }
svg.plot { max-width: 100%; height: auto; display: block; }
.analysis-settings { display: flex; flex-wrap: wrap; gap: 2px 18px; margin: 6px 0 12px; font-size: 0.9rem; }
.analysis-settings div { display: flex; gap: 6px; }
.analysis-settings dt { color: var(--muted); }
.analysis-settings dd { margin: 0; font-variant-numeric: tabular-nums; }
.analysis-tables { display: flex; flex-wrap: wrap; gap: 12px 24px; align-items: flex-start; max-width: 100%; overflow-x: auto; }
.analysis-numbers td[data-json] { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.triptych { display: grid; grid-template-columns: repeat(3, minmax(0, 1fr)); gap: 12px; }
.triptych img { width: 100%; image-rendering: auto; }
.comparison { margin-bottom: 12px; }
.render-stats, .ghosts { margin-top: 8px; }
.ghosts tr.focused th, .ghosts tr.focused td { font-weight: 600; }
.params { color: var(--muted); font-size: 0.85rem; }
.download { font-size: 0.9rem; }
footer { color: var(--muted); font-size: 0.85rem; border-top: 1px solid var(--rule); margin-top: 40px; padding-bottom: 24px; }
)css";
}

}  // namespace lenslab
