// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Section 4 of the paper: the square-pattern paths from face i to each of its
// neighbours, stored as one tree per face (each node knows its parent).

#ifndef CGAL_PMP_INTERNAL_DENOISING_SQUARE_PATTERN_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_SQUARE_PATTERN_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Region (0..5) of a point with areal coordinates (l0, l1, l2) relative to a
// triangle, or -1 if it lies inside or on the triangle. The six outer regions
// are the sign patterns with one or two negative coordinates; the region is
// read from a table by the pattern (no branch: the pattern of a neighbour is
// unpredictable).
inline int areal_region(double l0, double l1, double l2)
{
  // by mask (bit k: l_k < 0): 1 (-,+,+) beyond the edge opposite vertex 0,
  // 3 (-,-,+) beyond vertex 2, 2 (+,-,+) beyond the edge opposite vertex 1,
  // 6 (+,-,-) beyond vertex 0, 4 (+,+,-) beyond the edge opposite vertex 2,
  // 5 (-,+,-) beyond vertex 1; 0 is inside, and 7 cannot happen (the
  // coordinates sum to 1)
  static constexpr std::int8_t by_mask[8] = {-1, 0, 2, 1, 4, 5, 3, -1};
  const int mask = int(l0 < 0.) | (int(l1 < 0.) << 1) | (int(l2 < 0.) << 2);
  return by_mask[mask];
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

  Square_pattern_frame(const Flat_mesh& m, const Face_data& fd, std::size_t i)
  {
    const auto& t = m.triangles[i];
    a = m.points[t[0]];
    b = m.points[t[1]];
    c = m.points[t[2]];
    n = fd.normals[i];
    twice_area = dot(cross(b - a, c - a), n);
    degenerate = squared_norm(n) == 0. || !(twice_area > 0.);
  }

  // The region (0..5) of a neighbour with centroid p, or -1 if p projects
  // inside face i or on its border (dropped: section 4 has no region for it). A degenerate face i
  // puts every neighbour in region 0.
  int region(const Vec3& p) const
  {
    if(degenerate)
      return 0;
    const double l0 = dot(cross(b - p, c - p), n) / twice_area;
    const double l1 = dot(cross(c - p, a - p), n) / twice_area;
    return areal_region(l0, l1, 1. - l0 - l1);
  }
};

// Scratch of square_pattern_tree: the kept neighbours of face i in input
// order (`region`, `distance`), then in region order (`by_region_*`; the
// sort keys are the distance to c_i, then the input index, so renumbered
// faces (Flat_mesh::input_face) get the same trees); `sorted` for the large
// regions.
struct Square_pattern_scratch
{
  // ((distance, input index), face) of the nodes of a large region
  typedef std::vector<std::pair<std::pair<double, std::uint32_t>, std::uint32_t>> Sorted;
  std::vector<std::int32_t> region;
  std::vector<double> distance, by_region_distance;
  std::vector<std::uint32_t> by_region_input, by_region_face;
  Sorted sorted;
};

// Regions of more nodes than this are sorted by comparisons; smaller ones
// by counting (sort_square_pattern_region).
constexpr std::size_t square_pattern_counting_max = 128;

// Writes faces[0 .. n) to out in the order of (distance, input), a strict
// order (the input indices differ; no distance is NaN). Up to
// square_pattern_counting_max nodes, each node's place is the count of the
// nodes before it: branch-free, and for the few nodes of a region (about 12
// at r = 4d) faster than a comparison sort, whose every step is a coin toss
// (measured on 1.2M faces: the whole forest 2.11 s with std::sort, 1.81 s
// with this). Larger regions are sorted, in `sorted`.
inline void sort_square_pattern_region(const double* distance, const std::uint32_t* input, const std::uint32_t* faces,
                                       std::size_t n, std::uint32_t* out, Square_pattern_scratch::Sorted& sorted)
{
  if(n > square_pattern_counting_max)
  {
    sorted.resize(n);
    for(std::size_t k = 0; k < n; ++k)
      sorted[k] = {{distance[k], input[k]}, faces[k]};
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t k = 0; k < n; ++k)
      out[k] = sorted[k].second;
    return;
  }
  for(std::size_t a = 0; a < n; ++a)
  {
    const double da = distance[a];
    const std::uint32_t ia = input[a];
    std::uint32_t rank = 0;
    for(std::size_t b = 0; b < n; ++b)
      rank += std::uint32_t(distance[b] < da) | (std::uint32_t(distance[b] == da) & std::uint32_t(input[b] < ia));
    out[rank] = faces[a];
  }
}

