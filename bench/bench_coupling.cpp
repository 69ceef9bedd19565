// bench_coupling: coupling overhead per coupled step (everything but the two solves) against the
// number of Lagrangian points, N = 10^2 .. 10^5, over TCP loopback (./fsi bench coupling).
//
// Coupling: the real coupler (coupler::CouplingRun, endpoint tcp://127.0.0.1:0, coupling.h5
// and all) runs in one thread; two minimal participants built on participant::ParticipantSession run
// in two others, with trivial solves: the structure answers every StructureAdvance with its
// unchanged positions, the fluid answers InterpolateRequest with zero velocities and
// FluidAdvance with an empty AdvanceReply. A step then costs only the coupling: messages,
// Protobuf, the law of Eq. (5) and the coupler's bookkeeping (coupling.h5, heartbeats).
// Per step five arrays of N x 3 doubles travel (X, U, F, load, X^{n+1}: 120 N bytes) in two
// request/reply rounds (fluid; then fluid and structure together).
//
// Raw references, in the same process and the same rounds, the same bytes in the same pattern,
// three threads likewise, no Protobuf, no coupler logic:
//   tcp: POSIX TCP loopback sockets (TCP_NODELAY), 8-byte length prefix, read straight into and
//        written straight from the arrays: the cost of moving the bytes through a socket.
//   zmq: ZeroMQ ROUTER/DEALER raw frames (the coupler's transport without Protobuf), arrays
//        copied into and out of the messages.
//
// Columns: coupling ms/step is the wall period of a step seen by the fluid (from one
// InterpolateRequest to the next, after a warm-up), so it includes what the coupler does
// between steps (appending to coupling.h5 and flushing it); coupler_wall is the coupler's own
// /timings/step_wall_s (= overhead_s here, the solves being empty), which does not. Each number
// is the median of `rounds` rounds; ratios are medians of the per-round ratios (the raw blocks
// run right after each coupled run, so the machine's noise hits both alike).
//
// Goals (issue 3): coupling < 1 ms/step at 10^4 points; coupling / raw tcp <= 3.
// Options: --rounds R (default 7), --scale S (multiplies the step counts, default 1),
//          --min-points N / --max-points N (skip smaller / larger sizes), --no-raw (coupled runs only, for profiling),
//          --keep (keep the case folders).

#include "coupler/CouplingRun.hpp"
#include "proto/Endpoint.hpp"
#include "proto/PackedPoints.hpp"
#include "participant/ParticipantSession.hpp"
#include "proto/ZmqContext.hpp"
#include "case/CaseConfig.hpp"
#include "case/ModuleSetups.hpp"

#include <hdf5.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <zmq_addon.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace fsi;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double spacing_m = 0.005;
constexpr double dt_s = 5e-5;
constexpr double mass_per_area = 0.08;

struct Size {
  long n1, n2;
  long steps;  ///< measured steps (after the warm-up)
  long warmup; ///< steps discarded
  long points() const { return n1 * n2; }
};

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

PointArray sheet_positions(const Size &size) {
  PointArray x(size.points(), 3);
  for (long j = 0; j < size.n2; ++j)
    for (long i = 0; i < size.n1; ++i)
      x.row(j * size.n1 + i) << spacing_m * static_cast<double>(i), spacing_m * static_cast<double>(j), 0.0;
  return x;
}

// ---- the coupled run ------------------------------------------------------------------------

void write_case(const fs::path &dir, const Size &size) {
  fs::create_directories(dir);
  const long n_steps = size.warmup + size.steps;
  std::ofstream out(dir / "case.yaml");
  out.precision(17);
  out << "run:\n"
      << "  end_time_s: " << static_cast<double>(n_steps) * dt_s << "\n"
      << "  time_step_s: " << dt_s << "\n"
      << "  output_interval_s: " << static_cast<double>(n_steps) * dt_s << "\n"
      << "gravity_m_per_s2: [0, 0, 0]\n"
      << "structures:\n"
      << "  - name: sheet\n"
      << "    model: membrane\n"
      << "    size_m: [" << spacing_m * static_cast<double>(size.n1 - 1) << ", "
      << spacing_m * static_cast<double>(size.n2 - 1) << "]\n"
      << "    n_points: [" << size.n1 << ", " << size.n2 << "]\n"
      << "    origin_m: [0, 0, 0]\n"
      << "    material:\n"
      << "      mass_per_area_kg_per_m2: " << mass_per_area << "\n"
      << "      damping_kg_per_m2_s: 0.0\n"
      << "      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}\n"
      << "    edges: {s1_min: free, s1_max: free, s2_min: free, s2_max: free}\n"
      << "fluid:\n"
      << "  prescribed:\n"
      << "    uniform: {velocity_m_per_s: [0.2, 0.0, 0.1]}\n"
      << "coupling:\n"
      << "  law: penalty\n"
      << "  stiffness_n_per_m_per_measure: 3.2e4\n"
      << "  endpoint: tcp://127.0.0.1:0\n";
}

