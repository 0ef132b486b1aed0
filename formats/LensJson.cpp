#include "LensJson.h"

#include <cmath>

namespace lenslab {

namespace {

nlohmann::json finiteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json lensAnalysisJson(const LensAnalysis& a) {
    using nlohmann::json;
    const FirstOrder& fo = a.firstOrder;
    json surfaces = json::array();
    for (const Surface& s : a.lens.surfaces) {
        const Medium& m = s.mediumAfter;
        json surface = {{"z", s.z},
                        {"radius", s.radius},
                        {"n", s.indexAfter},
                        {"diameter", 2 * s.apertureRadius},
                        {"is_stop", s.isStop},
                        {"line", s.line},
                        {"glass", m.name},
                        {"catalog", m.catalog},
                        {"nd", refractiveIndex(m, kWavelengthD)},
                        {"vd", isDispersive(m) ? json(abbeNumber(m)) : json(nullptr)},
                        {"conic", s.conic},
                        {"aspheric", s.aspheric},
                        {"mirror", s.mirror}};
        if (s.obscurationRadius > 0) surface["obscuration_diameter"] = 2 * s.obscurationRadius;
        surfaces.push_back(surface);
    }
    const Chromatic& c = a.chromatic;
    return {
        {"name", a.lens.name},
        {"units", "mm"},
        {"convention", "origin at the front vertex, +z toward the scene, film at negative z"},
        {"layout", layoutName(a.lens.layout)},
        {"format", a.lens.format},
        {"wavelength_nm", a.lens.wavelength},
        {"primary_wavelength_nm", a.lens.primaryWavelength},
        {"dispersive", a.lens.isDispersive()},
        {"efl", fo.efl},
        {"efl_front", fo.eflFront},
        {"back_focal_distance", fo.backFocalDistance},
        {"front_focal_distance", fo.frontFocalDistance},
        {"F", {{"z", fo.zF}}},
        {"F_prime", {{"z", fo.zFPrime}}},
        {"P", {{"z", fo.zP}}},
        {"P_prime", {{"z", fo.zPPrime}}},
        {"stop", {{"z", a.lens.stop().z}, {"diameter", a.stopDiameter}, {"max_diameter", a.aperture.stopDiameterMax}, {"surface", a.lens.stopIndex}}},
        {"entrance_pupil", {{"z", a.pupils.entrance.z}, {"diameter", a.pupils.entrance.diameter}}},
        {"exit_pupil", {{"z", a.pupils.exit.z}, {"diameter", a.pupils.exit.diameter}}},
        {"fstop", a.fstop},
        {"fstop_min", a.aperture.fstopMin},
        {"fstop_max", a.aperture.fstopMax},
        {"full_stops", fullStops(a.aperture.fstopMin)},
        {"aperture_diameter", a.stopDiameter},
        {"focus",
         {{"infinity", a.focus.infinity},
          {"distance", a.focus.infinity ? json(nullptr) : json(a.focus.objectZ - a.lens.frontZ())},
          {"object_z", finiteOrNull(a.focus.objectZ)},
          {"image_z", a.focus.imageZExact},
          {"image_z_thick", a.focus.imageZThick},
          {"image_z_difference", a.focus.difference}}},
        {"field_of_view",
         {{"largest_field_deg", a.field.largestDegrees ? json(*a.field.largestDegrees) : json(nullptr)},
          {"source", a.field.source}}},
        {"chromatic",
         {{"efl_F", c.eflF},
          {"efl_d", c.eflD},
          {"efl_C", c.eflC},
          {"image_z_F", c.imageZF},
          {"image_z_d", c.imageZD},
          {"image_z_C", c.imageZC},
          {"longitudinal_colour_mm", c.longitudinalColour},
          {"lateral_colour_mm", c.lateral ? json(c.lateral->mm) : json(nullptr)},
          {"lateral_colour_field_deg", c.lateral ? json(c.lateral->fieldDegrees) : json(nullptr)},
          {"lateral_colour_image_height", c.lateral ? json(c.lateral->imageHeight) : json(nullptr)}}},
        {"surfaces", surfaces},
    };
}

}  // namespace lenslab
