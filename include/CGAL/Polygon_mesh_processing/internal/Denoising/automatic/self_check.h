// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The self-check of the automatic mode: a synthetic noisy copy of a
// candidate's result (its own residual shuffled over the vertices), the
// errors of a kernel run on that copy, and the iteration count they ask for.

#ifndef CGAL_PMP_INTERNAL_DENOISING_SELF_CHECK_H
#define CGAL_PMP_INTERNAL_DENOISING_SELF_CHECK_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// A synthetic noisy copy of `result` (a denoised version of `input`, same
// mesh `m`, vertex order of `m`) with the noise removed from it: the normal
// components of the residual input - result along result's vertex normals,
// shuffled over the vertices that are free (not `fixed`) and have an edge.
// The shuffle keeps the residual's distribution (dense or sparse, light or
// heavy-tailed) and breaks its spatial coherence, which is what shape removed
// would have. Fisher-Yates with std::mt19937 (whose output the standard
// fixes) seeded with `seed`, sequential: the same copy on every platform and
// for every thread count.
inline std::vector<Vec3> synthetic_noisy_copy(const Flat_mesh& m, const Csr& adjacency, const std::vector<Vec3>& input,
                                              const std::vector<Vec3>& result, const std::vector<char>& fixed,
                                              std::uint32_t seed = 1)
{
  const std::vector<Vec3> normals = area_weighted_vertex_normals(m, result);
  std::vector<std::uint32_t> free;
  std::vector<double> along;
  for(std::size_t v = 0; v < result.size(); ++v)
    if(!fixed[v] && adjacency.begin(v) != adjacency.end(v))
    {
      free.push_back(std::uint32_t(v));
      along.push_back(dot(input[v] - result[v], normals[v]));
    }
  std::mt19937 engine(seed);
  for(std::size_t i = along.size(); i > 1; --i)
    std::swap(along[i - 1], along[engine() % i]);
  std::vector<Vec3> copy = result;
  for(std::size_t i = 0; i < free.size(); ++i)
    copy[free[i]] = result[free[i]] + along[i] * normals[free[i]];
  return copy;
}

// The iterations of a self-check kept from its errors (errors[k]: after k
// iterations) for a run of `iterations` iterations. If a count no greater
// than `iterations` has an error within Selection_rules::self_check_tolerance
// of the smallest, the largest such count (the run is kept or shortened as
// little as the tolerance allows). Otherwise the run is lengthened, to the
// count of the smallest error: the copy's reference is the run's own
// result, which keeps whatever low-frequency noise the run left, so running
// on is penalised on the copy, and a minimum beyond the run's count in spite
// of that bias is evidence for the farther count rather than for the first
// one within the tolerance.
inline unsigned int self_check_iterations(const std::vector<double>& errors, unsigned int iterations)
{
  if(errors.empty())
    return 0;
  const auto smallest = std::min_element(errors.begin(), errors.end());
  const double limit = *smallest * (1. + Selection_rules::self_check_tolerance);
  if(std::isnan(limit))
    return iterations; // a NaN error: no evidence
  const std::size_t last = std::min<std::size_t>(iterations, errors.size() - 1);
  for(std::size_t i = last + 1; i-- > 0;)
    if(errors[i] <= limit)
      return unsigned(i);
  return unsigned(smallest - errors.begin());
}

// One self-check run (Automatic_selection::self_check_errors()): `kernel`
// on the paths of `s` from `copy` towards `result` (both in the vertex order
// of `s`), the vertices flagged in `fixed` held, for a run of `iterations`
// iterations. Returns the mean angles in degrees between the face normals
// of the copy after k iterations and those of `result`, from k = 0; the run
// goes to the first iteration that brings the copy no closer if
// `to_first_minimum`, or else on past `iterations` while each iteration
// brings it closer and the error stays within
// Selection_rules::self_check_tolerance of the smallest (up to
// Selection_rules::self_check_max_iterations). With `prevent_folds`, folds
// are checked against the copy's own orientation.
template <typename ConcurrencyTag>
std::vector<double> self_check_errors_on(const Intrinsic_setup& s, const Intrinsic_kernel& kernel,
                                         unsigned int iterations, const std::vector<Vec3>& result,
                                         std::vector<Vec3> copy, bool to_first_minimum, const std::vector<char>& fixed,
                                         unsigned int vertex_iterations, bool prevent_folds,
                                         Least_squares_recovery& recovery)
{
  Face_data target, current;
  compute_face_data<ConcurrencyTag>(s.mesh, result, target);
  compute_face_data<ConcurrencyTag>(s.mesh, copy, current);
  std::vector<double> errors(1, mean_angle_degrees(current.normals, target.normals));
  Fold_safeguard guard;
  guard.enabled = prevent_folds;
  const std::vector<Vec3> copy_normals = current.normals;
  guard.reference = guard.enabled ? &copy_normals : nullptr;
  Face_data faces;
  double smallest = errors.front();
  iterate_filter<ConcurrencyTag>(
      s, kernel, std::move(current), copy, fixed, vertex_iterations, guard, Selection_rules::self_check_max_iterations,
      [&](unsigned int k, const std::vector<Vec3>& p, std::vector<Vec3>&) {
        compute_face_data<ConcurrencyTag>(s.mesh, p, faces);
        errors.push_back(mean_angle_degrees(faces.normals, target.normals));
        const double e = errors.back(), before = errors[k - 1];
        smallest = std::min(smallest, e);
        if(to_first_minimum)
          return e < before;
        return k < iterations || (e < before && e <= smallest * (1. + Selection_rules::self_check_tolerance));
      },
      &recovery);
  return errors;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
