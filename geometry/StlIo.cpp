#include "geometry/StlIo.hpp"

#include "geometry/MeshErrors.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace fsi::geometry {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84; // 80-byte header + uint32 triangle count
constexpr std::size_t kBinaryFacetBytes = 50;  // 12 floats + uint16 attribute

using Corner = std::array<double, 3>;

struct CornerHash {
  std::size_t operator()(const Corner &c) const {
    std::size_t seed = 0;
    for (double value : c) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &value, sizeof bits);
      seed ^= std::hash<std::uint64_t>{}(bits) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
    }
    return seed;
  }
};

/// Turns a list of triangle corners (3 per triangle) into an indexed mesh, merging corners
/// with identical coordinates (-0.0 and 0.0 are the same corner).
TriangleSoup weld_corners(const std::vector<Corner> &corners) {
  std::unordered_map<Corner, int, CornerHash> index_of;
  std::vector<Corner> unique;
  TriangleSoup soup;
  soup.triangles.resize(static_cast<Eigen::Index>(corners.size() / 3), 3);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Corner c{corners[k][0] + 0.0, corners[k][1] + 0.0, corners[k][2] + 0.0};
    const auto [it, inserted] = index_of.emplace(c, static_cast<int>(unique.size()));
    if (inserted) {
      unique.push_back(c);
    }
    soup.triangles(static_cast<Eigen::Index>(k / 3), static_cast<Eigen::Index>(k % 3)) = it->second;
  }
  soup.vertices_m.resize(static_cast<Eigen::Index>(unique.size()), 3);
  for (std::size_t v = 0; v < unique.size(); ++v) {
    soup.vertices_m.row(static_cast<Eigen::Index>(v)) << unique[v][0], unique[v][1], unique[v][2];
  }
  return soup;
}

std::string read_all_bytes(const std::string &path) {
  if (!std::filesystem::exists(path)) {
    throw MeshFileNotFoundError(path);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw MeshFileUnreadableError(path, "it cannot be opened for reading");
  }
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool looks_binary(const std::string &bytes) {
  if (bytes.size() < kBinaryHeaderBytes) {
    return false;
  }
  std::uint32_t n_triangles = 0;
  std::memcpy(&n_triangles, bytes.data() + 80, sizeof n_triangles); // little-endian host
  return bytes.size() == kBinaryHeaderBytes + kBinaryFacetBytes * std::size_t{n_triangles};
}

/// Triangle corners as read (3 per triangle) and the region of each triangle.
struct ParsedStl {
  std::vector<Corner> corners;
  std::vector<int> region_of_triangle;
  std::vector<std::string> region_names;
};

ParsedStl parse_binary(const std::string &bytes) {
  const std::size_t n_triangles = (bytes.size() - kBinaryHeaderBytes) / kBinaryFacetBytes;
  ParsedStl parsed;
  parsed.corners.reserve(3 * n_triangles);
  for (std::size_t t = 0; t < n_triangles; ++t) {
    const char *facet = bytes.data() + kBinaryHeaderBytes + t * kBinaryFacetBytes;
    for (int corner = 0; corner < 3; ++corner) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * (corner + 1), sizeof xyz); // skip the facet normal
      parsed.corners.push_back({xyz[0], xyz[1], xyz[2]});
    }
  }
  parsed.region_names = {""};
  parsed.region_of_triangle.assign(n_triangles, 0);
  return parsed;
}

/// The rest of the current line, without surrounding blanks: the name after `solid`.
std::string rest_of_line(std::istream &in) {
  std::string line;
  std::getline(in, line);
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

/// Index of the region called `name`, added if new.
int region_index(std::vector<std::string> &names, const std::string &name) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found != names.end())
    return static_cast<int>(found - names.begin());
  names.push_back(name);
  return static_cast<int>(names.size()) - 1;
}

ParsedStl parse_ascii(const std::string &bytes, const std::string &path) {
  std::istringstream in(bytes);
  std::string word;
  if (!(in >> word) || word != "solid") {
    throw MeshFileUnreadableError(path, "it is neither binary STL nor ASCII STL starting "
                                        "with 'solid'");
  }
  ParsedStl parsed;
  int region = region_index(parsed.region_names, rest_of_line(in));
  while (in >> word) {
    if (word == "solid") {
      region = region_index(parsed.region_names, rest_of_line(in));
      continue;
    }
    if (word != "vertex") {
      continue;
    }
    Corner c{};
    if (!(in >> c[0] >> c[1] >> c[2])) {
      throw MeshFileUnreadableError(path, "vertex " + std::to_string(parsed.corners.size() + 1) +
                                              " does not have three numeric coordinates");
    }
    parsed.corners.push_back(c);
    if (parsed.corners.size() % 3 == 0)
      parsed.region_of_triangle.push_back(region);
  }
  if (parsed.corners.size() % 3 != 0) {
    throw MeshFileUnreadableError(path, "its vertex count " + std::to_string(parsed.corners.size()) +
                                            " is not a multiple of three");
  }
  return parsed;
}

