// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The x86 kernels of the paper's filter pass on face normals (n = m = 1, no
// step lengths): SSE2, and AVX2 chosen at run time. Each computes bitwise
// the same normals as the generic engine of path_weights.h.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_SIMD_H
#define CGAL_PMP_INTERNAL_DENOISING_PATH_WEIGHTS_SIMD_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/weights/path_weights.h>

#include <cstdint>
#include <vector>

#if defined(__SSE2__) && !defined(CGAL_PMP_DENOISING_NO_SIMD)
#include <emmintrin.h>
#define CGAL_PMP_DENOISING_SSE2 1
// AVX2 variant of the SSE2 kernel, compiled for that target only (the rest
// of the program keeps the compiler's flags) and chosen at run time when the
// processor has AVX2. CGAL_PMP_DENOISING_NO_AVX2 turns it off.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(CGAL_PMP_DENOISING_NO_AVX2)
#include <immintrin.h>
#define CGAL_PMP_DENOISING_AVX2 1
#define CGAL_PMP_DENOISING_AVX2_TARGET __attribute__((target("avx2")))
#endif
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

#ifdef CGAL_PMP_DENOISING_SSE2
// exp_nonpositive on two values at once: the same operations in the same
// order, so each lane is bitwise the scalar result.
inline __m128d exp_nonpositive_2(__m128d x, const Exp_table& table)
{
  const __m128d shifter = _mm_set1_pd(6755399441055744.0);
  const __m128d low = _mm_set1_pd(-707.);
  const __m128d keep = _mm_cmpgt_pd(x, low);
  const __m128d xc = _mm_or_pd(_mm_and_pd(keep, x), _mm_andnot_pd(keep, low));
  const double to_index = 64. / 6.93147180559945309417e-01;
  const __m128d t = _mm_add_pd(_mm_mul_pd(xc, _mm_set1_pd(to_index)), shifter);
  const __m128d md = _mm_sub_pd(t, shifter);
  const __m128d r = _mm_sub_pd(_mm_sub_pd(xc, _mm_mul_pd(md, _mm_set1_pd(6.93147180369123816490e-01 / 64.))),
                               _mm_mul_pd(md, _mm_set1_pd(1.90821492927058770002e-10 / 64.)));
  const __m128d r2 = _mm_mul_pd(r, r);
  const __m128d inner1 = _mm_add_pd(_mm_set1_pd(0.5), _mm_mul_pd(r, _mm_set1_pd(1. / 6.)));
  const __m128d inner2 = _mm_add_pd(_mm_set1_pd(1. / 24.), _mm_mul_pd(r, _mm_set1_pd(1. / 120.)));
  const __m128d poly =
      _mm_add_pd(_mm_add_pd(_mm_set1_pd(1.), r), _mm_mul_pd(r2, _mm_add_pd(inner1, _mm_mul_pd(r2, inner2))));
  const __m128i m = _mm_sub_epi64(_mm_castpd_si128(t), _mm_set1_epi64x(0x4338000000000000ll));
  const std::int64_t m0 = _mm_cvtsi128_si64(m), m1 = _mm_cvtsi128_si64(_mm_unpackhi_epi64(m, m));
  const __m128d base = _mm_set_pd(table.two_to_j_64[m1 & 63], table.two_to_j_64[m0 & 63]);
  // (m >> 6) << 52 without an arithmetic 64-bit shift: the sign bits that
  // differ are shifted out
  const __m128i k = _mm_slli_epi64(_mm_and_si128(m, _mm_set1_epi64x(~std::int64_t(63))), 46);
  const __m128d scale = _mm_castsi128_pd(_mm_add_epi64(_mm_castpd_si128(base), k));
  return _mm_and_pd(keep, _mm_mul_pd(poly, scale));
}

