// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The rules of intrinsic_denoising() when some of the filter's parameters are
// given and the others left to it (with everything left to it, the automatic
// selection of automatic_selection.h runs instead): the missing ones derived
// from the estimated noise level, and the stopping rule that needs no ground
// truth.

#ifndef CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_PARAMETERS_H
#define CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/noise_estimate.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// What the automatic mode derives from the noise level (relative to the mean
// edge length).
struct Automatic_choice
{
  Setup_defaults kernel;
  unsigned int max_iterations = 0;
};

// The default of progress_callback: does nothing.
struct No_progress
{
  void operator()(std::size_t, std::size_t) const {}
};

inline Automatic_choice automatic_choice(double noise)
{
  using R = Automatic_rules;
  Automatic_choice c;
  const double s = std::clamp(R::sigma_offset + R::sigma_slope * noise, R::min_sigma, R::max_sigma);
  c.kernel.sigma_spatial = c.kernel.sigma_range = s;
  c.kernel.relative_radius =
      std::clamp(R::radius_offset + R::radius_slope * noise, R::min_relative_radius, R::relative_radius);
  c.max_iterations = R::max_iterations;
  return c;
}

// RMS distance between `points` and `input` over the vertices that have a
// face, relative to `unit`.
inline double relative_rms_displacement(const Flat_mesh& m, const std::vector<Vec3>& points,
                                        const std::vector<Vec3>& input, double unit)
{
  double sum = 0.;
  std::size_t count = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(m.vertex_face_offsets[v] != m.vertex_face_offsets[v + 1])
    {
      sum += squared_norm(points[v] - input[v]);
      ++count;
    }
  return count == 0 || !(unit > 0.) ? 0. : std::sqrt(sum / double(count)) / unit;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
