// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Geometric neighbourhoods (as in Zhang et al. 2015, used by eq. 8): the faces
// connected to face i through shared vertices whose centroid lies within a
// radius of c_i, grown by breadth-first search; likewise for vertices through
// edges. Stored in CSR form.

#ifndef CGAL_PMP_INTERNAL_DENOISING_NEIGHBORHOODS_H
#define CGAL_PMP_INTERNAL_DENOISING_NEIGHBORHOODS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Lists of indices by face: the items of face f are
// items[offsets[f]] .. items[offsets[f+1]-1].
struct Csr
{
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> items;

  std::size_t size() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::uint32_t begin(std::size_t f) const { return offsets[f]; }
  std::uint32_t end(std::size_t f) const { return offsets[f + 1]; }
};

// Calls f(g) for every face g sharing a vertex with face f (f itself included).
struct Face_vertex_adjacency
{
  const Flat_mesh& m;
  template <typename F>
  void operator()(std::uint32_t f, const F& fn) const
  {
    for(std::uint32_t v : m.triangles[f])
      for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
        fn(m.vertex_faces[k]);
  }
};

// Calls f(w) for every item w listed for item v in a CSR adjacency (the
// vertices joined to v by an edge, the faces sharing a vertex with v...).
struct Csr_adjacency
{
  const Csr& adjacency;
  template <typename F>
  void operator()(std::uint32_t v, const F& fn) const
  {
    for(std::uint32_t k = adjacency.begin(v); k < adjacency.end(v); ++k)
      fn(adjacency.items[k]);
  }
};
typedef Csr_adjacency Vertex_edge_adjacency; // over vertex_adjacency()

// The vertices joined to each vertex by an edge, in increasing order.
inline Csr vertex_adjacency(const Flat_mesh& m)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<std::vector<std::uint32_t>> lists(nv);
  for(const auto& t : m.triangles)
    for(int k = 0; k < 3; ++k)
    {
      lists[t[k]].push_back(t[(k + 1) % 3]);
      lists[t[(k + 1) % 3]].push_back(t[k]);
    }
  Csr csr;
  csr.offsets.assign(nv + 1, 0);
  for(std::size_t v = 0; v < nv; ++v)
  {
    auto& l = lists[v];
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    csr.offsets[v + 1] = csr.offsets[v] + std::uint32_t(l.size());
  }
  csr.items.reserve(csr.offsets[nv]);
  for(const auto& l : lists)
    csr.items.insert(csr.items.end(), l.begin(), l.end());
  return csr;
}

// No limit on the size of a neighbourhood.
constexpr std::size_t unlimited_neighbors = std::size_t(-1);

// The mark of a new search in stamp arrays (-1 = never visited): a new
// value for each search, so that an abandoned search leaves no item marked
// as visited by the next one; the arrays are cleared when the marks run out.
template <typename... Stamps>
std::uint32_t fresh_mark(std::uint32_t& next_mark, Stamps&... stamps)
{
  if(next_mark == std::uint32_t(-1))
  {
    (std::fill(stamps.begin(), stamps.end(), std::uint32_t(-1)), ...);
    next_mark = 0;
  }
  return next_mark++;
}

// The largest neighbourhood searched for a face with a radius r: 16 times
// the number of faces a disc of radius r holds at the mesh's mean face area
// (and at least 256). A geometric neighbourhood grows with the local density
// of faces: where the faces are much smaller than on average (a locally
// refined region, or a connected component modelled at a much finer scale
// than the rest), a radius set from the mean spacing would take in
// thousands of faces, each costing a path and a weight at every iteration.
// There the radius is halved until the neighbourhood holds no more than
// this; elsewhere (on regular meshes a neighbourhood holds about 2.4 r^2 /
// d^2 faces, d the mean distance between adjacent centroids) it is the
// paper's neighbourhood, unchanged.
inline std::size_t max_neighbors_within(double radius, double mean_face_area)
{
  const double pi = 3.14159265358979323846;
  if(!(mean_face_area > 0.) || !std::isfinite(radius))
    return unlimited_neighbors;
  const double faces_in_disc = pi * radius * radius / mean_face_area;
  const double cap = std::max(256., std::ceil(16. * faces_in_disc));
  return cap < 1e18 ? std::size_t(cap) : unlimited_neighbors;
}

// The cap of max_neighbors_within() for the faces of `fd`.
inline std::size_t max_neighbors_within(double radius, const Face_data& fd)
{
  double total = 0.;
  for(double a : fd.areas)
    total += a;
  return max_neighbors_within(radius, fd.areas.empty() ? 0. : total / double(fd.areas.size()));
}

