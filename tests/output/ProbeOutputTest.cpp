// Probes in the results file (/probes/<name>: [n_saved, 3] rows aligned with /time_s, units)
// and in probes.csv (header, one flushed line per step); a record with the wrong number of
// probes is refused before anything is written.

#include "OutputTestSupport.hpp"

#include "structure_solver/output/ProbeCsv.hpp"
#include "structure_solver/output/ResultsReader.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fsi::structure::output::testing {
namespace {

ProbeState probe_state(int probe, int saved_index) {
  return {Vec3(probe, saved_index, 0.5), Vec3(-probe, 0.25 * saved_index, 1.0)};
}

std::vector<std::string> lines_of(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

class ProbeOutput : public ScratchFolderTest {};

TEST_F(ProbeOutput, ProbesAreRowsAlignedWithTimeAndReadBackExactly) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    writer.add_structure(sheet_layout());
    writer.add_structure(fiber_layout());
    writer.add_probe("tip");
    writer.add_probe("centre");
    for (int k = 0; k < 3; ++k) {
      SampleStep sample(k);
      sample.record.probes = {probe_state(0, k), probe_state(1, k)};
      writer.write_step(sample.record);
    }
  }
  const ResultsReader reader(h5_path());
  EXPECT_EQ(reader.probe_names(), (std::vector<std::string>{"centre", "tip"}));
  EXPECT_EQ(reader.dataset_shape("/probes/tip/position_m"), (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(reader.string_attribute("/probes/tip/position_m", "units"), "m");
  EXPECT_EQ(reader.string_attribute("/probes/centre/velocity_m_per_s", "units"), "m/s");
  const PointArray velocity = reader.probe_series("centre", "velocity_m_per_s");
  ASSERT_EQ(velocity.rows(), 3);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(Vec3(velocity.row(k).transpose()), probe_state(1, k).velocity_m_per_s);
}

TEST_F(ProbeOutput, WithoutProbesTheFileHasNoProbesGroup) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
  }
  EXPECT_TRUE(ResultsReader(h5_path()).probe_names().empty());
}

TEST_F(ProbeOutput, ARecordWithTheWrongNumberOfProbesIsRefused) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  writer.add_structure(sheet_layout());
  writer.add_structure(fiber_layout());
  writer.add_probe("tip");
  const SampleStep sample(0); // no probe states
  EXPECT_THROW(writer.write_step(sample.record), std::invalid_argument);
  EXPECT_EQ(writer.n_saved(), 0);
  EXPECT_THROW(writer.add_probe("tip"), std::invalid_argument);
}

TEST_F(ProbeOutput, TheCsvHasAHeaderAndOneLinePerStepOnDiskAtOnce) {
  const auto path = folder_ / "probes.csv";
  ProbeCsv csv(path, {"tip", "c"});
  csv.append(0.0, {probe_state(0, 0), probe_state(1, 0)});
  csv.append(0.125, {probe_state(0, 1), probe_state(1, 1)});
  const auto lines = lines_of(path); // read while the writer is still open: flushed
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "time_s,tip.x_m,tip.y_m,tip.z_m,tip.u_m_per_s,tip.v_m_per_s,tip.w_m_per_s,"
                      "c.x_m,c.y_m,c.z_m,c.u_m_per_s,c.v_m_per_s,c.w_m_per_s");
  EXPECT_EQ(lines[2], "0.125,0,1,0.5,0,0.25,1,1,1,0.5,-1,0.25,1");
  EXPECT_THROW(csv.append(0.25, {probe_state(0, 2)}), std::invalid_argument);
}

} // namespace
} // namespace fsi::structure::output::testing
