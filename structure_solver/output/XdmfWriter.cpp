#include "structure_solver/output/XdmfWriter.hpp"

#include "structure_solver/output/ResultsPaths.hpp"

#include <array>
#include <charconv>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace fsi::structure::output {
namespace {

namespace fs = std::filesystem;

/// Shortest text that reads back as exactly `value`.
std::string round_trip_text(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string xml_escaped(const std::string &text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
    case '&':
      escaped += "&amp;";
      break;
    case '<':
      escaped += "&lt;";
      break;
    case '>':
      escaped += "&gt;";
      break;
    case '"':
      escaped += "&quot;";
      break;
    default:
      escaped += c;
    }
  }
  return escaped;
}

std::string relative_reference(const fs::path &h5_path, const fs::path &xdmf_path) {
  const fs::path h5 = fs::absolute(h5_path).lexically_normal();
  const fs::path folder = fs::absolute(xdmf_path).parent_path().lexically_normal();
  const fs::path relative = h5.lexically_relative(folder);
  return xml_escaped((relative.empty() ? h5 : relative).generic_string());
}

} // namespace

XdmfWriter::XdmfWriter(std::filesystem::path xdmf_path, const std::filesystem::path &h5_path)
    : xdmf_path_(std::move(xdmf_path)), h5_reference_(relative_reference(h5_path, xdmf_path_)) {
  write_atomically();
}

void XdmfWriter::add_structure(const StructureLayout &layout, const Connectivity &connectivity) {
  if (!times_s_.empty()) {
    throw std::logic_error("XDMF index " + xdmf_path_.string() +
                           ": structures must be added before the first step");
  }
  structures_.push_back({layout.name, xdmf_topology_type(connectivity), connectivity.n_cells(),
                         connectivity.nodes_per_cell, layout.n_points()});
}

void XdmfWriter::append_step(double time_s) {
  times_s_.push_back(time_s);
  write_atomically();
}

std::string XdmfWriter::document() const {
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"time_series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < times_s_.size(); ++k) {
    xml << step_grid(k);
  }
  xml << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  return xml.str();
}

void XdmfWriter::write_atomically() const {
  fs::path temporary = xdmf_path_;
  temporary += ".tmp";
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << document();
    out.close();
    if (!out) {
      const int cause = errno; // ENOSPC, EROFS, EACCES, ...: the stream does not say
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error("cannot write the XDMF index '" + xdmf_path_.string() + "' through '" +
                               temporary.string() + "': " +
                               (cause != 0 ? std::string(std::strerror(cause))
                                           : std::string("does the folder exist and is it writable?")));
    }
  }
  std::error_code error;
  fs::rename(temporary, xdmf_path_, error);
  if (error) {
    throw std::runtime_error("cannot rename '" + temporary.string() + "' to the XDMF index '" +
                             xdmf_path_.string() + "': " + error.message());
  }
}

std::string XdmfWriter::step_grid(std::size_t step_index) const {
  std::ostringstream xml;
  xml << "      <Grid Name=\"saved_" << step_index
      << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "        <Time Value=\"" << round_trip_text(times_s_[step_index]) << "\"/>\n";
  for (const StructureEntry &structure : structures_) {
    xml << structure_grid(structure, step_index);
  }
  xml << "      </Grid>\n";
  return xml.str();
}

std::string XdmfWriter::structure_grid(const StructureEntry &structure,
                                       std::size_t step_index) const {
  const std::string indent = "            ";
  std::ostringstream xml;
  xml << "        <Grid Name=\"" << structure.name << "\" GridType=\"Uniform\">\n"
      << topology(structure) << "          <Geometry GeometryType=\"XYZ\">\n"
      << row_hyperslab(structure, paths::position_m, step_index, indent)
      << "          </Geometry>\n"
      << "          <Attribute Name=\"" << paths::velocity_m_per_s
      << "\" AttributeType=\"Vector\" Center=\"Node\">\n"
      << row_hyperslab(structure, paths::velocity_m_per_s, step_index, indent)
      << "          </Attribute>\n"
      << "        </Grid>\n";
  return xml.str();
}

std::string XdmfWriter::topology(const StructureEntry &structure) const {
  std::ostringstream xml;
  xml << "          <Topology TopologyType=\"" << structure.topology_type
      << "\" NumberOfElements=\"" << structure.n_cells << "\"";
  if (structure.topology_type == "Polyline") {
    xml << " NodesPerElement=\"" << structure.nodes_per_cell << "\"";
  }
  xml << ">\n"
      << "            <DataItem Dimensions=\"" << structure.n_cells << " "
      << structure.nodes_per_cell << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
      << hdf_reference(paths::structure_dataset(structure.name, paths::connectivity))
      << "</DataItem>\n"
      << "          </Topology>\n";
  return xml.str();
}

/// Row `step_index` of a [n_saved, n_points, 3] dataset, written so that both ParaView readers
/// read it (checked with ParaView 5.11 by tests/output/ParaViewOpenTest.cpp):
///   <DataItem Type="HyperSlab" Dimensions="1 n 3" NumberType="Float" Precision="8" Format="HDF">
///     run.h5:/structures/s/position_m|k 0 0:1 1 1:1 n 3:N n 3
///     <DataItem Dimensions="3 3" NumberType="Int" Format="XML">k 0 0 1 1 1 1 n 3</DataItem>
///     <DataItem Dimensions="N n 3" ... Format="HDF">run.h5:/structures/s/position_m</DataItem>
///   </DataItem>
/// - Xdmf3 (the default reader) ignores `Type` on a DataItem and reads the item as a plain HDF
///   array: its text is the Xdmf3 hyperslab form "file:dataset|start:stride:count:dataspace"
///   (row k only). Xdmf3 cannot show a real `ItemType="HyperSlab"`: it is a lazy reference whose
///   number type is unknown to VTK before reading ("Skipping unrecognized array type [None]").
/// - The legacy Xdmf2 reader (XDMFReader) takes `Type` as the XDMF 2 spelling of `ItemType`,
///   ignores the text, and selects start/stride/count from the two child items.
std::string XdmfWriter::row_hyperslab(const StructureEntry &structure, const std::string &dataset,
                                      std::size_t step_index, const std::string &indent) const {
  const std::string row_shape = std::to_string(structure.n_points) + " 3";
  const std::string all_rows = std::to_string(times_s_.size()) + " " + row_shape;
  const std::string reference = hdf_reference(paths::structure_dataset(structure.name, dataset));
  const std::string start = std::to_string(step_index) + " 0 0";
  std::ostringstream xml;
  xml << indent << "<DataItem Type=\"HyperSlab\" Dimensions=\"1 " << row_shape
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">\n"
      << indent << "  " << reference << "|" << start << ":1 1 1:1 " << row_shape << ":" << all_rows
      << "\n"
      << indent << "  <DataItem Dimensions=\"3 3\" NumberType=\"Int\" Format=\"XML\">" << start
      << " 1 1 1 1 " << row_shape << "</DataItem>\n"
      << indent << "  <DataItem Dimensions=\"" << all_rows
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << reference << "</DataItem>\n"
      << indent << "</DataItem>\n";
  return xml.str();
}

std::string XdmfWriter::hdf_reference(const std::string &dataset_path) const {
  return h5_reference_ + ":" + dataset_path;
}

} // namespace fsi::structure::output
