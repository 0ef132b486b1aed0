#pragma once
// `lenslab report` and the server's report job: builds the report site (index.html, style.css,
// assets/ with diagrams and renders, manifest.json as the cache) from the lenses and scenes.
// Items whose inputs are unchanged since the last build in the same folder are reused.
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

struct ReportOptions {
    std::filesystem::path outputDir;
    std::string lensDir, sceneDir;    // bundled lens tables (*.dat) and scenes (*.pbrt); empty: the source tree's
    // Lens ids in lensDir or paths of .dat files; empty: every bundled lens.
    std::vector<std::string> lenses;
    // Paths of further lens tables (uploaded lenses) added to those; a repeated id gets a suffix.
    std::vector<std::string> extraLenses;
    // What to call a lens given by its path (an upload, stored under an id: the file name it was
    // uploaded as): its heading and the file its `lenslab lens` line names. Else its id and file.
    std::map<std::string, std::string> lensNames;
    // Lenses rendered through every scene with a realistic camera (those of them in the report).
    std::vector<std::string> renderLenses = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};
    std::optional<double> fstop;      // tables and diagrams; nullopt: each lens at its widest
    double focusDistance = 2000;      // mm from the front vertex, tables and diagrams (infinity allowed)
    bool focusGiven = false;          // --focus given: every lens at it (else 20 focal lengths where 2 m is too close)
    double renderFstop = 5.6;         // renders; a lens slower than this renders at its widest
    int spp = 128;                    // renders' samples per pixel
    int width = 360;                  // renders' width in pixels; height from the scene's aspect
    bool quick = false;               // for tests: 96 pixels wide, 4 spp, fewer curve samples
    int threads = 0;                  // render threads, 0 = all cores
};

struct ReportProgress {
    std::string item;     // what was just finished, e.g. "render dgauss.50mm in cornell (accurate)"
    bool reused = false;  // taken from the cache
    int done = 0, total = 0;
};

struct ReportSummary {
    std::filesystem::path indexPath;
    int items = 0, built = 0, reused = 0;
    int renders = 0;                    // renderScene calls made by this build
    int lenses = 0, scenes = 0;
    double seconds = 0;
    std::vector<std::string> problems;  // items that failed (shown in the page too)
};

class ReportCancelled : public std::runtime_error {
public:
    ReportCancelled() : std::runtime_error("report cancelled") {}
};

// Throws std::runtime_error for an unusable output folder or an unknown lens, ReportCancelled when
// *cancel turns true (checked between items and inside renders). A lens or scene that fails is
// reported in the page and the summary; the rest of the report is still built.
ReportSummary buildReport(const ReportOptions& options,
                          const std::function<void(const ReportProgress&)>& onProgress = {},
                          const std::atomic<bool>* cancel = nullptr);

}  // namespace lenslab
