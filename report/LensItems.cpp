#include "LensItems.h"

#include <exception>
#include <filesystem>

#include "AnalysisJson.h"
#include "AnalysisPlots.h"
#include "AnalysisTables.h"
#include "GhostFormats.h"
#include "GhostPlot.h"
#include "analysis/GhostAnalysis.h"
#include "firstorder/Focus.h"
#include "analysis/LensDesignAnalysis.h"
#include "LensDiagram.h"
#include "SiteFiles.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

using nlohmann::json;

// The report's one setting for every lens's tables and diagrams (the report command's flags).
// Without --focus a lens that cannot focus as close as the default (a 500 mm reflex lens at 2 m)
// focuses at kLongLensFocus focal lengths instead.
constexpr double kLongLensFocus = 20;

LensSettings tableSettings(const ReportOptions& o, const std::string& path) {
    LensSettings s;
    if (o.fstop) s.fstop = Setting{*o.fstop, "report --fstop"};
    double focus = o.focusDistance;
    if (!o.focusGiven) {
        try {
            const FirstOrder fo = computeFirstOrder(loadLensSystem(path));
            if (closestFocusDistance(fo) > focus) focus = kLongLensFocus * fo.efl;
        } catch (const std::exception&) {
            // measureLens reports what is wrong with the lens
        }
    }
    s.focusDistance = Setting{focus, o.focusGiven ? "report --focus" : "report's default focus"};
    return s;
}

// The designer's analysis as the web page first shows it and `lenslab analyze` makes it: the widest
// aperture focused at infinity, or the report's --fstop and --focus where given (not the tables'
// 2 m default focus, which would part the report's numbers from the page's).
LensSettings designSettings(const ReportOptions& o) {
    LensSettings s;
    if (o.fstop) s.fstop = Setting{*o.fstop, "report --fstop"};
    if (o.focusGiven) s.focusDistance = Setting{o.focusDistance, "report --focus"};
    return s;
}

// lenslab analyze's plots and data for the lens at designSettings, cached like the tables.
DesignPlots buildDesignPlots(ItemRunner& runner, const std::string& id, const std::string& path, const ReportOptions& o) {
    DesignPlots design;
    const LensSettings settings = designSettings(o);
    const std::string label = "analysis " + id;
    InputsHash h = itemInputs("analysis");
    h.addFile(path).add(o.fstop.value_or(0)).add(settings.focusDistance ? settings.focusDistance->value : 0.0);  // 0: infinity
    const std::string folder = "assets/lenses/" + id + "-analysis/";
    const ManifestItem* item = runner.run("analysis/" + id, label, h.hex(), [&] {
        DesignAnalysisInputs inputs;
        inputs.lens = settings;
        const LensDesignAnalysis a = analyzeLensDesign(loadLensSystem(path), inputs);
        ManifestItem m;
        m.data = {{"fstop", a.lens.fstop},
                  {"focus", a.lens.focus.infinity ? "infinity" : formatNumber(a.lens.focus.objectZ - a.lens.lens.frontZ()) + " mm"},
                  {"settings_html", analysisSettingsHtml(a)},
                  {"tables_html", analysisTablesHtml(a)},
                  {"captions", json::array()}};
        m.files.push_back(folder + "analysis.json");
        writeSiteFile(runner.site(), m.files.back(), designAnalysisJson(a).dump(1) + "\n");
        for (const NamedSvg& plot : designAnalysisPlots(a)) {
            m.files.push_back(folder + plot.name + ".svg");
            writeSiteFile(runner.site(), m.files.back(), plot.svg + "\n");
            m.data["captions"].push_back(plot.caption);
        }
        const GhostAnalysis ghosts = analyzeGhosts(a.lens);
        m.data["ghosts"] = ghostAnalysisJson(ghosts);
        m.files.push_back(folder + "ghosts.svg");
        writeSiteFile(runner.site(), m.files.back(), ghostPlotSvg(ghosts, "ghosts-" + id) + "\n");
        m.data["captions"].push_back(
            "Ghosts: every two-reflection path's blur on the film against its peak intensity beside the direct image of "
            "the sun (paraxial, on axis, d line), the ones focused near the film a series of their own.");
        return m;
    });
    if (!item) {
        design.problem = "the lens designer's analysis failed (see the problems list)";
        return design;
    }
    design.jsonFile = item->files.front();
    design.plots.assign(item->files.begin() + 1, item->files.end());
    design.fstop = item->data.value("fstop", 0.0);
    design.focus = item->data.value("focus", std::string());
    design.captions = item->data.value("captions", std::vector<std::string>{});
    design.settingsHtml = item->data.value("settings_html", std::string());
    design.tablesHtml = item->data.value("tables_html", std::string());
    design.ghosts = item->data.value("ghosts", json::object());
    return design;
}

}  // namespace

LensEntry buildLensEntry(ItemRunner& runner, const std::string& id, const std::string& path, const ReportOptions& o) {
    LensEntry entry;
    const LensSettings settings = tableSettings(o, path);
    const LensFactsRequest request{settings, o.quick};
    InputsHash lensInputs = itemInputs("lens");
    lensInputs.addFile(path).add(o.fstop.value_or(0)).add(o.focusDistance).add(o.quick ? "quick" : "full");
    const std::string jsonFile = "assets/lenses/" + id + ".json";
    const ManifestItem* facts = runner.run("lens/" + id, "lens data " + id, lensInputs.hex(), [&] {
        const LensFacts f = measureLens(id, path, request);
        ManifestItem item;
        item.data = lensFactsJson(f);
        if (f.error.empty()) {
            writeSiteFile(runner.site(), jsonFile, f.analysis.dump(2) + "\n");
            item.files = {jsonFile};
        }
        return item;
    });
    if (facts) {
        entry.facts = lensFactsFromJson(facts->data);
    } else {
        entry.facts.id = id;
        entry.facts.error = "the lens data could not be stored (see the problems list)";
    }
    entry.facts.path = path;
    const auto given = o.lensNames.find(path);
    entry.name = given != o.lensNames.end() ? given->second : id;
    entry.fileName = given != o.lensNames.end() ? given->second : std::filesystem::path(path).filename().string();
    if (entry.facts.error.empty()) entry.jsonFile = jsonFile;

    for (const char* mode : {"exact", "thick", "overlay"}) {
        const std::string label = std::string("diagram ") + id + " (" + mode + ")";
        if (!entry.facts.error.empty()) {
            runner.skip(label);
            continue;
        }
        DiagramOptions d;
        d.mode = parseDiagramMode(mode);
        d.lens = settings;
        d.width = o.quick ? 480 : 960;
        d.height = o.quick ? 240 : 480;
        const std::string image = "assets/lenses/" + id + "-" + mode + ".png";
        InputsHash h = itemInputs("diagram");
        h.addFile(path).add(mode).add(o.fstop.value_or(0)).add(o.focusDistance).add(double(d.width)).add(double(d.height));
        const ManifestItem* item = runner.run("diagram/" + id + "/" + mode, label, h.hex(), [&] {
            writeSiteFile(runner.site(), image, drawLensDiagramPng(loadLensSystem(path), d));
            ManifestItem m;
            m.files = {image};
            return m;
        });
        if (item) entry.diagrams.push_back({mode, image, d.width, d.height});
        else entry.problem = "a diagram could not be drawn (see the problems list)";
    }
    if (entry.facts.error.empty()) entry.design = buildDesignPlots(runner, id, path, o);
    else runner.skip("analysis " + id);
    return entry;
}

}  // namespace lenslab
