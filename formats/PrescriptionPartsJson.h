#pragma once
// The parts of a prescription beyond its radii, gaps and glasses as JSON, written alike in the lens
// JSON (LensJson.h) and the editor's rows (PrescriptionJson.h), and read back from the editor's:
//   aperture: {"shape": "circular"|"rectangular"|"elliptical", "half_width_x", "half_width_y",
//              "centre_x", "centre_y"} (mm)
//   frame:    {"decentre": [x, y, z] (mm), "tilt_degrees": [about x, y, z], "mode": "basic"|
//              "decentre and return"|"bend"|"reverse", "order": "decentre then tilt"|"tilt then decentre"}
//   form:     "kind": "even asphere"|"odd asphere"|"toroidal"|"Qbfs"|"Qcon", "form_terms": [the terms
//              used, prescription/SurfaceForm.h], "normalisation_radius" (mm), keys of the surface's own
//   fields:   {"type": "object angle"|"object height"|"paraxial image height"|"real image height",
//              "points": [{"x", "y", "weight"}]}
// Every reader refuses, as LensTableError naming the row, a missing or mistyped value, a name it
// does not know and a non-finite number.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

nlohmann::json apertureJson(const SurfaceAperture& aperture);
nlohmann::json frameJson(const FrameChange& frame);
nlohmann::json designFieldsJson(const DesignFields& fields);
void addSurfaceFormJson(nlohmann::json& surface, const SurfaceForm& form);

// One JSON object's fields, read for the lens `file`'s row `line` (0: the lens as a whole); `path`
// ("clear_aperture.") prefixes the field names in messages.
class JsonFields {
public:
    JsonFields(const nlohmann::json& object, const std::string& file, int line, std::string path = "");

    [[noreturn]] void fail(const std::string& problem) const;
    bool has(const char* field) const;  // present and not null
    double number(const char* field, double fallback) const;
    std::optional<double> optionalNumber(const char* field) const;  // absent or null: none
    bool flag(const char* field) const;                             // absent: false
    std::string text(const char* field) const;                      // absent or null: ""
    std::vector<double> numbers(const char* field, std::size_t most) const;  // absent: none
    std::vector<std::string> texts(const char* field, std::size_t most) const;
    JsonFields object(const char* field) const;  // a field that must be an object
    std::vector<JsonFields> objects(const char* field, std::size_t most) const;

private:
    // The list `field` holds, of at most `most` entries (`what`: "numbers").
    const nlohmann::json& listOf(const char* field, std::size_t most, const char* what) const;
    const nlohmann::json& object_;
    std::string file_;
    int line_;
    std::string path_;
};

SurfaceAperture apertureFromJson(const JsonFields& in);
FrameChange frameFromJson(const JsonFields& in);
DesignFields designFieldsFromJson(const JsonFields& in);
SurfaceForm surfaceFormFromJson(const JsonFields& surface);  // "kind" absent: an even asphere

}  // namespace lenslab
