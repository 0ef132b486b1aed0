// `lenslab serve` with the FakeRenderer in place of the ray tracer: the real HTTP service, queue and
// storage, with renders whose duration the tests control (spp = milliseconds per 16-pixel tile).
// Besides serve's options it takes limits that `lenslab serve` keeps at their defaults, so that tests
// reach them in seconds: --answer-timeout S and --downloads-per-client N.
#include <iostream>
#include <map>

#include "ArgParser.h"
#include "FakeRenderer.h"
#include "ServeCommand.h"
#include "ServeOptions.h"

int main(int argc, char** argv) {
    try {
        std::vector<std::string> args;
        std::map<std::string, int> testLimits;
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            if ((arg == "--answer-timeout" || arg == "--downloads-per-client") && i + 1 < argc)
                testLimits[arg] = std::stoi(argv[++i]);
            else
                args.push_back(arg);
        }
        auto config = lenslab::parseServeOptions(args);
        if (!config) return 0;
        if (testLimits.count("--answer-timeout")) config->http.answerTimeoutSeconds = testLimits["--answer-timeout"];
        if (testLimits.count("--downloads-per-client")) config->http.downloadsPerClient = testLimits["--downloads-per-client"];
        return lenslab::serveUntilStopped(*config, std::make_unique<lenslab::FakeRenderer>());
    } catch (const std::exception& e) {
        std::cerr << "fake render server: " << e.what() << "\n";
        return 1;
    }
}
