// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Section 4 of the paper: the square-pattern paths from face i to each of its
// neighbours, stored as one tree per face (each node knows its parent).

#ifndef CGAL_PMP_INTERNAL_DENOISING_SQUARE_PATTERN_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_SQUARE_PATTERN_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/path_forest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>
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

// Region (0..5) of a point with areal coordinates (l0, l1, l2) relative to a
// triangle, or -1 if it lies inside or on the triangle. The six outer regions
// are the sign patterns with one or two negative coordinates.
inline int areal_region(double l0, double l1, double l2)
{
  const int mask = (l0 < 0. ? 1 : 0) | (l1 < 0. ? 2 : 0) | (l2 < 0. ? 4 : 0);
  switch(mask)
  {
  case 1: return 0; // (-,+,+): beyond the edge opposite vertex 0
  case 3: return 1; // (-,-,+): beyond vertex 2
  case 2: return 2; // (+,-,+): beyond the edge opposite vertex 1
  case 6: return 3; // (+,-,-): beyond vertex 0
  case 4: return 4; // (+,+,-): beyond the edge opposite vertex 2
  case 5: return 5; // (-,+,-): beyond vertex 1
  default: return -1; // inside (mask 0); mask 7 cannot happen (coordinates sum to 1)
  }
}

// Face i's frame for the regions of its neighbours (its corners, its normal
// and twice its area, computed once per face): region(p) takes the areal
// coordinates of the projection of p on the plane of face i. Projecting p
// along the unit normal n changes none of the signed areas below (each is a
// determinant with n), so the projection is implicit.
struct Square_pattern_frame
{
  Vec3 a, b, c, n;
  double twice_area = 0.;
  bool degenerate = true; // zero normal or area: every neighbour in region 0
  double reach2 = 0.;     // squared distance from c_i to its farthest corner

  Square_pattern_frame(const Flat_mesh& m, const Face_data& fd, std::size_t i)
  {
    const auto& t = m.triangles[i];
    a = m.points[t[0]];
    b = m.points[t[1]];
    c = m.points[t[2]];
    n = fd.normals[i];
    twice_area = dot(cross(b - a, c - a), n);
    degenerate = squared_norm(n) == 0. || !(twice_area > 0.);
    const Vec3& ci = fd.centroids[i];
    reach2 = (std::max)((std::max)(squared_norm(a - ci), squared_norm(b - ci)), squared_norm(c - ci));
  }

  // The region (0..5) of a neighbour with centroid p, or -1 if p projects
  // inside face i or on its border (dropped, NOTES 6). A degenerate face i
  // puts every neighbour in region 0.
  int region(const Vec3& p) const
  {
    if(degenerate)
      return 0;
    const double l0 = dot(cross(b - p, c - p), n) / twice_area;
    const double l1 = dot(cross(c - p, a - p), n) / twice_area;
    return areal_region(l0, l1, 1. - l0 - l1);
  }

  // Whether region(p) is certainly not -1, without computing it: face i lies
  // in the disk of radius sqrt(reach2) around c_i in its plane, so a point
  // whose projection is farther from c_i than that (by a relative margin far
  // above the rounding errors) projects outside face i.
  bool certainly_outside(const Vec3& p, const Vec3& ci) const
  {
    if(degenerate)
      return true;
    const Vec3 d = p - ci;
    const double h = dot(d, n);
    return squared_norm(d) - h * h > 1.0001 * reach2;
  }
};

// (distance, input index, face): ties in distance are broken by the input
// index, so renumbered faces (Flat_mesh::input_face) get the same trees
typedef std::array<std::vector<std::tuple<double, std::uint32_t, std::uint32_t>>, 6> Square_pattern_regions;

// Appends to `out` the square-pattern tree of face i over its neighbours
// [nb, nb_end) (parents local to the tree). Neighbours whose projected
// centroid falls inside face i are dropped (NOTES 6). For a degenerate face i
// (zero normal) the regions are undefined: all its neighbours hang directly
// from i.
inline void square_pattern_tree(const Flat_mesh& m, const Face_data& fd, std::size_t i, const std::uint32_t* nb,
                                const std::uint32_t* nb_end, Square_pattern_regions& regions,
                                std::vector<Path_node>& out)
{
  for(auto& r : regions)
    r.clear();
  const std::size_t item_begin = out.size(); // parents are local to the item's nodes
  const Vec3& ci = fd.centroids[i];
  const bool degenerate = squared_norm(fd.normals[i]) == 0.;
  const Square_pattern_frame frame(m, fd, i);
  for(; nb != nb_end; ++nb)
  {
    const std::uint32_t j = *nb;
    const int r = frame.region(fd.centroids[j]);
    if(r >= 0)
      regions[r].emplace_back(squared_norm(fd.centroids[j] - ci), m.input_index(j), j);
  }
  for(auto& r : regions)
  {
    std::sort(r.begin(), r.end()); // by distance, ties by input face index
    const std::int32_t start = std::int32_t(out.size() - item_begin);
    for(std::size_t k = 1; k <= r.size(); ++k)
    {
      std::int32_t parent = Path_forest::root;
      if(!degenerate)
      {
        const std::uint32_t pk = square_pattern_parent_rank(std::uint32_t(k));
        parent = pk == 0 ? Path_forest::root : start + std::int32_t(pk) - 1;
      }
      out.push_back(Path_node{std::get<2>(r[k - 1]), parent});
    }
  }
}

