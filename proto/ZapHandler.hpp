#pragma once
// The coupler's ZeroMQ authentication handler (ZAP, ZeroMQ RFC 27): a thread answering, for the
// process's CURVE server sockets, whether a connecting client's public key is one of the
// admitted participants', and naming it (the User-Id every message of that connection then
// carries). Without a handler libzmq lets every CURVE client in, so the coupler's channel also
// drops every message that arrives without a User-Id (fail closed): a dead handler locks
// everyone out instead of letting everyone in. One per process (ZAP's endpoint is fixed).

#include <atomic>
#include <map>
#include <string>
#include <thread>

namespace fsi::proto {

class ZapHandler {
public:
  /// admitted: participant name -> public key (Z85). Starts answering before it returns;
  /// throws TransportError if another handler already serves this process.
  explicit ZapHandler(const std::map<std::string, std::string> &admitted);
  ~ZapHandler();
  ZapHandler(const ZapHandler &) = delete;
  ZapHandler &operator=(const ZapHandler &) = delete;

  /// Connections refused so far (unknown key or another mechanism).
  long refused() const { return refused_.load(); }

private:
  void serve(void *socket);

  std::map<std::string, std::string> name_of_key_; ///< public key (Z85) -> name
  std::atomic<bool> stop_{false};
  std::atomic<long> refused_{0};
  std::thread thread_;
};

} // namespace fsi::proto
