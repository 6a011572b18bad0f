// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The iterations of Algorithm 1 on paths set up once: filter the face normals
// of the current mesh (eq. 8), move the vertices (eq. 10), and let the caller
// look at the result after each iteration and stop. Shared by
// intrinsic_denoising() (fixed mode, some parameters given), the automatic
// selection and the benchmarks that read every iteration.

#ifndef CGAL_PMP_INTERNAL_DENOISING_FILTER_ITERATIONS_H
#define CGAL_PMP_INTERNAL_DENOISING_FILTER_ITERATIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/intrinsic_setup.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/normal_filter_pass.h>

#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Runs up to `max_iterations` iterations on the paths of `s` from `points`
// (updated in place), whose face data are `current` (the setup's input_faces
// when `points` is the input: copied, or moved if the setup is not run
// again). After iteration k (from 1),
// `after(k, points, filtered)` is called with the filtered normals of that
// pass; it returns false to stop. Returns the number of iterations run.
// With an enabled `recovery`, the vertices move by its least-squares step
// instead of eq. 10 (see update_vertices).
template <typename ConcurrencyTag, typename After>
unsigned int iterate_filter(const Intrinsic_setup& s, const Intrinsic_kernel& kernel, Face_data current,
                            std::vector<Vec3>& points, const std::vector<char>& fixed, unsigned int vertex_iterations,
                            Fold_safeguard& guard, unsigned int max_iterations, const After& after,
                            Least_squares_recovery* recovery = nullptr)
{
  std::vector<Vec3> filtered, centroids, next;
  for(unsigned int it = 0; it < max_iterations; ++it)
  {
    if(it > 0)
      compute_face_data<ConcurrencyTag>(s.mesh, points, current);
    intrinsic_filter_pass<ConcurrencyTag>(s.paths, current.normals, current.areas, kernel, filtered);
    update_vertices<ConcurrencyTag>(s.mesh, points, filtered, fixed, vertex_iterations, centroids, next, &guard,
                                    recovery);
    if(!after(it + 1, static_cast<const std::vector<Vec3>&>(points), filtered))
      return it + 1;
  }
  return max_iterations;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
