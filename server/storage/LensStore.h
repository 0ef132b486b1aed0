#pragma once
// The lenses the service knows: the bundled tables (read-only, id = file name without .dat) and
// uploaded ones (stored under DATA/lenses/<id>.dat, listed in the database, id chosen by the
// service; the upload's own name is only shown, never used as a path).
#include <memory>
#include <optional>
#include <shared_mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "storage/Database.h"
#include "settings/LensAnalysis.h"
#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"

namespace lenslab {

struct StoredLens {
    std::string id;
    std::string name;         // shown to people: the bundled file name or the upload's name
    std::string description;  // first comment line of the table
    bool bundled = false;
    double created = 0;       // seconds since the epoch (uploads)
    std::string path;         // the table on disk, inside the lens folders
    LensSystem system;
    double efl = 0, fstopMin = 0, fstopMax = 0;
};

class LensStoreFull : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class LensStore {
public:
    // Loads the bundled tables and the uploads recorded in the database; tables that no longer
    // parse and upload files without a record are skipped (and reported on stderr).
    LensStore(const std::string& bundledDir, const std::string& uploadDir, Database& database, int maxUploads);

    std::vector<std::shared_ptr<const StoredLens>> list() const;
    std::shared_ptr<const StoredLens> find(const std::string& id) const;  // nullptr when unknown

    // Parses and checks the table (LensTableError with the upload name and line, OpticsError when
    // it has no first-order data), stores it, and returns it. LensStoreFull at the upload limit.
    std::shared_ptr<const StoredLens> add(const std::string& uploadName, const std::string& text,
                                          std::optional<TableLayout> layout);

    enum class Removal { Removed, NotFound, ReadOnly };
    Removal remove(const std::string& id);

private:
    void loadBundled(const std::string& folder);
    void loadUploads();

    std::string uploadDir_;
    Database& database_;
    int maxUploads_;
    mutable std::shared_mutex mutex_;
    std::vector<std::shared_ptr<const StoredLens>> lenses_;  // bundled first, then uploads by age
};

// The name shown for an upload: its last path component, limited to a safe alphabet and length.
std::string uploadDisplayName(const std::string& clientName);

}  // namespace lenslab
