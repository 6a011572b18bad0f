// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tangential relaxation of a denoised mesh. Eq. 10 moves every vertex along
// the normals of its faces only, so whatever part of the noise moved a
// vertex along the surface stays: noise along a viewing direction (a depth
// scan), noise along noisy vertex normals (tilted from the surface's), and
// the scrambled small triangles of irregular meshes. This step moves each
// vertex along the surface only, toward the area-weighted centroid of its
// faces' centroids, in the directions its faces leave free: with the
// normal tensor T_v = sum A_f n_f n_f^T / sum A_f of the faces around v,
// the eigenvectors whose eigenvalue is below a fraction of the largest (two
// on a flat or smooth part, one along a crease, none at a corner). No vertex
// ends farther from where the denoiser left it than a fraction of how far
// the denoiser moved it from the input: a vertex the denoiser hardly moved
// (noise-free, or an exact vertex among sparse outliers) stays.

#ifndef CGAL_PMP_INTERNAL_DENOISING_TANGENTIAL_RELAXATION_H
#define CGAL_PMP_INTERNAL_DENOISING_TANGENTIAL_RELAXATION_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Tangential_relaxation_rules
{
  // Steps, each moving a vertex by this fraction of the way to its target
  // (the target projected on its free directions).
  static constexpr unsigned int steps = 5;
  static constexpr double step = 0.5;
  // A direction is free if its eigenvalue of the normal tensor is below this
  // fraction of the largest.
  static constexpr double free_direction_ratio = 0.1;
  // A vertex ends at most this fraction of its denoising displacement (input
  // to denoised) away from its denoised position.
  static constexpr double displacement_fraction = 0.5;
};

namespace tangential_relaxation_detail {

// Whether each vertex lies on a border edge (an edge with one face).
inline std::vector<char> border_vertices(const Flat_mesh& m)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<char> border(nv, 0);
  std::vector<std::uint32_t> around;
  for(std::size_t v = 0; v < nv; ++v)
  {
    around.clear();
    for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
      for(std::uint32_t w : m.triangles[m.vertex_faces[k]])
        if(w != v)
          around.push_back(w);
    std::sort(around.begin(), around.end());
    // each interior edge (v, w) has two faces, so w appears twice
    for(std::size_t i = 0; i < around.size();)
    {
      std::size_t j = i;
      while(j < around.size() && around[j] == around[i])
        ++j;
      if(j - i == 1)
      {
        border[v] = 1;
        break;
      }
      i = j;
    }
  }
  return border;
}

// The projector on the free directions of the normal tensor of the faces
// around v (zero if v has no face of positive area).
inline std::array<double, 9> free_projector(const Flat_mesh& m, std::size_t v, const Face_data& faces)
{
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  double total = 0.;
  for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
  {
    const std::uint32_t f = m.vertex_faces[k];
    const double a = faces.areas[f];
    const Vec3& n = faces.normals[f];
    if(!(a > 0.))
      continue;
    const Eigen::Vector3d e(n[0], n[1], n[2]);
    t += a * e * e.transpose();
    total += a;
  }
  std::array<double, 9> p{};
  if(!(total > 0.))
    return p;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(t / total);
  const Eigen::Vector3d values = solver.eigenvalues(); // ascending
  const Eigen::Matrix3d vectors = solver.eigenvectors();
  for(int k = 0; k < 3; ++k)
  {
    if(!(values[k] < Tangential_relaxation_rules::free_direction_ratio * values[2]))
      continue;
    const Eigen::Vector3d e = vectors.col(k);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        p[3 * i + j] += e[i] * e[j];
  }
  return p;
}

} // namespace tangential_relaxation_detail

// Relaxes `points`, a denoised version of `input` on mesh `m` (vertex order
// of `m`), as described above. Vertices with `held[v]` set, vertices on the
// border and vertices with no face stay. With an enabled `guard`, each step
// goes through the fold safeguard (Fold_safeguard), with the faces' normals
// before the relaxation as their targets and `guard.reference` as their
// reference orientation (if null, as in update_vertices(), the orientation
// before the relaxation). Returns the number of vertices
// that moved. Every decision depends only on the previous step's positions:
// the result does not depend on the number of threads.
template <typename ConcurrencyTag>
std::size_t relax_tangentially(const Flat_mesh& m, const std::vector<Vec3>& input, std::vector<Vec3>& points,
                               const std::vector<char>& held, Fold_safeguard& guard)
{
  namespace T = tangential_relaxation_detail;
  using Rules = Tangential_relaxation_rules;
  const std::size_t nv = m.number_of_vertices();
  const std::vector<char> border = T::border_vertices(m);
  Face_data start;
  compute_face_data<ConcurrencyTag>(m, points, start);
  const std::vector<Vec3>* const saved_reference = guard.reference;
  if(!guard.reference)
    guard.reference = &start.normals;
  const std::vector<Vec3> origin = points;
  std::vector<std::array<double, 9>> projector(nv);
  std::vector<double> cap(nv, 0.);
  for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t b, std::size_t e) {
    for(std::size_t v = b; v < e; ++v)
    {
      if((!held.empty() && held[v]) || border[v] || m.vertex_face_offsets[v] == m.vertex_face_offsets[v + 1])
        continue;
      cap[v] = Rules::displacement_fraction * std::sqrt(squared_norm(input[v] - origin[v]));
      if(cap[v] > 0.)
        projector[v] = T::free_projector(m, v, start);
    }
  });
  Face_data current;
  std::vector<Vec3> next(nv);
  for(unsigned int s = 0; s < Rules::steps; ++s)
  {
    compute_face_data<ConcurrencyTag>(m, points, current);
    for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
      {
        next[v] = points[v];
        if(!(cap[v] > 0.))
          continue;
        Vec3 sum = {0., 0., 0.};
        double area = 0.;
        for(std::uint32_t k = m.vertex_face_offsets[v]; k < m.vertex_face_offsets[v + 1]; ++k)
        {
          const std::uint32_t f = m.vertex_faces[k];
          sum = sum + current.areas[f] * current.centroids[f];
          area += current.areas[f];
        }
        if(!(area > 0.))
          continue;
        const Vec3 d = (1. / area) * sum - points[v];
        const std::array<double, 9>& p = projector[v];
        const Vec3 move = {p[0] * d[0] + p[1] * d[1] + p[2] * d[2], p[3] * d[0] + p[4] * d[1] + p[5] * d[2],
                           p[6] * d[0] + p[7] * d[1] + p[8] * d[2]};
        Vec3 offset = points[v] + Rules::step * move - origin[v];
        const double length = std::sqrt(squared_norm(offset));
        if(length > cap[v])
          offset = (cap[v] / length) * offset;
        next[v] = origin[v] + offset;
      }
    });
    if(guard.enabled)
      apply_fold_safeguard<ConcurrencyTag>(m, points, next, start.normals, guard);
    points.swap(next);
  }
  guard.reference = saved_reference;
  std::size_t moved = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(!(points[v] == origin[v]))
      ++moved;
  return moved;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
