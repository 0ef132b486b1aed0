#include "jobs/RenderRequest.h"

#include <cmath>
#include <limits>
#include <variant>

#include "core/HttpError.h"
#include "core/Identifiers.h"
#include "cameras/GhostSelection.h"
#include "cameras/LensModeMap.h"
#include "film/SensorSpec.h"

namespace lenslab {

namespace {

using nlohmann::json;

std::string fieldText(const json& body, const char* field, const std::string& fallback) {
    if (!body.contains(field)) return fallback;
    const json& v = body.at(field);
    if (!v.is_string()) throw HttpError(400, std::string(field) + " must be a string");
    return v.get<std::string>();
}

std::optional<double> fieldNumber(const json& body, const char* field, double min, double max) {
    if (!body.contains(field) || body.at(field).is_null()) return std::nullopt;
    const json& v = body.at(field);
    if (!v.is_number()) throw HttpError(400, std::string(field) + " must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < min || x > max)
        throw HttpError(400, std::string(field) + " must lie between " + json(min).dump() + " and " + json(max).dump() +
                                 ", got " + v.dump());
    return x;
}

// [x, y], each within +-limit.
std::optional<std::array<double, 2>> fieldPair(const json& body, const char* field, double limit) {
    if (!body.contains(field) || body.at(field).is_null()) return std::nullopt;
    const json& v = body.at(field);
    const auto within = [&](const json& x) { return x.is_number() && std::fabs(x.get<double>()) <= limit; };
    if (!v.is_array() || v.size() != 2 || !within(v[0]) || !within(v[1]))
        throw HttpError(400, std::string(field) + " must be two numbers [x, y], each within +-" + json(limit).dump() + ", got " +
                                 v.dump().substr(0, 80));
    return std::array<double, 2>{v[0].get<double>(), v[1].get<double>()};
}

int fieldInteger(const json& body, const char* field, int fallback, int min, int max, const std::string& limitName) {
    if (!body.contains(field)) return fallback;
    const json& v = body.at(field);
    if (!v.is_number() || std::floor(v.get<double>()) != v.get<double>())
        throw HttpError(400, std::string(field) + " must be a whole number");
    const double x = v.get<double>();
    if (x < min || x > max)
        throw HttpError(400, std::string(field) + " must lie between " + std::to_string(min) + " and " + std::to_string(max) +
                                 " (" + limitName + "), got " + v.dump());
    return static_cast<int>(x);
}

std::string identifierField(const json& body, const char* field, const std::string& fallback) {
    const std::string id = fieldText(body, field, fallback);
    if (!isSafeIdentifier(id)) throw HttpError(400, std::string(field) + " '" + id.substr(0, 80) + "' is not a valid id");
    return id;
}

// An object of numbers (and cfa's word), each key checked as the renderer will take it.
std::optional<SensorPairs> sensorField(const json& body) {
    if (!body.contains("sensor") || body.at("sensor").is_null()) return std::nullopt;
    const json& v = body.at("sensor");
    if (!v.is_object()) throw HttpError(400, "sensor must be an object of numbers, as {\"iso\": 800, \"cfa\": \"rggb\"}");
    SensorPairs pairs;
    for (const auto& item : v.items()) {
        if (item.value().is_number()) pairs.emplace_back(item.key(), item.value().get<double>());
        else if (item.value().is_string()) pairs.emplace_back(item.key(), item.value().get<std::string>());
        else throw HttpError(400, "sensor: " + item.key().substr(0, 40) + " must be a number (cfa: a pattern's name)");
    }
    try {
        sensorSpecFromPairs(pairs);
    } catch (const SensorSpecError& e) {
        throw HttpError(400, e.what());
    }
    return pairs;
}

json sensorJson(const std::optional<SensorPairs>& sensor) {
    if (!sensor) return nullptr;
    json object = json::object();
    for (const auto& [key, value] : *sensor) object[key] = std::visit([](const auto& v) { return json(v); }, value);
    return object;
}

}  // namespace

RenderRequest parseRenderRequest(const json& body, const RenderLimits& limits, const std::string& defaultScene) {
    if (!body.is_object()) throw HttpError(400, "the render request must be a JSON object");
    static const char* kFields[] = {"scene", "lens", "fstop", "focaldistance", "filmdiagonal",
                                    "mode", "spectral", "spp", "width", "height", "ghosts", "ghost_model",
                                    "tilt", "swing", "shift", "sensor"};
    for (const auto& item : body.items()) {
        bool known = false;
        for (const char* f : kFields) known = known || item.key() == f;
        if (!known) throw HttpError(400, "unknown field '" + item.key().substr(0, 40) + "' in the render request");
    }
    RenderRequest r;
    if (!body.contains("scene") && defaultScene.empty()) throw HttpError(400, "scene is required (see GET /api/scenes)");
    r.scene = identifierField(body, "scene", defaultScene);
    r.lens = identifierField(body, "lens", r.lens);
    constexpr double kAny = std::numeric_limits<double>::max();  // lens settings' ranges are optics' to check
    r.fstop = fieldNumber(body, "fstop", -kAny, kAny);
    r.focusDistance = fieldNumber(body, "focaldistance", 1, 1e7);
    r.filmDiagonal = fieldNumber(body, "filmdiagonal", 1, 500);
    r.mode = fieldText(body, "mode", r.mode);
    const std::optional<LensMode> mode = parseLensMode(r.mode);
    if (!mode) throw HttpError(400, "mode must be exact|thick|auto, got '" + r.mode.substr(0, 40) + "'");
    r.mode = lensModeName(*mode);  // round one's accurate/approximate, stored under today's names
    if (body.contains("spectral") && !body["spectral"].is_null()) {
        if (!body["spectral"].is_boolean()) throw HttpError(400, "spectral must be true, false or null");
        r.spectral = body["spectral"].get<bool>();
    }
    // ghosts: a name, or the number of the brightest ghosts as a number or its text.
    if (body.contains("ghosts") && !body["ghosts"].is_null()) {
        r.ghosts = body["ghosts"].is_number_integer() ? std::to_string(body["ghosts"].get<long long>()) : fieldText(body, "ghosts", "");
        if (!parseGhostSelection(*r.ghosts)) throw HttpError(400, badGhostsMessage(*r.ghosts));
    }
    if (body.contains("ghost_model") && !body["ghost_model"].is_null()) {
        r.ghostModel = fieldText(body, "ghost_model", "");
        if (!parseGhostModel(*r.ghostModel)) throw HttpError(400, badGhostModelMessage(*r.ghostModel));
    }
    r.tilt = fieldNumber(body, "tilt", -45, 45);
    r.swing = fieldNumber(body, "swing", -45, 45);
    r.shift = fieldPair(body, "shift", 100);
    r.sensor = sensorField(body);
    r.spp = fieldInteger(body, "spp", r.spp, 1, limits.maxSpp, "the service's spp limit");
    r.width = fieldInteger(body, "width", r.width, 8, limits.maxWidth, "the service's width limit");
    r.height = fieldInteger(body, "height", r.height, 8, limits.maxHeight, "the service's height limit");
    return r;
}

LensSettings lensSettings(const RenderRequest& r) {
    LensSettings s;
    if (r.fstop) s.fstop = Setting{*r.fstop, "field fstop"};
    if (r.focusDistance) s.focusDistance = Setting{*r.focusDistance, "field focaldistance"};
    return s;
}

nlohmann::json renderRequestJson(const RenderRequest& r) {
    auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
    return {{"scene", r.scene},
            {"lens", r.lens},
            {"fstop", optional(r.fstop)},
            {"focaldistance", optional(r.focusDistance)},
            {"filmdiagonal", optional(r.filmDiagonal)},
            {"mode", r.mode},
            {"spectral", r.spectral ? json(*r.spectral) : json(nullptr)},
            {"ghosts", r.ghosts ? json(*r.ghosts) : json(nullptr)},
            {"ghost_model", r.ghostModel ? json(*r.ghostModel) : json(nullptr)},
            {"tilt", optional(r.tilt)},
            {"swing", optional(r.swing)},
            {"shift", r.shift ? json(*r.shift) : json(nullptr)},
            {"sensor", sensorJson(r.sensor)},
            {"spp", r.spp},
            {"width", r.width},
            {"height", r.height}};
}

}  // namespace lenslab
