#pragma once
// Results of heavy work (diagrams as PNG, analyses and previews as JSON text) by request key, least
// recently used first out, within a byte budget. Requests for a key being computed wait for that
// computation instead of starting another; a computation that throws is not cached and its error
// reaches every waiter.
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

struct ResultCacheStats {
    std::uint64_t hits = 0, misses = 0;
    std::size_t entries = 0, bytes = 0;
};

class ResultCache {
public:
    explicit ResultCache(std::size_t maxBytes) : maxBytes_(maxBytes) {}

    // The cached result (a hit), or null; never computes.
    std::shared_ptr<const Bytes> cached(const std::string& key);
    std::shared_ptr<const Bytes> getOrCompute(const std::string& key, const std::function<Bytes()>& compute);
    // Drops every entry whose key starts with `prefix` (a deleted lens's diagrams).
    void forget(const std::string& prefix);
    ResultCacheStats stats() const;

private:
    struct Entry {
        std::shared_ptr<const Bytes> bytes;
        std::list<std::string>::iterator age;
    };
    std::shared_ptr<const Bytes> hit(std::map<std::string, Entry>::iterator it);  // under the lock
    void insert(const std::string& key, std::shared_ptr<const Bytes> bytes);

    std::size_t maxBytes_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> entries_;
    std::list<std::string> ages_;  // most recently used first
    std::map<std::string, std::shared_future<std::shared_ptr<const Bytes>>> computing_;
    std::size_t bytes_ = 0;
    std::uint64_t hits_ = 0, misses_ = 0;
};

// A UTF-8 text (a JSON answer) as cached bytes, and back.
inline Bytes textBytes(const std::string& text) { return Bytes(text.begin(), text.end()); }
inline std::string bytesText(const Bytes& bytes) { return std::string(bytes.begin(), bytes.end()); }

}  // namespace lenslab
