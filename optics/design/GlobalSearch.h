#pragma once
// A global search over a design problem: basin hopping around damped least squares. From the best
// design so far, each hop moves every variable by a random fraction of its size (seeded: the same
// seed gives the same hops), descends with damped least squares, and keeps the result if its merit is
// lower. Damped least squares alone finds the nearest minimum; the hops let it leave one.
#include <cstdint>

#include "design/DampedLeastSquares.h"

namespace lenslab {

struct GlobalSearchOptions {
    int hops = 8;
    double spread = 0.1;      // each variable moves by up to this fraction of its value (uniform), or of its scale near 0
    std::uint64_t seed = 1;
    OptimiserOptions local;   // each descent's (progress reports every accepted step of every descent)
};

struct GlobalSearchResult {
    OptimiserResult best;     // its start is the first descent's start
    int hopsImproved = 0;     // hops whose descent beat the best so far
    int evaluations = 0;      // over every descent
};

GlobalSearchResult searchGlobally(const DesignProblem& problem, const GlobalSearchOptions& options = {});

}  // namespace lenslab
