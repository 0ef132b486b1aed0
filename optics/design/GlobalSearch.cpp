#include "design/GlobalSearch.h"

#include <cmath>
#include <random>

namespace lenslab {

GlobalSearchResult searchGlobally(const DesignProblem& problem, const GlobalSearchOptions& options) {
    GlobalSearchResult out;
    out.best = optimiseDampedLeastSquares(problem, options.local);
    out.evaluations = out.best.evaluations;
    const MeritEvaluation firstStart = out.best.start;
    std::mt19937_64 random(options.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int hop = 0; hop < options.hops; ++hop) {
        if (out.best.stop == StopReason::Cancelled || out.best.end.merit == 0) break;
        DesignProblem from = problem;
        std::vector<double> x = out.best.values;
        for (double& v : x) v += options.spread * unit(random) * (std::fabs(v) > 1e-12 ? std::fabs(v) : 1e-3);
        for (std::size_t j = 0; j < x.size(); ++j) setVariableValue(from.start, problem.variables[j], x[j]);
        if (!evaluateDesign(problem, x).valid) continue;
        OptimiserResult descent = optimiseDampedLeastSquares(from, options.local);
        out.evaluations += descent.evaluations;
        if (descent.end.merit < out.best.end.merit) {
            out.best = std::move(descent);
            ++out.hopsImproved;
        }
    }
    out.best.start = firstStart;
    out.best.evaluations = out.evaluations;
    return out;
}

}  // namespace lenslab
