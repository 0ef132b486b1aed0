#include "design/DampedLeastSquares.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "prescription/OpticsError.h"

namespace lenslab {

namespace {

constexpr double kMaxDamping = 1e10;
constexpr double kMinDamping = 1e-15;

// The size of a variable's difference step: a millionth of its value, or of the scale such values
// take where it is near zero (a flat surface's curvature, an unused aspheric term).
double differenceStep(const DesignVariable& v, double value) {
    double scale = 1;
    switch (v.kind) {
        case VariableKind::Curvature: scale = 1e-2; break;
        case VariableKind::Thickness: scale = 1; break;
        case VariableKind::Conic: scale = 0.1; break;
        case VariableKind::Asphere: scale = std::pow(10.0, -3.0 * (v.term + 1)); break;
        case VariableKind::Index: scale = 1; break;
        case VariableKind::Abbe: scale = 10; break;
    }
    return 1e-6 * (std::fabs(value) + scale);
}

std::vector<double> clamped(const DesignProblem& problem, std::vector<double> x) {
    for (std::size_t j = 0; j < x.size(); ++j) {
        const DesignVariable& v = problem.variables[j];
        if (v.lower) x[j] = std::max(x[j], *v.lower);
        if (v.upper) x[j] = std::min(x[j], *v.upper);
    }
    return x;
}

// Solves (A + damping diag(A)) x = b by Cholesky; false when the matrix is not positive definite.
bool solveDamped(std::vector<double> a, const std::vector<double>& b, double damping, std::vector<double>& x) {
    const std::size_t n = b.size();
    double largest = 0;
    for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, a[i * n + i]);
    for (std::size_t i = 0; i < n; ++i) a[i * n + i] += damping * std::max(a[i * n + i], 1e-12 * largest) + 1e-300;
    for (std::size_t j = 0; j < n; ++j) {
        double d = a[j * n + j];
        for (std::size_t k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
        if (!(d > 0)) return false;
        a[j * n + j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < n; ++i) {
            double s = a[i * n + j];
            for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / a[j * n + j];
        }
    }
    x = b;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < i; ++k) x[i] -= a[i * n + k] * x[k];
        x[i] /= a[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;) {
        for (std::size_t k = i + 1; k < n; ++k) x[i] -= a[k * n + i] * x[k];
        x[i] /= a[i * n + i];
    }
    return true;
}

class Search {
public:
    Search(const DesignProblem& problem, const OptimiserOptions& options) : problem_(problem), options_(options) {}

    MeritEvaluation evaluate(const std::vector<double>& x) {
        ++evaluations_;
        return evaluateDesign(problem_, x);
    }

    // x evaluated from a nearby point already evaluated: where the two differ only in the image
    // distance, the base's rays are moved to the new plane instead of traced again.
    MeritEvaluation evaluateNear(const std::vector<double>& x, const std::vector<double>& baseX, const MeritEvaluation& base) {
        int moved = -1;
        for (std::size_t j = 0; j < x.size(); ++j)
            if (x[j] != baseX[j]) {
                if (!movesImageOnly(j) || moved >= 0) return evaluate(x);
                moved = int(j);
            }
        if (moved < 0 || !base.valid) return evaluate(x);
        ++evaluations_;
        return evaluateMeritAtImageDistance(base, x[moved], problem_.merit);
    }

    bool cancelled() const { return options_.cancelled && options_.cancelled(); }

    // Column j of the Jacobian: forward differences, backward where the forward lens is not valid;
    // a variable whose neighbours are both invalid is held for this step (its column zero).
    std::vector<double> jacobian(const std::vector<double>& x, const MeritEvaluation& at) {
        const std::vector<double>& r = at.residuals;
        const std::size_t m = r.size(), n = x.size();
        std::vector<double> jac(m * n, 0.0);
        tbb::parallel_for(std::size_t(0), n, [&](std::size_t j) {
            if (cancelled()) return;
            const double h = differenceStep(problem_.variables[j], x[j]);
            for (double sign : {1.0, -1.0}) {
                std::vector<double> moved = x;
                moved[j] += sign * h;
                moved = clamped(problem_, moved);
                const double step = moved[j] - x[j];
                if (step == 0) continue;
                const MeritEvaluation e = evaluateNear(moved, x, at);
                if (!e.valid) continue;
                for (std::size_t i = 0; i < m; ++i) jac[i * n + j] = (e.residuals[i] - r[i]) / step;
                return;
            }
        });
        return jac;
    }

