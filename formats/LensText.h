#pragma once
// A lens analysis as the text table `lenslab lens` prints.
#include <string>

#include "settings/LensAnalysis.h"

namespace lenslab {

std::string lensAnalysisText(const LensAnalysis& analysis);

}  // namespace lenslab
