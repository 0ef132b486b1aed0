#pragma once
// The report's cache: for every item built (a diagram, a render), the hash of its inputs, the
// files it wrote under the site folder and the numbers it measured. Kept as manifest.json in the
// site folder; an item whose inputs are unchanged and whose files are all present is reused.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lenslab {

struct ManifestItem {
    std::string hash;
    std::vector<std::string> files;  // relative to the site folder
    nlohmann::json data;             // what the item measured (render time, rays/s, ...)
};

struct ReportManifest {
    std::map<std::string, ManifestItem> items;  // by item id, e.g. "render/cornell/dgauss.50mm/accurate"
};

// Empty when the file is missing, unreadable or of another format version: everything is rebuilt.
ReportManifest readManifest(const std::filesystem::path& siteDir);
// Written atomically (temporary file, then rename).
void writeManifest(const ReportManifest& manifest, const std::filesystem::path& siteDir);

// The stored item when its hash equals `hash` and every file it lists exists; otherwise nullptr.
const ManifestItem* reusableItem(const ReportManifest& manifest, const std::string& id, const std::string& hash,
                                 const std::filesystem::path& siteDir);

}  // namespace lenslab
