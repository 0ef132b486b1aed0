#pragma once
// The Zemax glass catalogs (.agf) uploaded to the service: stored under DATA/glass-catalogs/<id>.agf,
// listed in the database, and added to the glass lookup after the bundled makers (GlassCatalog.h,
// CatalogPrecedence::AfterBundled: an upload adds glass names, never changes the glass a name finds
// elsewhere), at start before any lens is read and at once on upload, so that lenses read
// afterwards find their glasses. A catalog that stored lenses take glasses from is not deleted:
// those lenses would stop reading at the next start.
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <functional>
#include <string>
#include <vector>

#include "prescription/Medium.h"
#include "storage/Database.h"

namespace lenslab {

struct StoredGlassCatalog {
    std::string id;
    std::string name;      // the catalog's name in the glass lookup: the file name's stem in upper case
    std::string fileName;  // the upload's name, as shown
    double created = 0;    // seconds since the epoch
    std::string path;      // the file on disk
    std::string digest;    // SHA-256 of the file
    std::vector<Medium> glasses;
    std::vector<int> formulaNumbers;  // Zemax's, parallel to glasses
};

class GlassCatalogStore {
public:
    // Reads the catalogs the database records (files without a record are deleted; a catalog that no
    // longer reads is skipped and reported on stderr) and adds them to the glass lookup, oldest first.
    GlassCatalogStore(const std::string& folder, Database& database);
    ~GlassCatalogStore();  // takes its catalogs out of the glass lookup

    std::vector<std::shared_ptr<const StoredGlassCatalog>> list() const;  // oldest first
    std::shared_ptr<const StoredGlassCatalog> find(const std::string& id) const;  // nullptr: unknown

    // Parses the file (LensTableError naming the upload and the line), stores it and adds it to the
    // lookup. HttpError 409 when its name is a bundled maker's or a loaded catalog's, or past the
    // limits on catalogs and glasses held.
    std::shared_ptr<const StoredGlassCatalog> add(const std::string& uploadName, const std::string& bytes);

    // Deletes a catalog unless `usersOf(catalog name)` names lenses (HttpError 409 naming them).
    // No lens is read meanwhile (holdCatalogs waits), so none can take a glass from it. False: unknown.
    bool remove(const std::string& id, const std::function<std::vector<std::string>(const std::string&)>& usersOf);

    // Held while a lens is read and stored (or a preview computed): no catalog is deleted meanwhile,
    // so a lens stored with a glass of a catalog always finds the catalog there.
    std::shared_lock<std::shared_mutex> holdCatalogs() const;

    // SHA-256 of the catalogs held, in lookup order: part of the key of every cached result that
    // reads glasses (a catalog deleted and uploaded again under its name with other glasses
    // changes it).
    std::string digest() const;

    static constexpr int kMaxCatalogs = 64;
    static constexpr std::size_t kMaxGlasses = 50000;  // in all the catalogs (about 300 bytes each)

private:
    void renewDigest();  // under mutex_, whenever catalogs_ changes

    std::string folder_;
    Database& database_;
    mutable std::shared_mutex deleting_;  // shared: lenses being read; exclusive: a deletion
    mutable std::mutex mutex_;            // the list, and the lookup's names against it
    std::vector<std::shared_ptr<const StoredGlassCatalog>> catalogs_;
    std::string digest_;                  // digest(): of catalogs_
};

}  // namespace lenslab