// Calls `search(r2, max_neighbors)`, which returns false if it found more
// than `max_neighbors` neighbours, with the squared radius `r2` halved until
// it returns true. Where more neighbours than the cap lie at the very
// position searched from (degenerate faces), r2 reaches 0 and the search is
// run without the cap: it takes them all rather than looping.
template <typename Search>
void search_within_cap(double r2, std::size_t max_neighbors, const Search& search)
{
  while(!search(r2, max_neighbors))
  {
    if(!(r2 > 0.))
    {
      search(r2, unlimited_neighbors);
      return;
    }
    r2 *= 0.5;
  }
}

// Scratch state of a neighbourhood search over n items.
struct Neighborhood_search
{
  std::vector<std::uint32_t> stamp, queue;
  explicit Neighborhood_search(std::size_t n = 0) : stamp(n, std::uint32_t(-1)) {}

  // Neighbours of item i (item i itself excluded), in breadth-first order: an
  // item enters the neighbourhood of i, and the search goes on through it, if
  // its position lies within sqrt(r2) of the position of i and it is
  // adjacent to an item already reached. Afterwards queue = {i, neighbours}.
  // With `max_neighbors`, a search that finds more is abandoned and run
  // again with the squared radius halved, until it finds no more (or the
  // radius is 0).
  template <typename Adjacency>
  void run(std::size_t i, const std::vector<Vec3>& positions, const Adjacency& adjacent, double r2,
           std::size_t max_neighbors = unlimited_neighbors)
  {
    search_within_cap(r2, max_neighbors, [&](double r2_try, std::size_t max_try) {
      return search(i, positions, adjacent, r2_try, max_try);
    });
  }

private:
  template <typename Adjacency>
  bool search(std::size_t i, const std::vector<Vec3>& positions, const Adjacency& adjacent, double r2,
              std::size_t max_neighbors)
  {
    const Vec3& pi = positions[i];
    const std::uint32_t mark = fresh_mark(next_mark, stamp);
    queue.clear();
    queue.push_back(std::uint32_t(i));
    stamp[i] = mark;
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      if(queue.size() - 1 > max_neighbors)
        return false;
      adjacent(queue[q], [&](std::uint32_t g) {
        if(stamp[g] == mark)
          return;
        stamp[g] = mark;
        if(squared_norm(positions[g] - pi) <= r2)
          queue.push_back(g);
      });
    }
    return queue.size() - 1 <= max_neighbors;
  }

  std::uint32_t next_mark = 0;
};

// The geometric neighbourhood of a face, searched through the vertices: the
// faces around each vertex of a face reached are tested once per vertex, not
// once per face around it (about 40% fewer tests than going from face to
// face over a face-to-face adjacency, and no adjacency to build). It reaches
// exactly the faces Neighborhood_search::run reaches with
// Face_vertex_adjacency (a face is tested as soon as it shares a vertex with
// a face reached, and the test depends on its centroid only), in the same
// order (the faces around a vertex already searched are all marked, so
// skipping it changes nothing): where a vertex has thousands of faces
// around it (a fan of slivers), they are tested once per search, not once
// per face reached. Afterwards queue = {i, neighbours}.
struct Face_fan_search
{
  std::vector<std::uint32_t> face_stamp, vertex_stamp;
  std::vector<std::uint32_t> queue; // room for every face: written without bounds checks
  std::size_t count = 0;            // queue[0 .. count): {i, neighbours}

  explicit Face_fan_search(const Flat_mesh& m)
      : face_stamp(m.number_of_faces(), std::uint32_t(-1)), vertex_stamp(m.number_of_vertices(), std::uint32_t(-1)),
        queue(m.number_of_faces() + 1)
  {
  }

  const std::uint32_t* neighbors_begin() const { return queue.data() + 1; }
  const std::uint32_t* neighbors_end() const { return queue.data() + count; }
  // after run_from_vertex(): the faces found
  const std::uint32_t* found_begin() const { return queue.data(); }
  const std::uint32_t* found_end() const { return queue.data() + count; }

  // With `max_neighbors`, as Neighborhood_search::run.
  void run(std::size_t i, const Flat_mesh& m, const std::vector<Vec3>& centroids, double r2,
           std::size_t max_neighbors = unlimited_neighbors)
  {
    search_within_cap(r2, max_neighbors,
                      [&](double r2_try, std::size_t max_try) { return search(i, m, centroids, r2_try, max_try); });
  }

