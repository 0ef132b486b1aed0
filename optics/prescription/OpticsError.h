#pragma once
// A request the lens cannot satisfy (an f-number outside its range, a focus distance it cannot
// reach, an afocal system): the message names the request and the valid range.
#include <stdexcept>

namespace lenslab {

class OpticsError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An OpticsError about one lens setting whose message starts with where the setting came from (a
// flag, a JSON field, a scene line): callers pass it on as it is.
class SettingError : public OpticsError {
public:
    using OpticsError::OpticsError;
};

// The lens is afocal (parallel rays leave parallel): it has no focal points, no f-number, no focus.
class AfocalError : public OpticsError {
public:
    using OpticsError::OpticsError;
};

}  // namespace lenslab
