#include "ZmqContext.hpp"

#include "common/Allocator.hpp"

namespace fsi::proto {

namespace {

// One I/O thread moves about a gigabyte per second, far more than one coupled step needs.
constexpr int io_threads = 1;

// Every step, each array frame (2.4 MB at 10^5 points) is allocated by the sender and by
// ZeroMQ on the receiving side, and freed once used: the allocator must keep such blocks
// (common::keep_freed_memory; the executables call it first thing, this covers tests and benches).
zmq::context_t *make_context() {
  common::keep_freed_memory();
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
