// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Paths from an item (face or vertex) to each of its neighbours, stored as one
// tree per item; the sums of eq. 9 are accumulated along them.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_FOREST_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_FOREST_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Square pattern: parent of rank k (k = 1, 2, ...) in a region is the rank
// (ceil(sqrt(k)) - 1)^2, rank 0 standing for face i: 1 -> i, 2..4 -> 1,
// 5..9 -> 4, 10..16 -> 9, ...
inline std::uint32_t square_pattern_parent_rank(std::uint32_t k)
{
  std::uint32_t s = 0;
  while(s * s < k)
    ++s; // s = ceil(sqrt(k))
  return (s - 1) * (s - 1);
}

// The local parents of the first `size` ranks of a region starting at local
// index 0: local[k] = square_pattern_parent_rank(k + 1) - 1, that is -1 (the
// root) for rank 1. Path_forest::parents() writes the first `width` of them
// for every region, whatever its size.
struct Square_pattern_parent_table
{
  static constexpr std::uint32_t width = 32, size = 1024;
  std::int32_t local[size];
  Square_pattern_parent_table()
  {
    for(std::uint32_t k = 0; k < size; ++k)
      local[k] = std::int32_t(square_pattern_parent_rank(k + 1)) - 1;
  }
  static const Square_pattern_parent_table& instance()
  {
    static const Square_pattern_parent_table table;
    return table;
  }
};

// The paths of every item (face or vertex), as trees rooted at the item. The
// nodes of item i
// are nodes offsets[i] .. offsets[i+1]-1; node k is item `face[k]` and its
// parent is node `offsets[i] + parent[k]`, or item i itself when parent[k] is
// `root`. A parent always comes before its children, so one forward sweep
// over a face's nodes accumulates every path sum (eq. 9).
//
// The parents are stored one of two ways:
// - `parent[k]`, one per node (geodesic, graph and direct paths);
// - for square-pattern trees (section 4), `square_regions[i]`, the sizes of
//   the six regions of face i, whose nodes are stored region after region,
//   each region sorted by distance: the node of rank k (1, 2, ...) in its
//   region hangs from the node of rank (ceil(sqrt(k)) - 1)^2 of the same
//   region, rank 0 being face i. Six zero sizes for a face with nodes mark a
//   degenerate face i (no plane to split), whose nodes all hang from i.
//   That is 24 bytes per face instead of 4 per node (about 60 per face).
// `parents(i, scratch)` gives item i's local parents either way.
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
  std::vector<std::int32_t> parent;                         // local to the face's node range; empty with square_regions
  std::vector<std::array<std::uint32_t, 6>> square_regions; // by face, instead of `parent`
  std::vector<char> weighted;                               // empty: every node is weighted
  std::vector<double> step;                                 // empty: every step length is 1

  // The local parents of item i's nodes (node offsets[i] + k hangs from node
  // offsets[i] + parents(i)[k], or from item i if that is `root`): the
  // stored array, or, for square-pattern trees, `scratch` filled from the
  // region sizes (room for the item's node count plus
  // Square_pattern_parent_table::width).
  const std::int32_t* parents(std::size_t i, std::int32_t* scratch) const
  {
    if(square_regions.empty())
      return parent.data() + offsets[i];
    const std::uint32_t count = offsets[i + 1] - offsets[i];
    const Square_pattern_parent_table& table = Square_pattern_parent_table::instance();
    const std::uint32_t width = Square_pattern_parent_table::width, tabled = Square_pattern_parent_table::size;
    std::uint32_t start = 0; // local index of the region's first node
    for(const std::uint32_t size : square_regions[i])
    {
      std::int32_t* out = scratch + start;
      // a fixed number of values, whatever the size (no loop exit to
      // mispredict); the next region overwrites those past its end
      for(std::uint32_t k = 0; k < width; ++k)
        out[k] = std::int32_t(start) + table.local[k];
      out[0] = root; // rank 1 (written past the last node when size is 0)
      for(std::uint32_t k = width; k < size && k < tabled; ++k)
        out[k] = std::int32_t(start) + table.local[k];
      for(std::uint32_t k = tabled; k < size; ++k)
        out[k] = std::int32_t(start + square_pattern_parent_rank(k + 1)) - 1;
      start += size;
    }
    if(start != count) // degenerate face i: every node hangs from i
      std::fill(scratch, scratch + count, root);
    return scratch;
  }

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

// Every node's local parent, one per node, whichever way the forest stores
// them.
inline std::vector<std::int32_t> all_parents(const Path_forest& forest)
{
  std::vector<std::int32_t> all(forest.face.size());
  std::vector<std::int32_t> scratch(forest.max_nodes_per_face() + Square_pattern_parent_table::width);
  for(std::size_t i = 0; i < forest.number_of_faces(); ++i)
  {
    const std::int32_t* p = forest.parents(i, scratch.data());
    std::copy(p, p + (forest.offsets[i + 1] - forest.offsets[i]), all.begin() + forest.offsets[i]);
  }
  return all;
}

// Stores the parents of a square-pattern forest one per node (the faster
// form for the filter passes), dropping the region sizes.
inline void store_parents(Path_forest& forest)
{
  if(forest.square_regions.empty())
    return;
  forest.parent = all_parents(forest);
  std::vector<std::array<std::uint32_t, 6>>().swap(forest.square_regions);
}

// Step lengths of eq. 4: the distance between the positions of each node and
// of its parent (item i for a root child), divided by `unit`.
inline void set_step_lengths(Path_forest& forest, const std::vector<Vec3>& positions, double unit)
{
  forest.step.resize(forest.face.size());
  std::vector<std::int32_t> scratch(forest.max_nodes_per_face() + Square_pattern_parent_table::width);
  for(std::size_t i = 0; i < forest.number_of_faces(); ++i)
  {
    const std::int32_t* parent = forest.parents(i, scratch.data());
    for(std::uint32_t k = forest.offsets[i]; k < forest.offsets[i + 1]; ++k)
    {
      const std::int32_t p = parent[k - forest.offsets[i]];
      const std::size_t from = p == Path_forest::root ? i : forest.face[forest.offsets[i] + p];
      forest.step[k] = norm(positions[forest.face[k]] - positions[from]) / unit;
    }
  }
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
