#include "AnalysisJson.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

using nlohmann::json;

json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json numbers(const std::vector<double>& values) {
    json a = json::array();
    for (double v : values) a.push_back(number(v));
    return a;
}

json number(std::optional<double> v) { return v ? number(*v) : json(nullptr); }

json point(Point2 p) { return json::array({p.x, p.y}); }
json point(std::optional<Point2> p) { return p ? point(*p) : json(nullptr); }

json statisticsJson(const SpotStatistics& s) {
    return {{"rms_radius_mm", s.rmsRadius}, {"geo_radius_mm", s.geometricRadius}, {"centroid_mm", point(s.centroid)}};
}

json spotJson(const SpotDiagram& s) {
    json points = json::array();
    const std::size_t step = (s.points.size() + kMaxJsonSpotPoints - 1) / kMaxJsonSpotPoints;
    for (std::size_t k = 0; k < s.points.size(); k += std::max<std::size_t>(step, 1)) points.push_back(point(s.points[k]));
    json out = statisticsJson(s.statistics);
    out.update({{"wavelength_nm", s.wavelength},
                {"transmission", s.transmission},
                {"rays_launched", s.raysLaunched},
                {"rays_passed", s.points.size()},
                {"pupil_sampling", {{"rings", s.sampling.rings}, {"azimuths", s.sampling.azimuths}, {"change_on_doubling", s.samplingChange}}},
                {"points", points}});
    return out;
}

json fanJson(const RayFan& f) {
    return {{"wavelength_nm", f.wavelength}, {"pupil", numbers(f.pupil)}, {"tangential_mm", numbers(f.tangential)},
            {"sagittal_mm", numbers(f.sagittal)}};
}

json fieldJson(const FieldAnalysis& f, const LensDesignAnalysis& a) {
    json spots = json::array();
    for (const SpotDiagram& s : f.spots) spots.push_back(spotJson(s));
    return {{"field_deg", f.fieldDegrees},
            {"traced", f.traced},
            {"image_height_mm", f.chiefImage ? json(std::hypot(f.chiefImage->x, f.chiefImage->y)) : json(nullptr)},
            {"chief_ray_image_mm", point(f.chiefImage)},
            {"reference_mm", point(f.reference)},
            {"spots", spots},
            {"polychromatic", statisticsJson(f.polychromatic)},
            {"rms_wavefront_waves", numbers(f.rmsWavefrontWaves)},
            {"distortion_percent", number(f.distortionPercent)},
            {"relative_illumination", number(f.relativeIllumination)},
            {"mtf",
             {{"frequencies_lpmm", a.frequencies},
              {"diffraction", {{"sagittal", numbers(f.diffractionSagittal)}, {"tangential", numbers(f.diffractionTangential)}}},
              {"geometric", {{"sagittal", numbers(f.geometricSagittal)}, {"tangential", numbers(f.geometricTangential)}}},
              {"diffraction_limit", numbers(a.diffractionLimit)}}}};
}

// Third-order sums, mm: S_I to S_V and the primary colours (analysis/SeidelSums.h).
json seidelTermsJson(const SeidelTerms& t) {
    return {{"spherical", t.spherical}, {"coma", t.coma}, {"astigmatism", t.astigmatism}, {"petzval", t.petzval},
            {"distortion", t.distortion}, {"axial_colour", t.axialColour}, {"lateral_colour", t.lateralColour}};
}

json seidelJson(const SeidelSums& s) {
    json surfaces = json::array();
    for (const SeidelTerms& t : s.surfaces) surfaces.push_back(seidelTermsJson(t));
    return {{"field_deg", s.fieldDegrees}, {"stop_radius", s.marginalHeight}, {"lagrange_invariant", s.lagrangeInvariant},
            {"total", seidelTermsJson(s.total)}, {"surfaces", surfaces}};
}

json focalShiftJson(const std::vector<FocalShiftSample>& samples) {
    json out = {{"wavelength_nm", json::array()}, {"image_z", json::array()}, {"shift_mm", json::array()}};
    for (const FocalShiftSample& s : samples) {
        out["wavelength_nm"].push_back(s.wavelength);
        out["image_z"].push_back(s.imageZ);
        out["shift_mm"].push_back(s.shift);
    }
    return out;
}

