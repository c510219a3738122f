// A parallel loop over independent work items (images to undistort, to sample colours from...).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Runs task(i) for every i in [0, count) on min(num_threads, count) threads (at least one), items
// handed out in increasing order. Progress is reported as "stage", done, count after each item
// (calls are serialized). When a task throws, the workers stop taking new items and the first
// exception (in item order among those thrown) is rethrown once all of them have returned, so a
// bad input gives the same error whatever the thread count.
void ParallelFor(size_t count, int num_threads, const std::function<void(size_t)>& task,
                 const ProgressCallback& progress = {}, const std::string& stage = "");

// A thread-count option's value: `requested` when it is positive, every core (at least one) when
// it is 0, the default of the options whose results do not depend on the count.
int ResolveThreadCount(int requested);

}  // namespace sfm_pruning