// The paper's case of intrinsic_filter_pass (n = m = 1, no step lengths)
// with SSE2: the two roots of a node (its step ||n_k - n_parent|| and its
// range term ||n_k - n_i||) are taken by one instruction, and the weights two
// nodes at a time. Every operation is the scalar engine's, in its order, so
// the result is bitwise that of intrinsic_filter_pass_generic (a test checks).
template <typename ConcurrencyTag>
void intrinsic_filter_pass_l1_sse2(const Path_forest& forest, const std::vector<Vec3>& normals,
                                   const std::vector<double>& areas, const Intrinsic_kernel& kernel,
                                   std::vector<Vec3>& out)
{
  const std::size_t n = forest.number_of_faces();
  const std::size_t max_nodes = forest.max_nodes_per_face();
  const double a = 1. / (2. * kernel.sigma_spatial * kernel.sigma_spatial),
               b = 1. / (2. * kernel.sigma_range * kernel.sigma_range);
  const Exp_table& table = Exp_table::instance();
  for_each_chunk<ConcurrencyTag>(n, [&](std::size_t ib, std::size_t ie) {
    // sums[2 (k + 1)] = spatial sum of node k, sums[2 (k + 1) + 1] its range
    // sum; slot 0 is the root's (0, 0); one spare node pads an odd count
    std::vector<double> sums(2 * (max_nodes + 2), 0.), weight(max_nodes + 1);
    std::vector<std::int32_t> parent_scratch(max_nodes + Square_pattern_parent_table::width);
    const __m128d va = _mm_set1_pd(a), vb = _mm_set1_pd(b);
    const __m128d sign = _mm_set1_pd(-0.);
    for(std::size_t i = ib; i < ie; ++i)
    {
      const std::uint32_t nb = forest.offsets[i], ne = forest.offsets[i + 1];
      const std::uint32_t* face = forest.face.data() + nb;
      const std::int32_t* parent = forest.parents(i, parent_scratch.data());
      const std::uint32_t count = ne - nb;
      const Vec3& ni = normals[i];
      // high lanes: the root's normal, for the range terms
      const __m128d nix = _mm_set1_pd(ni[0]), niy = _mm_set1_pd(ni[1]), niz = _mm_set1_pd(ni[2]);
      double* sum_slot = sums.data();
      for(std::uint32_t k = 0; k < count; ++k)
      {
        const std::int32_t p = parent[k];
        const Vec3& nk = normals[face[k]];
        const Vec3& nf = normals[p < 0 ? std::uint32_t(i) : face[p]];
        const __m128d dx = _mm_sub_pd(_mm_set1_pd(nk[0]), _mm_loadl_pd(nix, &nf[0]));
        const __m128d dy = _mm_sub_pd(_mm_set1_pd(nk[1]), _mm_loadl_pd(niy, &nf[1]));
        const __m128d dz = _mm_sub_pd(_mm_set1_pd(nk[2]), _mm_loadl_pd(niz, &nf[2]));
        const __m128d sq = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
        _mm_storeu_pd(sum_slot + 2 * (k + 1), _mm_add_pd(_mm_loadu_pd(sum_slot + 2 * (p + 1)), _mm_sqrt_pd(sq)));
      }
      if(count % 2)
        _mm_storeu_pd(sum_slot + 2 * (count + 1), _mm_setzero_pd());
      for(std::uint32_t k = 0; k < count; k += 2)
      {
        const __m128d v0 = _mm_loadu_pd(sum_slot + 2 * (k + 1)), v1 = _mm_loadu_pd(sum_slot + 2 * (k + 2));
        const __m128d sp = _mm_unpacklo_pd(v0, v1), rg = _mm_unpackhi_pd(v0, v1);
        const __m128d x =
            _mm_sub_pd(_mm_mul_pd(_mm_xor_pd(_mm_mul_pd(sp, sp), sign), va), _mm_mul_pd(_mm_mul_pd(rg, rg), vb));
        _mm_storeu_pd(weight.data() + k, exp_nonpositive_2(x, table));
      }
      out[i] = weighted_normal_average(forest, i, nb, ne, weight.data(), normals, areas, kernel.include_self);
    }
  });
}
#endif

