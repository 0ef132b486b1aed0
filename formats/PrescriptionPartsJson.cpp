#include "PrescriptionPartsJson.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lenslab {

using nlohmann::json;

namespace {

const char* frameModeName(FrameMode mode) {
    switch (mode) {
        case FrameMode::Basic: return "basic";
        case FrameMode::DecentreAndReturn: return "decentre and return";
        case FrameMode::Bend: return "bend";
        case FrameMode::Reverse: return "reverse";
    }
    return "basic";
}

const char* tiltOrderName(TiltOrder order) {
    return order == TiltOrder::DecentreThenTilt ? "decentre then tilt" : "tilt then decentre";
}

// The value of an enumeration whose name is `field`'s text, the names listed in the message otherwise.
template <class E, std::size_t N>
E namedValue(const JsonFields& in, const char* field, const std::array<E, N>& values, const char* (*name)(E)) {
    const std::string text = in.text(field);
    std::string known;
    for (const E value : values) {
        if (text == name(value)) return value;
        known += std::string(known.empty() ? "" : ", ") + "\"" + name(value) + "\"";
    }
    in.fail(std::string(field) + " must be one of " + known);
}

std::array<double, 3> threeNumbers(const JsonFields& in, const char* field) {
    const std::vector<double> v = in.numbers(field, 3);
    if (v.size() != 3) in.fail(std::string(field) + " must be a list of 3 numbers (x, y, z)");
    return {v[0], v[1], v[2]};
}

}  // namespace

json apertureJson(const SurfaceAperture& a) {
    return {{"shape", apertureKindName(a.kind)}, {"half_width_x", a.halfWidthX}, {"half_width_y", a.halfWidthY},
            {"centre_x", a.centreX}, {"centre_y", a.centreY}};
}

json frameJson(const FrameChange& f) {
    return {{"decentre", f.decentre}, {"tilt_degrees", f.tiltDegrees}, {"mode", frameModeName(f.mode)},
            {"order", tiltOrderName(f.order)}};
}

json designFieldsJson(const DesignFields& fields) {
    json points = json::array();
    for (const FieldPoint& p : fields.points) points.push_back({{"x", p.x}, {"y", p.y}, {"weight", p.weight}});
    return {{"type", fieldTypeName(fields.type)}, {"points", points}};
}

void addSurfaceFormJson(json& surface, const SurfaceForm& form) {
    surface["kind"] = surfaceKindName(form.kind);
    surface["form_terms"] = std::vector<double>(form.terms.begin(), form.terms.begin() + form.termCount);
    surface["normalisation_radius"] = form.normalisationRadius;
}

JsonFields::JsonFields(const json& object, const std::string& file, int line, std::string path)
    : object_(object), file_(file), line_(line), path_(std::move(path)) {
    if (!object_.is_object())
        throw LensTableError(file_, line_, (path_.empty() ? std::string("a row") : path_.substr(0, path_.size() - 1)) + " must be an object");
}

void JsonFields::fail(const std::string& problem) const { throw LensTableError(file_, line_, path_ + problem); }

bool JsonFields::has(const char* field) const { return object_.contains(field) && !object_.at(field).is_null(); }

double JsonFields::number(const char* field, double fallback) const {
    if (!has(field)) return fallback;
    const json& v = object_.at(field);
    if (!v.is_number()) fail(std::string(field) + " must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(std::string(field) + " is not a finite number");
    return x;
}

std::optional<double> JsonFields::optionalNumber(const char* field) const {
    if (!has(field)) return std::nullopt;
    return number(field, 0);
}

bool JsonFields::flag(const char* field) const {
    if (!has(field)) return false;
    if (!object_.at(field).is_boolean()) fail(std::string(field) + " must be true or false");
    return object_.at(field).get<bool>();
}

std::string JsonFields::text(const char* field) const {
    if (!has(field)) return "";
    if (!object_.at(field).is_string()) fail(std::string(field) + " must be a string");
    return object_.at(field).get<std::string>();
}

const json& JsonFields::listOf(const char* field, std::size_t most, const char* what) const {
    const json& list = object_.at(field);
    if (!list.is_array() || list.size() > most)
        fail(std::string(field) + " must be a list of at most " + std::to_string(most) + " " + what);
    return list;
}

std::vector<double> JsonFields::numbers(const char* field, std::size_t most) const {
    if (!has(field)) return {};
    const json& list = listOf(field, most, "numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (!list[i].is_number() || !std::isfinite(list[i].get<double>()))
            fail(std::string(field) + " " + std::to_string(i + 1) + " is not a finite number");
        out.push_back(list[i].get<double>());
    }
    return out;
}

std::vector<std::string> JsonFields::texts(const char* field, std::size_t most) const {
    if (!has(field)) return {};
    const json& list = listOf(field, most, "strings");
    std::vector<std::string> out;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (!list[i].is_string()) fail(std::string(field) + " " + std::to_string(i + 1) + " is not a string");
        out.push_back(list[i].get<std::string>());
    }
    return out;
}

