#include "ItemRunner.h"

#include <map>
#include <stdexcept>
#include <vector>

#include "PublicMessage.h"
#include "SourceDigests.h"

#include "Render.h"

#ifndef LENSLAB_VERSION
#error "LENSLAB_VERSION must be defined by the build"
#endif

namespace lenslab {

namespace fs = std::filesystem;

ItemRunner::ItemRunner(fs::path site, ReportManifest previous, int total,
                       const std::function<void(const ReportProgress&)>& onProgress, const std::atomic<bool>* cancel,
                       ReportSummary& summary)
    : site_(std::move(site)), previous_(std::move(previous)), total_(total), onProgress_(onProgress), cancel_(cancel),
      summary_(summary) {}

const ManifestItem* ItemRunner::run(const std::string& id, const std::string& label, const std::string& hash,
                                    const std::function<ManifestItem()>& make) {
    checkCancel();
    ++summary_.items;
    const ManifestItem* item = reusableItem(previous_, id, hash, site_);
    const bool reused = item != nullptr;
    if (reused) {
        ++summary_.reused;
        next_.items[id] = *item;
    } else {
        try {
            ManifestItem built = make();
            built.hash = hash;
            next_.items[id] = std::move(built);
            ++summary_.built;
        } catch (const ReportCancelled&) {
            throw;
        } catch (const RenderCancelled&) {
            throw ReportCancelled();
        } catch (const std::exception& e) {
            summary_.problems.push_back(publicMessage(label + ": " + e.what()));
            skip(label);
            return nullptr;
        }
    }
    report(label, reused);
    return &next_.items[id];
}

void ItemRunner::skip(const std::string& label) { report(label, false); }

void ItemRunner::checkCancel() const {
    if (cancel_ && cancel_->load()) throw ReportCancelled();
}

ReportManifest ItemRunner::keptSoFar() const {
    ReportManifest kept = next_;
    kept.items.insert(previous_.items.begin(), previous_.items.end());  // insert keeps this build's entries
    return kept;
}

void ItemRunner::removeStaleFiles() const {
    for (const auto& [id, item] : previous_.items) {
        if (next_.items.count(id)) continue;
        for (const std::string& f : item.files) {
            std::error_code ec;
            fs::remove(site_ / f, ec);
        }
    }
}

void ItemRunner::report(const std::string& label, bool reused) {
    ++done_;
    if (onProgress_) onProgress_({label, reused, done_, total_});
}

InputsHash itemInputs(const std::string& kind, const CodeDigests& code) {
    // The parts whose code makes each kind of item (and the report's own, which lays them out).
    static const std::map<std::string, std::vector<CodePart>> kMadeBy = {
        {"lens", {CodePart::Optics, CodePart::Formats}},
        {"analysis", {CodePart::Optics, CodePart::Formats}},
        {"diagram", {CodePart::Optics, CodePart::Image, CodePart::Diagram}},
        {"render", {CodePart::Optics, CodePart::Image, CodePart::Raytracer}},
        {"difference", {CodePart::Optics, CodePart::Image, CodePart::Raytracer}},
        {"speed", {CodePart::Optics, CodePart::Image, CodePart::Raytracer}},
        {"slanted-edge", {CodePart::Optics, CodePart::Image, CodePart::Raytracer}}};
    InputsHash h;
    h.add(std::string("lenslab ") + LENSLAB_VERSION).add(kind).add(code.digests[int(CodePart::Report)]);
    const auto it = kMadeBy.find(kind);
    if (it == kMadeBy.end()) throw std::logic_error("report item kind '" + kind + "' has no code listed");
    for (CodePart part : it->second) h.add(code.digests[int(part)]);
    return h;
}

CodeDigests builtCode() {
    CodeDigests c;
    for (int i = 0; i < kCodeParts; ++i) c.digests[i] = kSourceDigests[i];
    return c;
}

InputsHash itemInputs(const char* kind) { return itemInputs(kind, builtCode()); }

}  // namespace lenslab
