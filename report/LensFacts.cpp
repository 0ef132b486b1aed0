#include "LensFacts.h"

#include <cmath>
#include <exception>
#include <filesystem>

#include "settings/LensAnalysis.h"
#include "LensJson.h"
#include "PublicMessage.h"

namespace lenslab {

namespace {

std::vector<ThickLensErrorSample> thickErrorAcrossPupil(const LensAnalysis& a, int count) {
    std::vector<double> heights;
    const double radius = 0.5 * a.pupils.entrance.diameter;
    for (int k = 1; k <= count; ++k) heights.push_back(radius * k / count);  // the axial ray itself has no error to show
    return thickLensError(a.lens, a.thick, a.firstOrder, heights);
}

// The distortion curve up to where chief rays leave the image circle (or stop existing).
std::vector<DistortionSample> distortionInsideCircle(const LensAnalysis& a, double circle, int count) {
    std::vector<DistortionSample> kept;
    for (const DistortionSample& s : distortionCurve(a.lens, a.firstOrder, 85.0, count)) {
        if (!s.found || s.imageHeight > circle) break;
        kept.push_back(s);
    }
    return kept;
}

}  // namespace

LensFacts measureLens(const std::string& id, const std::string& path, const LensFactsRequest& request) {
    LensFacts f;
    f.id = id;
    f.path = path;
    try {
        LensSystem lens = loadLensSystem(path);
        lens.name = std::filesystem::path(path).filename().string();  // published: not where it lies
        if (!lens.comments.empty()) f.description = lens.comments.front();
        const LensAnalysis a = analyzeLens(lens, request.lens);
        f.analysis = lensAnalysisJson(a);
        f.thickError = thickErrorAcrossPupil(a, request.quick ? 12 : 41);
        f.filmZ = a.focus.imageZExact;
        // Rays that still reach the film at the search's limit (a doublet with its stop at the glass
        // passes them at any angle) bound no image circle: none, as when no ray reaches the centre.
        const double limit = 2 * std::fabs(a.firstOrder.efl) + 50;
        const double circle = imageCircleRadius(a.lens, f.filmZ, limit);
        f.imageCircleRadius = circle < limit ? circle : 0;
        if (f.imageCircleRadius > 0)
            f.illumination = relativeIllumination(a.lens, f.filmZ, f.imageCircleRadius,
                                                  request.quick ? RelativeIlluminationOptions{12, 48}
                                                                : RelativeIlluminationOptions{48, 128});
        f.distortion = distortionInsideCircle(a, f.imageCircleRadius, request.quick ? 18 : 86);
    } catch (const std::exception& e) {
        f.error = publicMessage(e.what());  // the page is public
    }
    return f;
}

nlohmann::json lensFactsJson(const LensFacts& f) {
    using nlohmann::json;
    json thick = json::array(), illumination = json::array(), distortion = json::array();
    for (const auto& s : f.thickError) thick.push_back({s.height, s.transverseError, s.angleError, s.blocked});
    for (const auto& s : f.illumination) illumination.push_back({s.filmRadius, s.passingArea, s.relativeIllumination});
    for (const auto& s : f.distortion) distortion.push_back({s.fieldDegrees, s.imageHeight, s.paraxialHeight, s.distortionPercent});
    // Not the path: the facts are published (assets/lenses/ID.json, manifest.json); it is set again
    // from the lens source on every build.
    return {{"id", f.id},
            {"description", f.description},
            {"error", f.error},     {"analysis", f.analysis},
            {"thick_error", thick}, {"film_z", f.filmZ},
            {"image_circle_radius", f.imageCircleRadius},
            {"illumination", illumination},
            {"distortion", distortion}};
}

LensFacts lensFactsFromJson(const nlohmann::json& j) {
    LensFacts f;
    f.id = j.at("id").get<std::string>();
    f.description = j.at("description").get<std::string>();
    f.error = j.at("error").get<std::string>();
    f.analysis = j.at("analysis");
    f.filmZ = j.at("film_z").get<double>();
    f.imageCircleRadius = j.at("image_circle_radius").get<double>();
    for (const auto& s : j.at("thick_error"))
        f.thickError.push_back({s[0].get<double>(), s[1].get<double>(), s[2].get<double>(), s[3].get<bool>()});
    for (const auto& s : j.at("illumination"))
        f.illumination.push_back({s[0].get<double>(), s[1].get<double>(), s[2].get<double>()});
    for (const auto& s : j.at("distortion"))
        f.distortion.push_back({s[0].get<double>(), s[1].get<double>(), s[2].get<double>(), s[3].get<double>(), true});
    return f;
}

}  // namespace lenslab