std::string wait_for_endpoint(const fs::path &file, const std::atomic<bool> &coupler_done) {
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < deadline && !coupler_done) {
    std::ifstream in(file);
    std::string text;
    if (in >> text && !text.empty())
      return text;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  throw std::runtime_error("the coupler wrote no " + file.string());
}

participant::SessionSettings settings_for(const std::string &endpoint, proto::Role role,
                                          const std::string &fingerprint) {
  participant::SessionSettings s;
  s.coupler = proto::Endpoint::parse(endpoint);
  s.role = role;
  s.name = "bench";
  s.case_fingerprint = fingerprint;
  s.handshake_timeout = std::chrono::milliseconds(30000);
  return s;
}

/// Structure participant: its positions never change (the trivial solve).
void run_structure(const std::string &endpoint, const std::string &fingerprint, const Size &size) {
  participant::ParticipantSession session(settings_for(endpoint, proto::v2::ROLE_STRUCTURE, fingerprint));
  const long n = size.points();
  const PointArray x = sheet_positions(size);
  proto::v2::StructureTopology topology;
  topology.set_name("sheet");
  topology.set_model("membrane");
  topology.set_n1(static_cast<std::uint32_t>(size.n1));
  topology.set_n2(static_cast<std::uint32_t>(size.n2));
  for (long i = 0; i < n; ++i)
    topology.add_point_measure(spacing_m * spacing_m);
  topology.set_mass_per_measure(mass_per_area);
  session.handshake({topology});

  proto::Message reply;
  auto *body = reply.envelope().mutable_advance_reply();
  reply.add_points(*body->mutable_position_m(), n) = x;
  reply.add_points(*body->mutable_velocity_m_per_s(), n).setZero();
  reply.envelope().set_step(0);
  session.send(reply); // X^0, V^0
  body->clear_velocity_m_per_s();
  while (true) {
    const proto::Message &message = session.next_request();
    const proto::Envelope &request = message.envelope();
    if (request.has_shutdown())
      return;
    if (!request.has_structure_advance())
      throw std::runtime_error("bench structure: unexpected " + std::string(proto::body_name(request)));
    message.points(request.structure_advance().load_density_n_per_measure(), n, "load_density_n_per_measure");
    body->set_time_s(request.structure_advance().time_s() + request.structure_advance().dt_s());
    reply.add_points(*body->mutable_position_m(), n) = x;
    reply.envelope().set_step(request.step());
    session.send(reply);
  }
}

/// Fluid participant: zero velocity everywhere; notes when each InterpolateRequest arrived.
void run_fluid(const std::string &endpoint, const std::string &fingerprint, long n,
               std::vector<Clock::time_point> &arrivals) {
  participant::ParticipantSession session(settings_for(endpoint, proto::v2::ROLE_FLUID, fingerprint));
  session.handshake();
  const PointArray zero = PointArray::Zero(n, 3);
  proto::Message interpolated, advanced;
  auto *velocity = interpolated.envelope().mutable_interpolate_reply();
  auto *done = advanced.envelope().mutable_advance_reply();
  while (true) {
    const proto::Message &message = session.next_request();
    const proto::Envelope &request = message.envelope();
    if (request.has_shutdown())
      return;
    if (request.has_interpolate_request()) {
      arrivals.push_back(Clock::now());
      message.points(request.interpolate_request().position_m(), n, "position_m");
      interpolated.add_points(*velocity->mutable_velocity_m_per_s(), zero);
      interpolated.envelope().set_step(request.step());
      session.send(interpolated);
    } else if (request.has_fluid_advance()) {
      message.points(request.fluid_advance().force_density_n_per_measure(), n, "force_density_n_per_measure");
      done->set_time_s(request.fluid_advance().time_s() + request.fluid_advance().dt_s());
      advanced.envelope().set_step(request.step());
      session.send(advanced);
    } else {
      throw std::runtime_error("bench fluid: unexpected " + std::string(proto::body_name(request)));
    }
  }
}

