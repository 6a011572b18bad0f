// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One pass of eq. 8 on face normals, the step Algorithm 1 repeats: the
// generic engine, or the SIMD kernel of the paper's case where the processor
// runs it; and the forest layout the kernel prefers.

#ifndef CGAL_PMP_INTERNAL_DENOISING_NORMAL_FILTER_PASS_H
#define CGAL_PMP_INTERNAL_DENOISING_NORMAL_FILTER_PASS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/path_weights.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/path_weights_simd.h>

#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// One pass of eq. 8 on face normals, through the generic engine: the engine with phi = psi = J = n and the
// face areas as measure. out[i] = normalised sum over the weighted nodes j of
// face i's tree of A_j g(d^s) g(d^r) n_j (plus A_i n_i with the self term). A
// face whose weighted sum vanishes (no neighbour, or weights that cancel)
// keeps its normal.
template <typename ConcurrencyTag>
void intrinsic_filter_pass_generic(const Path_forest& forest, const std::vector<Vec3>& normals,
                                   const std::vector<double>& areas, const Intrinsic_kernel& kernel,
                                   std::vector<Vec3>& out)
{
  out.resize(forest.number_of_faces());
  const auto normal_sq = [&normals](std::uint32_t a, std::uint32_t b) { return squared_norm(normals[a] - normals[b]); };
  intrinsic_weights_pass<ConcurrencyTag>(
      forest, kernel, normal_sq, normal_sq, [&](std::size_t i, std::uint32_t b, std::uint32_t e, const double* w) {
        out[i] = weighted_normal_average(forest, i, b, e, w, normals, areas, kernel.include_self);
      });
}

// Whether intrinsic_filter_pass is fastest on square-pattern forests that
// keep their parents as region sizes (the AVX2 kernel, see
// intrinsic_filter_faces_l1_avx2_shells) rather than one per node.
inline bool filter_pass_prefers_square_regions()
{
#ifdef CGAL_PMP_DENOISING_AVX2
  return cpu_has_avx2();
#else
  return false;
#endif
}

// One pass of eq. 8 on face normals: out[i] = normalised sum over the
// weighted nodes j of face i's tree of A_j g(d^s) g(d^r) n_j (plus A_i n_i
// with the self term). A face whose weighted sum vanishes (no neighbour, or
// weights that cancel) keeps its normal. The paper's case (n = m = 1, no step
// lengths) takes the SSE2 kernel where the compiler targets SSE2.
template <typename ConcurrencyTag>
void intrinsic_filter_pass(const Path_forest& forest, const std::vector<Vec3>& normals,
                           const std::vector<double>& areas, const Intrinsic_kernel& kernel, std::vector<Vec3>& out)
{
#ifdef CGAL_PMP_DENOISING_SSE2
  if(kernel.spatial_exponent == 1. && kernel.range_exponent == 1. && forest.step.empty())
  {
    out.resize(forest.number_of_faces());
#ifdef CGAL_PMP_DENOISING_AVX2
    if(cpu_has_avx2())
    {
      intrinsic_filter_pass_l1_avx2<ConcurrencyTag>(forest, normals, areas, kernel, out);
      return;
    }
#endif
    intrinsic_filter_pass_l1_sse2<ConcurrencyTag>(forest, normals, areas, kernel, out);
    return;
  }
#endif
  intrinsic_filter_pass_generic<ConcurrencyTag>(forest, normals, areas, kernel, out);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
