#pragma once
// Wall-clock time as the service records it: seconds since the Unix epoch.
#include <chrono>

namespace lenslab {

inline double secondsSinceEpoch() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace lenslab
