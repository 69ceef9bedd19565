#pragma once
// Read-only access to a results file written by ResultsWriter: the saved times and steps, the
// structures' layouts, connectivity and per-step arrays, and any string attribute. Used by the
// tests and by post-processing tools. The number of saved steps is the length of /time_s.

#include "common/Types.hpp"
#include "hdf5/H5Handle.hpp"
#include "structure_solver/output/ResultsRecords.hpp"
#include "structure_solver/output/StructureTopology.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::structure::output {

class ResultsReader {
public:
  /// Opens `h5_path` read-only; throws std::runtime_error naming the path on failure.
  explicit ResultsReader(const std::filesystem::path &h5_path);

  long n_saved() const;
  std::vector<double> time_s() const;
  std::vector<std::int64_t> steps() const;

  /// Names of the groups under /structures, in alphabetical order.
  std::vector<std::string> structure_names() const;
  StructureLayout layout(const std::string &structure) const;
  Connectivity connectivity(const std::string &structure) const;

  /// Row `saved_index` (0-based, < n_saved()) of `position_m` / `velocity_m_per_s`.
  PointArray position_m(const std::string &structure, long saved_index) const;
  PointArray velocity_m_per_s(const std::string &structure, long saved_index) const;

  /// A per-step scalar series of a structure ("max_stretch_ratio", "kinetic_energy_j", ...),
  /// first n_saved() values.
  std::vector<double> structure_series(const std::string &structure,
                                       const std::string &dataset) const;

  /// Names of the groups under /probes, in alphabetical order (none: the case has no probes).
  std::vector<std::string> probe_names() const;
  /// A probe's `position_m` or `velocity_m_per_s`: n_saved() rows of [x, y, z].
  PointArray probe_series(const std::string &probe, const std::string &dataset) const;

  /// Shape of any dataset, e.g. {n_saved, n_points, 3} for "/structures/sheet/position_m".
  std::vector<hsize_t> dataset_shape(const std::string &dataset_path) const;

  /// String attribute of any object ("/" for the root: "status", "config_yaml", ...).
  std::string string_attribute(const std::string &object_path, const std::string &name) const;
  /// Integer array attribute of any object (e.g. "grid_shape").
  std::vector<std::int64_t> int_attribute(const std::string &object_path,
                                          const std::string &name) const;

  const std::filesystem::path &h5_path() const { return h5_path_; }

private:
  void require_structure(const std::string &structure) const;
  hdf5::H5Handle open_dataset(const std::string &dataset_path) const;
  hdf5::H5Handle open_object(const std::string &object_path) const;
  PointArray point_row(const std::string &dataset_path, long saved_index) const;
  std::vector<std::string> group_members(const std::string &group_path) const;
  std::vector<double> leading_doubles(const std::string &dataset_path, hsize_t count) const;
  std::string context(const std::string &what) const;

  std::filesystem::path h5_path_;
  hdf5::H5Handle file_;
};

} // namespace fsi::structure::output
