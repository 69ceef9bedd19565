#include "structure_solver/output/ProbeCsv.hpp"

#include <stdexcept>

namespace fsi::structure::output {
namespace {

/// 15 significant digits: what a double holds exactly, without the noise of round-trip digits.
constexpr int significant_digits = 15;
constexpr const char *column_suffixes[] = {".x_m", ".y_m", ".z_m", ".u_m_per_s", ".v_m_per_s", ".w_m_per_s"};

} // namespace

ProbeCsv::ProbeCsv(std::filesystem::path path, const std::vector<std::string> &probe_names)
    : path_(std::move(path)), n_probes_(probe_names.size()), out_(path_, std::ios::trunc) {
  out_.precision(significant_digits);
  out_ << "time_s";
  for (const std::string &name : probe_names)
    for (const char *suffix : column_suffixes)
      out_ << ',' << name << suffix;
  out_ << '\n' << std::flush;
  check_stream("cannot create");
}

void ProbeCsv::append(double time_s, const std::vector<ProbeState> &probes) {
  if (probes.size() != n_probes_)
    throw std::invalid_argument("probe table '" + path_.string() + "': " + std::to_string(probes.size()) +
                                " probe states, the header names " + std::to_string(n_probes_) + " probes");
  out_ << time_s;
  for (const ProbeState &probe : probes) {
    for (int k = 0; k < 3; ++k)
      out_ << ',' << probe.position_m[k];
    for (int k = 0; k < 3; ++k)
      out_ << ',' << probe.velocity_m_per_s[k];
  }
  out_ << '\n' << std::flush;
  check_stream("cannot write to");
}

void ProbeCsv::check_stream(const std::string &what) {
  if (!out_)
    throw std::runtime_error(what + " the probe table '" + path_.string() + "'");
}

} // namespace fsi::structure::output
