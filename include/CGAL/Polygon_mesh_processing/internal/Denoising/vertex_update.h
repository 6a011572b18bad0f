// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eq. 10 (the vertex update of Sun et al. 2007) on flat arrays.

#ifndef CGAL_PMP_INTERNAL_DENOISING_VERTEX_UPDATE_H
#define CGAL_PMP_INTERNAL_DENOISING_VERTEX_UPDATE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/face_data.h>

#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// `iterations` steps of
//   v <- v + 1/|F_v| sum_{j in F_v} n_j (n_j . (c_j - v)),
// all vertices moved at once from the positions of the previous step (c_j are
// the centroids of that step). Vertices with `fixed[v] != 0` and vertices with
// no incident face do not move. `centroids` is scratch space.
template <typename ConcurrencyTag>
void update_vertices(const Flat_mesh& m, std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                     const std::vector<char>& fixed, unsigned int iterations, std::vector<Vec3>& centroids,
                     std::vector<Vec3>& next)
{
  const std::size_t nf = m.number_of_faces(), nv = m.number_of_vertices();
  centroids.resize(nf);
  next.resize(nv);
  for(unsigned int it = 0; it < iterations; ++it)
  {
    for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
      for(std::size_t f = b; f < e; ++f)
      {
        const auto& t = m.triangles[f];
        centroids[f] = (1. / 3.) * (points[t[0]] + points[t[1]] + points[t[2]]);
      }
    });
    for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        const std::uint32_t fb = m.vertex_face_offsets[v], fe = m.vertex_face_offsets[v + 1];
        if(fe == fb || (!fixed.empty() && fixed[v]))
        {
          next[v] = points[v];
          continue;
        }
        Vec3 move = {0., 0., 0.};
        for(std::uint32_t k = fb; k < fe; ++k)
        {
          const std::uint32_t f = m.vertex_faces[k];
          const Vec3& n = normals[f];
          move = move + dot(n, centroids[f] - points[v]) * n;
        }
        next[v] = points[v] + (1. / double(fe - fb)) * move;
      }
    });
    points.swap(next);
  }
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
