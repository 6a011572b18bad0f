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

// The faces sharing a vertex with each face (the face itself excluded), each
// once: Face_vertex_adjacency without its repeats, for searches that visit
// every face many times. The order of a list is that of the first visit.
template <typename ConcurrencyTag>
Csr face_face_adjacency(const Flat_mesh& m)
{
  const std::size_t nf = m.number_of_faces();
  Csr csr;
  csr.offsets.assign(nf + 1, 0);
  // pass 0 counts, pass 1 writes; each face writes only its own slots
  for(int pass = 0; pass < 2; ++pass)
  {
    if(pass == 1)
    {
      for(std::size_t f = 0; f < nf; ++f)
        csr.offsets[f + 1] += csr.offsets[f];
      csr.items.resize(csr.offsets[nf]);
    }
    for_each_chunk<ConcurrencyTag>(
        nf,
        [&](std::size_t fb, std::size_t fe) {
          std::vector<std::uint32_t> list;
          for(std::size_t f = fb; f < fe; ++f)
          {
            list.clear();
            for(std::uint32_t v : m.triangles[f])
              for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
              {
                const std::uint32_t g = m.vertex_faces[k];
                if(g != f && std::find(list.begin(), list.end(), g) == list.end())
                  list.push_back(g);
              }
            if(pass == 0)
              csr.offsets[f + 1] = std::uint32_t(list.size());
            else
              std::copy(list.begin(), list.end(), csr.items.begin() + csr.offsets[f]);
          }
        },
        4096);
  }
  return csr;
}

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
