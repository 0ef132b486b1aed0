#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>

#include "ArgParser.h"
#include "Commands.h"
#include "DesignInputs.h"
#include "DesignJson.h"

namespace lenslab {

int runToleranceCommand(const std::vector<std::string>& args) {
    ArgParser p("tolerance", "FILE [--spec T.json] [--merit M.json] [--trials N] [--seed S] [-o DIR [--format zmx|seq]]",
                "Tolerances a lens (docs/design.md): each tolerance alone at both limits (sensitivity), then N\n"
                "Monte Carlo trials with every tolerance drawn at once, the compensators set again in each. Prints\n"
                "the sensitivities, each operand's distribution and the yield; -o DIR writes results.json and the\n"
                "as-built lenses of the median, 90th-percentile and worst trials (p50.zmx, p90.zmx, worst.zmx).");
    declareDesignInputs(p);
    p.option("--spec", "T.json", "tolerances, compensators, draw and specification (default: radius 0.1%, thickness 0.02 mm,\n"
                                 "decentre 0.01 mm, tilt 0.01 deg, index 5e-4; the image distance as compensator)");
    p.option("--trials", "N", "Monte Carlo trials (default 100; 0: sensitivity only)");
    p.option("--seed", "S", "the trials' seed (default 1): trial k of seed S is the same lens everywhere");
    p.option("--most", "N", "sensitivity rows printed (default 15)");
    p.option("-o", "DIR", "results.json and the as-built lenses");
    p.option("--format", "F", "zmx | seq: the as-built lenses as Zemax or Code V files (default zmx; a gap-before table's are .dat)");
    p.flag("--json", "print the results as one JSON object");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    ToleranceProblem problem;
    problem.nominal = designTable(p);
    problem.merit = designMerit(p, problem.nominal);
    ToleranceInputs inputs = defaultToleranceInputs(problem.nominal);
    if (p.has("--spec")) {
        try {
            inputs = toleranceInputsFromJson(readJsonFile(p.get("--spec"), "tolerance"), problem.nominal, problem.merit);
        } catch (const DesignInputError& e) {
            throw std::runtime_error(p.get("--spec") + ": " + e.what());
        }
    }
    problem.tolerances = expandTolerances(problem.nominal, inputs.spec);
    problem.compensators = inputs.compensators;
    const long trials = p.has("--trials") ? *p.integer("--trials") : 100;
    if (trials < 0 || trials > 1000000) throw UsageError("tolerance: --trials must be 0 to 1000000");
    const bool json = p.has("--json");
    const std::string format = p.get("--format", "zmx");
    if (format != "zmx" && format != "seq") throw UsageError("tolerance: --format must be zmx or seq, got '" + format + "'");

    double cpu = processCpuSeconds();
    const std::vector<SensitivityRow> rows = toleranceSensitivity(problem);
    const double sensitivityCpu = processCpuSeconds() - cpu;
    MonteCarloOptions options;
    options.trials = int(trials);
    options.seed = p.has("--seed") ? std::uint64_t(*p.integer("--seed")) : 1;
    options.draw = inputs.draw;
    options.specification = inputs.specification;
    options.meritLimit = inputs.meritLimit;
    std::mutex printing;
    options.progress = [&](int done) {
        if (json || options.trials < 10 || done % (options.trials / 10) != 0) return;
        std::lock_guard<std::mutex> lock(printing);
        std::cerr << "  " << done << " of " << options.trials << " trials\n";
    };
    cpu = processCpuSeconds();
    const MonteCarloResult mc = runMonteCarlo(problem, options);
    const double monteCarloCpu = processCpuSeconds() - cpu;

    nlohmann::json j = {{"sensitivity", sensitivityJson(problem, rows)},
                        {"monte_carlo", monteCarloJson(problem, mc)},
                        {"seed", options.seed},
                        {"cpu_seconds", {{"sensitivity", sensitivityCpu}, {"monte_carlo", monteCarloCpu}}}};
    if (json) {
        std::cout << j.dump(2) << "\n";
    } else {
        const long most = p.has("--most") ? *p.integer("--most") : 15;
        std::cout << problem.tolerances.size() << " tolerances, " << problem.compensators.size() << " compensator(s)\n\n"
                  << sensitivityText(rows, std::size_t(std::max(0L, most))) << "\n";
        if (trials > 0)
            std::cout << monteCarloText(problem, mc) << "\nCPU " << sensitivityCpu << " s sensitivity, " << monteCarloCpu << " s Monte Carlo ("
                      << monteCarloCpu / trials << " s a trial)\n";
    }
    if (p.has("-o")) {
        const std::filesystem::path dir = p.get("-o");
        std::filesystem::create_directories(dir);
        std::ofstream(dir / "results.json") << j.dump(2) << "\n";
        for (const auto& [name, percentile] : {std::pair{"p50", 50.0}, std::pair{"p90", 90.0}, std::pair{"worst", 100.0}}) {
            const std::optional<int> k = trialAtPercentile(mc, percentile);
            if (!k) continue;
            const LensTable lens = asBuiltLens(problem, mc.trials[*k].departures);
            const std::string path = (dir / (std::string(name) + (lens.layout == TableLayout::GapAfter ? "." + format : ".dat"))).string();
            try {
                writeDesignTable(lens, path, problem.merit);
                if (!json) std::cout << "wrote " << path << " (trial " << *k << ")\n";
            } catch (const std::exception& e) {
                std::cerr << "lenslab tolerance: the " << name << " trial's lens is not written: " << e.what() << "\n";
            }
        }
    }
    return 0;
}

}  // namespace lenslab