/// Mean of a 1-D float64 dataset of coupling.h5 over rows [from, end).
double h5_mean(const fs::path &file, const char *dataset, long from) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0)
    throw std::runtime_error("cannot open " + file.string());
  const hid_t d = H5Dopen2(f, dataset, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  std::vector<double> values(n);
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  double sum = 0.0;
  long count = 0;
  for (hsize_t i = static_cast<hsize_t>(from); i < n; ++i, ++count)
    sum += values[i];
  return count ? sum / static_cast<double>(count) : 0.0;
}

struct CoupledResult {
  double period_s;       ///< per step, as the fluid saw it
  double coupler_wall_s; ///< the coupler's step_wall_s (coupling.h5)
  double law_s;          ///< the coupler's coupling_law_s
};

CoupledResult run_coupled(const fs::path &dir, const Size &size) {
  const auto config = case_config::CaseConfig::load(dir);
  const std::string fingerprint = config.fingerprint();
  const fs::path output = dir / "output";
  fs::remove_all(output);
  // A fresh logger per run: CouplingRun adds its log file to the default logger.
  auto logger = std::make_shared<spdlog::logger>("coupler", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  logger->set_level(spdlog::level::warn);
  spdlog::set_default_logger(logger);

  std::atomic<bool> coupler_done{false};
  int exit_code = -1;
  std::thread coupler([&] {
    try {
      coupler::CouplingRun run(case_config::coupling_setup(case_config::CaseConfig::load(dir), dir), output,
                               "tcp://127.0.0.1:0");
      exit_code = run.run();
    } catch (const std::exception &e) {
      std::cerr << "bench coupler: " << e.what() << "\n";
    }
    coupler_done = true;
  });
  std::string endpoint;
  try {
    endpoint = wait_for_endpoint(output / "coupler.endpoint", coupler_done);
  } catch (...) {
    coupler.join();
    throw;
  }
  std::vector<Clock::time_point> arrivals;
  arrivals.reserve(static_cast<std::size_t>(size.warmup + size.steps + 1));
  std::string failure;
  auto guarded = [&failure](auto work) {
    return [&failure, work] {
      try {
        work();
      } catch (const std::exception &e) {
        failure = e.what();
      }
    };
  };
  std::thread structure(guarded([&] { run_structure(endpoint, fingerprint, size); }));
  std::thread fluid(guarded([&] { run_fluid(endpoint, fingerprint, size.points(), arrivals); }));
  structure.join();
  fluid.join();
  coupler.join();
  if (!failure.empty() || exit_code != 0)
    throw std::runtime_error("coupled run of " + std::to_string(size.points()) + " points failed (coupler exit " +
                             std::to_string(exit_code) + ") " + failure);
  const long n_steps = size.warmup + size.steps;
  if (static_cast<long>(arrivals.size()) != n_steps)
    throw std::runtime_error("the fluid saw " + std::to_string(arrivals.size()) + " steps, expected " +
                             std::to_string(n_steps));
  CoupledResult r{};
  r.period_s = seconds(arrivals.back() - arrivals[static_cast<std::size_t>(size.warmup)]) /
               static_cast<double>(n_steps - 1 - size.warmup);
  r.coupler_wall_s = h5_mean(output / "coupling.h5", "/timings/step_wall_s", size.warmup);
  r.law_s = h5_mean(output / "coupling.h5", "/timings/coupling_law_s", size.warmup);
  return r;
}

// ---- raw reference 1: POSIX TCP loopback ------------------------------------------------------

void check_io(bool ok, const char *what) {
  if (!ok)
    throw std::runtime_error(std::string("raw tcp: ") + what + ": " + std::strerror(errno));
}

void write_all(int fd, const void *data, std::size_t n) {
  const char *p = static_cast<const char *>(data);
  while (n > 0) {
    const ssize_t k = ::send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR)
      continue;
    check_io(k > 0, "send");
    p += k;
    n -= static_cast<std::size_t>(k);
  }
}

