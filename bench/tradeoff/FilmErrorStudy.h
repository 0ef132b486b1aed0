#pragma once
// The geometric error of the cheaper lens traces against the exact double-precision trace, on the
// film, at the study's field positions: the thick lens (ThickLensFilmError) and the exact trace
// carried out in float (traceRayT<float>), both mapped back to the film the same way.
#include <vector>

#include "settings/LensAnalysis.h"
#include "cameras/ThickLensFilmError.h"
#include "TradeoffCases.h"

namespace lenslab::tradeoff {

struct FieldError {
    ThickLensFilmError thick;
    double floatMaxErrorMm = 0;  // worst float-traced ray against the same ray traced in double
};

// One entry per fieldCases() position (film radius = fraction x half diagonal).
std::vector<FieldError> measureFieldErrors(const LensAnalysis& analysis);

}  // namespace lenslab::tradeoff
