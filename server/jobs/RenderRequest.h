#pragma once
// The body of POST /api/renders: which scene, which lens and how to set it, how many samples and
// pixels. Millimetres throughout. Omitted camera settings keep the scene's own values.
#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "film/SensorSpec.h"
#include "settings/LensSettings.h"
#include "core/ServiceConfig.h"

namespace lenslab {

struct RenderRequest {
    std::string scene;                   // id from GET /api/scenes
    std::string lens = "dgauss.50mm";    // id from GET /api/lenses
    std::optional<double> fstop;         // unset: as in the scene
    std::optional<double> focusDistance; // front vertex to the plane of focus (field focaldistance); unset: as in the scene
    std::optional<double> filmDiagonal;  // unset: as in the scene
    std::optional<bool> spectral;        // unset: spectral when the lens disperses
    std::string mode = "exact";          // exact (every ray traced) | thick (thick lens) | auto
    std::optional<std::string> ghosts;   // lens flare: off | auto | all | N (cameras/GhostSelection.h); unset: the scene's
    std::optional<std::string> ghostModel;  // exact | paraxial; unset: the scene's
    // A tilt-shift lens (renderer/raytracer/cameras/LensMount.h): degrees, and x, y millimetres.
    std::optional<double> tilt, swing;
    std::optional<std::array<double, 2>> shift;
    // A real camera sensor (renderer/raytracer/film/SensorSpec.h): its keys and values as given,
    // checked; unset: the noiseless film.
    std::optional<SensorPairs> sensor;
    int spp = 16;
    int width = 320, height = 240;
};

// Checks every field's type and range against the limits; HttpError 400 naming the field.
// `defaultScene` fills an omitted scene.
RenderRequest parseRenderRequest(const nlohmann::json& body, const RenderLimits& limits,
                                 const std::string& defaultScene);

// The request's fstop and focaldistance as lens settings named by their fields.
LensSettings lensSettings(const RenderRequest& request);

// The request in the body's own field names (what job listings show and resubmission reuses).
nlohmann::json renderRequestJson(const RenderRequest& request);

}  // namespace lenslab
