// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Geometric neighbourhoods of faces (as in Zhang et al. 2015, used by eq. 8):
// the faces connected to face i through shared vertices whose centroid lies
// within a radius of c_i, grown by breadth-first search. Stored in CSR form.

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

// Neighbours of every face (face i itself excluded), in breadth-first order.
// A face enters the neighbourhood, and the search goes on through it, if its
// centroid lies within `radius` of c_i and it shares a vertex with a face
// already reached.
template <typename ConcurrencyTag>
Csr geometric_neighborhoods(const Flat_mesh& m, const std::vector<Vec3>& centroids, double radius)
{
  const std::size_t nf = m.number_of_faces();
  const double r2 = radius * radius;
  // Pass 1 fills one list per chunk, pass 2 concatenates them.
  std::vector<std::uint32_t> counts(nf, 0);
  struct Chunk
  {
    std::size_t first;
    std::vector<std::uint32_t> items;
  };
  std::vector<Chunk> chunks;
  // few chunks: each one allocates a visit stamp array of the mesh's size
  const std::size_t chunk_size = (std::max)(std::size_t(4096), nf / 32 + 1);
  const std::size_t nchunks = (nf + chunk_size - 1) / chunk_size;
  chunks.resize(nchunks);
  for_each_chunk<ConcurrencyTag>(
      nchunks,
      [&](std::size_t cb, std::size_t ce) {
        std::vector<std::uint32_t> stamp(nf, std::uint32_t(-1));
        std::vector<std::uint32_t> queue;
        for(std::size_t c = cb; c < ce; ++c)
        {
          Chunk& chunk = chunks[c];
          chunk.first = c * chunk_size;
          const std::size_t last = (std::min)(nf, chunk.first + chunk_size);
          for(std::size_t i = chunk.first; i < last; ++i)
          {
            const Vec3& ci = centroids[i];
            queue.clear();
            queue.push_back(std::uint32_t(i));
            stamp[i] = std::uint32_t(i);
            for(std::size_t q = 0; q < queue.size(); ++q)
            {
              for(std::uint32_t v : m.triangles[queue[q]])
                for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
                {
                  const std::uint32_t g = m.vertex_faces[k];
                  if(stamp[g] == std::uint32_t(i))
                    continue;
                  stamp[g] = std::uint32_t(i);
                  if(squared_norm(centroids[g] - ci) <= r2)
                    queue.push_back(g);
                }
            }
            counts[i] = std::uint32_t(queue.size() - 1);
            chunk.items.insert(chunk.items.end(), queue.begin() + 1, queue.end());
          }
        }
      },
      1);
  Csr csr;
  csr.offsets.assign(nf + 1, 0);
  for(std::size_t f = 0; f < nf; ++f)
    csr.offsets[f + 1] = csr.offsets[f] + counts[f];
  csr.items.reserve(csr.offsets[nf]);
  for(const Chunk& c : chunks)
    csr.items.insert(csr.items.end(), c.items.begin(), c.items.end());
  return csr;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
