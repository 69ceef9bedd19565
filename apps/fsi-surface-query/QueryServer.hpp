#pragma once
// The geometry engine of the Python post-processing, as a server on a pipe: the metrics of a
// rag in a pump (python/fsi/rag_metrics.py) ask it for the regions of an STL file, for exact
// distances of points to triangle sets (TriangleBvh) and for the close point pairs of a rag
// (SpatialHashGrid), so that they use the same geometry code as the solver.
//
// Protocol: one request is a text line, then its binary payload (native doubles and int64);
// one reply is a text line "ok ..." then its payload, or "error MESSAGE" (the request failed,
// the server goes on). All lengths in m.
//   regions PATH         -> ok R; per region: NAME line, then n line, then n x 9 doubles
//   set N + N x 9 doubles (triangles) -> ok ID KEPT   (zero-area triangles are left out)
//   nearest ID M CAPPED + M x 3 doubles [+ M doubles caps]
//                        -> ok; M doubles distance (inf: none within the cap), M int64
//                           triangle (index in the set's request; -1: none within the cap)
//   pairs F N D C + F x N x 3 doubles
//                        -> ok P; P x 3 int64 (frame, i, j), i < j, |x_i - x_j| < D, by frame,
//                           i, j; with C > 0 (the points a grid of C columns, point i at row
//                           i / C, column i % C) not grid neighbours: rows or columns 2 apart
//   quit                 -> the server ends (as at the end of its input)

#include "geometry/TriangleBvh.hpp"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace fsi::apps {

class QueryServer {
public:
  QueryServer(std::FILE *in, std::FILE *out);

  /// Answers requests until "quit" or the end of the input. Throws std::runtime_error on a
  /// request it cannot parse or a payload cut short: the pipe is then out of step.
  void serve();

private:
  struct TriangleSet {
    std::unique_ptr<geometry::TriangleBvh> bvh;
    std::vector<std::int32_t> request_index; ///< index in the request of each kept triangle
  };

  void answer(const std::string &line);
  void regions(const std::string &path);
  void add_set(long n_triangles);
  void nearest(long set, long n_points, bool capped);
  void pairs(long n_frames, long n_points, double distance_m, long grid_columns);

  std::vector<double> read_doubles(std::size_t count);
  void write_line(const std::string &line);
  template <typename T> void write_values(const std::vector<T> &values);

  std::FILE *in_;
  std::FILE *out_;
  std::vector<TriangleSet> sets_;
};

} // namespace fsi::apps
