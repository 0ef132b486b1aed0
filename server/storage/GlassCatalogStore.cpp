#include "storage/GlassCatalogStore.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "core/ContentDigest.h"
#include "core/HttpError.h"
#include "core/Identifiers.h"
#include "core/WallClock.h"
#include "prescription/GlassCatalog.h"
#include "prescription/GlassCatalogFile.h"
#include "storage/AtomicFile.h"
#include "storage/LensStore.h"
#include "storage/StorageError.h"

namespace lenslab {

namespace fs = std::filesystem;

namespace {

std::shared_ptr<StoredGlassCatalog> readCatalog(const std::string& bytes, const std::string& fileName) {
    GlassCatalogFile file = parseGlassCatalogFile(bytes, fileName);
    auto catalog = std::make_shared<StoredGlassCatalog>();
    catalog->name = file.name;
    catalog->fileName = fileName;
    catalog->digest = contentDigest(bytes);
    catalog->glasses = std::move(file.glasses);
    catalog->formulaNumbers = std::move(file.formulaNumbers);
    return catalog;
}

std::size_t glassesIn(const std::vector<std::shared_ptr<const StoredGlassCatalog>>& catalogs) {
    std::size_t n = 0;
    for (const auto& c : catalogs) n += c->glasses.size();
    return n;
}

}  // namespace

GlassCatalogStore::GlassCatalogStore(const std::string& folder, Database& database)
    : folder_(folder), database_(database) {
    fs::create_directories(folder_);
    database_.run(
        "CREATE TABLE IF NOT EXISTS glass_catalogs (id TEXT PRIMARY KEY, file_name TEXT NOT NULL, created REAL NOT NULL)");
    std::vector<std::string> known, fileless;
    database_.run("SELECT id, file_name, created FROM glass_catalogs ORDER BY created", {}, [&](const SqlRow& row) {
        const std::string id = row.text(0), fileName = row.text(1);
        known.push_back(id + ".agf");
        if (!isSafeIdentifier(id)) return;
        const std::string path = (fs::path(folder_) / (id + ".agf")).string();
        std::error_code missing;
        if (!fs::exists(path, missing) && !missing) {
            fileless.push_back(id);
            return;
        }
        try {
            auto catalog = readCatalog(readWholeFile(path), fileName);
            if (isGlassCatalogName(catalog->name))
                throw std::runtime_error("a catalog named " + catalog->name + " is loaded already");
            catalog->id = id;
            catalog->created = row.real(2);
            catalog->path = path;
            addGlassCatalog(catalog->name, catalog->glasses, CatalogPrecedence::AfterBundled);
            catalogs_.push_back(std::move(catalog));
        } catch (const std::exception& e) {
            std::cerr << "lenslab serve: skipping uploaded glass catalog " << id << ": " << e.what() << "\n";
        }
    });
    // A deletion cut off between its file and its record (kill -9) leaves a record without a file:
    // it is finished here, once, rather than skipped with a message at every start.
    for (const std::string& id : fileless) {
        try {
            database_.run("DELETE FROM glass_catalogs WHERE id = ?", {id});
            std::cerr << "lenslab serve: removed the record of glass catalog " << id
                      << ", whose file is gone (a deletion was cut off)\n";
        } catch (const std::exception& e) {  // a read-only data folder: still served, records as they are
            std::cerr << "lenslab serve: glass catalog " << id << " has no file, and its record stays: " << e.what() << "\n";
        }
    }
    renewDigest();
    std::error_code ec;
    for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec))
        if (std::find(known.begin(), known.end(), it->path().filename().string()) == known.end()) fs::remove(it->path(), ec);
}

GlassCatalogStore::~GlassCatalogStore() {
    for (const auto& catalog : catalogs_) removeGlassCatalog(catalog->name);
}

std::vector<std::shared_ptr<const StoredGlassCatalog>> GlassCatalogStore::list() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return catalogs_;
}

