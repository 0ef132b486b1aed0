#include "core/QueryParameters.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/HttpError.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

std::string shown(const std::string& value) { return "'" + value.substr(0, 40) + "'"; }

}  // namespace

std::optional<std::string> queryText(const httplib::Request& req, const std::string& name) {
    if (!req.has_param(name.c_str())) return std::nullopt;
    return req.get_param_value(name.c_str());
}

std::optional<double> queryNumber(const httplib::Request& req, const std::string& name, double min, double max) {
    const auto text = queryText(req, name);
    if (!text) return std::nullopt;
    // Plain decimal only: strtod would also take hexadecimal ("0x10"), and stop at a NUL ("4%00").
    const bool decimal = text->find_first_not_of("0123456789+-.eE") == std::string::npos;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(text->c_str(), &end);
    if (text->empty() || !decimal || end != text->c_str() + text->size() || errno == ERANGE || !std::isfinite(x))
        throw HttpError(400, name + " must be a number, got " + shown(*text));
    if (x < min || x > max)
        throw HttpError(400, name + " must lie between " + formatNumber(min) + " and " + formatNumber(max) + ", got " +
                                 shown(*text));
    return x;
}

LensSettings queryLensSettings(const httplib::Request& req) {
    constexpr double kAny = std::numeric_limits<double>::max();  // the range is optics' to check
    LensSettings s;
    if (const auto fstop = queryNumber(req, "fstop", -kAny, kAny)) s.fstop = Setting{*fstop, "query parameter fstop"};
    if (const auto focus = queryDistance(req, "focus", -kAny, kAny)) s.focusDistance = Setting{*focus, "query parameter focus"};
    if (const auto nm = queryNumber(req, "wavelength", -kAny, kAny)) s.wavelength = Setting{*nm, "query parameter wavelength"};
    return s;
}

std::optional<double> queryDistance(const httplib::Request& req, const std::string& name, double min, double max) {
    const auto text = queryText(req, name);
    if (text && (*text == "inf" || *text == "infinity")) return std::numeric_limits<double>::infinity();
    return queryNumber(req, name, min, max);
}

}  // namespace lenslab