#ifdef CGAL_PMP_DENOISING_AVX2
// Whether the processor runs AVX2 code (and the system saves its registers).
inline bool cpu_has_avx2()
{
  static const bool has = __builtin_cpu_supports("avx2") != 0;
  return has;
}

// exp_nonpositive_2 on four values: the same operations in the same order
// (no fused multiply-add: the target does not include FMA), so each lane is
// bitwise the scalar result.
CGAL_PMP_DENOISING_AVX2_TARGET inline __m256d exp_nonpositive_4(__m256d x, const Exp_table& table)
{
  const __m256d shifter = _mm256_set1_pd(6755399441055744.0);
  const __m256d low = _mm256_set1_pd(-707.);
  const __m256d keep = _mm256_cmp_pd(x, low, _CMP_GT_OQ);
  const __m256d xc = _mm256_blendv_pd(low, x, keep);
  const double to_index = 64. / 6.93147180559945309417e-01;
  const __m256d t = _mm256_add_pd(_mm256_mul_pd(xc, _mm256_set1_pd(to_index)), shifter);
  const __m256d md = _mm256_sub_pd(t, shifter);
  const __m256d r =
      _mm256_sub_pd(_mm256_sub_pd(xc, _mm256_mul_pd(md, _mm256_set1_pd(6.93147180369123816490e-01 / 64.))),
                    _mm256_mul_pd(md, _mm256_set1_pd(1.90821492927058770002e-10 / 64.)));
  const __m256d r2 = _mm256_mul_pd(r, r);
  const __m256d inner1 = _mm256_add_pd(_mm256_set1_pd(0.5), _mm256_mul_pd(r, _mm256_set1_pd(1. / 6.)));
  const __m256d inner2 = _mm256_add_pd(_mm256_set1_pd(1. / 24.), _mm256_mul_pd(r, _mm256_set1_pd(1. / 120.)));
  const __m256d poly = _mm256_add_pd(_mm256_add_pd(_mm256_set1_pd(1.), r),
                                     _mm256_mul_pd(r2, _mm256_add_pd(inner1, _mm256_mul_pd(r2, inner2))));
  const __m256i m = _mm256_sub_epi64(_mm256_castpd_si256(t), _mm256_set1_epi64x(0x4338000000000000ll));
  const __m256d base = _mm256_i64gather_pd(table.two_to_j_64, _mm256_and_si256(m, _mm256_set1_epi64x(63)), 8);
  const __m256i k = _mm256_slli_epi64(_mm256_and_si256(m, _mm256_set1_epi64x(~std::int64_t(63))), 46);
  const __m256d scale = _mm256_castsi256_pd(_mm256_add_epi64(_mm256_castpd_si256(base), k));
  return _mm256_and_pd(keep, _mm256_mul_pd(poly, scale));
}

// exp_nonpositive_4 on x[0..3] into e[0..3] (for callers compiled without AVX2).
CGAL_PMP_DENOISING_AVX2_TARGET inline void exp_nonpositive_4(const double* x, double* e, const Exp_table& table)
{
  _mm256_storeu_pd(e, exp_nonpositive_4(_mm256_loadu_pd(x), table));
}

// The two roots of one node k with normal nk: (||nk - nf||, ||nk - ni||),
// its step against its parent's normal nf and its range term against the
// root's normal ni, as the AVX2 kernels take them for a node left over
// from their pairs; x, y and z hold (nf, ni) component by component (built
// once per shell by the shells kernel).
inline __m128d node_roots(const Vec3& nk, __m128d x, __m128d y, __m128d z)
{
  const __m128d dx = _mm_sub_pd(_mm_set1_pd(nk[0]), x);
  const __m128d dy = _mm_sub_pd(_mm_set1_pd(nk[1]), y);
  const __m128d dz = _mm_sub_pd(_mm_set1_pd(nk[2]), z);
  return _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
}

