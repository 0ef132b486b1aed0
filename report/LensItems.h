#pragma once
// The report's items for one lens: its measured data (cached as JSON) and its three diagrams.
#include <string>

#include "BuildReport.h"
#include "ItemRunner.h"
#include "ReportContent.h"

namespace lenslab {

LensEntry buildLensEntry(ItemRunner& runner, const std::string& id, const std::string& path, const ReportOptions& options);

}  // namespace lenslab
