#include "storage/Database.h"

#include <memory>

#include "storage/StorageError.h"

namespace lenslab {

namespace {

struct StatementDeleter {
    void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
};

void bind(sqlite3_stmt* statement, int index, const SqlValue& value) {
    if (std::holds_alternative<std::nullptr_t>(value)) sqlite3_bind_null(statement, index);
    else if (auto i = std::get_if<std::int64_t>(&value)) sqlite3_bind_int64(statement, index, *i);
    else if (auto d = std::get_if<double>(&value)) sqlite3_bind_double(statement, index, *d);
    else {
        const std::string& s = std::get<std::string>(value);
        sqlite3_bind_text(statement, index, s.data(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
    }
}

// A step that failed because of the disk is the operator's to fix (StorageError: 507/503 with a
// message for the user); anything else is a DatabaseError.
[[noreturn]] void throwStepError(sqlite3* connection) {
    const std::string detail = "database: " + std::string(sqlite3_errmsg(connection));
    switch (sqlite3_errcode(connection) & 0xff) {
        case SQLITE_FULL: throw StorageError(StorageError::Kind::Full, detail);
        case SQLITE_READONLY:
        case SQLITE_PERM:
        case SQLITE_CANTOPEN: throw StorageError(StorageError::Kind::ReadOnly, detail);
        case SQLITE_IOERR: throw StorageError(StorageError::Kind::Failed, detail);
        default: throw DatabaseError(detail);
    }
}

}  // namespace

std::string SqlRow::text(int column) const { return optionalText(column).value_or(""); }

std::optional<std::string> SqlRow::optionalText(int column) const {
    if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
    const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(statement_, column));
    return std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(statement_, column)));
}

std::int64_t SqlRow::integer(int column) const { return sqlite3_column_int64(statement_, column); }

double SqlRow::real(int column) const { return sqlite3_column_double(statement_, column); }

std::optional<double> SqlRow::optionalReal(int column) const {
    if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
    return real(column);
}

Database::Database(const std::string& path) {
    if (sqlite3_open_v2(path.c_str(), &connection_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        const std::string message = connection_ ? sqlite3_errmsg(connection_) : "out of memory";
        sqlite3_close(connection_);
        throw DatabaseError("cannot open database " + path + ": " + message);
    }
    sqlite3_busy_timeout(connection_, 5000);
    run("PRAGMA journal_mode=WAL", {}, [](const SqlRow&) {});
    run("PRAGMA synchronous=FULL");
    // Without a limit the write-ahead log keeps its largest size after each checkpoint (4 MB after
    // a few hundred renders); with one it is truncated back.
    run("PRAGMA journal_size_limit=1048576", {}, [](const SqlRow&) {});
}

Database::~Database() { sqlite3_close(connection_); }

int Database::run(const std::string& sql, const std::vector<SqlValue>& parameters,
                  const std::function<void(const SqlRow&)>& onRow) {
    std::lock_guard<std::mutex> lock(mutex_);
    sqlite3_stmt* raw = nullptr;
    if (sqlite3_prepare_v2(connection_, sql.c_str(), -1, &raw, nullptr) != SQLITE_OK)
        throw DatabaseError("database: " + std::string(sqlite3_errmsg(connection_)) + " in: " + sql);
    std::unique_ptr<sqlite3_stmt, StatementDeleter> statement(raw);
    for (std::size_t i = 0; i < parameters.size(); ++i) bind(raw, static_cast<int>(i + 1), parameters[i]);
    for (;;) {
        const int step = sqlite3_step(raw);
        if (step == SQLITE_DONE) break;
        if (step != SQLITE_ROW) throwStepError(connection_);
        if (onRow) onRow(SqlRow(raw));
    }
    return sqlite3_changes(connection_);
}

}  // namespace lenslab
