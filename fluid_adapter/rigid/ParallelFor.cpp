#include "fluid_adapter/rigid/ParallelFor.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace fsi::fluid::rigid {

void parallel_for(std::size_t n, std::size_t n_threads,
                  const std::function<void(std::size_t, std::size_t)> &body,
                  std::size_t min_per_thread) {
  if (n_threads == 0)
    n_threads = std::max(1u, std::thread::hardware_concurrency());
  n_threads = std::min(n_threads, std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_per_thread)));
  if (n_threads <= 1) {
    body(0, n);
    return;
  }
  std::vector<std::exception_ptr> errors(n_threads);
  std::vector<std::thread> workers;
  workers.reserve(n_threads - 1);
  const auto run_chunk = [&](std::size_t chunk) {
    try {
      body(n * chunk / n_threads, n * (chunk + 1) / n_threads);
    } catch (...) {
      errors[chunk] = std::current_exception();
    }
  };
  for (std::size_t chunk = 1; chunk < n_threads; ++chunk)
    workers.emplace_back(run_chunk, chunk);
  run_chunk(0);
  for (std::thread &worker : workers)
    worker.join();
  for (const std::exception_ptr &error : errors)
    if (error)
      std::rethrow_exception(error);
}

} // namespace fsi::fluid::rigid
