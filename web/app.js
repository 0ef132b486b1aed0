// lenslab web page: the lens workbench. Plain ES modules against the service's API (docs/api.md),
// no build step and no external resources: lens.js (lenses and their controls), renders.js (renders
// and their history), viewer.js (exposure, comparison, zoom), report.js (the report build),
// token.js (the API token field), editor.js (the live prescription editor), analysis.js (the
// designer's analysis of the lens shown), glass-catalogs.js (uploaded glass catalogs), design.js
// (optimise and tolerance jobs).
import { showMessage } from "./api.js";
import { setUpTokenField } from "./token.js";
import { loadLenses, setUpLensPanel } from "./lens.js";
import { followReport, setUpReport } from "./report.js";
import { loadHistory, loadScenes, setUpRenderPanel } from "./renders.js";
import { setUpViewer } from "./viewer.js";
import { setUpEditor } from "./editor.js";
import { setUpDesign } from "./design.js";
import { loadGlassCatalogs } from "./glass-catalogs.js";

async function start() {
  setUpTokenField();
  setUpLensPanel();
  setUpRenderPanel();
  setUpViewer();
  setUpReport();
  setUpDesign();
  followReport();
  try {
    await setUpEditor();
    await Promise.all([loadLenses(), loadScenes(), loadGlassCatalogs()]);
    await loadHistory();
    document.body.dataset.ready = "true";
  } catch (e) {
    showMessage("The page could not load its data: " + e.message);
  }
}

start();
