// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eqs. 2-4 and 8-9: the weights of the intrinsic filter along path trees, for
// any signal, and the pass on face normals built on them. The path sums are
// accumulated from parent to child along each item's path tree, so one sweep
// over a neighbourhood gives every weight.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/path_forest.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Intrinsic_kernel
{
  double sigma_spatial = 0.4; // sigma_s, for d^s
  double sigma_range = 0.4;   // sigma_r, for d^r
  double spatial_exponent = 1.; // n
  double range_exponent = 1.;   // m
  bool include_self = false;    // add A_i n_i to the sum (NOTES 1)

  // term ||x||^p of a sum, from ||x||^2 (no pow for p = 1 or 2)
  static double power_term(double squared, double p)
  {
    if(p == 1.)
      return std::sqrt(squared);
    if(p == 2.)
      return squared;
    return std::pow(squared, 0.5 * p);
  }
  // d^2 from the sum S = d^p (d = S^(1/p))
  static double squared_distance(double sum, double p)
  {
    if(p == 1.)
      return sum * sum;
    if(p == 2.)
      return sum;
    return std::pow(sum, 2. / p);
  }
  // g(d^s; sigma_s) g(d^r; sigma_r) from the two path sums
  double weight(double spatial_sum, double range_sum) const
  {
    const double ds2 = squared_distance(spatial_sum, spatial_exponent);
    const double dr2 = squared_distance(range_sum, range_exponent);
    return std::exp(-ds2 / (2. * sigma_spatial * sigma_spatial) - dr2 / (2. * sigma_range * sigma_range));
  }
};

// The engine of the generalized intrinsic filter (section 3.1): for every
// item i, the kernel weight g(d^s; sigma_s) g(d^r; sigma_r) of each node of
// its path tree, the path sums of eq. 4 / eq. 9 being accumulated from parent
// to child in one forward sweep:
//   S^s(k) = S^s(parent) + ||phi_k - phi_parent||^n (x step length)
//   S^r(k) = S^r(parent) + ||psi_k - psi_i||^m      (x step length)
// with S(i) = 0, d^s = S^s^(1/n), d^r = S^r^(1/m). `spatial_sq(a, b)` returns
// ||phi_a - phi_b||^2 and `range_sq(a, b)` ||psi_a - psi_b||^2. Then
// `average(i, b, e, w)` receives the weights w[k - b] of the nodes k in
// [b, e) of item i's tree (path-only nodes included; they are the caller's
// to skip) and makes the filtered value of i.
template <typename ConcurrencyTag, typename SpatialSq, typename RangeSq, typename Average>
void intrinsic_weights_pass(const Path_forest& forest, const Intrinsic_kernel& kernel, const SpatialSq& spatial_sq,
                            const RangeSq& range_sq, const Average& average)
{
  const std::size_t n = forest.number_of_faces();
  const std::size_t max_nodes = forest.max_nodes_per_face();
  const bool with_steps = !forest.step.empty();
  for_each_chunk<ConcurrencyTag>(n, [&](std::size_t ib, std::size_t ie) {
    std::vector<double> spatial(max_nodes), range(max_nodes), weight(max_nodes);
    for(std::size_t i = ib; i < ie; ++i)
    {
      const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
      for(std::uint32_t k = b; k < e; ++k)
      {
        const std::uint32_t j = forest.face[k];
        const std::int32_t p = forest.parent[k];
        const bool from_root = p == Path_forest::root;
        const std::uint32_t from = from_root ? std::uint32_t(i) : forest.face[b + p];
        double ds = kernel.power_term(spatial_sq(j, from), kernel.spatial_exponent);
        double dr = kernel.power_term(range_sq(j, std::uint32_t(i)), kernel.range_exponent);
        if(with_steps)
        {
          ds *= forest.step[k];
          dr *= forest.step[k];
        }
        const std::uint32_t local = k - b;
        spatial[local] = (from_root ? 0. : spatial[p]) + ds;
        range[local] = (from_root ? 0. : range[p]) + dr;
        weight[local] = kernel.weight(spatial[local], range[local]);
      }
      average(i, b, e, weight.data());
    }
  });
}

// One pass of eq. 8 on face normals: the engine with phi = psi = J = n and the
// face areas as measure. out[i] = normalised sum over the weighted nodes j of
// face i's tree of A_j g(d^s) g(d^r) n_j (plus A_i n_i with the self term). A
// face whose weighted sum vanishes (no neighbour, or weights that cancel)
// keeps its normal.
template <typename ConcurrencyTag>
void intrinsic_filter_pass(const Path_forest& forest, const std::vector<Vec3>& normals,
                           const std::vector<double>& areas, const Intrinsic_kernel& kernel,
                           std::vector<Vec3>& out)
{
  out.resize(forest.number_of_faces());
  const auto normal_sq = [&normals](std::uint32_t a, std::uint32_t b) { return squared_norm(normals[a] - normals[b]); };
  intrinsic_weights_pass<ConcurrencyTag>(
      forest, kernel, normal_sq, normal_sq,
      [&](std::size_t i, std::uint32_t b, std::uint32_t e, const double* w) {
        Vec3 sum = {0., 0., 0.};
        if(kernel.include_self)
          sum = areas[i] * normals[i];
        for(std::uint32_t k = b; k < e; ++k)
          if(forest.is_weighted(k))
          {
            const std::uint32_t j = forest.face[k];
            sum = sum + (areas[j] * w[k - b]) * normals[j];
          }
        const double len = norm(sum);
        out[i] = (len > 0. && std::isfinite(len)) ? (1. / len) * sum : normals[i];
      });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
