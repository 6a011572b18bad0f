// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic mode of intrinsic_denoising(): parameters derived from the
// estimated noise level, and the stopping rule that needs no ground truth.

#ifndef CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_PARAMETERS_H
#define CGAL_PMP_INTERNAL_DENOISING_AUTOMATIC_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/noise_estimate.h>

#include <algorithm>
#include <cmath>
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

// The constants of the automatic mode. They were chosen on the package's
// benchmark (benchmark/Polygon_mesh_processing/auto_parameters_benchmark.cpp):
// among sigma = a + b * noise, r in {3, 4} d, the displacement fraction, the
// change tolerance and the iteration bounds, these gave a low mean log-ratio
// of E_n to the per-input best of a grid search over 12 inputs while keeping
// fandisk within 12% of its best (so the choice is fitted to those inputs;
// see the manual for its limits).
struct Automatic_rules
{
  static constexpr double sigma_offset = 0.2; // sigma_s = sigma_r = offset + slope * noise
  static constexpr double sigma_slope = 1.;
  static constexpr double min_sigma = 0.2, max_sigma = 1.4;
  static constexpr double relative_radius = 4.;
  // the stopping rule: stop once the RMS vertex displacement from the input
  // reaches this fraction of the noise level ...
  static constexpr double displacement_fraction = 0.95;
  // ... or once the filtered normals change by less than this mean angle
  // (degrees) from one iteration to the next, or after max_iterations
  static constexpr double change_tolerance = 0.005;
  static constexpr unsigned int max_iterations = 100;
  // neither test stops the iterations before this many, unless the noise level
  // is below min_noise (a noise-free mesh stops after one iteration): impulsive
  // noise moves few vertices far, and its displacement target is reached while
  // most of the noise is still there
  static constexpr unsigned int min_iterations = 10;
  static constexpr double min_noise = 0.02;
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
  c.kernel.relative_radius = R::relative_radius;
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
