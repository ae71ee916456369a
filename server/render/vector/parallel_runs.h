#pragma once
// A drawing's work split into runs over the cores (parallel/parallel_tasks.h):
// the runs are fixed by the count alone, so the result is the same however
// many cores take part.
#include <algorithm>
#include <cstddef>

#include "parallel/parallel_tasks.h"

namespace toond::render::vector {

// Calls work(run, first, end) for runs of `run_length` over [0, count).
template <class Work>
void for_each_run(std::size_t count, std::size_t run_length, Work&& work) {
  const std::size_t runs = (count + run_length - 1) / run_length;
  parallel::run_tasks(static_cast<int>(runs), parallel::hardware_threads(), [&](int run) {
    const std::size_t first = static_cast<std::size_t>(run) * run_length;
    work(static_cast<std::size_t>(run), first, std::min(count, first + run_length));
  });
}

}  // namespace toond::render::vector
