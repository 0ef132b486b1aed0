#pragma once
// An invariant of a fuzz target: when it breaks, say which and abort so libFuzzer keeps the input.
#include <cstdio>
#include <cstdlib>

namespace lenslab::fuzz {

inline void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
}

}  // namespace lenslab::fuzz
