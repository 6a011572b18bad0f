// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The candidates of the automatic mode: one candidate kernel run on set-up
// paths until its residual stops looking like noise (run_candidate()), the
// evidence read from its result (residual correlation at a common level,
// share of flat edges) and the choice among the candidates
// (choose_candidate()); the sizes of the setups they run on.

#ifndef CGAL_PMP_INTERNAL_DENOISING_CANDIDATES_H
#define CGAL_PMP_INTERNAL_DENOISING_CANDIDATES_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_description.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// One candidate's run: its trajectory (residual statistics after each
// iteration) and its result at the stop.
struct Candidate_run
{
  double sigma = 0., relative_radius = 0.;
  std::vector<Residual_statistics> trajectory;
  unsigned int iterations = 0; // the iterations kept (trajectory[iterations - 1]; 0: the input)
  bool stopped_by_correlation = false;
  double flat_share = -1.; // of the result (Selection_rules::flat_angle); -1: no interior edge
  double score = 0.;
  // the residual at the stop (residual_description.h): that of the
  // iteration the stopping rule rejected, or of the last one at the limit
  Residual_description stop_residual;
  std::vector<Vec3> points;  // in input vertex order
  std::vector<Vec3> normals; // last filtered normals, in input face order (if asked)
};

// The correlation where the RMS first reaches `level` along `trajectory`
// (linear between iterations); +infinity if it never does.
inline double correlation_at_rms(const std::vector<Residual_statistics>& trajectory, double level)
{
  double previous_rms = 0., previous_corr = 0.;
  for(std::size_t i = 0; i < trajectory.size(); ++i)
  {
    const Residual_statistics& s = trajectory[i];
    if(s.rms >= level)
    {
      if(i == 0 || !(s.rms > previous_rms))
        return s.correlation;
      const double t = (level - previous_rms) / (s.rms - previous_rms);
      return previous_corr + t * (s.correlation - previous_corr);
    }
    previous_rms = s.rms;
    previous_corr = s.correlation;
  }
  return std::numeric_limits<double>::infinity();
}

// The index of the candidate kept, and each candidate's score (set in runs):
// among the candidates whose result is about as piecewise flat as the
// flattest (if that one is flat enough to tell), or else among all, the
// lowest residual correlation at the common comparison level.
inline std::size_t choose_candidate(std::vector<Candidate_run>& runs)
{
  double smallest = std::numeric_limits<double>::infinity(), flattest = -1.;
  for(const Candidate_run& r : runs)
  {
    if(r.iterations > 0)
      smallest = std::min(smallest, r.trajectory[r.iterations - 1].rms);
    flattest = std::max(flattest, r.flat_share);
  }
  const double level = Selection_rules::comparison_fraction * smallest;
  const double min_share =
      flattest >= Selection_rules::min_flat_share ? flattest - Selection_rules::flat_share_margin : -1.;
  std::size_t best = runs.size();
  for(std::size_t c = 0; c < runs.size(); ++c)
  {
    runs[c].score = correlation_at_rms(runs[c].trajectory, level);
    if(runs[c].flat_share >= min_share && (best == runs.size() || runs[c].score < runs[best].score))
      best = c;
  }
  return best == runs.size() ? 0 : best;
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

// `base` with sigma_s = sigma_r = `sigma`: the candidates' kernels.
inline Intrinsic_kernel kernel_of_width(const Intrinsic_kernel& base, double sigma)
{
  Intrinsic_kernel kernel = base;
  kernel.sigma_spatial = kernel.sigma_range = sigma;
  return kernel;
}

// Runs one candidate kernel on the paths of `s` (built on the input, whose
// vertices have been renumbered for locality), from `input_points`, until an
// iteration's residual correlation reaches Selection_rules::stop_correlation
// (the result is then the iterate before it, which may be the input itself)
// or `max_iterations`; the residual at the stop is described
// (describe_residual()).
template <typename ConcurrencyTag>
Candidate_run run_candidate(const Intrinsic_setup& s, const Intrinsic_kernel& kernel, const Csr& adjacency,
                            const std::vector<Vec3>& input_points, const std::vector<char>& fixed,
                            unsigned int vertex_iterations, Fold_safeguard& guard, double unit, bool keep_normals,
                            Least_squares_recovery* recovery = nullptr,
                            unsigned int max_iterations = Selection_rules::max_iterations)
{
  Candidate_run run;
  run.sigma = kernel.sigma_spatial;
  run.relative_radius = s.centroid_distance > 0. ? s.radius / s.centroid_distance : 0.;
  std::vector<Vec3> points = input_points, kept = input_points;
  std::vector<Vec3> kept_normals = keep_normals ? s.input_faces.normals : std::vector<Vec3>();
  iterate_filter<ConcurrencyTag>(
      s, kernel, s.input_faces, points, fixed, vertex_iterations, guard, max_iterations,
      [&](unsigned int k, const std::vector<Vec3>& p, std::vector<Vec3>& filtered) {
        run.trajectory.push_back(residual_statistics(adjacency, p, input_points, unit));
        if(run.trajectory.back().correlation >= Selection_rules::stop_correlation)
        {
          run.stopped_by_correlation = true;
          run.stop_residual = describe_residual(adjacency, p, input_points);
          return false;
        }
        run.iterations = k;
        kept = p;
        if(keep_normals)
          kept_normals.swap(filtered); // the next pass overwrites all of `filtered`
        return true;
      },
      recovery);
  if(!run.stopped_by_correlation)
    run.stop_residual = describe_residual(adjacency, kept, input_points);
  Face_data current;
  compute_face_data<ConcurrencyTag>(s.mesh, kept, current);
  run.flat_share = flat_edge_fraction<ConcurrencyTag>(s.mesh, current.normals, Selection_rules::flat_angle);
  run.points = s.mesh.vertex_values_in_input_order(kept);
  if(keep_normals)
    run.normals = s.mesh.in_input_order(kept_normals);
  return run;
}

// Whether two relative radii (radius / d, rounded) are the same: equal
// within a relative 1e-9.
inline bool same_relative_radius(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }

// The bytes held by the arrays of the paths `p`.
inline std::size_t path_bytes(const Path_forest& p)
{
  return sizeof(std::uint32_t) * (p.offsets.size() + p.face.size() + p.parent.size()) + sizeof(double) * p.step.size() +
         sizeof(p.square_regions[0]) * p.square_regions.size() + p.weighted.size();
}

// The bytes held by the arrays of `s` (its mesh copy, face data and paths).
inline std::size_t setup_bytes(const Intrinsic_setup& s)
{
  const Flat_mesh& m = s.mesh;
  const Face_data& f = s.input_faces;
  return sizeof(Vec3) * (m.points.size() + f.normals.size() + f.centroids.size()) +
         sizeof(m.triangles[0]) * m.triangles.size() +
         sizeof(std::uint32_t) *
             (m.vertex_face_offsets.size() + m.vertex_faces.size() + m.input_face.size() + m.input_vertex.size()) +
         sizeof(double) * f.areas.size() + path_bytes(s.paths);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
