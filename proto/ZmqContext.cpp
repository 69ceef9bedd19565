#include "ZmqContext.hpp"

namespace fsi::proto {

namespace {

// One I/O thread moves about a gigabyte per second, far more than one coupled step needs.
constexpr int io_threads = 1;

} // namespace

zmq::context_t &ZmqContext::shared() {
  // Deliberately never destroyed: zmq_ctx_term() at static destruction blocks until every
  // socket is closed, so a process that calls std::exit() while a channel is alive (an error
  // path) would hang instead of exiting. The operating system reclaims it at exit.
  static zmq::context_t *const context = new zmq::context_t(io_threads);
  return *context;
}

} // namespace fsi::proto
