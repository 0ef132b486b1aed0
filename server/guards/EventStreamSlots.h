#pragma once
// Slots for server-sent event streams. cpp-httplib writes an answer on the thread that answers the
// request, so a stream holds one of the --http-threads workers for its job's life; 32 open streams
// stopped every other request (issue 23). A stream takes a slot first: at most a quarter of the
// workers in all and a few per client address; past either the client is answered 503 and polls.
// Render images being sent take slots of their own likewise (ServiceParts::downloads).
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace lenslab {

class EventStreamSlots : public std::enable_shared_from_this<EventStreamSlots> {
public:
    EventStreamSlots(std::size_t total, std::size_t perClient) : total_(total), perClient_(perClient) {}

    // A slot for `client`, given back when the last copy is destroyed; null when none is free.
    std::shared_ptr<void> take(const std::string& client);

    std::size_t total() const { return total_; }
    std::size_t perClient() const { return perClient_; }

private:
    void giveBack(const std::string& client);

    const std::size_t total_, perClient_;
    std::mutex mutex_;
    std::size_t open_ = 0;
    std::map<std::string, std::size_t> openByClient_;
};

}  // namespace lenslab
