#pragma once
// What `lenslab optimise` and `lenslab tolerance` share: the lens read as its table (with --layout),
// its merit function (--merit FILE, else the default merit), and writing a lens table by the output
// file's extension (.zmx, .seq, .dat), read back to check that it is the same lens.
#include <nlohmann/json.hpp>
#include <string>

#include "ArgParser.h"
#include "design/MeritFunction.h"

namespace lenslab {

void declareDesignInputs(ArgParser& p);

// The CPU time of the whole process so far (every thread), s: what a design run is measured by.
double processCpuSeconds();
LensTable designTable(const ArgParser& p);
MeritFunction designMerit(const ArgParser& p, const LensTable& table);
nlohmann::json readJsonFile(const std::string& path, const std::string& what);

// Writes the table as .zmx, .seq or .dat (by the path's extension), its substituted glasses (an as-built
// lens's melts) as the .smx beside it, and reads it back: throws std::runtime_error when the file does
// not read back to the same merit values (`merit`).
void writeDesignTable(const LensTable& table, const std::string& path, const MeritFunction& merit);

}  // namespace lenslab
