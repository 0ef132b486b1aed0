#pragma once
// Reading query parameters with their ranges checked; HttpError 400 naming the parameter.
#include <httplib.h>

#include <optional>
#include <string>

#include "settings/LensSettings.h"

namespace lenslab {

std::optional<double> queryNumber(const httplib::Request& req, const std::string& name, double min, double max);
// Millimetres, or "inf"/"infinity" (returned as infinity); nullopt when absent.
std::optional<double> queryDistance(const httplib::Request& req, const std::string& name, double min, double max);
std::optional<std::string> queryText(const httplib::Request& req, const std::string& name);

// fstop and focus (mm, or inf) as lens settings named by their parameter; their ranges are checked by
// analyzeLens against the lens.
LensSettings queryLensSettings(const httplib::Request& req);

}  // namespace lenslab
