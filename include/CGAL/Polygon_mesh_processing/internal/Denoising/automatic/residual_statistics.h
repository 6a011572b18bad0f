// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Statistics of the residual between a noisy input and a denoised version of
// it (same connectivity), which need no ground truth: its size, and how much
// the residuals of vertices joined by an edge agree.
//
// Why the agreement measures the denoising: the residual is the noise removed
// plus the signal removed. Noise that is independent from vertex to vertex
// has no correlation across edges; a light smoothing removes only its rough
// part (the residual is a high-pass of the noise: neighbours disagree, the
// correlation is negative), and a smoothing that removes shape (flattened
// curvature, rounded edges) leaves a residual that is smooth along the
// surface (neighbours agree, the correlation is positive). The correlation
// crosses zero where the smoothing starts to remove more shape than noise.

#ifndef CGAL_PMP_INTERNAL_DENOISING_RESIDUAL_STATISTICS_H
#define CGAL_PMP_INTERNAL_DENOISING_RESIDUAL_STATISTICS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Residual_statistics
{
  // RMS of |input - points| over the vertices with an edge, in units of `unit`
  double rms = 0.;
  // sum over edges (u, v) of r_u . r_v, over the sum of (|r_u|^2 + |r_v|^2) / 2:
  // in [-1, 1], 0 for residuals independent across edges
  double correlation = 0.;
};

// The correlation of the residual input - points across the edges whose two
// ends `keep` (a predicate on vertex indices): the sum over those edges
// (u, v) of r_u . r_v over the sum of (|r_u|^2 + |r_v|^2) / 2; 0 if there is
// no such edge. `adjacency` is vertex_adjacency(m). Sequential, one pass over
// the edges in a fixed order.
template <typename Keep>
double residual_edge_correlation(const Csr& adjacency, const std::vector<Vec3>& points, const std::vector<Vec3>& input,
                                 const Keep& keep)
{
  double cross = 0., energy = 0.;
  const std::size_t nv = adjacency.size();
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(adjacency.begin(v) == adjacency.end(v) || !keep(v))
      continue;
    const Vec3 rv = input[v] - points[v];
    const double rv2 = squared_norm(rv);
    for(std::uint32_t k = adjacency.begin(v); k < adjacency.end(v); ++k)
    {
      const std::uint32_t u = adjacency.items[k];
      if(u <= v || !keep(u))
        continue;
      const Vec3 ru = input[u] - points[u];
      cross += dot(rv, ru);
      energy += 0.5 * (rv2 + squared_norm(ru));
    }
  }
  return energy > 0. ? cross / energy : 0.;
}

// `adjacency` is vertex_adjacency(m). Sequential: passes over the vertices
// and edges in a fixed order, so the result does not depend on the thread
// count.
inline Residual_statistics residual_statistics(const Csr& adjacency, const std::vector<Vec3>& points,
                                               const std::vector<Vec3>& input, double unit)
{
  Residual_statistics s;
  double squares = 0.;
  std::size_t count = 0;
  for(std::size_t v = 0; v < adjacency.size(); ++v)
    if(adjacency.begin(v) != adjacency.end(v))
    {
      squares += squared_norm(input[v] - points[v]);
      ++count;
    }
  if(count > 0 && unit > 0.)
    s.rms = std::sqrt(squares / double(count)) / unit;
  s.correlation = residual_edge_correlation(adjacency, points, input, [](std::size_t) { return true; });
  return s;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
