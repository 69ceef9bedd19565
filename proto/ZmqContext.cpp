#include "ZmqContext.hpp"

namespace fsi::proto {

namespace {

// One I/O thread moves about a gigabyte per second, far more than one coupled step needs.
constexpr int io_threads = 1;

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
  static zmq::context_t *const context = context_slot() = new zmq::context_t(io_threads);
  return *context;
}

void ZmqContext::deliver_pending_and_close() noexcept {
  if (zmq::context_t *context = context_slot())
    context->close(); // zmq_ctx_term: waits for queued messages, up to each socket's linger
}

} // namespace fsi::proto