// Appends to `out` the nodes of face i's square-pattern tree over its
// neighbours [nb, nb_end), region after region, each sorted by distance, and
// returns the region sizes (Path_forest::square_regions). Neighbours whose
// projected centroid falls inside face i are dropped (section 4 has no region for them). For a
// degenerate face i (zero normal) the regions are undefined: its neighbours
// are appended by distance and the sizes are all 0 (all hang from i).
inline std::array<std::uint32_t, 6> square_pattern_tree(const Flat_mesh& m, const Face_data& fd, std::size_t i,
                                                        const std::uint32_t* nb, const std::uint32_t* nb_end,
                                                        Square_pattern_scratch& s, std::vector<std::uint32_t>& out)
{
  const std::size_t n = std::size_t(nb_end - nb);
  if(s.region.size() < n)
  {
    s.region.resize(n);
    s.distance.resize(n);
    s.by_region_distance.resize(n);
    s.by_region_input.resize(n);
    s.by_region_face.resize(n);
  }
  const Vec3& ci = fd.centroids[i];
  const Vec3* centroids = fd.centroids.data();
  const Square_pattern_frame frame(m, fd, i); // a degenerate frame puts every neighbour in region 0
  // local pointers: the compiler need not reload them after every store
  std::int32_t* region = s.region.data();
  double* distance = s.distance.data();
  std::array<std::uint32_t, 6> sizes{};
  for(std::size_t k = 0; k < n; ++k)
  {
    const Vec3& cj = centroids[nb[k]];
    const int r = frame.region(cj);
    region[k] = r;
    const double d2 = squared_norm(cj - ci);
    // NaN (from coordinates near the largest double, whose sums overflow)
    // goes last: the sort needs a strict order
    distance[k] = d2 == d2 ? d2 : std::numeric_limits<double>::infinity();
    sizes[r < 0 ? 0 : r] += std::uint32_t(r >= 0);
  }
  // region after region, each in input order
  std::array<std::uint32_t, 6> start{};
  for(int r = 1; r < 6; ++r)
    start[r] = start[r - 1] + sizes[r - 1];
  const std::uint32_t kept = start[5] + sizes[5];
  std::array<std::uint32_t, 6> fill = start;
  double* by_region_distance = s.by_region_distance.data();
  std::uint32_t* by_region_input = s.by_region_input.data();
  std::uint32_t* by_region_face = s.by_region_face.data();
  for(std::size_t k = 0; k < n; ++k)
  {
    const int r = region[k];
    if(r < 0)
      continue;
    const std::uint32_t at = fill[r]++;
    by_region_distance[at] = distance[k];
    by_region_input[at] = m.input_index(nb[k]);
    by_region_face[at] = nb[k];
  }
  const std::size_t first = out.size();
  out.resize(first + kept);
  for(int r = 0; r < 6; ++r)
    sort_square_pattern_region(by_region_distance + start[r], by_region_input + start[r], by_region_face + start[r],
                               sizes[r], out.data() + first + start[r], s.sorted);
  if(squared_norm(fd.normals[i]) == 0.)
    sizes.fill(0);
  return sizes;
}

// Forests of at least this many nodes keep their parents as region sizes
// (Path_forest::square_regions, 4 bytes less per node), smaller ones store a
// parent per node, which filter passes without a kernel for region sizes read
// about 4% faster (1.2M faces: 0.223 against 0.232 s). Which layout a filter
// pass prefers is the caller's choice (intrinsic_setup.h: 0, region sizes
// always, where the AVX2 kernel runs).
constexpr std::size_t square_pattern_compact_min_nodes = std::size_t(1) << 25;

// The square-pattern forest of every face, its tree built over the
// neighbours that `neighbors(i, scratch)` returns ([begin, end) pointers;
// scratch.tree is the tree's scratch), with the parents stored per node
// below compact_min_nodes nodes and kept as region sizes from there on.
template <typename ConcurrencyTag, typename MakeScratch, typename Neighbors>
Path_forest square_pattern_forest(const Flat_mesh& m, const Face_data& fd, std::size_t compact_min_nodes,
                                  const MakeScratch& make_scratch, const Neighbors& neighbors)
{
  Path_forest forest;
  forest.square_regions.resize(m.number_of_faces());
  build_lists<ConcurrencyTag>(m.number_of_faces(), forest.offsets, forest.face, make_scratch,
                              [&](std::size_t i, auto& scratch, std::vector<std::uint32_t>& out) {
                                const auto range = neighbors(i, scratch);
                                forest.square_regions[i] =
                                    square_pattern_tree(m, fd, i, range.first, range.second, scratch.tree, out);
                              });
  if(forest.face.size() < compact_min_nodes)
    store_parents(forest);
  return forest;
}

// Builds the square-pattern forest on the mesh as it is (the paper computes
// it once, on the input mesh), from the neighbourhoods `neighbors`.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Path_forest square_pattern_paths(const Flat_mesh& m, const Face_data& fd, const Csr& neighbors,
                                 std::size_t compact_min_nodes = square_pattern_compact_min_nodes)
{
  struct Scratch
  {
    Square_pattern_scratch tree;
  };
  return square_pattern_forest<ConcurrencyTag>(
      m, fd, compact_min_nodes, [] { return Scratch(); },
      [&neighbors](std::size_t i, Scratch&) {
        return std::make_pair(neighbors.items.data() + neighbors.begin(i), neighbors.items.data() + neighbors.end(i));
      });
}

// The same forest for the geometric neighbourhoods of radius `radius`
// (geometric_neighborhoods(), with the cap of max_neighbors_within()), each face's neighbourhood searched and turned
// into its tree at once, so that the neighbourhoods of all faces are never
// held in memory together. Each tree is built in a chunk of the faces, and
// the chunks are then copied into the forest: without parents (kept as
// region sizes) the chunks and the forest together take the memory of one
// forest with parents.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Path_forest square_pattern_paths_within(const Flat_mesh& m, const Face_data& fd, double radius,
                                        std::size_t compact_min_nodes = square_pattern_compact_min_nodes)
{
  struct Scratch
  {
    Face_fan_search search;
    Square_pattern_scratch tree;
  };
  const double r2 = radius * radius;
  const std::size_t max_neighbors = max_neighbors_within(radius, fd);
  // the search reaches the faces geometric_neighborhoods() lists
  return square_pattern_forest<ConcurrencyTag>(
      m, fd, compact_min_nodes,
      [&m] {
        return Scratch{Face_fan_search(m), {}};
      },
      [&](std::size_t i, Scratch& s) {
        s.search.run(i, m, fd.centroids, r2, max_neighbors);
        return std::make_pair(s.search.neighbors_begin(), s.search.neighbors_end());
      });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
