// Hand-run timing of the per-step work of the immersed boundary on a ~300k-cell mesh
// (67^3 cells), not a test:  ./fsi bench kernel_stencil
//   StencilBuild/<n>        nearest cells + KernelStencil for n random points: the cost per
//                           step must grow linearly with n (compare the times per point);
//   Spread/Interpolate      the transfers with a built stencil;
//   IndexBuild              the KD-tree, built once per mesh;
//   BoxQueries:<index>/<mesh>  the support queries alone, KD-tree against a uniform bucket
//                           grid sized for the largest cells, on a uniform mesh and on
//                           graded ones (spacing varying by 9x and 39x along each axis),
//                           with points spread out or in the finest zone.

#include "TestMeshes.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"
#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

namespace fsi::fluid::ibm {
namespace {

constexpr int cells_per_side = 67; // 300,763 cells

/// grading 0: uniform; 1: spacing varying by 9x along each axis; 2: by 39x.
const EulerianCells &mesh(int grading) {
  static const EulerianCells meshes[3] = {testing::uniform_grid(cells_per_side, 1.0),
                                          testing::stretched_grid(cells_per_side, 1.0, 0.8),
                                          testing::stretched_grid(cells_per_side, 1.0, 0.95)};
  return meshes[grading];
}

const CellIndex &index_of(int grading) {
  static const CellIndex indices[3] = {CellIndex(mesh(0)), CellIndex(mesh(1)), CellIndex(mesh(2))};
  return indices[grading];
}

/// A uniform bucket grid over the cell centres (the alternative to the KD-tree).
class BucketGrid {
public:
  BucketGrid(const EulerianCells &cells, double bucket_m) : cells_(cells), bucket_m_(bucket_m) {
    lo_ = cells.centres_m().colwise().minCoeff().transpose();
    for (int a = 0; a < 3; ++a)
      n_[a] = static_cast<int>((cells.centres_m().col(a).maxCoeff() - lo_[a]) / bucket_m) + 1;
    std::vector<std::size_t> counts(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    for (CellId c = 0; c < cells.n_cells(); ++c)
      ++counts[bucket_of(cells.centre_m(c)) + 1];
    for (std::size_t b = 1; b < counts.size(); ++b)
      counts[b] += counts[b - 1];
    starts_ = counts;
    sorted_.resize(static_cast<std::size_t>(cells.n_cells()));
    for (CellId c = 0; c < cells.n_cells(); ++c)
      sorted_[counts[bucket_of(cells.centre_m(c))]++] = c;
  }
  void cells_in_box(const Vec3 &point_m, double half_m, std::vector<CellId> &found) const {
    found.clear();
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::clamp(static_cast<int>(std::floor((point_m[a] - half_m - lo_[a]) / bucket_m_)), 0, n_[a] - 1);
      hi[a] = std::clamp(static_cast<int>(std::floor((point_m[a] + half_m - lo_[a]) / bucket_m_)), 0, n_[a] - 1);
    }
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k) {
          const std::size_t b = (static_cast<std::size_t>(i) * n_[1] + j) * n_[2] + k;
          for (std::size_t p = starts_[b]; p < starts_[b + 1]; ++p)
            if ((cells_.centre_m(sorted_[p]) - point_m).cwiseAbs().maxCoeff() < half_m)
              found.push_back(sorted_[p]);
        }
  }

private:
  std::size_t bucket_of(const Vec3 &x) const {
    int i[3];
    for (int a = 0; a < 3; ++a)
      i[a] = std::min(static_cast<int>((x[a] - lo_[a]) / bucket_m_), n_[a] - 1);
    return (static_cast<std::size_t>(i[0]) * n_[1] + i[1]) * n_[2] + i[2];
  }
  const EulerianCells &cells_;
  double bucket_m_;
  Vec3 lo_;
  int n_[3];
  std::vector<std::size_t> starts_;
  std::vector<CellId> sorted_;
};

void StencilBuild(benchmark::State &state) {
  const PointArray points_m = testing::random_points(static_cast<int>(state.range(0)), 0.05, 0.95, 1);
  for (auto _ : state) {
    const NearestCells nearest(index_of(0), points_m);
    const KernelStencil stencil(index_of(0), points_m, nearest.kernel_width_m());
    benchmark::DoNotOptimize(stencil.n_pairs());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(StencilBuild)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void SpreadAndInterpolate(benchmark::State &state) {
  const PointArray points_m = testing::random_points(static_cast<int>(state.range(0)), 0.05, 0.95, 1);
  const NearestCells nearest(index_of(0), points_m);
  const KernelStencil stencil(index_of(0), points_m, nearest.kernel_width_m());
  const PointArray forces_n = testing::random_points(static_cast<int>(state.range(0)), -1, 1, 2);
  const PointArray velocity = testing::random_points(mesh(0).n_cells(), -1, 1, 3);
  for (auto _ : state) {
    benchmark::DoNotOptimize(stencil.spread_point_forces(forces_n).data());
    benchmark::DoNotOptimize(stencil.interpolate(velocity).data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(SpreadAndInterpolate)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

void IndexBuild(benchmark::State &state) {
  for (auto _ : state) {
    const CellIndex index(mesh(0));
    benchmark::DoNotOptimize(&index);
  }
}
BENCHMARK(IndexBuild)->Unit(benchmark::kMillisecond);

/// Box queries of the kernel support for 10^4 points; range(0): 0 KD-tree, 1 bucket grid;
/// range(1): the grading of the mesh; range(2): 0 points spread over the cube, 1 points in
/// its centre, where the graded meshes are finest (refinement goes where the structure is).
void BoxQueries(benchmark::State &state) {
  const int graded = static_cast<int>(state.range(1));
  const EulerianCells &cells = mesh(graded);
  const PointArray points_m = state.range(2) == 0 ? testing::random_points(10000, 0.05, 0.95, 1)
                                                  : testing::random_points(10000, 0.45, 0.55, 1);
  const NearestCells nearest(index_of(graded), points_m);
  const BucketGrid grid(cells, 2.0 * cells.sizes_m().maxCoeff());
  std::vector<CellId> found;
  std::size_t n_found = 0;
  for (auto _ : state)
    for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
      const double half_m = PeskinKernel::support_radius * nearest.kernel_width_m()[k];
      if (state.range(0) == 0)
        index_of(graded).cells_in_box(points_m.row(k).transpose(), half_m, found);
      else
        grid.cells_in_box(points_m.row(k).transpose(), half_m, found);
      n_found += found.size();
    }
  benchmark::DoNotOptimize(n_found);
  state.SetItemsProcessed(state.iterations() * points_m.rows());
}
BENCHMARK(BoxQueries)
    ->ArgNames({"grid", "graded", "refined_zone"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

} // namespace
} // namespace fsi::fluid::ibm

BENCHMARK_MAIN();
