#pragma once
// A small wrapper over one SQLite connection: statements with bound parameters, rows as strings
// and numbers, one writer at a time (the connection is guarded by a mutex).
#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace lenslab {

class DatabaseError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using SqlValue = std::variant<std::nullptr_t, std::int64_t, double, std::string>;

class SqlRow {
public:
    explicit SqlRow(sqlite3_stmt* statement) : statement_(statement) {}
    std::string text(int column) const;
    std::optional<std::string> optionalText(int column) const;
    std::int64_t integer(int column) const;
    double real(int column) const;
    std::optional<double> optionalReal(int column) const;

private:
    sqlite3_stmt* statement_;
};

class Database {
public:
    // Opens (creating) the file, in WAL mode with full synchronisation.
    explicit Database(const std::string& path);
    ~Database();
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;

    // Runs one statement; onRow is called for each result row. Returns the number of changed rows.
    int run(const std::string& sql, const std::vector<SqlValue>& parameters = {},
            const std::function<void(const SqlRow&)>& onRow = {});

private:
    sqlite3* connection_ = nullptr;
    std::mutex mutex_;
};

}  // namespace lenslab
