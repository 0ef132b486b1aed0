#include <fstream>
#include <iostream>
#include <sstream>

#include "ArgParser.h"
#include "Commands.h"
#include "DesignInputs.h"
#include "DesignJson.h"
#include "design/GlassSnap.h"
#include "design/GlobalSearch.h"

namespace lenslab {

int runOptimiseCommand(const std::vector<std::string>& args) {
    ArgParser p("optimise", "FILE [--merit M.json] [--variables LIST] [--image-solve] [--global HOPS [--seed S]] -o out.zmx",
                "Optimises a lens by damped least squares (docs/design.md): the variables move until the merit\n"
                "stops falling; every step keeps a lens that can be built. Prints the merit as it falls, then each\n"
                "operand and variable before and after. --global adds basin hopping from a seed.");
    declareDesignInputs(p);
    p.option("--variables", "LIST", "curvature:1-6,thickness:6,conic:3,asphere4:5,index:1,abbe:1 (default: every curvature, and the image distance where the table states one)");
    p.flag("--image-solve", "hold the image distance at the paraxial marginal ray's focus");
    p.option("--global", "HOPS", "basin hopping: this many hops, each a descent from a random move of the best design");
    p.option("--seed", "S", "the hops' seed (default 1)");
    p.option("--max-iterations", "N", "per descent (default 200)");
    p.option("--snap-glasses", "CATALOGS", "after the search, each glass whose index or abbe varied becomes its nearest catalog glass\n"
                                           "(SCHOTT,OHARA,... or all), and the other variables are optimised again");
    p.option("-o", "OUT", "the optimised lens (.zmx, .seq or .dat; read back to check), or results as .json");
    p.flag("--json", "print the result as one JSON object");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    DesignProblem problem;
    problem.start = designTable(p);
    problem.merit = designMerit(p, problem.start);
    try {
        problem.variables = variablesFromText(p.get("--variables"), problem.start);
    } catch (const DesignInputError& e) {
        throw UsageError(std::string("optimise: --") + e.what());
    }
    problem.rules.marginalRayImageSolve = p.has("--image-solve");
    OptimiserOptions local;
    if (p.has("--max-iterations")) local.maxIterations = int(*p.integer("--max-iterations"));
    if (local.maxIterations < 1) throw UsageError("optimise: --max-iterations must be at least 1");
    const bool json = p.has("--json");
    local.progress = [&](const OptimiserProgress& progress) {
        if (!json) std::cerr << "  step " << progress.iteration << ": merit " << progress.merit << " (" << progress.evaluations << " evaluations)\n";
    };
    const LensTable startTable = problem.start;  // the lens as given, before any glass is snapped
    const double cpu = processCpuSeconds();
    OptimiserResult result;
    if (p.has("--global")) {
        GlobalSearchOptions options;
        options.hops = int(*p.integer("--global"));
        options.seed = p.has("--seed") ? std::uint64_t(*p.integer("--seed")) : 1;
        options.local = local;
        if (options.hops < 0 || options.hops > 1000) throw UsageError("optimise: --global takes 0 to 1000 hops");
        result = searchGlobally(problem, options).best;
    } else {
        result = optimiseDampedLeastSquares(problem, local);
    }
    if (p.has("--snap-glasses")) {
        std::vector<int> rows;
        std::vector<DesignVariable> others;
        for (const DesignVariable& v : problem.variables)
            (v.kind == VariableKind::Index || v.kind == VariableKind::Abbe ? rows.push_back(v.row) : others.push_back(v));
        std::vector<std::string> catalogs;
        std::stringstream names(p.get("--snap-glasses"));
        for (std::string name; std::getline(names, name, ',');)
            if (!name.empty() && name != "all") catalogs.push_back(name);
        DesignProblem refined = problem;
        refined.start = result.lens;
        for (const GlassChoice& c : snapToCatalogGlasses(refined.start, rows, catalogs))
            if (!json)
                std::cerr << "  surface " << c.row + 1 << ": model glass " << c.nd << " / " << c.vd << " -> " << c.glass.name << " ("
                          << c.glass.catalog << ") " << c.glass.nd << " / " << c.glass.vd << ", distance " << c.distance << "\n";
        refined.variables = others;
        const MeritEvaluation start = result.start;
        result = optimiseDampedLeastSquares(refined, local);
        result.start = start;
        problem = refined;
    }
    const double used = processCpuSeconds() - cpu;
    // The figures a designer quotes: both lenses on the analysis's converged sampling.
    MeritFunction settled = problem.merit;
    settled.settle = true;
    const MeritEvaluation before = evaluateMerit(startTable, settled), after = evaluateMerit(result.lens, settled);
    if (json) {
        nlohmann::json j = optimiserResultJson(problem, result);
        j["cpu_seconds"] = used;
        j["settled"] = {{"start", meritEvaluationJson(settled, before)}, {"end", meritEvaluationJson(settled, after)}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << optimiserResultText(problem, result) << "\non the analysis's converged sampling: merit " << before.merit << " -> "
                  << after.merit << "\nCPU " << used << " s\n";
    }
    if (p.has("-o")) {
        const std::string out = p.get("-o");
        if (out.size() > 5 && out.compare(out.size() - 5, 5, ".json") == 0) {
            std::ofstream f(out);
            if (!(f << optimiserResultJson(problem, result).dump(2) << "\n")) throw std::runtime_error(out + ": cannot write the file");
        } else {
            writeDesignTable(result.lens, out, problem.merit);
        }
        if (!json) std::cout << "wrote " << out << "\n";
    }
    return 0;
}

}  // namespace lenslab