    int evaluations() const { return evaluations_.load(); }

private:
    // Variable j is the image distance measured on the table's own image plane, and nothing else
    // follows from the variables (no pick-ups, no solve).
    bool movesImageOnly(std::size_t j) const {
        const DesignVariable& v = problem_.variables[j];
        return v.kind == VariableKind::Thickness && v.row + 1 == int(problem_.start.rows.size()) &&
               problem_.start.layout == TableLayout::GapAfter && problem_.merit.imagePlane == MeritImagePlane::Table &&
               !problem_.merit.settle && problem_.rules.pickups.empty() && !problem_.rules.marginalRayImageSolve;
    }

    const DesignProblem& problem_;
    const OptimiserOptions& options_;
    std::atomic<int> evaluations_{0};
};

// Geodesic acceleration (Transtrum & Sethna 2012): the residuals' second derivative along the step
// v, from one more evaluation at x + h v, gives the step's curvature a; x + v + a / 2 follows a curved
// valley (an operand of heavy weight held while others move) where the straight step leaves it.
// Kept only when the bend is small against the step (|a| <= 3/4 |v|, Marquardt's scaling).
void bendAlongValley(Search& search, const DesignProblem& problem, const std::vector<double>& x, const MeritEvaluation& current,
                     const std::vector<double>& jac, const std::vector<double>& a, double damping, std::vector<double>& next) {
    constexpr double kProbe = 0.1;
    const std::size_t n = x.size(), m = current.residuals.size();
    std::vector<double> v(n), probe = x;
    for (std::size_t j = 0; j < n; ++j) {
        v[j] = next[j] - x[j];
        probe[j] += kProbe * v[j];
    }
    const MeritEvaluation e = search.evaluateNear(probe, x, current);
    if (!e.valid) return;
    std::vector<double> g(n, 0.0);  // -J^T r_vv
    for (std::size_t i = 0; i < m; ++i) {
        double jv = 0;
        for (std::size_t j = 0; j < n; ++j) jv += jac[i * n + j] * v[j];
        const double rvv = 2 / kProbe * ((e.residuals[i] - current.residuals[i]) / kProbe - jv);
        for (std::size_t j = 0; j < n; ++j) g[j] -= jac[i * n + j] * rvv;
    }
    std::vector<double> bend;
    if (!solveDamped(a, g, damping, bend)) return;
    double vv = 0, bb = 0;
    for (std::size_t j = 0; j < n; ++j) {
        const double scale = std::max(a[j * n + j], 1e-300);
        vv += scale * v[j] * v[j];
        bb += scale * bend[j] * bend[j];
    }
    if (!(bb <= 0.75 * 0.75 * vv)) return;
    for (std::size_t j = 0; j < n; ++j) next[j] = x[j] + v[j] + 0.5 * bend[j];
    next = clamped(problem, next);
}

}  // namespace

const char* stopReasonText(StopReason reason) {
    switch (reason) {
        case StopReason::Converged: return "converged: the merit falls by less than the tolerance";
        case StopReason::CannotImprove: return "the merit cannot improve from here: no step of any damping lowers it";
        case StopReason::ZeroMerit: return "every operand meets its goal (merit 0)";
        case StopReason::IterationLimit: return "stopped at the iteration limit";
        case StopReason::Cancelled: return "cancelled";
    }
    return "";
}

