#include "TransportFixture.hpp"

#include <stdexcept>

#include <unistd.h>

namespace fsi::proto::test {

namespace {

std::filesystem::path make_temp_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "fsi-proto-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error("cannot create a temporary folder from " + pattern);
  }
  return pattern;
}

} // namespace

void TransportFixture::SetUp() { coupler_ = std::make_unique<CouplerChannel>(fresh_endpoint()); }

void TransportFixture::TearDown() {
  coupler_.reset();
  if (!temp_dir_.empty()) {
    std::filesystem::remove_all(temp_dir_);
  }
}

Endpoint TransportFixture::fresh_endpoint() {
  static int n_endpoints = 0;
  ++n_endpoints;
  switch (GetParam()) {
  case Endpoint::Transport::tcp:
    return Endpoint::parse("tcp://127.0.0.1:0");
  case Endpoint::Transport::ipc:
    temp_dir_ = make_temp_dir();
    return Endpoint::parse("ipc://" + (temp_dir_ / "coupler.sock").string());
  case Endpoint::Transport::inproc:
    break;
  }
  return Endpoint::parse("inproc://coupler-" + std::to_string(getpid()) + "-" +
                         std::to_string(n_endpoints));
}

ParticipantChannel TransportFixture::make_participant(Role role, const std::string &name) {
  return ParticipantChannel(coupler_->endpoint(), role, name);
}

Incoming TransportFixture::receive_at_coupler() {
  auto incoming = coupler_->receive(patience);
  if (!incoming) {
    throw std::runtime_error("no message reached the coupler within 5 s");
  }
  return std::move(*incoming);
}

Message TransportFixture::receive_at(ParticipantChannel &participant) {
  auto envelope = participant.receive(patience);
  if (!envelope) {
    throw std::runtime_error("no message reached " + participant.routing_id() + " within 5 s");
  }
  return std::move(*envelope);
}

std::string transport_name(const ::testing::TestParamInfo<Endpoint::Transport> &info) {
  switch (info.param) {
  case Endpoint::Transport::tcp:
    return "tcp";
  case Endpoint::Transport::ipc:
    return "ipc";
  case Endpoint::Transport::inproc:
    return "inproc";
  }
  return "unknown";
}

} // namespace fsi::proto::test