void read_all(int fd, void *data, std::size_t n) {
  char *p = static_cast<char *>(data);
  while (n > 0) {
    const ssize_t k = ::recv(fd, p, n, 0);
    if (k < 0 && errno == EINTR)
      continue;
    check_io(k > 0, "recv");
    p += k;
    n -= static_cast<std::size_t>(k);
  }
}

/// One framed message: 8-byte length, then the bytes (one writev-like pair of sends is fine
/// with TCP_NODELAY: the header goes with the first segment of the payload most of the time).
void send_frame(int fd, const void *data, std::uint64_t n) {
  write_all(fd, &n, sizeof n);
  if (n > 0)
    write_all(fd, data, n);
}

std::uint64_t receive_frame(int fd, void *data, std::uint64_t capacity) {
  std::uint64_t n = 0;
  read_all(fd, &n, sizeof n);
  if (n == ~std::uint64_t{0})
    return n;
  if (n > capacity)
    throw std::runtime_error("raw tcp: frame larger than expected");
  read_all(fd, data, n);
  return n;
}

void no_delay(int fd) {
  int one = 1;
  check_io(setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one) == 0, "TCP_NODELAY");
}

int connect_to(std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  check_io(fd >= 0, "socket");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  check_io(::connect(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0, "connect");
  no_delay(fd);
  return fd;
}

/// Times `steps` raw steps after `warmup` ones; returns seconds per step.
double run_raw_tcp(long n, long warmup, long steps) {
  const std::size_t bytes = sizeof(double) * 3 * static_cast<std::size_t>(n);
  const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  check_io(listener >= 0, "socket");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  check_io(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0, "bind");
  check_io(::listen(listener, 4) == 0, "listen");
  socklen_t length = sizeof address;
  check_io(getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length) == 0, "getsockname");
  const std::uint16_t port = ntohs(address.sin_port);

  // Fluid: X -> U (N x 3), F -> empty; structure: load -> X (N x 3).
  auto fluid = std::thread([=] {
    const int fd = connect_to(port);
    std::uint8_t role = 0;
    write_all(fd, &role, 1);
    PointArray in(n, 3), out = PointArray::Zero(n, 3);
    for (std::uint64_t k = 0;; ++k) {
      if (receive_frame(fd, in.data(), bytes) == ~std::uint64_t{0})
        break;
      if (k % 2 == 0)
        send_frame(fd, out.data(), bytes);
      else
        send_frame(fd, nullptr, 0);
    }
    ::close(fd);
  });
  auto structure = std::thread([=] {
    const int fd = connect_to(port);
    std::uint8_t role = 1;
    write_all(fd, &role, 1);
    PointArray in(n, 3), out = PointArray::Random(n, 3);
    while (receive_frame(fd, in.data(), bytes) != ~std::uint64_t{0})
      send_frame(fd, out.data(), bytes);
    ::close(fd);
  });
  int fds[2] = {-1, -1};
  for (int i = 0; i < 2; ++i) {
    const int fd = ::accept(listener, nullptr, nullptr);
    check_io(fd >= 0, "accept");
    no_delay(fd);
    std::uint8_t role = 0;
    read_all(fd, &role, 1);
    fds[role] = fd;
  }
  ::close(listener);
  const int to_fluid = fds[0], to_structure = fds[1];
  PointArray x = PointArray::Random(n, 3), u(n, 3), f = PointArray::Random(n, 3), load = -f;
  Clock::time_point start;
  for (long step = 0; step < warmup + steps; ++step) {
    if (step == warmup)
      start = Clock::now();
    send_frame(to_fluid, x.data(), bytes);
    receive_frame(to_fluid, u.data(), bytes);
    send_frame(to_structure, load.data(), bytes);
    send_frame(to_fluid, f.data(), bytes);
    receive_frame(to_structure, x.data(), bytes);
    receive_frame(to_fluid, u.data(), bytes); // empty
  }
  const double per_step = seconds(Clock::now() - start) / static_cast<double>(steps);
  const std::uint64_t stop = ~std::uint64_t{0};
  write_all(to_fluid, &stop, sizeof stop);
  write_all(to_structure, &stop, sizeof stop);
  fluid.join();
  structure.join();
  ::close(to_fluid);
  ::close(to_structure);
  return per_step;
}

