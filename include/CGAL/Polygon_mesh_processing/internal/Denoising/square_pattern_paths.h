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

// Areal coordinates of the projection of p on the plane of triangle (a, b, c)
// with unit normal n. Returns false if the triangle is degenerate.
inline bool projected_areal_coordinates(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                        const Vec3& p, std::array<double, 3>& l)
{
  const double twice_area = dot(cross(b - a, c - a), n);
  if(!(twice_area > 0.))
    return false;
  // Projecting p along n changes none of these signed areas: each is a
  // determinant with n, so the projection is implicit.
  l[0] = dot(cross(b - p, c - p), n) / twice_area;
  l[1] = dot(cross(c - p, a - p), n) / twice_area;
  l[2] = 1. - l[0] - l[1];
  return true;
}

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
  const auto& t = m.triangles[i];
  const Vec3& ci = fd.centroids[i];
  const Vec3& ni = fd.normals[i];
  const bool degenerate = squared_norm(ni) == 0.;
  for(; nb != nb_end; ++nb)
  {
    const std::uint32_t j = *nb;
    const double dist = squared_norm(fd.centroids[j] - ci);
    std::array<double, 3> l;
    if(degenerate ||
       !projected_areal_coordinates(m.points[t[0]], m.points[t[1]], m.points[t[2]], ni, fd.centroids[j], l))
    {
      regions[0].emplace_back(dist, m.input_index(j), j);
      continue;
    }
    const int r = areal_region(l[0], l[1], l[2]);
    if(r >= 0)
      regions[r].emplace_back(dist, m.input_index(j), j);
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
// held in memory together.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Path_forest square_pattern_paths_within(const Flat_mesh& m, const Face_data& fd, double radius)
{
  struct Scratch
  {
    Neighborhood_search search;
    Square_pattern_regions regions;
  };
  const std::size_t n = m.number_of_faces();
  const double r2 = radius * radius;
  const Face_vertex_adjacency adjacent{m};
  Path_forest forest;
  build_lists<ConcurrencyTag, Path_node>(
      n, forest.offsets, [n] { return Scratch{Neighborhood_search(n), {}}; },
      [&](std::size_t i, Scratch& s, std::vector<Path_node>& out) {
        s.search.run(i, fd.centroids, adjacent, r2);
        square_pattern_tree(m, fd, i, s.search.queue.data() + 1, s.search.queue.data() + s.search.queue.size(),
                            s.regions, out);
      },
      [&forest](const std::vector<Path_node>& chunk) { forest.append_nodes(chunk); });
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
