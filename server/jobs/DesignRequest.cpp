#include "jobs/DesignRequest.h"

#include <atomic>
#include <set>

#include "DesignJson.h"
#include "PrescriptionJson.h"
#include "PublicMessage.h"
#include "ZemaxWriter.h"

namespace lenslab {

namespace {

using nlohmann::json;

void refuseUnknownFields(const json& body, const std::set<std::string>& known) {
    if (!body.is_object()) throw DesignRequestError("body", "the body must be a JSON object (or empty)");
    for (const auto& item : body.items())
        if (!known.count(item.key())) {
            std::string names;
            for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
            throw DesignRequestError(item.key(), "unknown field '" + item.key().substr(0, 40) + "' (" + names + " are known)");
        }
}

long long integerField(const json& body, const char* name, long long fallback, long long lo, long long hi) {
    if (!body.contains(name)) return fallback;
    const json& v = body.at(name);
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
        throw DesignRequestError(name, std::string(name) + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
    return v.get<long long>();
}

// The design library's refusal of an input (DesignInputError, checkDesignProblem's invalid_argument)
// as the request's, naming the body's field.
template <class Read>
auto readField(const char* field, Read read) -> decltype(read()) {
    try {
        return read();
    } catch (const std::invalid_argument& e) {
        throw DesignRequestError(field, e.what());
    }
}

MeritFunction meritField(const json& body, const LensTable& lens) {
    return readField("merit", [&] {
        DesignProblem meritAlone;  // no variables: checks the operands and wavelengths only
        meritAlone.start = lens;
        meritAlone.merit = body.contains("merit") ? meritFromJson(body.at("merit"), lens) : defaultMerit(lens);
        checkDesignProblem(meritAlone);
        return meritAlone.merit;
    });
}

std::function<bool()> pollOf(DesignJobControl& job) {
    return [&job] { return job.cancelled(); };
}

// The optimised lens as .zmx text, or why a .zmx cannot state it.
json zmxFields(const LensTable& lens) {
    try {
        return {{"zmx", writeZemaxText(withRowCatalogsInTheFile(lens))}};
    } catch (const LensTableError& e) {
        return {{"zmx", nullptr}, {"zmx_problem", publicMessage(e.what())}};
    }
}

}  // namespace

DesignWork optimiseWork(const LensTable& lens, const json& body) {
    refuseUnknownFields(body, {"merit", "variables", "max_iterations"});
    DesignProblem problem;
    problem.start = lens;
    problem.merit = meritField(body, lens);
    problem.variables = readField("variables", [&] {
        if (body.contains("variables") && !body.at("variables").is_string())
            throw std::invalid_argument("variables must be text, as curvature:1-6,thickness:6");
        return variablesFromText(body.value("variables", std::string()), lens);
    });
    readField("variables", [&] { checkDesignProblem(problem); });  // a variable named twice
    const int maxIterations = int(integerField(body, "max_iterations", kMaxOptimiserIterations, 1, kMaxOptimiserIterations));
    return [problem, maxIterations](DesignJobControl& job) -> json {
        OptimiserOptions options;
        options.maxIterations = maxIterations;
        options.cancelled = pollOf(job);
        std::vector<double> history;
        options.progress = [&](const OptimiserProgress& p) {
            history.push_back(p.merit);
            job.report({{"iteration", p.iteration}, {"evaluations", p.evaluations}, {"merit", p.merit}, {"history", history}});
        };
        const OptimiserResult result = optimiseDampedLeastSquares(problem, options);
        if (job.cancelled()) return nullptr;
        const LensTable optimised = withGapAfterRows(result.lens);
        json out = {{"optimiser", optimiserResultJson(problem, result)}, {"prescription", prescriptionJson(optimised)}};
        out.update(zmxFields(optimised));
        return out;
    };
}

DesignWork toleranceWork(const LensTable& lens, const json& body) {
    refuseUnknownFields(body, {"merit", "tolerances", "trials", "seed"});
    ToleranceProblem problem;
    problem.nominal = lens;
    problem.merit = meritField(body, lens);
    const ToleranceInputs inputs = readField("tolerances", [&] {
        return body.contains("tolerances") ? toleranceInputsFromJson(body.at("tolerances"), lens, problem.merit)
                                           : defaultToleranceInputs(lens);
    });
    problem.tolerances = readField("tolerances", [&] { return expandTolerances(lens, inputs.spec); });
    problem.compensators = inputs.compensators;
    MonteCarloOptions monteCarlo;
    monteCarlo.trials = int(integerField(body, "trials", 100, 0, kMaxToleranceTrials));
    monteCarlo.seed = std::uint64_t(integerField(body, "seed", 1, 0, (1LL << 53)));  // exact in every JSON reader
    monteCarlo.draw = inputs.draw;
    monteCarlo.specification = inputs.specification;
    monteCarlo.meritLimit = inputs.meritLimit;
    return [problem, monteCarlo](DesignJobControl& job) -> json {
        const int trials = monteCarlo.trials;
        const auto report = [&](const char* phase, int done) { job.report({{"phase", phase}, {"trials_done", done}, {"trials", trials}}); };
        report("sensitivity", 0);
        OptimiserOptions compensation = compensatorSearch();
        compensation.cancelled = pollOf(job);
        const std::vector<SensitivityRow> rows = toleranceSensitivity(problem, compensation);
        if (job.cancelled()) return nullptr;
        report("monte carlo", 0);
        MonteCarloOptions options = monteCarlo;
        options.compensation = compensation;
        options.cancelled = pollOf(job);
        std::atomic<int> finished{0};  // progress comes from every trial's thread
        options.progress = [&](int) { report("monte carlo", ++finished); };
        const MonteCarloResult result = runMonteCarlo(problem, options);
        if (job.cancelled()) return nullptr;
        return {{"sensitivity", sensitivityJson(problem, rows)}, {"monte_carlo", monteCarloJson(problem, result)}, {"seed", monteCarlo.seed}};
    };
}

}  // namespace lenslab
