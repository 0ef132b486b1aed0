#include "BuildReport.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>

#include "ItemRunner.h"
#include "LensItems.h"
#include "prescription/NumberText.h"
#include "RenderItems.h"
#include "ReportPage.h"
#include "SiteFiles.h"
#include "SlantedEdgeComparison.h"
#include "SlantedEdgeSection.h"

#if !defined(LENSLAB_VERSION) || !defined(LENSLAB_SOURCE_DIR)
#error "LENSLAB_VERSION and LENSLAB_SOURCE_DIR must be defined by the build"
#endif

namespace lenslab {

namespace fs = std::filesystem;

namespace {

struct LensSource {
    std::string id, path;
};

std::vector<LensSource> resolveLenses(const ReportOptions& o) {
    std::vector<LensSource> lenses;
    if (o.lenses.empty()) {
        std::error_code ec;
        for (fs::directory_iterator it(o.lensDir, ec), end; !ec && it != end; it.increment(ec))
            if (isLensFileName(it->path().string())) lenses.push_back({it->path().stem().string(), it->path().string()});
        std::sort(lenses.begin(), lenses.end(), [](const LensSource& a, const LensSource& b) { return a.id < b.id; });
    }
    for (const std::string& name : o.lenses) {
        const fs::path table = fs::path(o.lensDir) / (name + ".dat"), zemax = fs::path(o.lensDir) / (name + ".zmx");
        const fs::path path = fs::is_regular_file(table) ? table : fs::is_regular_file(zemax) ? zemax : fs::path(name);
        if (!fs::is_regular_file(path))
            throw std::runtime_error("lens '" + name + "' is neither a bundled lens id nor a lens table file");
        lenses.push_back({path.stem().string(), path.string()});
    }
    for (const std::string& path : o.extraLenses) {
        if (!fs::is_regular_file(path)) throw std::runtime_error("lens table '" + path + "' not found");
        std::string id = fs::path(path).stem().string();
        const std::string stem = id;
        for (int k = 2; std::any_of(lenses.begin(), lenses.end(), [&](const LensSource& l) { return l.id == id; }); ++k)
            id = stem + "-" + std::to_string(k);
        lenses.push_back({id, path});
    }
    if (lenses.empty()) throw std::runtime_error("no lens tables (*.dat) in " + o.lensDir);
    return lenses;
}

std::string nowUtc() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char b[32];
    std::strftime(b, sizeof b, "%Y-%m-%d %H:%M UTC", &tm);
    return b;
}

const LensEntry* findLens(const std::vector<LensEntry>& lenses, const std::string& id) {
    for (const LensEntry& l : lenses)
        if (l.facts.id == id && l.facts.error.empty()) return &l;
    return nullptr;
}

std::string fstopText(std::optional<double> fstop) {
    if (!fstop) return "each lens at its widest";
    return "f/" + formatFNumber(*fstop);
}

// The settings shown in the page's header.
std::vector<std::string> parameterLines(const ReportOptions& o, const RenderPlan& plan) {
    char focus[128] = "infinity";
    if (!std::isinf(o.focusDistance))
        std::snprintf(focus, sizeof focus, "%g mm from the front vertex%s", o.focusDistance,
                      o.focusGiven ? "" : " (20 focal lengths for a lens that cannot focus so close)");
    return {
        std::string("Lens tables and diagrams: ") + fstopText(o.fstop) + ", focused at " + focus,
        "Renders: " + std::to_string(plan.width) + " pixels wide, " + std::to_string(plan.spp) + " samples per pixel, " +
            fstopText(o.renderFstop) + " (or the lens's widest when it is slower), focus and film as each scene sets them, " +
            (o.threads > 0 ? std::to_string(o.threads) : std::string("all")) + " render threads",
        std::string("Mode: ") + (o.quick ? "quick (a test build: tiny images, few samples)" : "full"),
    };
}

// Runs every item of the report (cached or built) into `content`: lenses, then renders per scene,
// then the speed study.
void buildItems(ItemRunner& runner, const std::vector<LensSource>& lensSources, const std::vector<SceneSource>& scenes,
                const std::vector<std::string>& renderIds, const RenderPlan& plan, const ReportOptions& o,
                ReportContent& content) {
    for (const LensSource& l : lensSources) content.lenses.push_back(buildLensEntry(runner, l.id, l.path, o));
    const auto chart = std::find_if(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kColourChartSceneId; });
    if (chart != scenes.end())
        for (LensEntry& lens : content.lenses) {
            if (lens.facts.error.empty() && lens.facts.analysis.value("dispersive", false))
                lens.colourFringes = buildColourFringes(runner, *chart, lens, plan, o);
            else
                for (const char* film : {"spectral", "rgb"}) runner.skip("colour chart " + lens.facts.id + " (" + film + ")");
        }
    for (const SceneSource& s : scenes) {
        ReportScene entry{s, {}};
        if (s.realisticCamera)
            for (const std::string& id : renderIds) {
                if (const LensEntry* lens = findLens(content.lenses, id)) {
                    entry.pairs.push_back(buildRenderPair(runner, s, *lens, plan, o));
                } else {
                    for (const char* what : {"render (accurate)", "render (approximate)", "difference"})
                        runner.skip(std::string(what) + " " + id + " in " + s.id);
                }
            }
        content.scenes.push_back(std::move(entry));
    }
    const auto edges = std::find_if(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kSlantedEdgeSceneId; });
    if (edges != scenes.end()) content.slantedEdges = buildSlantedEdges(runner, *edges, content.lenses, o);
    const auto ladderScene =
        std::find_if(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kSensorLadderSceneId; });
    const LensEntry* ladderLens = renderIds.empty() ? nullptr : findLens(content.lenses, renderIds.front());
    if (ladderScene != scenes.end() && ladderLens)
        content.sensorLadder = buildSensorLadder(runner, *ladderScene, *ladderLens, plan, o);
    else if (ladderScene != scenes.end() && !renderIds.empty())
        for (double iso : kSensorLadderIsos) runner.skip("sensor ladder at ISO " + formatNumber(iso));
    const ReportScene* speedScene = nullptr;
    for (const ReportScene& s : content.scenes)
        if (!speedScene && s.scene.realisticCamera) speedScene = &s;
    if (!speedScene || renderIds.empty()) return;
    if (const LensEntry* lens = findLens(content.lenses, renderIds.front()))
        content.speed = buildSpeedStudy(runner, *speedScene, *lens, plan, o);
    else
        for (std::size_t k = 0; k < 2 * plan.speedSpps.size(); ++k) runner.skip("speed study");
}

}  // namespace

