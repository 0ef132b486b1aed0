// `lenslab serve` with the FakeRenderer in place of the ray tracer: the real HTTP service, queue and
// storage, with renders whose duration the tests control (spp = milliseconds per 16-pixel tile).
#include <iostream>

#include "ArgParser.h"
#include "FakeRenderer.h"
#include "ServeCommand.h"
#include "ServeOptions.h"

int main(int argc, char** argv) {
    try {
        const auto config = lenslab::parseServeOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (!config) return 0;
        return lenslab::serveUntilStopped(*config, std::make_unique<lenslab::FakeRenderer>());
    } catch (const std::exception& e) {
        std::cerr << "fake render server: " << e.what() << "\n";
        return 1;
    }
}
