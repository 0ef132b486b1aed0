#pragma once
// Damped least squares (Levenberg-Marquardt, Marquardt's scaling, Nielsen's damping rule) over a
// design problem: the Jacobian of the operands' residuals by forward differences, its columns
// evaluated side by side on every thread, then kept up to date by Broyden's secant updates from the
// steps taken (differences again where a secant Jacobian misleads). A step is taken only when the
// lens it leads to is valid (evaluateMerit) and its merit is lower, else the damping rises and a
// shorter, steeper step is tried. Bounds on variables are kept by clamping. Stops when even the
// undamped (Gauss-Newton) step promises to lower the merit by less than a set fraction, or two steps
// in a row from fresh Jacobians each lowered it by less; when no step lowers it at all (the merit
// cannot improve from here); at the iteration limit; or when cancelled.
#include <functional>
#include <string>
#include <vector>

#include "design/DesignProblem.h"

namespace lenslab {

enum class StopReason {
    Converged,       // the Gauss-Newton step promises less than the tolerance, or two steps gave less
    CannotImprove,   // no step lowers the merit (the damping rose past its limit)
    ZeroMerit,       // every operand meets its goal
    IterationLimit,
    Cancelled,
};
const char* stopReasonText(StopReason reason);  // a sentence for the terminal and the page

struct OptimiserProgress {
    int iteration = 0;
    int evaluations = 0;
    double merit = 0;
    double damping = 0;
    const std::vector<double>* values = nullptr;  // the variables' values at this merit
};

struct OptimiserOptions {
    int maxIterations = 200;
    double relativeTolerance = 1e-3;  // a fall of the merit smaller than this fraction counts as none (scipy's ftol)
    double initialDamping = 1e-3;
    // Each step bent along the valley by the residuals' second derivative along it (one evaluation
    // more a step): for merits where a heavily weighted operand is held while others move.
    bool geodesicAcceleration = false;
    std::function<void(const OptimiserProgress&)> progress;  // after each accepted step
    std::function<bool()> cancelled;                         // polled between evaluations
};

struct OptimiserResult {
    std::vector<double> values;    // the variables at the end
    LensTable lens;                // the lens they make
    MeritEvaluation start, end;    // the merit before and after (the run's fixed sampling)
    int iterations = 0;
    int evaluations = 0;           // merit evaluations, derivatives included
    StopReason stop = StopReason::Converged;
    std::vector<double> history;   // the merit after each accepted step, the start first
};

// Throws std::invalid_argument for a problem that does not apply to its lens (checkDesignProblem)
// and OpticsError when the starting lens itself is not valid (naming why).
OptimiserResult optimiseDampedLeastSquares(const DesignProblem& problem, const OptimiserOptions& options = {});

}  // namespace lenslab
