#include "ZmqContext.hpp"

#include <malloc.h>

namespace fsi::proto {

namespace {

// One I/O thread moves about a gigabyte per second, far more than one coupled step needs.
constexpr int io_threads = 1;

// Every step, each array frame (2.4 MB at 10^5 points) is allocated by the sender and by
// ZeroMQ on the receiving side, and freed once used. glibc's defaults hand such blocks back to
// the kernel (mmap/munmap, or trimming the heap) and page-fault them in again the next step:
// at 10^5 points that made a coupled step 44 ms instead of 7 (./fsi bench coupling). Both
// settings are needed: either one alone turns glibc's adaptive thresholds off and is worse.
constexpr int mmap_threshold_bytes = 32 << 20; // glibc's largest on 64-bit; bigger arrays are mmapped
constexpr int trim_threshold_bytes = 256 << 20;

zmq::context_t *make_context() {
  mallopt(M_MMAP_THRESHOLD, mmap_threshold_bytes);
  mallopt(M_TRIM_THRESHOLD, trim_threshold_bytes);
  return new zmq::context_t(io_threads);
}

} // namespace

namespace {
zmq::context_t *&context_slot() {
  static zmq::context_t *context = nullptr;
  return context;
}
} // namespace

zmq::context_t &ZmqContext::shared() {
  // Deliberately never destroyed at static destruction: zmq_ctx_term() blocks until every
  // socket is closed, so a process that calls std::exit() while a channel is alive (an error
  // path) would hang instead of exiting. Executables end it explicitly with
  // deliver_pending_and_close(); otherwise the operating system reclaims it at exit.
  static zmq::context_t *const context = context_slot() = make_context();
  return *context;
}

void ZmqContext::deliver_pending_and_close() noexcept {
  if (zmq::context_t *context = context_slot())
    context->close(); // zmq_ctx_term: waits for queued messages, up to each socket's linger
}

} // namespace fsi::proto
