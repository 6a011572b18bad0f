// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Estimate of the noise level of a triangle mesh from the mesh alone: at each
// vertex, a quadric height field is fitted by least squares to the vertex and
// its two rings of neighbours, in the frame of the vertex normal; the
// residual's standard deviation measures what a smooth surface cannot
// explain. A quadric absorbs the surface's curvature, so a smooth noise-free
// mesh gives residuals near zero; a sharp feature gives large residuals at
// the few vertices near it, which a low quantile over all vertices ignores.

#ifndef CGAL_PMP_INTERNAL_DENOISING_NOISE_ESTIMATE_H
#define CGAL_PMP_INTERNAL_DENOISING_NOISE_ESTIMATE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// The quantile of the per-vertex residuals that is read, and its ratio to the
// noise's standard deviation when the residuals are pure Gaussian noise
// (measured on noisy planes and on the flat faces of a cube: 0.84-0.86; a
// two-ring fit has about 13 degrees of freedom). A low quantile ignores the
// vertices near sharp features, which on a coarse CAD mesh can be half of
// them.
struct Noise_quantile
{
  static constexpr double quantile = 0.25;
  static constexpr double ratio_to_sigma = 0.85;
};

struct Noise_estimate
{
  // the noise's standard deviation relative to the mean edge length: the
  // Noise_quantile of the local fits' residuals, divided by its ratio
  double relative_noise = 0.;
  double mean_edge_length = 0.;
  std::size_t fitted_vertices = 0;
  // per-vertex residual standard deviations (relative), -1 where no fit
  std::vector<double> residuals;
};

// The residual standard deviation of the quadric fit at every vertex, in units
// of `unit`; -1 for a vertex with fewer than `min_points` points in its two
// rings or no normal.
template <typename ConcurrencyTag>
std::vector<double> local_fit_residuals(const Flat_mesh& m, const Csr& adjacency, const std::vector<Vec3>& normals,
                                        double unit)
{
  constexpr std::size_t min_points = 10; // 6 unknowns, at least 4 degrees of freedom left
  constexpr std::size_t max_points = 64; // bounds the work at vertices of huge valence
  const std::size_t nv = m.number_of_vertices();
  std::vector<double> out(nv, -1.);
  if(!(unit > 0.))
    return out;
  const double inv = 1. / unit;
  for_each_chunk<ConcurrencyTag>(nv, [&](std::size_t b, std::size_t e) {
    std::vector<std::uint32_t> ring;
    for(std::size_t v = b; v < e; ++v)
    {
      const Vec3& n = normals[v];
      if(squared_norm(n) == 0. || adjacency.begin(v) == adjacency.end(v))
        continue;
      // v and its two rings, nearest rings first (a linear search keeps the
      // ring free of duplicates: it holds at most max_points vertices)
      ring.clear();
      ring.push_back(std::uint32_t(v));
      for(std::size_t depth = 0, first = 0; depth < 2; ++depth)
      {
        const std::size_t last = ring.size();
        for(std::size_t i = first; i < last; ++i)
          for(std::uint32_t k = adjacency.begin(ring[i]); k < adjacency.end(ring[i]) && ring.size() < max_points; ++k)
          {
            const std::uint32_t w = adjacency.items[k];
            if(std::find(ring.begin(), ring.end(), w) == ring.end())
              ring.push_back(w);
          }
        first = last;
      }
      if(ring.size() < min_points)
        continue;
      // tangent frame (t1, t2, n)
      const Vec3 a = std::abs(n[0]) < 0.9 ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
      Vec3 t1 = cross(n, a);
      t1 = (1. / norm(t1)) * t1;
      const Vec3 t2 = cross(n, t1);
      Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> ath = Eigen::Matrix<double, 6, 1>::Zero();
      double hh = 0.;
      const Vec3& p = m.points[v];
      for(std::uint32_t w : ring)
      {
        const Vec3 d = m.points[w] - p;
        const double x = dot(d, t1) * inv, y = dot(d, t2) * inv, h = dot(d, n) * inv;
        Eigen::Matrix<double, 6, 1> row;
        row << x * x, x * y, y * y, x, y, 1.;
        ata.noalias() += row * row.transpose();
        ath += h * row;
        hh += h * h;
      }
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(ata);
      if(ldlt.info() != Eigen::Success)
        continue;
      const Eigen::Matrix<double, 6, 1> c = ldlt.solve(ath);
      if(!c.allFinite())
        continue;
      // residual sum of squares = h.h - c.(A^T h) for the least-squares c
      const double ssr = std::max(0., hh - c.dot(ath));
      out[v] = std::sqrt(ssr / double(ring.size() - 6));
    }
  });
  return out;
}

// The noise estimate of `m`, relative to its mean edge length.
template <typename ConcurrencyTag>
Noise_estimate estimate_noise(const Flat_mesh& m, double quantile = Noise_quantile::quantile,
                              double ratio = Noise_quantile::ratio_to_sigma)
{
  Noise_estimate est;
  est.mean_edge_length = mean_edge_length<ConcurrencyTag>(m);
  const Csr adjacency = vertex_adjacency(m);
  est.residuals =
      local_fit_residuals<ConcurrencyTag>(m, adjacency, area_weighted_vertex_normals(m), est.mean_edge_length);
  std::vector<double> valid;
  valid.reserve(est.residuals.size());
  for(double r : est.residuals)
    if(r >= 0.)
      valid.push_back(r);
  est.fitted_vertices = valid.size();
  if(valid.empty())
    return est;
  const std::size_t k = std::min(valid.size() - 1, std::size_t(quantile * double(valid.size())));
  std::nth_element(valid.begin(), valid.begin() + std::ptrdiff_t(k), valid.end());
  est.relative_noise = valid[k] / ratio;
  return est;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
