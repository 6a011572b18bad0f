// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eqs. 8-9: one pass of the intrinsic filter on face normals. The sums of
// eq. 9 are accumulated from parent to child along each face's path tree, so
// one sweep over a neighbourhood gives every weight.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/square_pattern_paths.h>

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

// Per-face scratch for the path sums, sized for the largest neighbourhood.
struct Path_sums
{
  std::vector<double> spatial, range;
  explicit Path_sums(std::size_t n) : spatial(n), range(n) {}
};

// Path sums of eq. 9 for every node of face i's tree: after the call,
// sums.spatial[k] = sum over consecutive path nodes of ||n_{x+1} - n_x||^n and
// sums.range[k] = sum over path nodes of ||n_x - n_i||^m, for the path from i
// to node k (face i's own term of the range sum is 0).
inline void accumulate_path_sums(const Path_forest& forest, std::size_t i, const std::vector<Vec3>& normals,
                                 const Intrinsic_kernel& kernel, Path_sums& sums)
{
  const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
  const Vec3& ni = normals[i];
  for(std::uint32_t k = b; k < e; ++k)
  {
    const Vec3& nk = normals[forest.face[k]];
    const std::int32_t p = forest.parent[k];
    const std::uint32_t local = k - b;
    const bool from_root = p == Path_forest::root;
    const Vec3& np = from_root ? ni : normals[forest.face[b + p]];
    double ds = kernel.power_term(squared_norm(nk - np), kernel.spatial_exponent);
    double dr = kernel.power_term(squared_norm(nk - ni), kernel.range_exponent);
    if(!forest.step.empty())
    {
      ds *= forest.step[k];
      dr *= forest.step[k];
    }
    sums.spatial[local] = (from_root ? 0. : sums.spatial[p]) + ds;
    sums.range[local] = (from_root ? 0. : sums.range[p]) + dr;
  }
}

// One pass of eq. 8 on all faces: out[i] = normalised sum over the weighted nodes j of
// face i's tree of A_j g(d^s) g(d^r) n_j. A face whose weighted sum vanishes
// (no neighbour, or weights that cancel) keeps its normal.
template <typename ConcurrencyTag>
void intrinsic_filter_pass(const Path_forest& forest, const std::vector<Vec3>& normals,
                           const std::vector<double>& areas, const Intrinsic_kernel& kernel,
                           std::vector<Vec3>& out)
{
  const std::size_t nf = forest.number_of_faces();
  out.resize(nf);
  const std::size_t max_nodes = forest.max_nodes_per_face();
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t fb, std::size_t fe) {
    Path_sums sums(max_nodes);
    for(std::size_t i = fb; i < fe; ++i)
    {
      accumulate_path_sums(forest, i, normals, kernel, sums);
      Vec3 sum = {0., 0., 0.};
      if(kernel.include_self)
        sum = areas[i] * normals[i];
      const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
      for(std::uint32_t k = b; k < e; ++k)
      {
        if(!forest.is_weighted(k))
          continue;
        const std::uint32_t j = forest.face[k];
        const double w = areas[j] * kernel.weight(sums.spatial[k - b], sums.range[k - b]);
        sum = sum + w * normals[j];
      }
      const double len = norm(sum);
      out[i] = (len > 0. && std::isfinite(len)) ? (1. / len) * sum : normals[i];
    }
  });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
