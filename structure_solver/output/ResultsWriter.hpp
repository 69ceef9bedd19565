#pragma once
// The results file of a run: an HDF5 file with one row per saved step in extendable datasets,
// and an XDMF index beside it so ParaView shows the moving sheets and filaments.
//
// Layout (all SI; every dataset has a `units` attribute):
//   /                      attrs units="SI", config_yaml, code_version, status, created_utc
//   /time_s                [n_saved]            float64
//   /step                  [n_saved]            int64
//   /structures/<name>/    attrs model, grid_shape={n1,n2}, point_order, release_time_s,
//                          exit_time_s (NaN while the structure is in the scene or waiting)
//       connectivity       [n_cells, 4] quads (membrane) or [n1-1, 2] segments (filament)
//       position_m, velocity_m_per_s            [n_saved, n_points, 3] float64
//       max_stretch_ratio, kinetic_energy_j, elastic_energy_j, potential_energy_j  [n_saved]
//   /probes/<name>/        only when the case has probes
//       position_m, velocity_m_per_s            [n_saved, 3] float64
//
// The file is flushed after every step and status change, so it stays readable when the
// process dies. The root attribute `complete_steps`, rewritten after each step's rows are
// flushed, is the number of rows a reader may trust (ResultsReader, python/fsi/results_file.py):
// a process killed during a flush may leave a row extended but not written.

#include "hdf5/H5Handle.hpp"
#include "structure_solver/output/ProbeSeries.hpp"
#include "structure_solver/output/ResultsRecords.hpp"
#include "structure_solver/output/StructureSeries.hpp"
#include "structure_solver/output/XdmfWriter.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fsi::structure::output {

class ResultsWriter {
public:
  /// Creates (truncates) `h5_path` and writes an empty XDMF index at `xdmf_path`. Throws
  /// std::runtime_error naming the path when either cannot be created.
  ResultsWriter(std::filesystem::path h5_path, std::filesystem::path xdmf_path, RunMetadata meta);
  ~ResultsWriter();

  ResultsWriter(const ResultsWriter &) = delete;
  ResultsWriter &operator=(const ResultsWriter &) = delete;

  /// Adds `/structures/<name>`; all structures come before the first write_step().
  void add_structure(const StructureLayout &layout);
  /// Adds `/probes/<name>` (and `/probes` with the first one); before the first write_step().
  void add_probe(const std::string &name);

  /// Appends one saved step (structures in add_structure() order, probes in add_probe()
  /// order), flushes the HDF5 file and
  /// rewrites the XDMF index. Throws std::invalid_argument (nothing written) when the record
  /// does not match the structures; std::runtime_error naming file and dataset when HDF5
  /// fails, after which the writer refuses further steps.
  void write_step(const StepRecord &record);

  /// Records that structure `index` (add_structure() order) left the scene at time_s, why
  /// ("past_plane", "torn"), and flushes.
  void set_exit(std::size_t index, double time_s, const std::string &reason);

  /// Sets the root `status` attribute ("running", "completed", "diverged: <why>",
  /// "interrupted") and flushes.
  void set_status(const std::string &status);

  long n_saved() const { return n_saved_; }
  const std::filesystem::path &h5_path() const { return h5_path_; }

private:
  void write_root_attributes(const RunMetadata &meta);
  void check_before_first_step(const std::string &what) const;
  void check_record(const StepRecord &record) const;
  void append_rows(const StepRecord &record);
  void flush();
  void throw_if_failed() const;
  [[noreturn]] void fail(const std::exception &error);

  std::filesystem::path h5_path_;
  hdf5::H5Handle file_;
  hdf5::H5Handle structures_group_;
  std::unique_ptr<hdf5::ExtendableDataset> time_s_;
  std::unique_ptr<hdf5::ExtendableDataset> step_;
  std::vector<StructureSeries> structures_;
  hdf5::H5Handle probes_group_;
  std::vector<ProbeSeries> probes_;
  std::unique_ptr<XdmfWriter> xdmf_;
  long n_saved_ = 0;
  std::string failure_;
};

} // namespace fsi::structure::output
