#pragma once
// `lenslab serve` options -> ServiceConfig, with the default folders.
#include <optional>
#include <string>
#include <vector>

#include "core/ServiceConfig.h"

namespace lenslab {

// nullopt when --help was asked for (the help text is printed). UsageError for bad options.
std::optional<ServiceConfig> parseServeOptions(const std::vector<std::string>& args);

// $XDG_DATA_HOME/lenslab, else ~/.local/share/lenslab, else ./data.
std::string defaultDataDir();

}  // namespace lenslab
