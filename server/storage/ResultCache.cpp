#include "storage/ResultCache.h"

namespace lenslab {

std::shared_ptr<const Bytes> ResultCache::hit(std::map<std::string, Entry>::iterator it) {
    ++hits_;
    ages_.splice(ages_.begin(), ages_, it->second.age);
    return it->second.bytes;
}

std::shared_ptr<const Bytes> ResultCache::cached(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : hit(it);
}

std::shared_ptr<const Bytes> ResultCache::getOrCompute(const std::string& key, const std::function<Bytes()>& compute) {
    std::promise<std::shared_ptr<const Bytes>> promise;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (auto it = entries_.find(key); it != entries_.end()) return hit(it);
        if (auto it = computing_.find(key); it != computing_.end()) {
            ++hits_;
            auto pending = it->second;
            lock.unlock();
            return pending.get();
        }
        ++misses_;
        computing_.emplace(key, promise.get_future().share());
    }
    try {
        auto bytes = std::make_shared<const Bytes>(compute());
        std::lock_guard<std::mutex> lock(mutex_);
        insert(key, bytes);
        computing_.erase(key);
        promise.set_value(bytes);
        return bytes;
    } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        computing_.erase(key);
        promise.set_exception(std::current_exception());
        throw;
    }
}

void ResultCache::insert(const std::string& key, std::shared_ptr<const Bytes> bytes) {
    if (bytes->size() > maxBytes_) return;
    ages_.push_front(key);
    bytes_ += bytes->size();
    entries_[key] = Entry{std::move(bytes), ages_.begin()};
    while (bytes_ > maxBytes_) {
        auto oldest = entries_.find(ages_.back());
        bytes_ -= oldest->second.bytes->size();
        entries_.erase(oldest);
        ages_.pop_back();
    }
}

void ResultCache::forget(const std::string& prefix) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = entries_.lower_bound(prefix); it != entries_.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
        bytes_ -= it->second.bytes->size();
        ages_.erase(it->second.age);
        it = entries_.erase(it);
    }
}

ResultCacheStats ResultCache::stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return {hits_, misses_, entries_.size(), bytes_};
}

}  // namespace lenslab