ReportSummary buildReport(const ReportOptions& options, const std::function<void(const ReportProgress&)>& onProgress,
                          const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    ReportOptions o = options;
    if (o.lensDir.empty()) o.lensDir = LENSLAB_SOURCE_DIR "/lenses";
    if (o.sceneDir.empty()) o.sceneDir = LENSLAB_SOURCE_DIR "/scenes";
    if (o.outputDir.empty()) throw std::runtime_error("report: no output folder given");
    fs::create_directories(o.outputDir);
    const std::vector<LensSource> lensSources = resolveLenses(o);
    std::vector<SceneSource> scenes = listScenes(o.sceneDir);
    const RenderPlan plan = renderPlan(o);

    std::vector<std::string> renderIds;
    for (const LensSource& l : lensSources)
        if (std::find(o.renderLenses.begin(), o.renderLenses.end(), l.id) != o.renderLenses.end()) renderIds.push_back(l.id);
    int realisticScenes = 0;
    for (const SceneSource& s : scenes) realisticScenes += s.realisticCamera;
    const bool speed = realisticScenes > 0 && !renderIds.empty();
    const bool chart = std::any_of(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kColourChartSceneId; });
    const bool edges = std::any_of(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kSlantedEdgeSceneId; });
    const bool ladder = !renderIds.empty() &&
        std::any_of(scenes.begin(), scenes.end(), [](const SceneSource& s) { return s.id == kSensorLadderSceneId; });
    std::vector<std::string> lensIds;
    for (const LensSource& l : lensSources) lensIds.push_back(l.id);
    const int total = (chart ? 7 : 5) * static_cast<int>(lensSources.size()) + 3 * realisticScenes * static_cast<int>(renderIds.size()) +
                      (speed ? 2 * static_cast<int>(plan.speedSpps.size()) : 0) + (edges ? slantedEdgeItemCount(lensIds) : 0) +
                      (ladder ? static_cast<int>(std::size(kSensorLadderIsos)) : 0) + 1;

    ReportSummary summary;
    ItemRunner runner(o.outputDir, readManifest(o.outputDir), total, onProgress, cancel, summary);
    ReportContent content;
    content.version = LENSLAB_VERSION;
    content.generatedAt = nowUtc();
    try {
        buildItems(runner, lensSources, scenes, renderIds, plan, o, content);
        runner.checkCancel();
    } catch (const ReportCancelled&) {
        writeManifest(runner.keptSoFar(), o.outputDir);
        throw;
    }

    content.parameters = parameterLines(o, plan);
    content.problems = summary.problems;
    writeSiteFile(o.outputDir, "style.css", reportStyleSheet());
    writeSiteFile(o.outputDir, "index.html", reportHtml(content));
    writeManifest(runner.next(), o.outputDir);
    runner.removeStaleFiles();
    if (onProgress) onProgress({"page", false, total, total});

    summary.indexPath = o.outputDir / "index.html";
    summary.lenses = static_cast<int>(lensSources.size());
    summary.scenes = static_cast<int>(scenes.size());
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

}  // namespace lenslab