std::shared_ptr<const StoredGlassCatalog> GlassCatalogStore::find(const std::string& id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& catalog : catalogs_)
        if (catalog->id == id) return catalog;
    return nullptr;
}

std::shared_ptr<const StoredGlassCatalog> GlassCatalogStore::add(const std::string& uploadName, const std::string& bytes) {
    const auto catalog = readCatalog(bytes, uploadDisplayName(uploadName, "upload.agf"));
    catalog->id = newRandomIdentifier("catalog-");
    catalog->created = secondsSinceEpoch();
    catalog->path = (fs::path(folder_) / (catalog->id + ".agf")).string();

    std::lock_guard<std::mutex> lock(mutex_);
    // A second catalog of one name would be ambiguous in a GCAT line and in every message.
    if (isGlassCatalogName(catalog->name))
        throw HttpError(409, "a glass catalog named " + catalog->name + " is there already (bundled, given to lenslab serve, "
                             "or uploaded); upload this one under another file name, e.g. ?name=" + catalog->name + "-2.agf");
    if (catalogs_.size() >= static_cast<std::size_t>(kMaxCatalogs))
        throw HttpError(409, "the service holds " + std::to_string(catalogs_.size()) +
                                 " uploaded glass catalogs, its limit; delete some first");
    if (const std::size_t held = glassesIn(catalogs_); held + catalog->glasses.size() > kMaxGlasses)
        throw HttpError(409, "the uploaded glass catalogs hold " + std::to_string(held) + " glasses; with this one's " +
                                 std::to_string(catalog->glasses.size()) + " they would pass the limit of " +
                                 std::to_string(kMaxGlasses) + "; delete some first");
    writeFileAtomically(catalog->path, bytes);
    database_.run("INSERT INTO glass_catalogs (id, file_name, created) VALUES (?, ?, ?)",
                  {catalog->id, catalog->fileName, catalog->created});
    addGlassCatalog(catalog->name, catalog->glasses, CatalogPrecedence::AfterBundled);
    catalogs_.push_back(catalog);
    renewDigest();
    return catalog;
}

bool GlassCatalogStore::remove(const std::string& id,
                               const std::function<std::vector<std::string>(const std::string&)>& usersOf) {
    std::unique_lock<std::shared_mutex> noLensRead(deleting_);
    const auto catalog = find(id);
    if (!catalog) return false;
    if (const auto lenses = usersOf(catalog->name); !lenses.empty()) {
        std::string names;
        for (std::size_t i = 0; i < lenses.size() && i < 5; ++i) names += (i ? ", " : "") + lenses[i];
        throw HttpError(409, "glass catalog " + catalog->name + " is used by " + std::to_string(lenses.size()) +
                                 (lenses.size() == 1 ? " stored lens (" : " stored lenses (") + names +
                                 (lenses.size() > 5 ? ", ..." : "") + "); delete " +
                                 (lenses.size() == 1 ? "it" : "them") + " first (DELETE /api/lenses/{id})");
    }
    std::lock_guard<std::mutex> lock(mutex_);
    std::error_code error;
    fs::remove(catalog->path, error);
    if (error && error != std::errc::no_such_file_or_directory)
        throw StorageError(storageErrorKind(error.value()), "cannot remove " + catalog->path + ": " + error.message());
    database_.run("DELETE FROM glass_catalogs WHERE id = ?", {id});
    removeGlassCatalog(catalog->name);
    catalogs_.erase(std::find(catalogs_.begin(), catalogs_.end(), catalog));
    renewDigest();
    return true;
}

std::string GlassCatalogStore::digest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return digest_;
}

void GlassCatalogStore::renewDigest() {
    std::string all;
    for (const auto& catalog : catalogs_) all += catalog->name + "\n" + catalog->digest + "\n";
    digest_ = contentDigest(all);
}

std::shared_lock<std::shared_mutex> GlassCatalogStore::holdCatalogs() const {
    return std::shared_lock<std::shared_mutex>(deleting_);
}

}  // namespace lenslab
