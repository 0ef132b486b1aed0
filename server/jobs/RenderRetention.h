#pragma once
// Collects finished renders by the retention policy: first those finished longer ago than the
// age limit, then the oldest past the count limit, then the oldest until their files fit the size
// limit. Runs at start and after every job (a render ended, a waiting one cancelled), so the data
// folder and the job list stop growing with the number of renders. Each limit is one query that
// returns only the jobs past it: a pass reads none of the jobs it keeps, nor measures their files.
#include "jobs/JobQueue.h"
#include "jobs/JobStore.h"
#include "core/ServiceConfig.h"

namespace lenslab {

// Deletes what the policy no longer keeps (files and rows); returns how many renders went.
int collectRenders(JobQueue& jobs, const JobStore& store, const RetentionPolicy& policy, double now);

}  // namespace lenslab