// What each number means, in words, beside the numbers (docs/analysis.md has the long form).
json definitionsJson(const LensDesignAnalysis& a) {
    const bool chief = a.reference == SpotReference::ChiefRay;
    const char* plane = a.imagePlane == ImagePlane::Paraxial ? "the paraxial image of the plane of focus at the primary wavelength"
                        : a.imagePlane == ImagePlane::Film   ? "the film as the camera focuses it (least RMS spot on axis at the primary wavelength)"
                                                             : "least RMS spot over the analysed fields and wavelengths, weighted";
    return {{"image_plane", plane},
            {"reference", chief ? "every spot's radii about the primary wavelength's chief ray"
                                : "each wavelength's radii about its own centroid; the polychromatic spot's about the weighted centroid"},
            {"pupil_sampling", "area-uniform: Gauss-Legendre rings in r^2 times equally spaced azimuths over the stop (real rays "
                               "aimed), doubled until the RMS radius moves by at most 0.1%; blocked rays take their area with them"},
            {"field", "the angle of a distant object's chief ray to the axis in object space"},
            {"traced", "false: no ray of the field reaches the image plane (not imaged); it has no image height, distortion "
                       "or relative illumination (null)"},
            {"wavelength_weights", "relative weights of the wavelengths in every polychromatic number"},
            {"mtf", "geometric: the spot's weighted rays; diffraction: the FFT of the pupil function; both polychromatic, "
                    "sagittal along x, tangential along y"}};
}

}  // namespace

json designAnalysisJson(const LensDesignAnalysis& a) {
    json fields = json::array(), distortionPerField = json::array(), illuminationPerField = json::array();
    for (const FieldAnalysis& f : a.fields) {
        fields.push_back(fieldJson(f, a));
        distortionPerField.push_back(number(f.distortionPercent));
        illuminationPerField.push_back(number(f.relativeIllumination));
    }
    json curvature = json::array();
    for (std::size_t j = 0; j < a.fieldCurvature.size(); ++j) {
        json c = {{"wavelength_nm", a.wavelengths[j]}, {"tangential_mm", json::array()}, {"sagittal_mm", json::array()}};
        for (const FieldCurvatureSample& s : a.fieldCurvature[j]) {
            c["tangential_mm"].push_back(s.found ? json(s.tangentialShift) : json(nullptr));
            c["sagittal_mm"].push_back(s.found ? json(s.sagittalShift) : json(nullptr));
        }
        curvature.push_back(c);
    }
    json distortionCurve = {{"field_deg", json::array()}, {"percent", json::array()}};
    for (const DistortionSample& s : a.distortion) {
        distortionCurve["field_deg"].push_back(s.fieldDegrees);
        distortionCurve["percent"].push_back(s.found ? json(s.distortionPercent) : json(nullptr));
    }
    json illumination = {{"film_radius_mm", json::array()}, {"relative_illumination", json::array()}};
    for (const IlluminationSample& s : a.illumination) {
        illumination["film_radius_mm"].push_back(s.filmRadius);
        illumination["relative_illumination"].push_back(s.relativeIllumination);
    }
    json shifts = json::array();
    for (const FocalShiftSample& s : a.focalShift) shifts.push_back(s.shift);
    json fans = json::array();
    for (const FieldAnalysis& f : a.fields) {
        json perWavelength = json::array();
        for (const RayFan& r : f.fans) perWavelength.push_back(fanJson(r));
        fans.push_back({{"field_deg", f.fieldDegrees}, {"fans", perWavelength}});
    }
    return {
        {"name", a.lens.lens.name},
        {"units", "mm, nm, degrees, lp/mm"},
        {"convention", "lens space: +z toward the scene; spot points relative to each field's reference point and fan "
                       "points to its primary chief ray on the image plane; focus shifts positive toward the lens"},
        {"definitions", definitionsJson(a)},
        {"fstop", a.lens.fstop},
        {"focus_distance", a.lens.focus.infinity ? json(nullptr) : json(a.lens.focus.objectZ - a.lens.lens.frontZ())},
        {"image_plane", imagePlaneName(a.imagePlane)},
        {"image_z", a.imageZ},
        {"image_planes", {{"paraxial_z", a.planes.paraxialZ}, {"film_z", a.planes.filmZ}, {"best_z", a.planes.bestZ}}},
        {"reference", spotReferenceName(a.reference)},
        {"primary_wavelength_nm", a.primaryWavelength},
        {"efl", a.lens.firstOrder.efl},
        {"largest_field_deg", a.largestFieldDegrees ? json(*a.largestFieldDegrees) : json(nullptr)},
        {"largest_field_source", a.largestFieldSource},
        {"obscuration", a.obscuration},
        {"wavelengths_nm", a.wavelengths},
        {"weights", a.weights},
        {"fields", fields},
        {"distortion_percent", distortionPerField},
        {"relative_illumination", illuminationPerField},
        {"chromatic_focal_shift_mm", shifts},
        {"ray_fans", fans},
        {"field_curvature", {{"field_deg", a.curveFieldDegrees}, {"wavelengths", curvature}}},
        {"curves",
         {{"distortion", distortionCurve},
          {"relative_illumination", illumination},
          {"chromatic_focal_shift", focalShiftJson(a.focalShiftSpectrum)}}},
        {"seidel_sums", a.seidel ? seidelJson(*a.seidel) : json(nullptr)},
    };
}

}  // namespace lenslab
