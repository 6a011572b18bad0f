// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the automatic mode reports of the noise it removed: the correlation
// of the residual (input - result) between vertices 1 to 8 edges apart, the
// number of edges over which it stays high, and the share of its energy
// along one direction. Independent noise removed leaves a residual that is
// uncorrelated beyond one edge and spread over the directions of the
// normals; the noise of a depth scan is correlated over several edges and
// lies along the viewing rays, nearly one direction; shape removed is
// correlated over the size of the shape's details. Descriptive only: no
// rule of the mode reads these figures.

#ifndef CGAL_PMP_INTERNAL_DENOISING_RESIDUAL_DESCRIPTION_H
#define CGAL_PMP_INTERNAL_DENOISING_RESIDUAL_DESCRIPTION_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/vec3.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Residual_description_rules
{
  // the correlation is read between vertices 1 to max_hops edges apart ...
  static constexpr std::size_t max_hops = 8;
  // ... around at most this many vertices spread over the mesh (every
  // n-th), so that the cost stays a few milliseconds on any mesh
  static constexpr std::size_t sources = 2000;
  // the residual is "correlated over h edges" while its correlation stays at
  // least this value
  static constexpr double correlated = 0.5;
};

struct Residual_description
{
  // hop_correlations[h - 1]: sum of r_u . r_v over the pairs of vertices h
  // edges apart (shortest path in edges) over the sum of
  // (|r_u|^2 + |r_v|^2) / 2, in [-1, 1]
  std::vector<double> hop_correlations;
  unsigned int correlation_length = 0; // hops with a correlation of at least Residual_description_rules::correlated
  double axis_share = 0.;              // largest eigenvalue of sum r r^T over its trace, in [1/3, 1]
};

// The largest eigenvalue of the symmetric 3x3 matrix of upper triangle
// a00 a01 a02 a11 a12 a22 (the trigonometric solution of its cubic).
inline double largest_symmetric_eigenvalue(double a00, double a01, double a02, double a11, double a12, double a22)
{
  const double off = a01 * a01 + a02 * a02 + a12 * a12;
  const double q = (a00 + a11 + a22) / 3.;
  if(off == 0.)
    return std::max(a00, std::max(a11, a22));
  const double b00 = a00 - q, b11 = a11 - q, b22 = a22 - q;
  const double p = std::sqrt((b00 * b00 + b11 * b11 + b22 * b22 + 2. * off) / 6.);
  const double det = b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02) + a02 * (a01 * a12 - b11 * a02);
  const double half = std::clamp(det / (2. * p * p * p), -1., 1.);
  return q + 2. * p * std::cos(std::acos(half) / 3.);
}

// The share of the energy of the residual input - points (over the
// vertices with an edge in `adjacency`) along its principal direction.
inline double residual_axis_share(const Csr& adjacency, const std::vector<Vec3>& points, const std::vector<Vec3>& input)
{
  double c[6] = {0., 0., 0., 0., 0., 0.};
  for(std::size_t v = 0; v < adjacency.size(); ++v)
  {
    if(adjacency.begin(v) == adjacency.end(v))
      continue;
    const Vec3 r = input[v] - points[v];
    c[0] += r[0] * r[0];
    c[1] += r[0] * r[1];
    c[2] += r[0] * r[2];
    c[3] += r[1] * r[1];
    c[4] += r[1] * r[2];
    c[5] += r[2] * r[2];
  }
  const double trace = c[0] + c[3] + c[5];
  return trace > 0. ? largest_symmetric_eigenvalue(c[0], c[1], c[2], c[3], c[4], c[5]) / trace : 0.;
}

// The description of the residual input - points on the mesh of vertex
// adjacency `adjacency` (vertex_adjacency()): breadth-first searches to
// Residual_description_rules::max_hops edges from every n-th vertex with an
// edge. Sequential, in a fixed order: the same figures for every thread
// count.
inline Residual_description describe_residual(const Csr& adjacency, const std::vector<Vec3>& points,
                                              const std::vector<Vec3>& input)
{
  typedef Residual_description_rules Rules;
  Residual_description d;
  const std::size_t nv = adjacency.size();
  std::vector<double> cross(Rules::max_hops, 0.), energy(Rules::max_hops, 0.);
  std::vector<std::uint32_t> hops(nv, std::uint32_t(-1));
  std::vector<std::uint32_t> reached;
  const std::size_t stride = std::max<std::size_t>(1, nv / Rules::sources);
  for(std::size_t s = 0; s < nv; s += stride)
  {
    if(adjacency.begin(s) == adjacency.end(s))
      continue;
    const Vec3 rs = input[s] - points[s];
    const double es = squared_norm(rs);
    reached.assign(1, std::uint32_t(s));
    hops[s] = 0;
    std::size_t ring_begin = 0;
    for(std::uint32_t h = 1; h <= Rules::max_hops; ++h)
    {
      const std::size_t ring_end = reached.size();
      for(std::size_t i = ring_begin; i < ring_end; ++i)
        for(std::uint32_t k = adjacency.begin(reached[i]); k < adjacency.end(reached[i]); ++k)
        {
          const std::uint32_t u = adjacency.items[k];
          if(hops[u] != std::uint32_t(-1))
            continue;
          hops[u] = h;
          reached.push_back(u);
          const Vec3 ru = input[u] - points[u];
          cross[h - 1] += dot(rs, ru);
          energy[h - 1] += 0.5 * (es + squared_norm(ru));
        }
      ring_begin = ring_end;
    }
    for(std::uint32_t v : reached)
      hops[v] = std::uint32_t(-1);
  }
  for(std::size_t h = 0; h < Rules::max_hops; ++h)
    d.hop_correlations.push_back(energy[h] > 0. ? cross[h] / energy[h] : 0.);
  while(d.correlation_length < Rules::max_hops && d.hop_correlations[d.correlation_length] >= Rules::correlated)
    ++d.correlation_length;
  d.axis_share = residual_axis_share(adjacency, points, input);
  return d;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