inline __m128d node_roots(const Vec3& nk, const Vec3& nf, const Vec3& ni)
{
  return node_roots(nk, _mm_set_pd(ni[0], nf[0]), _mm_set_pd(ni[1], nf[1]), _mm_set_pd(ni[2], nf[2]));
}

// The weights of the `count` nodes of a face from their path sums
// (sums[2 (k + 1)] spatial, sums[2 (k + 1) + 1] range; room for up to three
// spare nodes, which pad the count to a multiple of 4), four at a time:
// weight[k] = exp(-s_k^2 a - r_k^2 b), with va = a and vb = b in every lane.
CGAL_PMP_DENOISING_AVX2_TARGET inline void weights_from_sums_avx2(double* sums, std::uint32_t count, __m256d va,
                                                                  __m256d vb, double* weight, const Exp_table& table)
{
  const __m256d sign = _mm256_set1_pd(-0.);
  std::uint32_t k;
  for(k = count; k % 4 != 0; ++k)
    _mm_storeu_pd(sums + 2 * (k + 1), _mm_setzero_pd());
  for(k = 0; k < count; k += 4)
  {
    // (s k, r k, s k+1, r k+1) and (s k+2, r k+2, s k+3, r k+3)
    const __m256d v0 = _mm256_loadu_pd(sums + 2 * (k + 1)), v1 = _mm256_loadu_pd(sums + 2 * (k + 3));
    // (s k, s k+2, s k+1, s k+3) and the same for r
    const __m256d sp = _mm256_unpacklo_pd(v0, v1), rg = _mm256_unpackhi_pd(v0, v1);
    const __m256d x = _mm256_sub_pd(_mm256_mul_pd(_mm256_xor_pd(_mm256_mul_pd(sp, sp), sign), va),
                                    _mm256_mul_pd(_mm256_mul_pd(rg, rg), vb));
    _mm256_storeu_pd(weight + k, _mm256_permute4x64_pd(exp_nonpositive_4(x, table), 0xD8));
  }
}

