#include "jobs/JobStore.h"

namespace lenslab {

namespace {

const char* kColumns =
    "id, request, state, created, started, finished, error, interrupted, tiles_done, tiles_total, stats, image_bytes, "
    "warnings";
const char* kFinished = "state IN ('done', 'failed', 'cancelled')";
// Oldest finish first; a job marked interrupted has no finish time and goes first.
const char* kByFinish = " ORDER BY finished, created";

JobRecord readJob(const SqlRow& row) {
    JobRecord j;
    j.id = row.text(0);
    j.request = nlohmann::json::parse(row.text(1), nullptr, false);
    j.state = parseJobState(row.text(2));
    j.created = row.real(3);
    j.started = row.optionalReal(4);
    j.finished = row.optionalReal(5);
    j.error = row.text(6);
    j.interrupted = row.integer(7) != 0;
    j.tilesDone = static_cast<int>(row.integer(8));
    j.tilesTotal = static_cast<int>(row.integer(9));
    j.stats = nlohmann::json::parse(row.text(10), nullptr, false);
    j.imageBytes = row.integer(11);
    const nlohmann::json warnings = nlohmann::json::parse(row.text(12), nullptr, false);
    if (warnings.is_array()) j.warnings = warnings.get<std::vector<std::string>>();
    return j;
}

std::vector<std::string> ids(Database& database, const std::string& sql, const std::vector<SqlValue>& parameters) {
    std::vector<std::string> found;
    database.run(sql, parameters, [&](const SqlRow& row) { found.push_back(row.text(0)); });
    return found;
}

SqlValue optionalValue(const std::optional<double>& v) { return v ? SqlValue(*v) : SqlValue(nullptr); }

// A column later versions added, to a database an earlier one created.
void addJobColumnIfMissing(Database& database, const std::string& name, const std::string& declaration) {
    bool present = false;
    database.run("SELECT name FROM pragma_table_info('jobs') WHERE name = ?", {name},
                 [&](const SqlRow&) { present = true; });
    if (!present) database.run("ALTER TABLE jobs ADD COLUMN " + name + " " + declaration);
}

}  // namespace

JobStore::JobStore(Database& database) : database_(database) {
    database_.run(
        "CREATE TABLE IF NOT EXISTS jobs (id TEXT PRIMARY KEY, request TEXT NOT NULL, state TEXT NOT NULL, "
        "created REAL NOT NULL, started REAL, finished REAL, error TEXT NOT NULL DEFAULT '', "
        "interrupted INTEGER NOT NULL DEFAULT 0, tiles_done INTEGER NOT NULL DEFAULT 0, "
        "tiles_total INTEGER NOT NULL DEFAULT 0, stats TEXT NOT NULL DEFAULT '{}', image_bytes INTEGER, "
        "warnings TEXT NOT NULL DEFAULT '[]')");
    addJobColumnIfMissing(database_, "image_bytes", "INTEGER");  // NULL: not measured yet
    addJobColumnIfMissing(database_, "warnings", "TEXT NOT NULL DEFAULT '[]'");
    database_.run("CREATE INDEX IF NOT EXISTS jobs_by_finish ON jobs (finished, created)");
}

void JobStore::insert(const JobRecord& j) {
    database_.run(std::string("INSERT INTO jobs (") + kColumns + ") VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                  {j.id, j.request.dump(), std::string(jobStateName(j.state)), j.created, optionalValue(j.started),
                   optionalValue(j.finished), j.error, std::int64_t(j.interrupted), std::int64_t(j.tilesDone),
                   std::int64_t(j.tilesTotal), j.stats.dump(), j.imageBytes, nlohmann::json(j.warnings).dump()});
}

void JobStore::save(const JobRecord& j) {
    database_.run(
        "UPDATE jobs SET state = ?, started = ?, finished = ?, error = ?, interrupted = ?, tiles_done = ?, "
        "tiles_total = ?, stats = ?, image_bytes = ?, warnings = ? WHERE id = ?",
        {std::string(jobStateName(j.state)), optionalValue(j.started), optionalValue(j.finished), j.error,
         std::int64_t(j.interrupted), std::int64_t(j.tilesDone), std::int64_t(j.tilesTotal), j.stats.dump(),
         j.imageBytes, nlohmann::json(j.warnings).dump(), j.id});
}

std::optional<JobRecord> JobStore::find(const std::string& id) const {
    std::optional<JobRecord> found;
    database_.run(std::string("SELECT ") + kColumns + " FROM jobs WHERE id = ?", {id},
                  [&](const SqlRow& row) { found = readJob(row); });
    return found;
}

std::vector<JobRecord> JobStore::recent(int limit) const {
    std::vector<JobRecord> jobs;
    database_.run(std::string("SELECT ") + kColumns + " FROM jobs ORDER BY created DESC LIMIT ?", {std::int64_t(limit)},
                  [&](const SqlRow& row) { jobs.push_back(readJob(row)); });
    return jobs;
}

std::vector<JobRecord> JobStore::queued() const {
    std::vector<JobRecord> jobs;
    database_.run(std::string("SELECT ") + kColumns + " FROM jobs WHERE state = 'queued' ORDER BY created", {},
                  [&](const SqlRow& row) { jobs.push_back(readJob(row)); });
    return jobs;
}

std::vector<std::string> JobStore::finishedBefore(double time) const {
    return ids(database_, std::string("SELECT id FROM jobs WHERE ") + kFinished + " AND COALESCE(finished, created) < ?" +
                              kByFinish, {time});
}

std::vector<std::string> JobStore::oldestFinished(int count) const {
    return ids(database_, std::string("SELECT id FROM jobs WHERE ") + kFinished + kByFinish + " LIMIT ?",
               {std::int64_t(count)});
}

std::vector<std::string> JobStore::finishedBeyondBytes(std::int64_t keptBytes) const {
    // Each job's bytes added up from the newest: those whose sum passes the limit go.
    return ids(database_,
               std::string("SELECT id FROM (SELECT id, finished, created, SUM(COALESCE(image_bytes, 0)) OVER "
                           "(ORDER BY finished DESC, created DESC ROWS UNBOUNDED PRECEDING) AS newer FROM jobs WHERE ") +
                   kFinished + ") WHERE newer > ?" + kByFinish,
               {keptBytes});
}

int JobStore::finishedCount() const {
    int count = 0;
    database_.run(std::string("SELECT COUNT(*) FROM jobs WHERE ") + kFinished, {},
                  [&](const SqlRow& row) { count = static_cast<int>(row.integer(0)); });
    return count;
}

std::vector<std::string> JobStore::withoutImageBytes() const {
    return ids(database_, "SELECT id FROM jobs WHERE image_bytes IS NULL", {});
}

void JobStore::setImageBytes(const std::string& id, std::int64_t bytes) {
    database_.run("UPDATE jobs SET image_bytes = ? WHERE id = ?", {bytes, id});
}

bool JobStore::remove(const std::string& id) { return database_.run("DELETE FROM jobs WHERE id = ?", {id}) > 0; }

int JobStore::markInterrupted() {
    return database_.run(
        "UPDATE jobs SET state = 'failed', interrupted = 1, "
        "error = 'interrupted: the service stopped while this job was rendering; resubmit it' "
        "WHERE state = 'running'");
}

}  // namespace lenslab
