#pragma once
// Where the coupler listens and participants connect: "tcp://HOST:PORT", "ipc:///PATH" or
// "inproc://NAME". Parsed and checked once, before any socket sees it, so that a typo in a case
// file is reported with the allowed forms instead of a ZeroMQ errno.

#include <cstdint>
#include <string>
#include <string_view>

namespace fsi::proto {

class Endpoint {
public:
  enum class Transport { tcp, ipc, inproc };

  /// Parses an endpoint; throws TransportError naming the text and the allowed forms.
  /// tcp hosts: IPv4 address, [IPv6 address], host name or * (all interfaces, bind only);
  /// port 0 or * asks the system for a free port (bind only).
  static Endpoint parse(std::string_view text);

  Transport transport() const { return transport_; }
  /// tcp: the host without brackets ("127.0.0.1", "::1", "localhost", "*"); empty otherwise.
  const std::string &host() const { return host_; }
  /// tcp: the port, 0 for "any free port"; 0 otherwise.
  std::uint16_t port() const { return port_; }
  /// ipc: the socket path; inproc: the name; empty for tcp.
  const std::string &address() const { return address_; }
  /// The canonical text handed to ZeroMQ.
  const std::string &str() const { return text_; }

  bool is_ipv6() const { return is_ipv6_; }
  /// The endpoint as ZeroMQ can bind it: ZeroMQ binds addresses and interface names but does
  /// not resolve host names, so localhost becomes 127.0.0.1.
  Endpoint bind_form() const;
  /// True when only this machine can reach it: ipc, inproc, or tcp on 127.0.0.0/8, ::1 or
  /// localhost. Host names other than localhost count as remote (they are not resolved).
  bool is_loopback() const;

  /// Throws TransportError unless the coupler may bind here: a tcp endpoint that is not
  /// loopback lets other machines in, so it needs CURVE or an explicit insecure_remote.
  void check_bindable(bool remote_allowed) const;
  /// Throws TransportError for what can only be bound: tcp port 0 or host *.
  void check_connectable() const;

private:
  static Endpoint parse_tcp(std::string_view text, std::string_view rest);
  static Endpoint parse_ipc(std::string_view text, std::string_view rest);
  static Endpoint parse_inproc(std::string_view text, std::string_view rest);
  static std::uint16_t parse_port(std::string_view text, std::string_view port);
  static void check_host(std::string_view text, std::string_view host, bool bracketed);
  void make_text();

  Transport transport_ = Transport::tcp;
  std::string host_;
  std::uint16_t port_ = 0;
  std::string address_;
  bool is_ipv6_ = false;
  std::string text_;
};

} // namespace fsi::proto