// Faces [ib, ie) of the AVX2 kernel. The roots of two nodes (four values)
// are taken by one instruction into `roots`, then added to the parents'
// sums in tree order, so the roots do not wait for the sums; the weights are
// computed four nodes at a time. The operations on each value are the SSE2
// kernel's, in its order. Scratch: sums 2 (max_nodes + 4), roots
// 2 (max_nodes + 2), weight max_nodes + 4 doubles, parent_scratch
// max_nodes + Square_pattern_parent_table::width.
CGAL_PMP_DENOISING_AVX2_TARGET inline void
intrinsic_filter_faces_l1_avx2(const Path_forest& forest, const std::vector<Vec3>& normals,
                               const std::vector<double>& areas, double a, double b, bool include_self, std::size_t ib,
                               std::size_t ie, double* sums, double* roots, double* weight,
                               std::int32_t* parent_scratch, std::vector<Vec3>& out)
{
  const Exp_table& table = Exp_table::instance();
  const __m256d va = _mm256_set1_pd(a), vb = _mm256_set1_pd(b);
  const Vec3* nrm = normals.data();
  for(std::size_t i = ib; i < ie; ++i)
  {
    const std::uint32_t nb = forest.offsets[i], ne = forest.offsets[i + 1];
    const std::uint32_t* face = forest.face.data() + nb;
    const std::int32_t* parent = forest.parents(i, parent_scratch);
    const std::uint32_t count = ne - nb;
    const Vec3& ni = nrm[i];
    // lanes (step k, range k, step k+1, range k+1): the step is taken
    // against the parent's normal, the range against the root's
    const __m256d nix = _mm256_set1_pd(ni[0]), niy = _mm256_set1_pd(ni[1]), niz = _mm256_set1_pd(ni[2]);
    std::uint32_t k = 0;
    for(; k + 1 < count; k += 2)
    {
      const std::int32_t p0 = parent[k], p1 = parent[k + 1];
      const Vec3& n0 = nrm[face[k]];
      const Vec3& n1 = nrm[face[k + 1]];
      const Vec3& f0 = nrm[p0 < 0 ? std::uint32_t(i) : face[p0]];
      const Vec3& f1 = nrm[p1 < 0 ? std::uint32_t(i) : face[p1]];
      const __m256d dx = _mm256_sub_pd(_mm256_set_pd(n1[0], n1[0], n0[0], n0[0]),
                                       _mm256_blend_pd(nix, _mm256_set_pd(0., f1[0], 0., f0[0]), 0x5));
      const __m256d dy = _mm256_sub_pd(_mm256_set_pd(n1[1], n1[1], n0[1], n0[1]),
                                       _mm256_blend_pd(niy, _mm256_set_pd(0., f1[1], 0., f0[1]), 0x5));
      const __m256d dz = _mm256_sub_pd(_mm256_set_pd(n1[2], n1[2], n0[2], n0[2]),
                                       _mm256_blend_pd(niz, _mm256_set_pd(0., f1[2], 0., f0[2]), 0x5));
      const __m256d sq =
          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
      _mm256_storeu_pd(roots + 2 * k, _mm256_sqrt_pd(sq));
    }
    if(k < count)
    {
      const std::int32_t p = parent[k];
      _mm_storeu_pd(roots + 2 * k, node_roots(nrm[face[k]], nrm[p < 0 ? std::uint32_t(i) : face[p]], ni));
    }
    // sums[2 (k + 1)] = spatial sum of node k, sums[2 (k + 1) + 1] its range
    // sum; slot 0 is the root's (0, 0)
    for(k = 0; k < count; ++k)
      _mm_storeu_pd(sums + 2 * (k + 1),
                    _mm_add_pd(_mm_loadu_pd(sums + 2 * (parent[k] + 1)), _mm_loadu_pd(roots + 2 * k)));
    weights_from_sums_avx2(sums, count, va, vb, weight, table);
    out[i] = weighted_normal_average(forest, i, nb, ne, weight, normals, areas, include_self);
  }
}

