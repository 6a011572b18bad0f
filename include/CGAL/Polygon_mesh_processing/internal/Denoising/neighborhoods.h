// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Geometric neighbourhoods (as in Zhang et al. 2015, used by eq. 8): the faces
// connected to face i through shared vertices whose centroid lies within a
// radius of c_i, grown by breadth-first search; likewise for vertices through
// edges. Stored in CSR form.

#ifndef CGAL_PMP_INTERNAL_DENOISING_NEIGHBORHOODS_H
#define CGAL_PMP_INTERNAL_DENOISING_NEIGHBORHOODS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/face_data.h>

#include <algorithm>
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

// Scratch state of a neighbourhood search over n items.
struct Neighborhood_search
{
  std::vector<std::uint32_t> stamp, queue;
  explicit Neighborhood_search(std::size_t n = 0) : stamp(n, std::uint32_t(-1)) {}

  // Neighbours of item i (item i itself excluded), in breadth-first order: an
  // item enters the neighbourhood of i, and the search goes on through it, if
  // its position lies within sqrt(r2) of the position of i and it is
  // adjacent to an item already reached. Afterwards queue = {i, neighbours}.
  template <typename Adjacency>
  void run(std::size_t i, const std::vector<Vec3>& positions, const Adjacency& adjacent, double r2)
  {
    const Vec3& pi = positions[i];
    const std::uint32_t mark = std::uint32_t(i);
    queue.clear();
    queue.push_back(mark);
    stamp[i] = mark;
    for(std::size_t q = 0; q < queue.size(); ++q)
      adjacent(queue[q], [&](std::uint32_t g) {
        if(stamp[g] == mark)
          return;
        stamp[g] = mark;
        if(squared_norm(positions[g] - pi) <= r2)
          queue.push_back(g);
      });
  }
};

// The geometric neighbourhood of a face, searched through the vertices: the
// faces around each vertex of a face reached are tested once per vertex, not
// once per face around it (about 40% fewer tests than going from face to
// face over a face-to-face adjacency, and no adjacency to build). It reaches
// exactly the faces Neighborhood_search::run reaches with
// Face_vertex_adjacency (a face is tested as soon as it shares a vertex with
// a face reached, and the test depends on its centroid only), in another
// order. Afterwards queue = {i, neighbours}.
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

  void run(std::size_t i, const Flat_mesh& m, const std::vector<Vec3>& centroids, double r2)
  {
    const Vec3& ci = centroids[i];
    const std::uint32_t mark = std::uint32_t(i);
    std::uint32_t* q_out = queue.data();
    q_out[0] = mark;
    count = 1;
    face_stamp[i] = mark;
    for(std::size_t q = 0; q < count; ++q)
      for(std::uint32_t v : m.triangles[q_out[q]])
      {
        if(vertex_stamp[v] == mark)
          continue;
        vertex_stamp[v] = mark;
        // branch-free: whether a face is new and within the radius is
        // unpredictable, so it is written anyway and counted only if both
        for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
        {
          const std::uint32_t g = m.vertex_faces[k];
          const bool fresh = face_stamp[g] != mark;
          face_stamp[g] = mark;
          const bool within = squared_norm(centroids[g] - ci) <= r2;
          q_out[count] = g;
          count += std::size_t(fresh & within);
        }
      }
  }
};

// Neighbours of every item, as Neighborhood_search::run finds them. For
// faces (positions: centroids; adjacency: shared vertices) this is the
// geometric neighbourhood of eq. 8.
template <typename ConcurrencyTag, typename Adjacency>
Csr geometric_neighborhoods(const std::vector<Vec3>& positions, const Adjacency& adjacent, double radius)
{
  const std::size_t n = positions.size();
  const double r2 = radius * radius;
  Csr csr;
  build_lists<ConcurrencyTag>(
      n, csr.offsets, csr.items, [n] { return Neighborhood_search(n); },
      [&](std::size_t i, Neighborhood_search& s, std::vector<std::uint32_t>& out) {
        s.run(i, positions, adjacent, r2);
        out.insert(out.end(), s.queue.begin() + 1, s.queue.end());
      });
  return csr;
}

// The geometric neighbourhoods of faces.
template <typename ConcurrencyTag>
Csr geometric_neighborhoods(const Flat_mesh& m, const std::vector<Vec3>& centroids, double radius)
{
  return geometric_neighborhoods<ConcurrencyTag>(centroids, Face_vertex_adjacency{m}, radius);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
