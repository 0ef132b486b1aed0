#include "design/ToleranceAnalysis.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <random>

#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

// SplitMix64's finaliser: a trial's stream from the seed and its number, independent of the order
// the threads take trials in.
std::uint64_t trialKey(std::uint64_t seed, int trial) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (std::uint64_t(trial) + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

bool meets(const MeritEvaluation& e, const MonteCarloOptions& options) {
    if (!e.valid) return false;
    for (const OperandLimit& l : options.specification) {
        const double v = e.values[l.operand];
        if (l.bound == OperandBound::AtMost ? v > l.value : l.bound == OperandBound::AtLeast ? v < l.value : v != l.value) return false;
    }
    return !options.meritLimit || e.merit <= *options.meritLimit;
}

ToleranceTrial measure(const ToleranceProblem& problem, const std::vector<double>& departures, const OptimiserOptions& compensation) {
    ToleranceTrial trial;
    trial.departures = departures;
    DesignProblem compensate;
    compensate.start = perturbedLens(problem.nominal, problem.tolerances, departures);
    compensate.variables = problem.compensators;
    compensate.merit = problem.merit;
    try {
        const OptimiserResult r = optimiseDampedLeastSquares(compensate, compensation);
        trial.evaluation = r.end;
        trial.compensators = r.values;
    } catch (const OpticsError&) {
        trial.evaluation = evaluateMerit(compensate.start, problem.merit);  // invalid, with its reason
    }
    return trial;
}

}  // namespace

std::vector<double> drawDepartures(const ToleranceProblem& problem, ToleranceDraw draw, std::uint64_t seed, int trial) {
    std::mt19937_64 random(trialKey(seed, trial));
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::normal_distribution<double> normal(0.0, 0.5);
    std::vector<double> out;
    for (const Tolerance& t : problem.tolerances) {
        double u = 0;
        if (draw == ToleranceDraw::Uniform) u = uniform(random);
        else
            do u = normal(random);
            while (std::fabs(u) > 1);
        out.push_back(u * t.limit);
    }
    return out;
}

LensTable asBuiltLens(const ToleranceProblem& problem, const std::vector<double>& departures, ToleranceTrial* trial) {
    const ToleranceTrial measured = measure(problem, departures, compensatorSearch());
    LensTable lens = perturbedLens(problem.nominal, problem.tolerances, departures);
    for (std::size_t j = 0; j < measured.compensators.size(); ++j)
        setVariableValue(lens, problem.compensators[j], measured.compensators[j]);
    if (trial) *trial = measured;
    return lens;
}

Distribution distributionOf(std::vector<double> values, int bins) {
    Distribution d;
    d.count = static_cast<int>(values.size());
    if (values.empty()) return d;
    std::sort(values.begin(), values.end());
    const auto at = [&](double p) {
        const double rank = p * (values.size() - 1);
        const std::size_t below = static_cast<std::size_t>(std::floor(rank));
        const std::size_t above = std::min(below + 1, values.size() - 1);
        return values[below] + (rank - below) * (values[above] - values[below]);
    };
    double sum = 0;
    for (double v : values) sum += v;
    d.mean = sum / values.size();
    d.p50 = at(0.5);
    d.p90 = at(0.9);
    d.p98 = at(0.98);
    d.min = values.front();
    d.max = values.back();
    d.histogram.assign(bins, 0);
    const double width = (d.max - d.min) / bins;
    for (double v : values) {
        const int bin = width > 0 ? std::min(bins - 1, static_cast<int>((v - d.min) / width)) : 0;
        ++d.histogram[bin];
    }
    return d;
}

MonteCarloResult runMonteCarlo(const ToleranceProblem& problem, const MonteCarloOptions& options) {
    MonteCarloResult out;
    out.nominal = measure(problem, std::vector<double>(problem.tolerances.size(), 0.0), options.compensation).evaluation;
    out.trials.resize(options.trials);
    std::atomic<int> done{0};
    std::atomic<bool> stopped{false};
    tbb::parallel_for(0, options.trials, [&](int k) {
        if (stopped.load() || (options.cancelled && options.cancelled())) {
            stopped = true;
            return;
        }
        out.trials[k] = measure(problem, drawDepartures(problem, options.draw, options.seed, k), options.compensation);
        const int finished = ++done;
        if (options.progress) options.progress(finished);
    });
    out.cancelled = stopped.load();
    if (out.cancelled) return out;
    std::vector<std::vector<double>> values(problem.merit.operands.size());
    std::vector<double> merits;
    int passing = 0;
    for (const ToleranceTrial& t : out.trials) {
        if (!t.evaluation.valid) {
            ++out.invalid;
            continue;
        }
        for (std::size_t i = 0; i < values.size(); ++i) values[i].push_back(t.evaluation.values[i]);
        merits.push_back(t.evaluation.merit);
        if (meets(t.evaluation, options)) ++passing;
    }
    for (auto& v : values) out.operands.push_back(distributionOf(std::move(v)));
    out.merit = distributionOf(std::move(merits));
    out.yield = options.trials > 0 ? double(passing) / options.trials : 0.0;
    return out;
}

std::optional<int> trialAtPercentile(const MonteCarloResult& result, double percentile) {
    std::vector<int> valid;
    for (int k = 0; k < int(result.trials.size()); ++k)
        if (result.trials[k].evaluation.valid) valid.push_back(k);
    if (valid.empty()) return std::nullopt;
    std::sort(valid.begin(), valid.end(),
              [&](int a, int b) { return result.trials[a].evaluation.merit < result.trials[b].evaluation.merit; });
    const double rank = std::clamp(percentile, 0.0, 100.0) / 100 * (valid.size() - 1);
    return valid[static_cast<std::size_t>(std::lround(rank))];
}

std::vector<SensitivityRow> toleranceSensitivity(const ToleranceProblem& problem, const OptimiserOptions& compensation) {
    const std::size_t n = problem.tolerances.size();
    const MeritEvaluation nominal = measure(problem, std::vector<double>(n, 0.0), compensation).evaluation;
    std::vector<SensitivityRow> rows(n);
    // Cancelled, the compensators stop at once but each measurement still evaluates its lens: the
    // rows left are skipped, or a 100-tolerance lens took 20 s to stop.
    const auto cancelled = [&] { return compensation.cancelled && compensation.cancelled(); };
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
        SensitivityRow& row = rows[k];
        row.tolerance = problem.tolerances[k];
        if (cancelled()) return;
        std::vector<double> departures(n, 0.0);
        departures[k] = row.tolerance.limit;
        row.plus = measure(problem, departures, compensation).evaluation;
        if (cancelled()) return;
        departures[k] = -row.tolerance.limit;
        row.minus = measure(problem, departures, compensation).evaluation;
        const auto change = [&](const MeritEvaluation& e) {
            return e.valid ? std::fabs(e.merit - nominal.merit) : std::numeric_limits<double>::infinity();
        };
        row.meritChange = std::max(change(row.plus), change(row.minus));
    });
    std::stable_sort(rows.begin(), rows.end(), [](const SensitivityRow& a, const SensitivityRow& b) { return a.meritChange > b.meritChange; });
    return rows;
}

}  // namespace lenslab
