#include "ReportManifest.h"

#include <fstream>

#include "SiteFiles.h"

namespace lenslab {

namespace fs = std::filesystem;

namespace {

constexpr int kFormat = 1;
const char* const kFileName = "manifest.json";

}  // namespace

ReportManifest readManifest(const fs::path& siteDir) {
    ReportManifest manifest;
    std::ifstream in(siteDir / kFileName);
    if (!in) return manifest;
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || j.value("format", 0) != kFormat || !j.contains("items") ||
        !j["items"].is_object())
        return manifest;
    for (const auto& [id, item] : j["items"].items()) {
        if (!item.is_object() || !item.contains("hash") || !item["hash"].is_string()) continue;
        ManifestItem m;
        m.hash = item["hash"].get<std::string>();
        if (item.contains("files") && item["files"].is_array())
            for (const auto& f : item["files"])
                if (f.is_string()) m.files.push_back(f.get<std::string>());
        m.data = item.value("data", nlohmann::json::object());
        manifest.items[id] = std::move(m);
    }
    return manifest;
}

void writeManifest(const ReportManifest& manifest, const fs::path& siteDir) {
    nlohmann::json items = nlohmann::json::object();
    for (const auto& [id, item] : manifest.items)
        items[id] = {{"hash", item.hash}, {"files", item.files}, {"data", item.data}};
    writeSiteFile(siteDir, kFileName, nlohmann::json{{"format", kFormat}, {"items", items}}.dump(1) + "\n");
}

const ManifestItem* reusableItem(const ReportManifest& manifest, const std::string& id, const std::string& hash,
                                 const fs::path& siteDir) {
    const auto it = manifest.items.find(id);
    if (it == manifest.items.end() || it->second.hash != hash) return nullptr;
    for (const std::string& f : it->second.files) {
        std::error_code ec;
        if (!fs::is_regular_file(siteDir / f, ec)) return nullptr;
    }
    return &it->second;
}

}  // namespace lenslab
