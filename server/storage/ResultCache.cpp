#include "storage/DiagramCache.h"

namespace lenslab {

std::shared_ptr<const Bytes> DiagramCache::getOrDraw(const std::string& key, const std::function<Bytes()>& draw) {
    std::promise<std::shared_ptr<const Bytes>> promise;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (auto it = entries_.find(key); it != entries_.end()) {
            ++hits_;
            ages_.splice(ages_.begin(), ages_, it->second.age);
            return it->second.bytes;
        }
        if (auto it = drawing_.find(key); it != drawing_.end()) {
            ++hits_;
            auto pending = it->second;
            lock.unlock();
            return pending.get();
        }
        ++misses_;
        drawing_.emplace(key, promise.get_future().share());
    }
    try {
        auto bytes = std::make_shared<const Bytes>(draw());
        std::lock_guard<std::mutex> lock(mutex_);
        insert(key, bytes);
        drawing_.erase(key);
        promise.set_value(bytes);
        return bytes;
    } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        drawing_.erase(key);
        promise.set_exception(std::current_exception());
        throw;
    }
}

void DiagramCache::insert(const std::string& key, std::shared_ptr<const Bytes> bytes) {
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

void DiagramCache::forget(const std::string& prefix) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = entries_.lower_bound(prefix); it != entries_.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
        bytes_ -= it->second.bytes->size();
        ages_.erase(it->second.age);
        it = entries_.erase(it);
    }
}

DiagramCacheStats DiagramCache::stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return {hits_, misses_, entries_.size(), bytes_};
}

}  // namespace lenslab