OptimiserResult optimiseDampedLeastSquares(const DesignProblem& problem, const OptimiserOptions& options) {
    checkDesignProblem(problem);
    Search search(problem, options);
    OptimiserResult out;
    std::vector<double> x = clamped(problem, startingValues(problem));
    MeritEvaluation current = search.evaluate(x);
    if (!current.valid) throw OpticsError("the starting lens is not valid: " + current.problem);
    out.start = current;
    out.history.push_back(current.merit);
    const std::size_t n = x.size(), m = current.residuals.size();
    double damping = options.initialDamping;
    std::vector<double> jac;
    bool fresh = false;      // jac is this point's own difference Jacobian, not a secant update of an older one
    int smallSteps = 0;      // accepted steps in a row that lowered the merit by less than the tolerance
    out.stop = StopReason::IterationLimit;
    const auto finish = [&](StopReason reason) { out.stop = reason; };
    while (out.iterations < options.maxIterations) {
        if (current.merit == 0) {
            finish(StopReason::ZeroMerit);
            break;
        }
        if (n == 0) {
            finish(StopReason::CannotImprove);
            break;
        }
        if (jac.empty()) {
            jac = search.jacobian(x, current);
            fresh = true;
        }
        if (search.cancelled()) {
            finish(StopReason::Cancelled);
            break;
        }
        // The normal equations: A = J^T J, g = -J^T r.
        std::vector<double> a(n * n, 0.0), g(n, 0.0);
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const double jij = jac[i * n + j];
                if (jij == 0) continue;
                g[j] -= jij * current.residuals[i];
                for (std::size_t k = 0; k < n; ++k) a[j * n + k] += jij * jac[i * n + k];
            }
        if (std::all_of(g.begin(), g.end(), [](double v) { return v == 0; })) {
            finish(StopReason::CannotImprove);  // no variable moves any operand that counts
            break;
        }
        // What the linear model promises for a step: the merit it would leave.
        const auto modelMerit = [&](const std::vector<double>& next) {
            double sum = 0;
            for (std::size_t i = 0; i < m; ++i) {
                double r = current.residuals[i];
                for (std::size_t j = 0; j < n; ++j) r += jac[i * n + j] * (next[j] - x[j]);
                sum += r * r;
            }
            return sum;
        };
        const auto stepFrom = [&](double lambda, std::vector<double>& next) {
            std::vector<double> step;
            if (!solveDamped(a, g, lambda, step)) return false;
            next = x;
            for (std::size_t j = 0; j < n; ++j) next[j] += step[j];
            next = clamped(problem, next);
            return true;
        };
        // Converged when even the undamped (Gauss-Newton) step of this point's own Jacobian promises
        // less than the tolerance: a small damped step alone says only that the damping is too high
        // (a narrow valley, where one operand's weight dwarfs the rest).
        std::vector<double> next;
        if (fresh && stepFrom(kMinDamping, next) && current.merit - modelMerit(next) <= options.relativeTolerance * current.merit) {
            finish(StopReason::Converged);
            break;
        }
        if (!stepFrom(damping, next)) {
            damping *= 10;
            if (damping > kMaxDamping) {
                finish(StopReason::CannotImprove);
                break;
            }
            continue;
        }
        if (next == x) {
            finish(StopReason::CannotImprove);
            break;
        }
        const double promised = current.merit - modelMerit(next);
        if (options.geodesicAcceleration) bendAlongValley(search, problem, x, current, jac, a, damping, next);
        MeritEvaluation trial = search.evaluateNear(next, x, current);
        if (trial.valid && trial.merit < current.merit) {
            // Nielsen's rule: the better the model predicted the fall, the less damping next.
            const double rho = promised > 0 ? (current.merit - trial.merit) / promised : 0;
            damping = std::max(kMinDamping, damping * std::max(0.1, 1 - std::pow(2 * rho - 1, 3)));
            const bool small = current.merit - trial.merit <= options.relativeTolerance * current.merit;
            // Broyden's secant update: the Jacobian learns the residuals' change along the step, so
            // the next step needs no new differences.
            double norm = 0;
            for (std::size_t j = 0; j < n; ++j) norm += (next[j] - x[j]) * (next[j] - x[j]);
            for (std::size_t i = 0; i < m && norm > 0; ++i) {
                double predicted = current.residuals[i];
                for (std::size_t j = 0; j < n; ++j) predicted += jac[i * n + j] * (next[j] - x[j]);
                const double miss = (trial.residuals[i] - predicted) / norm;
                for (std::size_t j = 0; j < n; ++j) jac[i * n + j] += miss * (next[j] - x[j]);
            }
            x = next;
            current = std::move(trial);
            ++out.iterations;
            out.history.push_back(current.merit);
            if (options.progress) options.progress({out.iterations, search.evaluations(), current.merit, damping, &x});
            // Two small steps in a row, each from a Jacobian of its own point, end the search (an
            // underdetermined merit's model always promises more than the lens can give); a small
            // step from a secant Jacobian asks for a fresh one first.
            if (small) {
                if (fresh && ++smallSteps >= 2) {
                    finish(StopReason::Converged);
                    break;
                }
                jac.clear();
            } else {
                smallSteps = 0;
            }
            fresh = false;
        } else if (!fresh) {
            jac.clear();  // the secant Jacobian misled: differences again at this point, same damping
        } else {
            damping *= 10;
            if (damping > kMaxDamping) {
                finish(StopReason::CannotImprove);
                break;
            }
        }
        if (search.cancelled()) {
            finish(StopReason::Cancelled);
            break;
        }
    }
    out.values = x;
    out.lens = designLens(problem, x);
    out.end = current;
    out.evaluations = search.evaluations();
    return out;
}

}  // namespace lenslab
