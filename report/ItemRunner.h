#pragma once
// Runs the report's items through the cache (manifest.json): an item whose inputs hash is unchanged
// and whose files are all present is reused, anything else built. Counts what it did into the
// summary, reports progress, and checks for cancellation before every item.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>

#include "BuildReport.h"
#include "InputsHash.h"
#include "ReportManifest.h"

namespace lenslab {

class ItemRunner {
public:
    ItemRunner(std::filesystem::path site, ReportManifest previous, int total,
               const std::function<void(const ReportProgress&)>& onProgress, const std::atomic<bool>* cancel,
               ReportSummary& summary);

    // The item, reused or made by `make` (which need not set the hash); nullptr when making it threw,
    // the message then being added to the summary's problems. Cancellation propagates as ReportCancelled.
    const ManifestItem* run(const std::string& id, const std::string& label, const std::string& hash,
                            const std::function<ManifestItem()>& make);

    // An item that will not be made (what it needs failed earlier): counted for progress only.
    void skip(const std::string& label);
    // Counts one renderScene call (the summary's renders).
    void countRender() { ++summary_.renders; }
    // ReportCancelled when cancellation was asked for.
    void checkCancel() const;

    const ReportManifest& next() const { return next_; }
    // The items of this build so far plus the previous build's not yet reached: what to keep when a
    // build stops early, so that the next one still reuses both.
    ReportManifest keptSoFar() const;
    const std::filesystem::path& site() const { return site_; }
    const std::atomic<bool>* cancel() const { return cancel_; }

    // Deletes the files of previous items this build no longer has (a lens or scene removed).
    void removeStaleFiles() const;

private:
    void report(const std::string& label, bool reused);

    std::filesystem::path site_;
    ReportManifest previous_, next_;
    int total_, done_ = 0;
    const std::function<void(const ReportProgress&)>& onProgress_;
    const std::atomic<bool>* cancel_;
    ReportSummary& summary_;
};

// The code that makes report items, part by part: a SHA-256 of each part's sources, taken at build
// time (report/SourceDigests.cmake).
enum class CodePart { Optics, Formats, Image, Diagram, Raytracer, Report };
constexpr int kCodeParts = 6;
struct CodeDigests {
    std::string digests[kCodeParts];
};
CodeDigests builtCode();  // this build's

// A hash already holding the lenslab version, the item kind and the digests of the code that makes
// that kind (lens data, diagram, render, difference, speed): an item made by other code is rebuilt.
InputsHash itemInputs(const std::string& kind, const CodeDigests& code);
InputsHash itemInputs(const char* kind);  // with builtCode()

}  // namespace lenslab
