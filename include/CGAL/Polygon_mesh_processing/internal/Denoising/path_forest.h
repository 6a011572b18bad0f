// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Paths from an item (face or vertex) to each of its neighbours, stored as one
// tree per item; the sums of eq. 9 are accumulated along them.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_FOREST_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_FOREST_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// The paths of every item (face or vertex), as trees rooted at the item. The
// nodes of item i
// are nodes offsets[i] .. offsets[i+1]-1; node k is item `face[k]` and its
// parent is node `offsets[i] + parent[k]`, or item i itself when parent[k] is
// `root`. A parent always comes before its children, so one forward sweep
// over a face's nodes accumulates every path sum (eq. 9).
//
// Two optional per-node arrays (empty: the square pattern's case):
// - `weighted[k] == 0` marks a node that only lies on paths (a face a
//   geodesic crosses on its way to a neighbour) and gets no weight itself;
// - `step[k]` is the step length ||q_k - q_parent|| of eq. 4, multiplying the
//   node's terms of both sums (empty: step length 1, as in eq. 8-9).
// A node of a path tree: the item and its parent (local index or root).
struct Path_node
{
  std::uint32_t face;
  std::int32_t parent;
};

struct Path_forest
{
  static constexpr std::int32_t root = -1;
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> face;
  std::vector<std::int32_t> parent; // local to the face's node range
  std::vector<char> weighted;       // empty: every node is weighted
  std::vector<double> step;         // empty: every step length is 1

  // appends nodes (of the trees, in order) to face and parent, reserving
  // room for all nodes (offsets complete) at the first call
  template <typename Nodes>
  void append_nodes(const Nodes& nodes)
  {
    if(face.capacity() < offsets.back())
    {
      face.reserve(offsets.back());
      parent.reserve(offsets.back());
    }
    for(const auto& node : nodes)
    {
      face.push_back(node.face);
      parent.push_back(node.parent);
    }
  }

  bool is_weighted(std::size_t k) const { return weighted.empty() || weighted[k] != 0; }
  double step_length(std::size_t k) const { return step.empty() ? 1. : step[k]; }

  std::size_t number_of_faces() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::size_t max_nodes_per_face() const
  {
    std::size_t mx = 0;
    for(std::size_t f = 0; f + 1 < offsets.size(); ++f)
      mx = (std::max)(mx, std::size_t(offsets[f + 1] - offsets[f]));
    return mx;
  }
};

// Direct paths L = {i, j}: every neighbour hangs from item i.
inline Path_forest direct_paths(const Csr& neighbors)
{
  Path_forest forest;
  forest.offsets = neighbors.offsets;
  forest.face = neighbors.items;
  forest.parent.assign(neighbors.items.size(), Path_forest::root);
  return forest;
}

// Step lengths of eq. 4: the distance between the positions of each node and
// of its parent (item i for a root child), divided by `unit`.
inline void set_step_lengths(Path_forest& forest, const std::vector<Vec3>& positions, double unit)
{
  forest.step.resize(forest.face.size());
  for(std::size_t i = 0; i < forest.number_of_faces(); ++i)
    for(std::uint32_t k = forest.offsets[i]; k < forest.offsets[i + 1]; ++k)
    {
      const std::int32_t p = forest.parent[k];
      const std::size_t from = p == Path_forest::root ? i : forest.face[forest.offsets[i] + p];
      forest.step[k] = norm(positions[forest.face[k]] - positions[from]) / unit;
    }
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
