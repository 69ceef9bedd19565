#include "structure_solver/output/ResultsReplay.hpp"

#include "structure_solver/output/ResultsReader.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::structure::output {

ReplayedSteps replay_results(const std::filesystem::path &source, ResultsWriter &writer, ProbeCsv *csv,
                             const std::vector<std::string> &structure_names,
                             const std::vector<std::string> &probe_names, long last_step, long output_every) {
  const ResultsReader reader(source);
  const auto names = reader.structure_names();
  for (const auto &name : structure_names)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw std::runtime_error("results file '" + source.string() + "' has no structure '" + name +
                               "' to continue from");
  const auto probes_there = reader.probe_names();
  for (const auto &name : probe_names)
    if (std::find(probes_there.begin(), probes_there.end(), name) == probes_there.end())
      throw std::runtime_error("results file '" + source.string() + "' has no probe '" + name + "' to continue from");

  const std::vector<double> times = reader.time_s();
  const std::vector<std::int64_t> steps = reader.steps();
  const char *scalar_names[] = {"max_stretch_ratio", "kinetic_energy_j", "elastic_energy_j", "potential_energy_j"};
  std::vector<std::vector<std::vector<double>>> scalars; // [structure][series][row]
  for (const auto &name : structure_names) {
    scalars.emplace_back();
    for (const char *series : scalar_names)
      scalars.back().push_back(reader.structure_series(name, series));
  }
  std::vector<PointArray> probe_x, probe_v;
  for (const auto &name : probe_names) {
    probe_x.push_back(reader.probe_series(name, "position_m"));
    probe_v.push_back(reader.probe_series(name, "velocity_m_per_s"));
  }

  ReplayedSteps kept;
  for (std::size_t row = 0; row < times.size() && steps[row] <= last_step; ++row) {
    if (steps[row] % output_every != 0)
      continue;
    std::vector<PointArray> x, v;
    for (const auto &name : structure_names) {
      x.push_back(reader.position_m(name, static_cast<long>(row)));
      v.push_back(reader.velocity_m_per_s(name, static_cast<long>(row)));
    }
    StepRecord record{steps[row], times[row], {}, {}};
    for (std::size_t s = 0; s < structure_names.size(); ++s)
      record.structures.push_back({&x[s], &v[s], scalars[s][0][row], scalars[s][1][row], scalars[s][2][row],
                                   scalars[s][3][row]});
    for (std::size_t p = 0; p < probe_names.size(); ++p)
      record.probes.push_back({probe_x[p].row(static_cast<Eigen::Index>(row)).transpose(),
                               probe_v[p].row(static_cast<Eigen::Index>(row)).transpose()});
    writer.write_step(record);
    if (csv)
      csv->append(record.time_s, record.probes);
    ++kept.n_rows;
    kept.last_step = steps[row];
  }
  return kept;
}

} // namespace fsi::structure::output
