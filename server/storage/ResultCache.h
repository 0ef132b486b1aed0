#pragma once
// Encoded diagrams by request key, least recently used first out, within a byte budget. Requests
// for a key being drawn wait for that drawing instead of starting another; a drawing that throws
// is not cached and its error reaches every waiter.
#include <cstdint>
#include <functional>
#include <future>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lenslab {

using Bytes = std::vector<std::uint8_t>;

struct DiagramCacheStats {
    std::uint64_t hits = 0, misses = 0;
    std::size_t entries = 0, bytes = 0;
};

class DiagramCache {
public:
    explicit DiagramCache(std::size_t maxBytes) : maxBytes_(maxBytes) {}

    std::shared_ptr<const Bytes> getOrDraw(const std::string& key, const std::function<Bytes()>& draw);
    // Drops every entry whose key starts with `prefix` (a deleted lens's diagrams).
    void forget(const std::string& prefix);
    DiagramCacheStats stats() const;

private:
    struct Entry {
        std::shared_ptr<const Bytes> bytes;
        std::list<std::string>::iterator age;
    };
    void insert(const std::string& key, std::shared_ptr<const Bytes> bytes);

    std::size_t maxBytes_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> entries_;
    std::list<std::string> ages_;  // most recently used first
    std::map<std::string, std::shared_future<std::shared_ptr<const Bytes>>> drawing_;
    std::size_t bytes_ = 0;
    std::uint64_t hits_ = 0, misses_ = 0;
};

}  // namespace lenslab
