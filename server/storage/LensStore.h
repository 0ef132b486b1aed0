#pragma once
// The lenses the service knows: the bundled tables (read-only, id = file name without .dat) and
// uploaded ones (stored under DATA/lenses/<id>.dat, listed in the database, id chosen by the
// service; the upload's own name is only shown, never used as a path).
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <stdexcept>
#include <string>
#include <thread>
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
    std::string digest;       // SHA-256 of the table's text and layout: the key of its cached analyses
    LensSystem system;
    double efl = 0, fstopMin = 0, fstopMax = 0;
};

class LensStoreFull : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Uploads are described (parsed, checked, their first-order data computed) after the service
// listens, not before: 500 stored uploads of 1 MiB took 132 s to describe, and the port stayed closed
// meanwhile (issue 32). Until a background thread has described an upload it is not listed; asked
// for by id, it is described on the spot.
class LensStore {
public:
    // Describes the bundled tables and registers the uploads recorded in the database (upload files
    // without a record are deleted). Tables that no longer parse are skipped and reported on stderr.
    LensStore(const std::string& bundledDir, const std::string& uploadDir, Database& database, int maxUploads);
    ~LensStore();  // stops the background description

    // Starts describing the registered uploads on a thread of its own, oldest first.
    void describeInBackground();

    // The described lenses: bundled first, then uploads by age.
    std::vector<std::shared_ptr<const StoredLens>> list() const;
    struct Counts {
        int lenses = 0;   // known, described or not
        int waiting = 0;  // uploads not described yet
    };
    Counts counts() const;
    // The lens with that id, described now if it was not yet; nullptr when unknown (or no longer
    // parsing).
    std::shared_ptr<const StoredLens> find(const std::string& id) const;

    // Parses and checks the table (LensTableError with the upload name and line, OpticsError when
    // it has no first-order data), stores it, and returns it. LensStoreFull at the upload limit.
    std::shared_ptr<const StoredLens> add(const std::string& uploadName, const std::string& text,
                                          std::optional<TableLayout> layout);

    // The ids of the lenses for which `test` is true, every upload described first if it was not yet.
    std::vector<std::string> lensesWhere(const std::function<bool(const StoredLens&)>& test) const;

    // Deletes an upload. `checkUnused` runs first, with submissions held off (holdLenses waits), and
    // throws to keep the lens: nothing can start using it between that check and the deletion.
    enum class Removal { Removed, NotFound, ReadOnly };
    Removal remove(const std::string& id, const std::function<void()>& checkUnused);

    // Held from a lens's lookup until what uses it is recorded (a render queued): the lens is not
    // deleted meanwhile.
    std::shared_lock<std::shared_mutex> holdLenses() const;

private:
    struct Entry;
    void registerBundled(const std::string& folder);
    void registerUploads();
    // The entry's lens, described once (by whichever thread comes first); nullptr when it fails.
    std::shared_ptr<const StoredLens> described(Entry& entry) const;
    std::shared_ptr<Entry> entryOf(const std::string& id) const;

    std::string uploadDir_;
    Database& database_;
    int maxUploads_;
    mutable std::shared_mutex deleting_;  // shared: lenses being taken into use; exclusive: a deletion
    mutable std::shared_mutex mutex_;
    std::vector<std::shared_ptr<Entry>> entries_;  // bundled first, then uploads by age
    std::atomic<bool> stopping_{false};
    std::thread describer_;
};

// The name shown for an upload: its last path component, limited to a safe alphabet and length;
// `fallback` when nothing is left.
std::string uploadDisplayName(const std::string& clientName, const std::string& fallback = "upload.dat");

}  // namespace lenslab