// Builds the square-pattern forest on the mesh as it is (the paper computes
// it once, on the input mesh), from the neighbourhoods `neighbors`.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Path_forest square_pattern_paths(const Flat_mesh& m, const Face_data& fd, const Csr& neighbors)
{
  Path_forest forest;
  build_lists<ConcurrencyTag, Path_node>(
      m.number_of_faces(), forest.offsets, [] { return Square_pattern_regions(); },
      [&](std::size_t i, Square_pattern_regions& regions, std::vector<Path_node>& out) {
        square_pattern_tree(m, fd, i, neighbors.items.data() + neighbors.begin(i),
                            neighbors.items.data() + neighbors.end(i), regions, out);
      },
      [&forest](const std::vector<Path_node>& chunk) { forest.append_nodes(chunk); });
  return forest;
}

// The same forest for the geometric neighbourhoods of radius `radius`
// (geometric_neighborhoods()), each face's neighbourhood searched and turned
// into its tree at once, so that the neighbourhoods of all faces are never
// held in memory together. From `two_pass_min_faces` faces on, the trees are
// written straight into the forest: a first pass counts each face's nodes
// (neighbourhood search and regions, no sort), a second builds the trees
// into place. That searches every neighbourhood twice (about a third more
// time for this stage) but never holds the trees twice: with per-chunk lists
// and one final copy, the chunks and the forest coexist, and the freed chunks
// are often not given back to the system (measured: 1042 MiB against 839 MiB
// for 1.2M faces). Both ways build the same forest.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Path_forest square_pattern_paths_within(const Flat_mesh& m, const Face_data& fd, double radius,
                                        std::size_t two_pass_min_faces = 200000)
{
  struct Scratch
  {
    Face_fan_search search;
    Square_pattern_regions regions;
    std::vector<Path_node> nodes;
  };
  const std::size_t n = m.number_of_faces();
  const double r2 = radius * radius;
  // the search reaches the faces geometric_neighborhoods() lists, in another
  // order; the trees do not depend on the order (they are sorted)
  Path_forest forest;
  if(n < two_pass_min_faces)
  {
    build_lists<ConcurrencyTag, Path_node>(
        n, forest.offsets, [&m] { return Scratch{Face_fan_search(m), {}, {}}; },
        [&](std::size_t i, Scratch& s, std::vector<Path_node>& out) {
          s.search.run(i, m, fd.centroids, r2);
          square_pattern_tree(m, fd, i, s.search.neighbors_begin(), s.search.neighbors_end(), s.regions, out);
        },
        [&forest](const std::vector<Path_node>& chunk) { forest.append_nodes(chunk); });
    return forest;
  }
  // few chunks: each allocates a search state as large as the mesh
  const std::size_t grain = (std::max)(std::size_t(2048), n / 64 + 1);
  forest.offsets.assign(n + 1, 0);
  for_each_chunk<ConcurrencyTag>(
      n,
      [&](std::size_t b, std::size_t e) {
        Face_fan_search search(m);
        for(std::size_t i = b; i < e; ++i)
        {
          search.run(i, m, fd.centroids, r2);
          const Square_pattern_frame frame(m, fd, i);
          const Vec3& ci = fd.centroids[i];
          std::uint32_t count = 0;
          for(const std::uint32_t* q = search.neighbors_begin(); q != search.neighbors_end(); ++q)
          {
            const Vec3& p = fd.centroids[*q];
            count += frame.certainly_outside(p, ci) || frame.region(p) >= 0 ? 1 : 0;
          }
          forest.offsets[i + 1] = count;
        }
      },
      grain);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(forest.offsets[i + 1] > (std::numeric_limits<std::uint32_t>::max)() - forest.offsets[i])
      throw std::length_error("square_pattern_paths_within: more than 2^32 path nodes");
    forest.offsets[i + 1] += forest.offsets[i];
  }
  forest.face.resize(forest.offsets[n]);
  forest.parent.resize(forest.offsets[n]);
  for_each_chunk<ConcurrencyTag>(
      n,
      [&](std::size_t b, std::size_t e) {
        Scratch s{Face_fan_search(m), {}, {}};
        for(std::size_t i = b; i < e; ++i)
        {
          s.search.run(i, m, fd.centroids, r2);
          s.nodes.clear();
          square_pattern_tree(m, fd, i, s.search.neighbors_begin(), s.search.neighbors_end(), s.regions, s.nodes);
          if(s.nodes.size() != forest.offsets[i + 1] - forest.offsets[i]) // both passes classify alike
            throw std::logic_error("square_pattern_paths_within: the two passes disagree");
          for(std::size_t k = 0; k < s.nodes.size(); ++k)
          {
            forest.face[forest.offsets[i] + k] = s.nodes[k].face;
            forest.parent[forest.offsets[i] + k] = s.nodes[k].parent;
          }
        }
      },
      grain);
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