JsonFields JsonFields::object(const char* field) const {
    if (!has(field)) fail(std::string(field) + " must be an object");
    return JsonFields(object_.at(field), file_, line_, path_ + field + ".");
}

std::vector<JsonFields> JsonFields::objects(const char* field, std::size_t most) const {
    if (!has(field)) return {};
    const json& list = listOf(field, most, "objects");
    std::vector<JsonFields> out;
    for (std::size_t i = 0; i < list.size(); ++i)
        out.emplace_back(list[i], file_, line_, path_ + field + " " + std::to_string(i + 1) + ".");
    return out;
}

SurfaceAperture apertureFromJson(const JsonFields& in) {
    SurfaceAperture a;
    a.kind = namedValue(in, "shape", std::array{ApertureKind::Circular, ApertureKind::Rectangular, ApertureKind::Elliptical},
                        apertureKindName);
    a.halfWidthX = in.number("half_width_x", 0);
    a.halfWidthY = in.number("half_width_y", 0);
    a.centreX = in.number("centre_x", 0);
    a.centreY = in.number("centre_y", 0);
    if (!(a.halfWidthX > 0) || !(a.halfWidthY > 0)) in.fail("half_width_x and half_width_y must be positive");
    if (a.kind == ApertureKind::Circular && a.halfWidthX != a.halfWidthY)
        in.fail("half_width_x and half_width_y of a circle are its radius, the same");
    return a;
}

FrameChange frameFromJson(const JsonFields& in) {
    FrameChange f;
    f.decentre = threeNumbers(in, "decentre");
    f.tiltDegrees = threeNumbers(in, "tilt_degrees");
    f.mode = namedValue(in, "mode", std::array{FrameMode::Basic, FrameMode::DecentreAndReturn, FrameMode::Bend, FrameMode::Reverse},
                        frameModeName);
    f.order = namedValue(in, "order", std::array{TiltOrder::DecentreThenTilt, TiltOrder::TiltThenDecentre}, tiltOrderName);
    return f;
}

DesignFields designFieldsFromJson(const JsonFields& in) {
    // As many as a Code V file may list (its XAN/YAN, 100 values).
    constexpr std::size_t kMaxFields = 100;
    DesignFields fields;
    fields.type = namedValue(in, "type",
                             std::array{FieldType::ObjectAngle, FieldType::ObjectHeight, FieldType::ParaxialImageHeight,
                                        FieldType::RealImageHeight},
                             fieldTypeName);
    for (const JsonFields& point : in.objects("points", kMaxFields)) {
        FieldPoint p{point.number("x", 0), point.number("y", 0), point.number("weight", 1)};
        if (p.weight < 0) point.fail("weight must not be negative");
        fields.points.push_back(p);
    }
    return fields;
}

SurfaceForm surfaceFormFromJson(const JsonFields& in) {
    SurfaceForm f;
    if (!in.has("kind")) return f;
    f.kind = namedValue(in, "kind",
                        std::array{SurfaceKind::EvenAsphere, SurfaceKind::OddAsphere, SurfaceKind::Toroidal, SurfaceKind::Qbfs,
                                   SurfaceKind::Qcon},
                        surfaceKindName);
    const std::vector<double> terms = in.numbers("form_terms", kFormTerms);
    if (f.isEvenAsphere() && !terms.empty()) in.fail("an even asphere's terms are \"aspheric\", not form_terms");
    std::copy(terms.begin(), terms.end(), f.terms.begin());
    f.termCount = int(terms.size());
    f.normalisationRadius = in.number("normalisation_radius", 0);
    return f;
}

}  // namespace lenslab
