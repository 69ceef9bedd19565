#pragma once
// The XDMF index that lets ParaView show the results file as moving sheets: a temporal
// collection with one Grid per saved step; each step is a spatial collection with one Grid per
// structure whose Geometry and velocity Attribute are row k of the structure's `position_m`
// and `velocity_m_per_s` datasets. The row is written in a form that both the default Xdmf3
// reader and the legacy XDMFReader read (see row_hyperslab() in the .cpp). The file is
// rewritten whole after each step through a temporary file and a rename, so it is always
// complete.
//
// The HDF5 file is referenced relative to the index's folder, so the pair can be moved. Known
// ParaView 5.11 limit: Xdmf3 resolves that reference by appending it to the index path up to
// its last '/', so `OpenDataFile("structure.xdmf")` (bare name, no '/') looks for
// "structure.xdmfstructure.h5"; open "./structure.xdmf" or an absolute path instead. Only an
// absolute reference would avoid this, at the price of breaking moved or copied results.

#include "structure_solver/output/ResultsRecords.hpp"
#include "structure_solver/output/StructureTopology.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::structure::output {

class XdmfWriter {
public:
  /// `h5_path` is referenced relative to the folder of `xdmf_path` (usually its file name),
  /// so the pair can be moved together. Writes an index with no steps; throws
  /// std::runtime_error naming `xdmf_path` when it cannot.
  XdmfWriter(std::filesystem::path xdmf_path, const std::filesystem::path &h5_path);

  /// Registers a structure (before the first step).
  void add_structure(const StructureLayout &layout, const Connectivity &connectivity);

  /// Adds the step saved at `time_s` (HDF5 row n_steps()) and rewrites the file.
  void append_step(double time_s);

  /// The XML text listing all steps appended so far.
  std::string document() const;

  std::size_t n_steps() const { return times_s_.size(); }
  const std::filesystem::path &path() const { return xdmf_path_; }

private:
  struct StructureEntry {
    std::string name;
    std::string topology_type;
    std::size_t n_cells;
    int nodes_per_cell;
    int n_points;
  };

  void write_atomically() const;
  std::string step_grid(std::size_t step_index) const;
  std::string structure_grid(const StructureEntry &structure, std::size_t step_index) const;
  std::string topology(const StructureEntry &structure) const;
  std::string row_hyperslab(const StructureEntry &structure, const std::string &dataset,
                            std::size_t step_index, const std::string &indent) const;
  std::string hdf_reference(const std::string &dataset_path) const;

  std::filesystem::path xdmf_path_;
  std::string h5_reference_;
  std::vector<StructureEntry> structures_;
  std::vector<double> times_s_;
};

} // namespace fsi::structure::output
