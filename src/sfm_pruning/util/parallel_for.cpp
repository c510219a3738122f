#include "sfm_pruning/util/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace sfm_pruning {

void ParallelFor(size_t count, int num_threads, const std::function<void(size_t)>& task,
                 const ProgressCallback& progress, const std::string& stage) {
  if (count == 0) return;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards done, first_error, first_error_item and the progress callback
  size_t done = 0;
  std::exception_ptr first_error;
  size_t first_error_item = count;
  ReportProgress(progress, stage, 0, count);

  const auto worker = [&]() {
    while (!failed.load()) {
      const size_t item = next.fetch_add(1);
      if (item >= count) return;
      try {
        task(item);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (item < first_error_item) {
          first_error_item = item;
          first_error = std::current_exception();
        }
        failed.store(true);
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      ReportProgress(progress, stage, ++done, count);
    }
  };

  const size_t num_workers = std::clamp<size_t>(static_cast<size_t>(std::max(num_threads, 1)), 1, count);
  std::vector<std::thread> workers;
  for (size_t t = 1; t < num_workers; ++t) workers.emplace_back(worker);
  worker();
  for (std::thread& thread : workers) thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

int ResolveThreadCount(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace sfm_pruning
