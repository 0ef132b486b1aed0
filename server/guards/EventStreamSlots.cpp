#include "guards/EventStreamSlots.h"

namespace lenslab {

std::shared_ptr<void> EventStreamSlots::take(const std::string& client) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        std::size_t& mine = openByClient_[client];
        if (open_ >= total_ || mine >= perClient_) {
            if (mine == 0) openByClient_.erase(client);
            return nullptr;
        }
        ++open_;
        ++mine;
    }
    return std::shared_ptr<void>(this, [self = shared_from_this(), client](void*) { self->giveBack(client); });
}

void EventStreamSlots::giveBack(const std::string& client) {
    std::lock_guard<std::mutex> lock(mutex_);
    --open_;
    if (--openByClient_[client] == 0) openByClient_.erase(client);
}

}  // namespace lenslab
