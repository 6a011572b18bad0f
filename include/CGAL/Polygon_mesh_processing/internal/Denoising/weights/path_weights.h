// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eqs. 2-4 and 8-9: the weights of the intrinsic filter along path trees,
// for any signal, and the normalised average of eq. 8 they feed. The path
// sums are accumulated from parent to child along each item's path tree, so
// one sweep over a neighbourhood gives every weight.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// exp(x) for x <= 0, accurate to about 1e-16 relative (as std::exp), inline
// and branch-free, for the weights loop: x = (64 k + j) ln(2)/64 + r with
// |r| <= ln(2)/128, exp(x) = 2^k * 2^(j/64) * e^r, the 64 values 2^(j/64)
// from a table and e^r from its Taylor polynomial of degree 5 (truncation
// below 4e-17). Results at and under 1e-307 (x <= -707) are flushed to 0.
struct Exp_table
{
  double two_to_j_64[64];
  Exp_table()
  {
    for(int j = 0; j < 64; ++j)
      two_to_j_64[j] = std::exp2(j / 64.);
  }
  static const Exp_table& instance()
  {
    static const Exp_table table;
    return table;
  }
};

inline double exp_nonpositive(double x, const Exp_table& table)
{
  const double shifter = 6755399441055744.0; // 1.5 * 2^52: adding it rounds to an integer m, kept in the low bits
  const std::uint64_t shifter_bits = 0x4338000000000000ull;
  const double xc = x > -707. ? x : -707.; // keeps k in range; the result is flushed below
  const double t = xc * (64. / 6.93147180559945309417e-01) + shifter;
  const double md = t - shifter;
  const double r = (xc - md * (6.93147180369123816490e-01 / 64.)) - md * (1.90821492927058770002e-10 / 64.);
  const double r2 = r * r;
  const double p = 1. + r + r2 * ((0.5 + r * (1. / 6.)) + r2 * ((1. / 24.) + r * (1. / 120.)));
  std::uint64_t m;
  std::memcpy(&m, &t, sizeof m);
  m -= shifter_bits; // m = 64 k + j in two's complement
  const double base = table.two_to_j_64[m & 63u];
  std::uint64_t bits;
  std::memcpy(&bits, &base, sizeof bits);
  bits += static_cast<std::uint64_t>(static_cast<std::int64_t>(m) >> 6) << 52; // times 2^k
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return x > -707. ? p * scale : 0.;
}

inline double exp_nonpositive(double x) { return exp_nonpositive(x, Exp_table::instance()); }

struct Intrinsic_kernel
{
  double sigma_spatial = 0.4;   // sigma_s, for d^s
  double sigma_range = 0.4;     // sigma_r, for d^r
  double spatial_exponent = 1.; // n
  double range_exponent = 1.;   // m
  bool include_self = false;    // add A_i n_i to the sum (eq. 8's N_i leaves face i out)

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
  // weight[k] = g(d^s; sigma_s) g(d^r; sigma_r) from the path sums spatial[k]
  // (= (d^s)^n) and range[k] (= (d^r)^m), for k < n; one plain loop per
  // exponent case, free of pow for the common ones (1 and 2); GCC does not
  // vectorise it under -frounding-math, which CGAL adds to every build
  void weights(const double* spatial, const double* range, std::size_t n, double* weight) const
  {
    const double a = 1. / (2. * sigma_spatial * sigma_spatial), b = 1. / (2. * sigma_range * sigma_range);
    const Exp_table& table = Exp_table::instance();
    if(spatial_exponent == 1. && range_exponent == 1.)
      for(std::size_t k = 0; k < n; ++k)
        weight[k] = exp_nonpositive(-(spatial[k] * spatial[k]) * a - (range[k] * range[k]) * b, table);
    else if(spatial_exponent == 2. && range_exponent == 2.)
      for(std::size_t k = 0; k < n; ++k)
        weight[k] = exp_nonpositive(-spatial[k] * a - range[k] * b, table);
    else
      for(std::size_t k = 0; k < n; ++k)
        weight[k] = exp_nonpositive(-squared_distance(spatial[k], spatial_exponent) * a -
                                        squared_distance(range[k], range_exponent) * b,
                                    table);
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
  const bool l1 = kernel.spatial_exponent == 1. && kernel.range_exponent == 1.;
  for_each_chunk<ConcurrencyTag>(n, [&](std::size_t ib, std::size_t ie) {
    // slot 0 holds the root's sums (0); node k of a tree is slot k + 1
    std::vector<double> spatial(max_nodes + 1, 0.), range(max_nodes + 1, 0.), weight(max_nodes);
    std::vector<std::int32_t> parent_scratch(max_nodes + Square_pattern_parent_table::width);
    for(std::size_t i = ib; i < ie; ++i)
    {
      const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
      const std::uint32_t* face = forest.face.data() + b;
      const std::int32_t* parent = forest.parents(i, parent_scratch.data());
      const std::uint32_t count = e - b;
      if(l1 && !with_steps) // the paper's case, without pow or branches
        for(std::uint32_t k = 0; k < count; ++k)
        {
          const std::int32_t p = parent[k];
          const std::uint32_t from = p < 0 ? std::uint32_t(i) : face[p];
          spatial[k + 1] = spatial[p + 1] + std::sqrt(spatial_sq(face[k], from));
          range[k + 1] = range[p + 1] + std::sqrt(range_sq(face[k], std::uint32_t(i)));
        }
      else
        for(std::uint32_t k = 0; k < count; ++k)
        {
          const std::int32_t p = parent[k];
          const std::uint32_t from = p < 0 ? std::uint32_t(i) : face[p];
          const double step = with_steps ? forest.step[b + k] : 1.;
          spatial[k + 1] =
              spatial[p + 1] + step * kernel.power_term(spatial_sq(face[k], from), kernel.spatial_exponent);
          range[k + 1] =
              range[p + 1] + step * kernel.power_term(range_sq(face[k], std::uint32_t(i)), kernel.range_exponent);
        }
      kernel.weights(spatial.data() + 1, range.data() + 1, count, weight.data());
      average(i, b, e, weight.data());
    }
  });
}

// Eq. 8's average for face i: the normalised sum over the weighted nodes
// [b, e) of its tree (weights w[0 .. e - b)) of A_j w n_j, plus A_i n_i with
// the self term. A face whose sum vanishes (no neighbour, or weights that
// cancel) keeps its normal. Every filter pass on face normals ends with it.
inline Vec3 weighted_normal_average(const Path_forest& forest, std::size_t i, std::uint32_t b, std::uint32_t e,
                                    const double* w, const std::vector<Vec3>& normals, const std::vector<double>& areas,
                                    bool include_self)
{
  Vec3 sum = {0., 0., 0.};
  if(include_self)
    sum = areas[i] * normals[i];
  const bool all_weighted = forest.weighted.empty();
  for(std::uint32_t k = b; k < e; ++k)
    if(all_weighted || forest.weighted[k])
    {
      const std::uint32_t j = forest.face[k];
      sum = sum + (areas[j] * w[k - b]) * normals[j];
    }
  const double len = norm(sum);
  return (len > 0. && std::isfinite(len)) ? (1. / len) * sum : normals[i];
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
