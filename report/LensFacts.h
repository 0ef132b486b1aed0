#pragma once
// What the report shows about one lens, measured once and cached: the first-order table (the very
// JSON `lenslab lens --json` prints), the thick-lens error, relative illumination and distortion.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "settings/LensSettings.h"

#include "analysis/Distortion.h"
#include "analysis/RelativeIllumination.h"
#include "firstorder/ThickLens.h"

namespace lenslab {

struct LensFacts {
    std::string id, path;
    std::string description;        // the table's first comment line (the design and its source)
    std::string error;              // why the lens could not be analysed; empty when it was
    nlohmann::json analysis;        // lensAnalysisJson at the report's f-number and focus
    std::vector<ThickLensErrorSample> thickError;  // parallel rays across the entrance pupil
    double filmZ = 0;               // film plane of the illumination curve (the focused image plane)
    // mm: the largest film radius any ray reaches; 0 for none (no ray reaches the centre, or rays
    // reach past 2 EFL + 50 mm, where the lens bounds no image circle)
    double imageCircleRadius = 0;
    std::vector<IlluminationSample> illumination;  // from the axis to the image circle
    std::vector<DistortionSample> distortion;      // object at infinity, chief rays inside the image circle
};

struct LensFactsRequest {
    LensSettings lens;            // aperture and focus of the tables and curves
    bool quick = false;           // fewer samples
};

// Never throws for a bad lens: the message goes to `error` and the curves stay empty.
LensFacts measureLens(const std::string& id, const std::string& path, const LensFactsRequest& request);

nlohmann::json lensFactsJson(const LensFacts& facts);
LensFacts lensFactsFromJson(const nlohmann::json& json);

}  // namespace lenslab