  // The faces around a point instead: those whose centroid lies within
  // sqrt(r2) of `center` (the position of vertex v), reached from the faces
  // around v through shared vertices, in queue[0 .. count) (v's own faces
  // too only if within).
  void run_from_vertex(std::uint32_t v, const Flat_mesh& m, const std::vector<Vec3>& centroids, const Vec3& center,
                       double r2)
  {
    const std::uint32_t mark = fresh_mark(next_mark, face_stamp, vertex_stamp);
    count = 0;
    scan_fan(v, m, centroids, center, r2, mark);
    expand(m, centroids, center, r2, mark, 0, unlimited_neighbors);
  }

private:
  bool search(std::size_t i, const Flat_mesh& m, const std::vector<Vec3>& centroids, double r2,
              std::size_t max_neighbors)
  {
    const std::uint32_t mark = fresh_mark(next_mark, face_stamp, vertex_stamp);
    queue[0] = std::uint32_t(i);
    count = 1;
    face_stamp[i] = mark;
    return expand(m, centroids, centroids[i], r2, mark, 1, max_neighbors);
  }

  // The breadth-first search from the faces queued (the first `seeds` of
  // them not neighbours), through the fans of their vertices; false if
  // more than `max_neighbors` are found.
  bool expand(const Flat_mesh& m, const std::vector<Vec3>& centroids, const Vec3& center, double r2, std::uint32_t mark,
              std::size_t seeds, std::size_t max_neighbors)
  {
    for(std::size_t q = 0; q < count; ++q)
      for(std::uint32_t v : m.triangles[queue[q]])
      {
        if(count - seeds > max_neighbors)
          return false;
        scan_fan(v, m, centroids, center, r2, mark);
      }
    return count - seeds <= max_neighbors;
  }

  // Queues the faces around vertex v not yet reached whose centroid is within
  // the radius, unless v's fan has been scanned in this search.
  void scan_fan(std::uint32_t v, const Flat_mesh& m, const std::vector<Vec3>& centroids, const Vec3& center, double r2,
                std::uint32_t mark)
  {
    if(vertex_stamp[v] == mark)
      return;
    vertex_stamp[v] = mark;
    std::uint32_t* q_out = queue.data();
    // branch-free: whether a face is new and within the radius is
    // unpredictable, so it is written anyway and counted only if both
    for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
    {
      const std::uint32_t g = m.vertex_faces[k];
      const bool fresh = face_stamp[g] != mark;
      face_stamp[g] = mark;
      const bool within = squared_norm(centroids[g] - center) <= r2;
      q_out[count] = g;
      count += std::size_t(fresh & within);
    }
  }

  std::uint32_t next_mark = 0;
};

// Neighbours of every item, as Neighborhood_search::run finds them. For
// faces (positions: centroids; adjacency: shared vertices) this is the
// geometric neighbourhood of eq. 8.
template <typename ConcurrencyTag, typename Adjacency>
Csr geometric_neighborhoods(const std::vector<Vec3>& positions, const Adjacency& adjacent, double radius,
                            std::size_t max_neighbors = unlimited_neighbors)
{
  const std::size_t n = positions.size();
  const double r2 = radius * radius;
  Csr csr;
  build_lists<ConcurrencyTag>(
      n, csr.offsets, csr.items, [n] { return Neighborhood_search(n); },
      [&](std::size_t i, Neighborhood_search& s, std::vector<std::uint32_t>& out) {
        s.run(i, positions, adjacent, r2, max_neighbors);
        out.insert(out.end(), s.queue.begin() + 1, s.queue.end());
      });
  return csr;
}

// The geometric neighbourhoods of faces: the lists geometric_neighborhoods()
// gives with Face_vertex_adjacency, in the same order, searched by
// Face_fan_search.
template <typename ConcurrencyTag>
Csr geometric_neighborhoods(const Flat_mesh& m, const std::vector<Vec3>& centroids, double radius,
                            std::size_t max_neighbors = unlimited_neighbors)
{
  const double r2 = radius * radius;
  Csr csr;
  build_lists<ConcurrencyTag>(
      m.number_of_faces(), csr.offsets, csr.items, [&m] { return Face_fan_search(m); },
      [&](std::size_t i, Face_fan_search& s, std::vector<std::uint32_t>& out) {
        s.run(i, m, centroids, r2, max_neighbors);
        out.insert(out.end(), s.neighbors_begin(), s.neighbors_end());
      });
  return csr;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
