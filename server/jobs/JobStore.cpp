#include "jobs/JobStore.h"

namespace lenslab {

namespace {

const char* kColumns = "id, request, state, created, started, finished, error, interrupted, tiles_done, tiles_total, stats";

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
    return j;
}

SqlValue optionalValue(const std::optional<double>& v) { return v ? SqlValue(*v) : SqlValue(nullptr); }

}  // namespace

JobStore::JobStore(Database& database) : database_(database) {
    database_.run(
        "CREATE TABLE IF NOT EXISTS jobs (id TEXT PRIMARY KEY, request TEXT NOT NULL, state TEXT NOT NULL, "
        "created REAL NOT NULL, started REAL, finished REAL, error TEXT NOT NULL DEFAULT '', "
        "interrupted INTEGER NOT NULL DEFAULT 0, tiles_done INTEGER NOT NULL DEFAULT 0, "
        "tiles_total INTEGER NOT NULL DEFAULT 0, stats TEXT NOT NULL DEFAULT '{}')");
}

void JobStore::insert(const JobRecord& j) {
    database_.run(std::string("INSERT INTO jobs (") + kColumns + ") VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                  {j.id, j.request.dump(), std::string(jobStateName(j.state)), j.created, optionalValue(j.started),
                   optionalValue(j.finished), j.error, std::int64_t(j.interrupted), std::int64_t(j.tilesDone),
                   std::int64_t(j.tilesTotal), j.stats.dump()});
}

void JobStore::save(const JobRecord& j) {
    database_.run(
        "UPDATE jobs SET state = ?, started = ?, finished = ?, error = ?, interrupted = ?, tiles_done = ?, "
        "tiles_total = ?, stats = ? WHERE id = ?",
        {std::string(jobStateName(j.state)), optionalValue(j.started), optionalValue(j.finished), j.error,
         std::int64_t(j.interrupted), std::int64_t(j.tilesDone), std::int64_t(j.tilesTotal), j.stats.dump(), j.id});
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

std::vector<JobRecord> JobStore::finished() const {
    std::vector<JobRecord> jobs;
    database_.run(std::string("SELECT ") + kColumns +
                      " FROM jobs WHERE state IN ('done', 'failed', 'cancelled') ORDER BY finished, created",
                  {}, [&](const SqlRow& row) { jobs.push_back(readJob(row)); });
    return jobs;
}

bool JobStore::remove(const std::string& id) { return database_.run("DELETE FROM jobs WHERE id = ?", {id}) > 0; }

int JobStore::markInterrupted() {
    return database_.run(
        "UPDATE jobs SET state = 'failed', interrupted = 1, "
        "error = 'interrupted: the service stopped while this job was rendering; resubmit it' "
        "WHERE state = 'running'");
}

}  // namespace lenslab
