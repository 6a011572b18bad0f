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
#include <cstddef>
#include <cstdint>
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
  // The shape test, made on the result of the schedule above (which keeps
  // sharp edges): a piecewise flat (CAD-like) result has most of its interior
  // edges at a dihedral angle under flat_angle degrees (0.78 to 0.97 of them
  // on the benchmark's CAD inputs); a smooth curved (organic) or irregular
  // surface few (0.16 to 0.30). Below min_flat_fraction the mesh is denoised
  // again from its input with the smooth-surface schedule: a wide kernel on a
  // small radius (almost a Gaussian smoothing of the normals), with the same
  // stopping rule.
  static constexpr double flat_angle = 1.;
  static constexpr double min_flat_fraction = 0.5;
  static constexpr double smooth_sigma = 1.4;
  static constexpr double smooth_relative_radius = 2.;
  // The smooth-surface schedule's stopping rule is tested from the first
  // iteration: its wide kernel takes the noise out in a few (the grid's best
  // on those inputs: 2 to 19), and on a coarse curved mesh whose curvature
  // the estimate takes for noise (CGAL's elephant, cow, dino, armadillo: 0.08
  // to 0.12 without noise) a floor of 10 iterations flattened details.
  static constexpr unsigned int smooth_min_iterations = 1;
  // At or above flat_faced_fraction the surface is made of large flat faces
  // (0.97 on the benchmark's cube and prism; 0.70 to 0.81 on the CAD meshes
  // with curved parts: fandisk, anchor_dense, fandisk_large). The input is
  // then denoised again with the first schedule's sigma on a radius of
  // flat_faced_relative_radius d, for flat_faced_max_iterations, stopped
  // earlier only if the normals stop changing (flat_faced_change_tolerance,
  // tested from min_iterations; the displacement test is off). On such faces
  // more smoothing only flattens them further: the grid's best is at r 8d
  // and 130-150 iterations (cube 0.188, prism 0.082 degrees, against 0.563
  // and 0.287 with the first schedule), and E_n still falls at 150. With the
  // first schedule's tolerance (0.005) the runs stopped after 20-47
  // iterations at 0.39 and 0.22 degrees, with 0.001 at 0.22 and 0.12. On
  // fandisk the same settings would double the error. The price: about 14
  // times the first schedule's time on those meshes (cube 0.10 -> 1.4 s).
  static constexpr double flat_faced_fraction = 0.9;
  static constexpr double flat_faced_relative_radius = 8.;
  static constexpr unsigned int flat_faced_max_iterations = 150;
  static constexpr double flat_faced_change_tolerance = 0.0002;
  // The flat-faced radius, two to 2.7 times the first schedule's, holds
  // about four to seven times its path nodes. Above this many (expected)
  // nodes the flat-faced schedule is skipped and the first schedule kept: its
  // node list alone would take over 1 GiB, and its 150 iterations minutes
  // (about a million faces at r 8d).
  static constexpr std::size_t flat_faced_max_path_nodes = std::size_t(1) << 28;
};

// Whether the flat-faced schedule stays within Automatic_rules'
// flat_faced_max_path_nodes, from the path nodes of the first schedule and
// its relative radius (the nodes grow as the square of the radius).
inline bool flat_faced_affordable(std::size_t first_schedule_nodes, double first_relative_radius)
{
  if(!(first_relative_radius > 0.))
    return false;
  const double ratio = Automatic_rules::flat_faced_relative_radius / first_relative_radius;
  return double(first_schedule_nodes) * ratio * ratio <= double(Automatic_rules::flat_faced_max_path_nodes);
}

// The fraction of the interior edges of m (pairs of faces sharing two
// vertices, both with a non-zero normal) whose faces' normals differ by less
// than `angle` degrees; -1 if there is no such edge. Parallel over faces;
// the counts are exact, so the result does not depend on the tag.
template <typename ConcurrencyTag>
double flat_edge_fraction(const Flat_mesh& m, const std::vector<Vec3>& normals, double angle)
{
  const std::size_t nf = m.number_of_faces();
  const double cos_angle = std::cos(angle * 3.14159265358979323846 / 180.);
  std::vector<std::uint32_t> flat(nf, 0), total(nf, 0);
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t f = b; f < e; ++f)
    {
      const Vec3& n = normals[f];
      if(squared_norm(n) == 0.)
        continue;
      for_each_edge_adjacent_face_after(m, f, [&](std::uint32_t g) {
        if(squared_norm(normals[g]) == 0.)
          return;
        ++total[f];
        // unit normals: the angle is under `angle` iff the cosine is above
        flat[f] += dot(n, normals[g]) > cos_angle ? 1u : 0u;
      });
    }
  });
  std::size_t flat_sum = 0, total_sum = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    flat_sum += flat[f];
    total_sum += total[f];
  }
  return total_sum == 0 ? -1. : double(flat_sum) / double(total_sum);
}

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
  c.kernel.relative_radius = std::clamp(R::radius_offset + R::radius_slope * noise, R::min_relative_radius, R::relative_radius);
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