// ---- raw reference 2: ZeroMQ frames, no Protobuf ---------------------------------------------

zmq::socket_t zmq_socket(zmq::socket_type type) {
  zmq::socket_t socket(proto::ZmqContext::shared(), type);
  socket.set(zmq::sockopt::linger, 0);
  return socket;
}

zmq::message_t message_of(const PointArray &a, std::size_t bytes) {
  zmq::message_t m(bytes);
  if (bytes > 0)
    std::memcpy(m.data(), a.data(), bytes);
  return m;
}

void copy_out(const zmq::message_t &m, PointArray &a) {
  if (m.size() > 0)
    std::memcpy(a.data(), m.data(), m.size());
}

double run_raw_zmq(long n, long warmup, long steps) {
  const std::size_t bytes = sizeof(double) * 3 * static_cast<std::size_t>(n);
  auto router = zmq_socket(zmq::socket_type::router);
  router.bind("tcp://127.0.0.1:0");
  const std::string endpoint = router.get(zmq::sockopt::last_endpoint);
  auto participant = [=](const char *id, bool is_fluid) {
    return std::thread([=] {
      auto dealer = zmq_socket(zmq::socket_type::dealer);
      dealer.set(zmq::sockopt::routing_id, id);
      dealer.connect(endpoint);
      dealer.send(zmq::str_buffer("hello"));
      PointArray in(n, 3), out = PointArray::Zero(n, 3);
      zmq::message_t request;
      for (std::uint64_t k = 0; dealer.recv(request) && request.size() > 0; ++k) {
        copy_out(request, in);
        dealer.send(message_of(out, is_fluid && k % 2 == 1 ? 0 : bytes), zmq::send_flags::none);
      }
    });
  };
  std::thread fluid = participant("fluid", true), structure = participant("structure", false);
  auto send_to = [&router](const std::string &id, zmq::message_t payload) {
    router.send(zmq::buffer(id), zmq::send_flags::sndmore);
    router.send(payload, zmq::send_flags::none);
  };
  auto receive = [&router](PointArray &into) {
    std::vector<zmq::message_t> frames;
    if (!zmq::recv_multipart(router, std::back_inserter(frames)) || frames.size() != 2)
      throw std::runtime_error("raw zmq: bad answer");
    copy_out(frames.back(), into);
    return frames.front().to_string();
  };
  PointArray x = PointArray::Random(n, 3), u(n, 3), f = PointArray::Random(n, 3), load = -f, scratch(n, 3);
  for (int i = 0; i < 2; ++i)
    receive(scratch); // the two hellos
  Clock::time_point start;
  for (long step = 0; step < warmup + steps; ++step) {
    if (step == warmup)
      start = Clock::now();
    send_to("fluid", message_of(x, bytes));
    receive(u);
    send_to("structure", message_of(load, bytes));
    send_to("fluid", message_of(f, bytes));
    for (int i = 0; i < 2; ++i) // structure: X^{n+1}; fluid: empty
      receive(x);
  }
  const double per_step = seconds(Clock::now() - start) / static_cast<double>(steps);
  send_to("fluid", zmq::message_t());
  send_to("structure", zmq::message_t());
  fluid.join();
  structure.join();
  return per_step;
}

// ---- the table --------------------------------------------------------------------------------

struct Options {
  int rounds = 7;
  double scale = 1.0;
  long min_points = 0;
  long max_points = 100000;
  bool keep = false;
  bool raw = true;
};

Options parse(int argc, char **argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    if (a == "--rounds")
      o.rounds = std::max(1, std::stoi(value()));
    else if (a == "--scale")
      o.scale = std::stod(value());
    else if (a == "--max-points")
      o.max_points = std::stol(value());
    else if (a == "--min-points")
      o.min_points = std::stol(value());
    else if (a == "--keep")
      o.keep = true;
    else if (a == "--no-raw")
      o.raw = false;
    else if (a == "-h" || a == "--help") {
      std::cout
          << "usage: bench_coupling [--rounds R] [--scale S] [--min-points N] [--max-points N] [--no-raw] [--keep]\n";
      std::exit(0);
    } else
      throw std::runtime_error("unknown option " + a + " (see --help)");
  }
  return o;
}

} // namespace

