#pragma once
// Running the service until SIGINT or SIGTERM, with a given renderer (the ray tracer for
// `lenslab serve`; tests substitute their own).
#include <memory>

#include "jobs/JobRenderer.h"
#include "core/ServiceConfig.h"

namespace lenslab {

// Loads (or makes and prints) the API token of config.access.tokenFile, then prints
// "lenslab serve: listening on http://HOST:PORT/" once it accepts requests.
int serveUntilStopped(ServiceConfig config, std::unique_ptr<JobRenderer> renderer);

}  // namespace lenslab
