#pragma once
// probes.csv: one line per saved step with every probe's position and velocity, for a quick
// look in a spreadsheet or pandas. Header:
//   time_s,<name>.x_m,<name>.y_m,<name>.z_m,<name>.u_m_per_s,<name>.v_m_per_s,<name>.w_m_per_s,...
// Numbers have 15 significant digits. Each line is flushed when written, so the file holds every saved step if the run stops.

#include "structure_solver/output/ResultsRecords.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fsi::structure::output {

class ProbeCsv {
public:
  /// Creates (truncates) `path` and writes the header; throws std::runtime_error naming the path.
  ProbeCsv(std::filesystem::path path, const std::vector<std::string> &probe_names);

  /// Appends the line of one saved step (probes in the order of the names) and flushes it.
  void append(double time_s, const std::vector<ProbeState> &probes);

  const std::filesystem::path &path() const { return path_; }

private:
  void check_stream(const std::string &what);

  std::filesystem::path path_;
  std::size_t n_probes_;
  std::ofstream out_;
};

} // namespace fsi::structure::output