int main(int argc, char **argv) try {
  const Options options = parse(argc, argv);
  const std::vector<Size> sizes = {
      {10, 10, 5000, 500}, {40, 25, 3000, 300}, {100, 100, 1000, 100}, {400, 250, 100, 10}};
  const fs::path root = fs::temp_directory_path() / ("fsi-bench-coupling-" + std::to_string(::getpid()));
  std::printf("coupling overhead per step over TCP loopback: real coupler + 2 trivial participants (3 threads "
              "on %u hardware threads), %d round(s); medians\n",
              std::thread::hardware_concurrency(), options.rounds);
  std::printf("%8s %10s %7s | %9s %9s %8s | %9s %9s | %8s %8s\n", "points", "bytes/step", "steps", "coupling",
              "coupler", "law", "raw tcp", "raw zmq", "coupling", "coupling");
  std::printf("%8s %10s %7s | %9s %9s %8s | %9s %9s | %8s %8s\n", "", "", "", "ms/step", "wall ms", "ms", "ms/step",
              "ms/step", "/tcp", "/zmq");
  bool goal_time = true, goal_ratio = true;
  double at_1e4 = -1.0, spread_1e4[2] = {0.0, 0.0};
  for (const Size &base : sizes) {
    if (base.points() > options.max_points || base.points() < options.min_points)
      continue;
    Size size = base;
    size.steps = std::max(10L, std::lround(static_cast<double>(base.steps) * options.scale));
    size.warmup = std::max(2L, std::lround(static_cast<double>(base.warmup) * options.scale));
    const fs::path dir = root / ("n" + std::to_string(size.points()));
    write_case(dir, size);
    std::vector<double> period, wall, law, tcp, zmq_raw, ratio_tcp, ratio_zmq;
    for (int r = 0; r < options.rounds; ++r) {
      const CoupledResult c = run_coupled(dir, size);
      const double t = options.raw ? run_raw_tcp(size.points(), size.warmup, size.steps) : 0.0;
      const double z = options.raw ? run_raw_zmq(size.points(), size.warmup, size.steps) : 0.0;
      period.push_back(c.period_s);
      wall.push_back(c.coupler_wall_s);
      law.push_back(c.law_s);
      tcp.push_back(t);
      zmq_raw.push_back(z);
      ratio_tcp.push_back(c.period_s / t);
      ratio_zmq.push_back(c.period_s / z);
    }
    const double ms = 1e3;
    std::printf("%8ld %10ld %7ld | %9.4f %9.4f %8.4f | %9.4f %9.4f | %8.2f %8.2f\n", size.points(), 120 * size.points(),
                size.steps, ms * median(period), ms * median(wall), ms * median(law), ms * median(tcp),
                ms * median(zmq_raw), median(ratio_tcp), median(ratio_zmq));
    std::fflush(stdout);
    if (size.points() >= 1000 && median(ratio_tcp) > 2.0)
      goal_ratio = false;
    if (size.points() == 10000) {
      at_1e4 = ms * median(period);
      goal_time = at_1e4 < 0.5;
      spread_1e4[0] = ms * *std::min_element(period.begin(), period.end());
      spread_1e4[1] = ms * *std::max_element(period.begin(), period.end());
    }
  }
  if (!options.keep)
    fs::remove_all(root);
  else
    std::printf("case folders kept in %s\n", root.c_str());
  if (at_1e4 < 0)
    std::printf("goal 1 (issue 12), < 0.5 ms/step at 10^4 points: not measured\n");
  else
    std::printf("goal 1 (issue 12), < 0.5 ms/step at 10^4 points: %s (median %.3f ms, rounds %.3f .. %.3f ms)\n",
                goal_time ? "met" : "MISSED", at_1e4, spread_1e4[0], spread_1e4[1]);
  std::printf("goal 2 (issue 12), coupling / raw tcp <= 2 from 10^3 points up: %s (bare ZeroMQ is already 2.5-3.5x "
              "raw TCP below 10^4 points on this kind of machine: docs/verification.md)\n",
              goal_ratio ? "met" : "MISSED");
  return 0;
} catch (const std::exception &e) {
  std::fprintf(stderr, "bench_coupling: %s\n", e.what());
  return 1;
}
