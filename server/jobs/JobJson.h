#pragma once
// A render job as GET /api/renders/{id} shows it: state, request, progress (tiles, elapsed, ETA),
// finished tiles after `tilesSince`, links to the images once done.
#include <nlohmann/json.hpp>

#include "jobs/JobQueue.h"

namespace lenslab {

nlohmann::json jobJson(const JobView& job, std::size_t tilesSince, double now);

}  // namespace lenslab