void append_float(std::string &out, float value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  out.append(raw, sizeof value);
}

Vec3 facet_normal(const TriangleSoup &soup, Eigen::Index t) {
  const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose();
  const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose();
  const Vec3 c = soup.vertices_m.row(soup.triangles(t, 2)).transpose();
  const Vec3 n = (b - a).cross(c - a);
  return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
}

std::string encode_binary(const TriangleSoup &soup) {
  std::string out(80, '\0');
  std::memcpy(out.data(), "binary STL written by fsi_collision", 35);
  const auto n_triangles = static_cast<std::uint32_t>(soup.triangles.rows());
  out.append(reinterpret_cast<const char *>(&n_triangles), sizeof n_triangles);
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 n = facet_normal(soup, t);
    for (int k = 0; k < 3; ++k)
      append_float(out, static_cast<float>(n[k]));
    for (int corner = 0; corner < 3; ++corner) {
      for (int k = 0; k < 3; ++k) {
        append_float(out, static_cast<float>(soup.vertices_m(soup.triangles(t, corner), k)));
      }
    }
    out.append(2, '\0'); // attribute byte count
  }
  return out;
}

/// ASCII STL with one `solid NAME` block per entry of `blocks` (the triangles it holds).
std::string encode_ascii(const TriangleSoup &soup, const std::vector<std::string> &names,
                         const std::vector<std::vector<Eigen::Index>> &blocks) {
  std::ostringstream out;
  out.precision(17);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    out << "solid " << names[b] << '\n';
    for (const Eigen::Index t : blocks[b]) {
      const Vec3 n = facet_normal(soup, t);
      out << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n    outer loop\n";
      for (int corner = 0; corner < 3; ++corner) {
        const auto row = soup.vertices_m.row(soup.triangles(t, corner));
        out << "      vertex " << row(0) << ' ' << row(1) << ' ' << row(2) << '\n';
      }
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid " << names[b] << '\n';
  }
  return out.str();
}

std::string encode_ascii(const TriangleSoup &soup) {
  std::vector<Eigen::Index> all(static_cast<std::size_t>(soup.triangles.rows()));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  return encode_ascii(soup, {"fsi_collision"}, {all});
}

void write_bytes(const std::string &path, const std::string &bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    throw std::runtime_error("cannot write STL file '" + path + "'; check that the folder exists and is writable.");
  }
}

} // namespace

RegionSoup read_stl_regions(const std::string &path) {
  const std::string bytes = read_all_bytes(path);
  if (bytes.empty()) {
    throw MeshFileUnreadableError(path, "the file is empty");
  }
  ParsedStl parsed = looks_binary(bytes) ? parse_binary(bytes) : parse_ascii(bytes, path);
  if (parsed.corners.empty()) {
    throw MeshFileUnreadableError(path, "it contains no triangle");
  }
  return {weld_corners(parsed.corners), std::move(parsed.region_names), std::move(parsed.region_of_triangle)};
}

TriangleSoup read_stl(const std::string &path) { return read_stl_regions(path).soup; }

void write_stl(const std::string &path, const TriangleSoup &soup, StlFormat format) {
  write_bytes(path, format == StlFormat::binary ? encode_binary(soup) : encode_ascii(soup));
}

void write_stl_regions(const std::string &path, const RegionSoup &regions) {
  const auto n_triangles = static_cast<std::size_t>(regions.soup.triangles.rows());
  if (regions.region_of_triangle.size() != n_triangles)
    throw std::invalid_argument("write_stl_regions: region_of_triangle has " +
                                std::to_string(regions.region_of_triangle.size()) + " entries for " +
                                std::to_string(n_triangles) + " triangles");
  std::vector<std::vector<Eigen::Index>> blocks(regions.region_names.size());
  for (std::size_t t = 0; t < n_triangles; ++t) {
    const int r = regions.region_of_triangle[t];
    if (r < 0 || static_cast<std::size_t>(r) >= blocks.size())
      throw std::invalid_argument("write_stl_regions: triangle " + std::to_string(t) + " has region " +
                                  std::to_string(r) + ", not one of the " + std::to_string(blocks.size()) +
                                  " region names");
    blocks[static_cast<std::size_t>(r)].push_back(static_cast<Eigen::Index>(t));
  }
  write_bytes(path, encode_ascii(regions.soup, regions.region_names, blocks));
}

} // namespace fsi::geometry
