#include "LensJson.h"

#include <cmath>

#include "FiniteOrNull.h"
#include "PrescriptionPartsJson.h"
#include "trace/ThinFilm.h"

namespace lenslab {

namespace {

// The fields added for decentred, tilted, shaped and non-even surfaces: present only where they apply.
void addSurfaceShape(nlohmann::json& surface, const Surface& s) {
    if (!s.name.empty()) surface["name"] = s.name;
    if (s.automaticAperture) surface["automatic_aperture"] = true;
    if (!s.form.isEvenAsphere()) addSurfaceFormJson(surface, s.form);
    if (s.clearShape) surface["clear_aperture"] = apertureJson(*s.clearShape);
    if (s.obscurationShape) surface["obscuration"] = apertureJson(*s.obscurationShape);
    if (s.frame) surface["frame"] = frameJson(*s.frame);
}

nlohmann::json surfacesJson(const LensSystem& lens) {
    using nlohmann::json;
    json surfaces = json::array();
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const Surface& s = lens.surfaces[i];
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
                        {"mirror", s.mirror},
                        {"coating", s.coating.text},
                        {"coating_default", s.coating.isDefault},
                        {"reflectance", surfaceResponse(lens, int(i), true, 1, lens.wavelength).reflectance}};
        if (s.obscurationRadius > 0) surface["obscuration_diameter"] = 2 * s.obscurationRadius;
        addSurfaceShape(surface, s);
        surfaces.push_back(surface);
    }
    return surfaces;
}

// What every lens reports, afocal or not: the prescription and the file's own figures.
nlohmann::json lensDescriptionJson(const LensSystem& lens) {
    using nlohmann::json;
    return {{"name", lens.name},
            {"units", "mm"},
            {"convention", "origin at the front vertex, +z toward the scene, film at negative z"},
            {"layout", layoutName(lens.layout)},
            {"format", lens.format},
            {"wavelength_nm", lens.wavelength},
            {"primary_wavelength_nm", lens.primaryWavelength},
            {"dispersive", lens.isDispersive()},
            {"surfaces", surfacesJson(lens)},
            {"warnings", warningsJson(lens.warnings)},
            {"rotationally_symmetric", lens.isRotationallySymmetric()},
            {"design",
             {{"wavelengths_nm", lens.wavelengths},
              {"wavelength_weights", lens.wavelengthWeights},
              {"fields", designFieldsJson(lens.fields)},
              {"object_distance", finiteOrNull(lens.objectDistance)},
              {"entrance_pupil_diameter", lens.entrancePupilDiameter ? json(*lens.entrancePupilDiameter) : json(nullptr)},
              {"f_number", lens.designFNumber ? json(*lens.designFNumber) : json(nullptr)},
              {"object_numerical_aperture",
               lens.objectNumericalAperture ? json(*lens.objectNumericalAperture) : json(nullptr)}}}};
}

}  // namespace

nlohmann::json warningsJson(const std::vector<LensWarning>& warnings) {
    nlohmann::json list = nlohmann::json::array();
    for (const LensWarning& w : warnings) list.push_back({{"line", w.line}, {"message", w.message}});
    return list;
}

nlohmann::json lensAnalysisJson(const LensAnalysis& a) {
    using nlohmann::json;
    json out = lensDescriptionJson(a.lens);
    out["afocal"] = a.afocal;
    if (a.afocal) {
        // Parallel rays leave parallel: no focal points, pupils or focus to report.
        for (const char* key : {"efl", "efl_front", "back_focal_distance", "front_focal_distance", "fstop"}) out[key] = nullptr;
        return out;
    }
    const FirstOrder& fo = a.firstOrder;
    out.update(json{
        {"efl", fo.efl},
        {"efl_front", fo.eflFront},
        {"back_focal_distance", fo.backFocalDistance},
        {"front_focal_distance", fo.frontFocalDistance},
        {"F", {{"z", fo.zF}}},
        {"F_prime", {{"z", fo.zFPrime}}},
        {"P", {{"z", fo.zP}}},
        {"P_prime", {{"z", fo.zPPrime}}},
    });
    if (!a.incomplete.empty()) {
        // First order only: the focal lengths at F, d and C, and why there is no aperture or focus.
        out["incomplete"] = a.incomplete;
        out["fstop"] = nullptr;
        out["chromatic"] = {{"efl_F", computeFirstOrder(atWavelength(a.lens, kWavelengthF)).efl},
                            {"efl_d", computeFirstOrder(atWavelength(a.lens, kWavelengthD)).efl},
                            {"efl_C", computeFirstOrder(atWavelength(a.lens, kWavelengthC)).efl}};
        return out;
    }
    const Chromatic& c = a.chromatic;
    out.update(json{
        {"stop", {{"z", a.lens.stop().z}, {"diameter", a.stopDiameter}, {"max_diameter", a.aperture.stopDiameterMax}, {"surface", a.lens.stopIndex}}},
        {"entrance_pupil", {{"z", a.pupils.entrance.z}, {"diameter", a.pupils.entrance.diameter}}},
        {"exit_pupil", {{"z", a.pupils.exit.z}, {"diameter", a.pupils.exit.diameter}}},
        {"fstop", a.fstop},
        {"fstop_min", a.aperture.fstopMin},
        {"fstop_max", a.aperture.fstopMaxOffered},
        {"full_stops", fullStops(a.aperture.fstopMin, a.aperture.fstopMaxOffered)},
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
    });
    return out;
}

}  // namespace lenslab
