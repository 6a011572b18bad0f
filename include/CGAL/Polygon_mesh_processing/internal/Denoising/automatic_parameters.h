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

#include <CGAL/Polygon_mesh_processing/internal/Denoising/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/noise_estimate.h>

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
  // r = clamp(radius_offset + radius_slope * noise, min_relative_radius,
  // relative_radius) d: 3d up to a noise level of 0.1, 4d from 0.2. Less
  // noise needs less averaging, and a smaller support keeps curved parts: at
  // sigma_E 0.1, r 3d against 4d (the first schedule's sigma and stopping
  // rule) took fandisk from 1.368 to 1.276 degrees, anchor_dense from 3.463
  // to 3.145, CGAL's cylinder from 2.287 to 1.341 and
  // cylinder_locally_refined from 0.900 to 0.651 (fandisk_large 2.655 ->
  // 2.686); at 0.15 the two radii are even on fandisk, at 0.2 4d is better.
  static constexpr double relative_radius = 4.;
  static constexpr double min_relative_radius = 3.;
  static constexpr double radius_offset = 2., radius_slope = 10.;
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
  // most of the noise is still there. 20 rather than 10: on CAD meshes with
  // impulsive noise (10-30% of the vertices, amplitudes 0.5 and 1) 10
  // iterations left so much noise that the shape test took them for curved
  // surfaces (fandisk, 20% at amplitude 1: 11.2 degrees, 4.4 with 20); on
  // the benchmark's Gaussian inputs only fandisk at sigma_E 0.1 gets worse
  // (1.318 -> 1.368 degrees), and 30 cost it more (1.454)
  static constexpr unsigned int min_iterations = 20;
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
