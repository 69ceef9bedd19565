#include "Endpoint.hpp"

#include "TransportError.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/un.h>

#include <algorithm>
#include <cctype>

namespace fsi::proto {

namespace {

constexpr std::string_view tcp_prefix = "tcp://";
constexpr std::string_view ipc_prefix = "ipc://";
constexpr std::string_view inproc_prefix = "inproc://";
constexpr std::size_t max_ipc_path_bytes = sizeof(sockaddr_un::sun_path) - 1;

[[noreturn]] void fail(std::string_view text, const std::string &why) {
  throw TransportError("endpoint '" + std::string(text) + "' is not valid: " + why +
                       "; use tcp://HOST:PORT (e.g. tcp://127.0.0.1:5555), ipc:///PATH or "
                       "inproc://NAME");
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

bool is_host_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '-' || c == '_';
}

bool is_ipv4_loopback(const std::string &host) {
  in_addr address{};
  return inet_pton(AF_INET, host.c_str(), &address) == 1 && (ntohl(address.s_addr) >> 24) == 127;
}

bool is_ipv6_loopback(const std::string &host) {
  in6_addr address{};
  if (inet_pton(AF_INET6, host.c_str(), &address) != 1) {
    return false;
  }
  const bool mapped_ipv4_loopback = IN6_IS_ADDR_V4MAPPED(&address) && address.s6_addr[12] == 127;
  return IN6_IS_ADDR_LOOPBACK(&address) || mapped_ipv4_loopback;
}

bool is_localhost(std::string host) {
  std::transform(host.begin(), host.end(), host.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return host == "localhost" || host == "localhost.";
}

} // namespace

Endpoint Endpoint::parse(std::string_view text) {
  if (starts_with(text, tcp_prefix)) {
    return parse_tcp(text, text.substr(tcp_prefix.size()));
  }
  if (starts_with(text, ipc_prefix)) {
    return parse_ipc(text, text.substr(ipc_prefix.size()));
  }
  if (starts_with(text, inproc_prefix)) {
    return parse_inproc(text, text.substr(inproc_prefix.size()));
  }
  fail(text, "it does not start with tcp://, ipc:// or inproc://");
}

Endpoint Endpoint::parse_tcp(std::string_view text, std::string_view rest) {
  const bool bracketed = !rest.empty() && rest.front() == '[';
  const auto host_end = bracketed ? rest.find(']') : rest.rfind(':');
  if (host_end == std::string_view::npos) {
    fail(text, bracketed ? "the IPv6 address has no closing ']'" : "it has no :PORT");
  }
  const auto host = bracketed ? rest.substr(1, host_end - 1) : rest.substr(0, host_end);
  const auto after_host = bracketed ? rest.substr(host_end + 1) : rest.substr(host_end);
  if (after_host.empty() || after_host.front() != ':') {
    fail(text, "it has no :PORT after the host");
  }
  check_host(text, host, bracketed);
  Endpoint endpoint;
  endpoint.transport_ = Transport::tcp;
  endpoint.host_ = std::string(host);
  endpoint.is_ipv6_ = bracketed;
  endpoint.port_ = parse_port(text, after_host.substr(1));
  endpoint.make_text();
  return endpoint;
}

void Endpoint::check_host(std::string_view text, std::string_view host, bool bracketed) {
  if (host.empty()) {
    fail(text, "the host is empty (use 127.0.0.1 for this machine)");
  }
  if (bracketed) {
    in6_addr address{};
    if (inet_pton(AF_INET6, std::string(host).c_str(), &address) != 1) {
      fail(text, "'" + std::string(host) + "' in brackets is not an IPv6 address");
    }
    return;
  }
  if (host.find(':') != std::string_view::npos) {
    fail(text, "the host '" + std::string(host) +
                   "' contains ':' (IPv6 addresses go in brackets, e.g. tcp://[::1]:5555)");
  }
  if (host != "*" && !std::all_of(host.begin(), host.end(), is_host_name_char)) {
    fail(text, "the host '" + std::string(host) + "' is neither an address nor a host name");
  }
}

std::uint16_t Endpoint::parse_port(std::string_view text, std::string_view port) {
  if (port == "*") {
    return 0;
  }
  const bool all_digits =
      !port.empty() && port.size() <= 5 &&
      std::all_of(port.begin(), port.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  const unsigned long value = all_digits ? std::stoul(std::string(port)) : 65536UL;
  if (value > 65535UL) {
    fail(text, "the port '" + std::string(port) + "' is not a number from 0 to 65535");
  }
  return static_cast<std::uint16_t>(value);
}

Endpoint Endpoint::parse_ipc(std::string_view text, std::string_view rest) {
  if (rest.empty()) {
    fail(text, "the ipc path is empty");
  }
  if (rest.size() > max_ipc_path_bytes) {
    fail(text, "the ipc path has " + std::to_string(rest.size()) + " characters, at most " +
                   std::to_string(max_ipc_path_bytes) + " are possible (pick a shorter path)");
  }
  Endpoint endpoint;
  endpoint.transport_ = Transport::ipc;
  endpoint.address_ = std::string(rest);
  endpoint.make_text();
  return endpoint;
}

Endpoint Endpoint::parse_inproc(std::string_view text, std::string_view rest) {
  if (rest.empty()) {
    fail(text, "the inproc name is empty");
  }
  Endpoint endpoint;
  endpoint.transport_ = Transport::inproc;
  endpoint.address_ = std::string(rest);
  endpoint.make_text();
  return endpoint;
}

void Endpoint::make_text() {
  switch (transport_) {
  case Transport::tcp:
    text_ = std::string(tcp_prefix) + (is_ipv6_ ? "[" + host_ + "]" : host_) + ":" +
            std::to_string(port_);
    break;
  case Transport::ipc:
    text_ = std::string(ipc_prefix) + address_;
    break;
  case Transport::inproc:
    text_ = std::string(inproc_prefix) + address_;
    break;
  }
}

Endpoint Endpoint::bind_form() const {
  if (transport_ != Transport::tcp || !is_localhost(host_)) {
    return *this;
  }
  Endpoint resolved = *this;
  resolved.host_ = "127.0.0.1";
  resolved.make_text();
  return resolved;
}

bool Endpoint::is_loopback() const {
  if (transport_ != Transport::tcp) {
    return true;
  }
  return is_ipv6_ ? is_ipv6_loopback(host_) : is_ipv4_loopback(host_) || is_localhost(host_);
}

void Endpoint::check_bindable(bool remote_allowed) const {
  if (remote_allowed || is_loopback()) {
    return;
  }
  throw TransportError(
      "refusing to bind " + text_ +
      ": other machines could connect to it, and without CURVE the coupling is neither authenticated "
      "nor encrypted; set coupling.security: curve (keys from ./fsi keys CASE), or bind a loopback address "
      "(127.0.0.1, [::1] or localhost), ipc:// or inproc://, or, on a network you trust entirely, set "
      "coupling.insecure_remote: true");
}

void Endpoint::check_connectable() const {
  if (transport_ != Transport::tcp) {
    return;
  }
  if (port_ == 0) {
    throw TransportError("cannot connect to " + text_ +
                         ": port 0 means 'any free port' and is for binding only; connect to "
                         "the port the coupler reports");
  }
  if (host_ == "*") {
    throw TransportError("cannot connect to " + text_ +
                         ": host * means 'all interfaces' and is for binding only; connect to "
                         "the coupler's address, e.g. 127.0.0.1");
  }
}

} // namespace fsi::proto
