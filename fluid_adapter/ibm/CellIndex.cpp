#include "fluid_adapter/ibm/CellIndex.hpp"

#include <nanoflann.hpp>

#include <cmath>
#include <limits>

namespace fsi::fluid::ibm {
namespace {

/// nanoflann's view of the cell centres.
struct CentreCloud {
  const PointArray &centres_m;
  std::size_t kdtree_get_point_count() const { return static_cast<std::size_t>(centres_m.rows()); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const {
    return centres_m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(axis));
  }
  template <class Box> bool kdtree_get_bbox(Box &) const { return false; }
};

} // namespace

struct CellIndex::Tree {
  using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, CentreCloud>,
                                                     CentreCloud, 3, std::uint32_t>;
  explicit Tree(const PointArray &centres_m)
      : cloud{centres_m}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(leaf_size)) {}

  /// Box search over the tree's nodes: nanoflann searches balls only, and the ball around
  /// the box holds 2.7 times as many cells. divlow / divhigh are the largest coordinate of
  /// the first child and the smallest of the second along divfeat.
  void search_box(const KdTree::Node *node, const Vec3 &lo_m, const Vec3 &hi_m, std::vector<CellId> &found) const {
    if (node->child1 == nullptr && node->child2 == nullptr) {
      for (auto i = node->node_type.lr.left; i < node->node_type.lr.right; ++i) {
        const auto cell = static_cast<Eigen::Index>(tree.vAcc[i]);
        const auto centre = cloud.centres_m.row(cell);
        if ((centre.array() > lo_m.transpose().array()).all() && (centre.array() < hi_m.transpose().array()).all())
          found.push_back(static_cast<CellId>(cell));
      }
      return;
    }
    const auto axis = static_cast<Eigen::Index>(node->node_type.sub.divfeat);
    if (lo_m[axis] < node->node_type.sub.divlow)
      search_box(node->child1, lo_m, hi_m, found);
    if (hi_m[axis] > node->node_type.sub.divhigh)
      search_box(node->child2, lo_m, hi_m, found);
  }

  static constexpr std::size_t leaf_size = 16;
  CentreCloud cloud;
  KdTree tree;
};

CellIndex::CellIndex(const EulerianCells &cells)
    : cells_(cells), tree_(std::make_unique<Tree>(cells.centres_m())) {
  for (Eigen::Index c = 0; c < cells.n_cells(); ++c)
    centre_box_m_.extend(Vec3(cells.centres_m().row(c).transpose()));
}

CellIndex::~CellIndex() = default;
CellIndex::CellIndex(CellIndex &&) noexcept = default;

void CellIndex::cells_in_box(const Vec3 &point_m, double half_width_m, std::vector<CellId> &found) const {
  found.clear();
  if (cells_.n_cells() == 0)
    return;
  const Vec3 half(half_width_m, half_width_m, half_width_m);
  const Eigen::AlignedBox3d box(point_m - half, point_m + half);
  if (!centre_box_m_.intersects(box))
    return; // a rank far from the point (the tree would walk down to a leaf to find nothing)
  tree_->search_box(tree_->tree.root_node, box.min(), box.max(), found);
}

CellIndex::Nearest CellIndex::nearest(const Vec3 &point_m) const {
  Nearest nearest{-1, std::numeric_limits<double>::infinity()};
  if (cells_.n_cells() == 0)
    return nearest;
  std::uint32_t cell = 0;
  double distance_sq_m2 = 0.0;
  nanoflann::KNNResultSet<double, std::uint32_t> result(1);
  result.init(&cell, &distance_sq_m2);
  tree_->tree.findNeighbors(result, point_m.data(), nanoflann::SearchParams());
  nearest.cell = static_cast<CellId>(cell);
  nearest.distance_m = std::sqrt(distance_sq_m2);
  return nearest;
}

CellIndex::Nearest CellIndex::nearest_within(const Vec3 &point_m, double beyond_m) const {
  if (cells_.n_cells() > 0) {
    const double lower_bound_m = centre_box_m_.exteriorDistance(point_m);
    if (lower_bound_m > beyond_m)
      return {-1, lower_bound_m};
  }
  return nearest(point_m);
}

} // namespace fsi::fluid::ibm