// The AVX2 kernel for square-pattern trees kept as region sizes: within a
// region, the nodes of ranks (q-1)^2 + 1 .. q^2 (a "shell") all hang from
// the node of rank (q-1)^2 (face i for q = 1), so the parent's normal and
// sums are loaded once per shell instead of once per node, and no parent
// index is read. The operations on each value are those of
// intrinsic_filter_faces_l1_avx2, in its order (bitwise the same result).
CGAL_PMP_DENOISING_AVX2_TARGET inline void
intrinsic_filter_faces_l1_avx2_shells(const Path_forest& forest, const std::vector<Vec3>& normals,
                                      const std::vector<double>& areas, double a, double b, bool include_self,
                                      std::size_t ib, std::size_t ie, double* sums, double* weight,
                                      std::int32_t* parent_scratch, std::vector<Vec3>& out)
{
  const Exp_table& table = Exp_table::instance();
  const __m256d va = _mm256_set1_pd(a), vb = _mm256_set1_pd(b);
  const Vec3* nrm = normals.data();
  for(std::size_t i = ib; i < ie; ++i)
  {
    const std::uint32_t nb = forest.offsets[i], ne = forest.offsets[i + 1];
    const std::uint32_t* face = forest.face.data() + nb;
    const std::uint32_t count = ne - nb;
    const Vec3& ni = nrm[i];
    const std::array<std::uint32_t, 6>& regions = forest.square_regions[i];
    std::uint32_t start = 0;
    for(const std::uint32_t size : regions)
    {
      std::uint32_t lo = 0; // first local rank - 1 of the shell
      for(std::uint32_t q = 1; lo < size; ++q)
      {
        const std::uint32_t hi = (std::min)(q * q, size);
        // the parent: face i for the first shell, else rank (q-1)^2
        const std::int32_t p = q == 1 ? -1 : std::int32_t(start + lo) - 1;
        const Vec3& np = nrm[p < 0 ? std::uint32_t(i) : face[p]];
        const __m128d ps = _mm_loadu_pd(sums + 2 * (p + 1));
        const __m256d ps2 = _mm256_set_m128d(ps, ps);
        const __m256d px = _mm256_set_pd(ni[0], np[0], ni[0], np[0]);
        const __m256d py = _mm256_set_pd(ni[1], np[1], ni[1], np[1]);
        const __m256d pz = _mm256_set_pd(ni[2], np[2], ni[2], np[2]);
        std::uint32_t k = start + lo;
        const std::uint32_t end = start + hi;
        for(; k + 1 < end; k += 2)
        {
          const Vec3& n0 = nrm[face[k]];
          const Vec3& n1 = nrm[face[k + 1]];
          const __m256d dx = _mm256_sub_pd(_mm256_set_pd(n1[0], n1[0], n0[0], n0[0]), px);
          const __m256d dy = _mm256_sub_pd(_mm256_set_pd(n1[1], n1[1], n0[1], n0[1]), py);
          const __m256d dz = _mm256_sub_pd(_mm256_set_pd(n1[2], n1[2], n0[2], n0[2]), pz);
          const __m256d sq =
              _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
          _mm256_storeu_pd(sums + 2 * (k + 1), _mm256_add_pd(ps2, _mm256_sqrt_pd(sq)));
        }
        if(k < end)
          _mm_storeu_pd(sums + 2 * (k + 1),
                        _mm_add_pd(ps, node_roots(nrm[face[k]], _mm256_castpd256_pd128(px), _mm256_castpd256_pd128(py),
                                                  _mm256_castpd256_pd128(pz))));
        lo = hi;
      }
      start += size;
    }
    if(start != count) // degenerate face i: every node hangs from i
    {
      const std::int32_t* parent = forest.parents(i, parent_scratch);
      for(std::uint32_t k = 0; k < count; ++k)
      {
        const std::int32_t p = parent[k];
        const __m128d r = node_roots(nrm[face[k]], nrm[p < 0 ? std::uint32_t(i) : face[p]], ni);
        _mm_storeu_pd(sums + 2 * (k + 1), _mm_add_pd(_mm_loadu_pd(sums + 2 * (p + 1)), r));
      }
    }
    weights_from_sums_avx2(sums, count, va, vb, weight, table);
    out[i] = weighted_normal_average(forest, i, nb, ne, weight, normals, areas, include_self);
  }
}

template <typename ConcurrencyTag>
void intrinsic_filter_pass_l1_avx2(const Path_forest& forest, const std::vector<Vec3>& normals,
                                   const std::vector<double>& areas, const Intrinsic_kernel& kernel,
                                   std::vector<Vec3>& out)
{
  const std::size_t max_nodes = forest.max_nodes_per_face();
  const double a = 1. / (2. * kernel.sigma_spatial * kernel.sigma_spatial),
               b = 1. / (2. * kernel.sigma_range * kernel.sigma_range);
  for_each_chunk<ConcurrencyTag>(forest.number_of_faces(), [&](std::size_t ib, std::size_t ie) {
    std::vector<double> sums(2 * (max_nodes + 4), 0.), weight(max_nodes + 4);
    std::vector<double> roots(forest.square_regions.empty() ? 2 * (max_nodes + 2) : 0); // the shells need none
    std::vector<std::int32_t> parent_scratch(max_nodes + Square_pattern_parent_table::width);
    if(forest.square_regions.empty())
      intrinsic_filter_faces_l1_avx2(forest, normals, areas, a, b, kernel.include_self, ib, ie, sums.data(),
                                     roots.data(), weight.data(), parent_scratch.data(), out);
    else
      intrinsic_filter_faces_l1_avx2_shells(forest, normals, areas, a, b, kernel.include_self, ib, ie, sums.data(),
                                            weight.data(), parent_scratch.data(), out);
  });
}
#endif

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
