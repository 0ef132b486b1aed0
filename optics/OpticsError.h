#pragma once
// A request the lens cannot satisfy (an f-number outside its range, a focus distance it cannot
// reach, an afocal system): the message names the request and the valid range.
#include <stdexcept>

namespace lenslab {

class OpticsError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace lenslab
