#include "GlassCatalogFlags.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "ArgParser.h"
#include "prescription/GlassCatalog.h"
#include "prescription/GlassCatalogFile.h"

namespace lenslab {

namespace {

void load(const std::string& path) {
    GlassCatalogFile catalog = readGlassCatalogFile(path);
    addGlassCatalog(catalog.name, std::move(catalog.glasses));
}

}  // namespace

std::vector<std::string> loadGlassCatalogs(const std::vector<std::string>& args) {
    if (const char* folder = std::getenv("LENSLAB_GLASS_CATALOGS"); folder && *folder) {
        std::vector<std::string> files;
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(folder, error))
            if (entry.is_regular_file() && isGlassCatalogFileName(entry.path().string())) files.push_back(entry.path().string());
        if (error) throw UsageError("LENSLAB_GLASS_CATALOGS: cannot read the folder " + std::string(folder));
        std::sort(files.begin(), files.end());
        for (const std::string& f : files) load(f);
    }
    const std::string flag = "--glass-catalog";
    std::vector<std::string> rest;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == flag) {
            if (i + 1 >= args.size()) throw UsageError(flag + " needs a file (a Zemax .agf glass catalog)");
            load(args[++i]);
        } else if (args[i].rfind(flag + "=", 0) == 0) {
            load(args[i].substr(flag.size() + 1));
        } else {
            rest.push_back(args[i]);
        }
    }
    return rest;
}

}  // namespace lenslab
