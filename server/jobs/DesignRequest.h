#pragma once
// The bodies of POST /api/lenses/{id}/optimise and POST /api/lenses/{id}/tolerance (docs/api.md,
// "Optimising and tolerancing") made into the work of a design job: every field is checked at once,
// against the lens, so that a bad merit or an unknown variable is a 400 before any work is queued;
// the optics run later, in the job, as `lenslab optimise` and `lenslab tolerance` run them.
//   optimise:  {"merit": {...}, "variables": "curvature:1-6,thickness:6", "max_iterations": N}
//   tolerance: {"merit": {...}, "tolerances": {...}, "trials": N, "seed": S}
// (merit and tolerances as docs/design.md's files; every field optional).
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "jobs/DesignJobs.h"
#include "prescription/LensTable.h"

namespace lenslab {

// A field the request cannot have: `field` names it, the message says why (and names it too).
class DesignRequestError : public std::invalid_argument {
public:
    DesignRequestError(std::string field, const std::string& message) : std::invalid_argument(message), field_(std::move(field)) {}
    const std::string& field() const { return field_; }

private:
    std::string field_;
};

constexpr int kMaxOptimiserIterations = 200;  // per descent, as lenslab optimise's default
constexpr int kMaxToleranceTrials = 2000;     // about 8 s of CPU for the Cooke triplet (docs/design.md)

// The job's result: {"optimiser": optimiserResultJson, "prescription": the editor's rows (PrescriptionJson.h),
// "zmx": the optimised lens as .zmx text (null, with "zmx_problem", for a lens a .zmx cannot state)}.
// Progress: {"iteration", "evaluations", "merit", "history": the merit after each step}.
DesignWork optimiseWork(const LensTable& lens, const nlohmann::json& body);

// The job's result: {"sensitivity": sensitivityJson, "monte_carlo": monteCarloJson, "seed"}.
// Progress: {"phase": "sensitivity" | "monte carlo", "trials_done", "trials"}.
DesignWork toleranceWork(const LensTable& lens, const nlohmann::json& body);

}  // namespace lenslab
