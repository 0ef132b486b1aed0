#pragma once
// Tolerance analysis (docs/design.md): what the tolerances do to a merit's operands once the
// compensators (the back focus, or any variable named) have been set again, as the assembler sets
// them. Sensitivity: each tolerance alone at its + and - limit. Monte Carlo: every tolerance at once,
// drawn at random per trial (seeded: trial k of seed s is the same lens on any machine and thread
// count), with each operand's distribution and the yield against a specification. Trials and
// sensitivities run side by side on every thread.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/DampedLeastSquares.h"
#include "design/Tolerance.h"

namespace lenslab {

// How the compensators are set in each perturbed lens: a short damped least-squares descent from
// their nominal values.
inline OptimiserOptions compensatorSearch() {
    OptimiserOptions o;
    o.maxIterations = 20;
    o.relativeTolerance = 1e-6;
    return o;
}

struct ToleranceProblem {
    LensTable nominal;
    MeritFunction merit;                      // its operands are what each trial measures
    std::vector<Tolerance> tolerances;
    std::vector<DesignVariable> compensators; // re-optimised on the merit in every perturbed lens
};

enum class ToleranceDraw {
    Uniform,  // uniform between -limit and +limit
    Normal,   // normal with sigma = limit / 2, truncated at the limit (a limit is two standard deviations)
};

// What a lens must meet to pass: an operand (its index in the merit) at most or at least a value.
struct OperandLimit {
    int operand = 0;
    OperandBound bound = OperandBound::AtMost;
    double value = 0;
};

struct ToleranceTrial {
    std::vector<double> departures;   // per tolerance
    MeritEvaluation evaluation;       // after compensation (invalid: the lens could not be built or traced)
    std::vector<double> compensators; // their values after compensation
};

// The departures of trial `trial` drawn from `seed` alone.
std::vector<double> drawDepartures(const ToleranceProblem& problem, ToleranceDraw draw, std::uint64_t seed, int trial);

// The as-built lens of a set of departures: perturbed, then its compensators set (damped least
// squares on the merit, from their nominal values). `trial` receives the measurement.
LensTable asBuiltLens(const ToleranceProblem& problem, const std::vector<double>& departures, ToleranceTrial* trial = nullptr);

struct Distribution {
    int count = 0;  // valid trials
    double mean = 0, p50 = 0, p90 = 0, p98 = 0, min = 0, max = 0;
    std::vector<int> histogram;  // `bins` equal bins from min to max
};

// Percentiles by linear interpolation between order statistics (the 0.9 percentile of n values lies
// at rank 0.9 (n - 1)).
Distribution distributionOf(std::vector<double> values, int bins = 20);

struct MonteCarloOptions {
    int trials = 100;
    std::uint64_t seed = 1;
    ToleranceDraw draw = ToleranceDraw::Normal;
    std::vector<OperandLimit> specification;  // empty: yield is the share of valid trials
    std::optional<double> meritLimit;         // the merit must be at most this too
    OptimiserOptions compensation = compensatorSearch();
    std::function<void(int done)> progress;   // after each trial (from any thread)
    std::function<bool()> cancelled;
};

struct MonteCarloResult {
    MeritEvaluation nominal;                  // the nominal lens, compensated the same way
    std::vector<ToleranceTrial> trials;       // in trial order
    std::vector<Distribution> operands;       // per merit operand
    Distribution merit;
    int invalid = 0;                          // trials whose lens could not be built or traced
    double yield = 0;                         // share of all trials that are valid and meet the specification
    bool cancelled = false;
};

MonteCarloResult runMonteCarlo(const ToleranceProblem& problem, const MonteCarloOptions& options);

// The trial ranked at `percentile` (0 to 100) by merit among the valid trials: 50 the median, 90
// the 90th percentile, 100 the worst. nullopt when no trial is valid.
std::optional<int> trialAtPercentile(const MonteCarloResult& result, double percentile);

struct SensitivityRow {
    Tolerance tolerance;
    MeritEvaluation plus, minus;   // the lens at +limit and -limit, compensated
    double meritChange = 0;        // the larger |merit - nominal merit| of the two (infinity: one is invalid)
};

// Every tolerance alone at both limits, ranked by meritChange, largest first. Once
// compensation.cancelled() answers true the rows not yet measured are left unmeasured.
std::vector<SensitivityRow> toleranceSensitivity(const ToleranceProblem& problem, const OptimiserOptions& compensation = compensatorSearch());

}  // namespace lenslab
