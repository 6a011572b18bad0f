// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Sparse (impulsive) noise: a few vertices far off the surface, the others
// exact. A filter that smooths every vertex removes the outliers but also
// shape everywhere else, and the result can be worse than the input. The
// residual between the input and a denoised result tells the two kinds of
// noise apart without ground truth:
//  - its normal components are heavy-tailed: most are small (the filter's
//    bias on exact vertices), a few large (the outliers). Vertices beyond a
//    few robust standard deviations (1.4826 times the median absolute value)
//    are flagged;
//  - at the vertices not flagged, the residual is smooth along the surface
//    when they were exact (shape removed: neighbours agree, correlation
//    across edges clearly positive), and rough when they carried noise of
//    their own (noise removed: correlation zero or negative, see
//    residual_statistics.h).
// When both hold, only the flagged vertices are noise: the automatic mode
// then denoises again with every other vertex held in place.

#ifndef CGAL_PMP_INTERNAL_DENOISING_SPARSE_NOISE_H
#define CGAL_PMP_INTERNAL_DENOISING_SPARSE_NOISE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/residual_statistics.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/neighborhoods/neighborhoods.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

struct Sparse_noise_rules
{
  // A vertex is an outlier if the normal component of its residual exceeds
  // this many robust standard deviations (about 0.3% of Gaussian noise does).
  static constexpr double outlier_threshold = 3.;
  // The residual at the other vertices must be this correlated across edges.
  // Measured on the development corpus (benchmark/Polygon_mesh_processing/
  // corpus_benchmark.cpp) after the automatic selection: with Gaussian noise
  // from -0.093 to -0.032 (128 inputs), with simulated depth-scan noise from
  // -0.103 to 0.040 (64), with impulsive noise (10% of the vertices) from
  // -0.001 to 0.634, above 0.1 on 27 of 32. The margin above the dense
  // noises' largest value keeps a mesh with noise on every vertex from being
  // taken for one with exact vertices.
  static constexpr double min_inlier_correlation = 0.1;
  // (The outliers are a minority by construction: the threshold is above the
  // median, so fewer than half of the vertices can be flagged.)
};

struct Sparse_noise_test
{
  std::vector<char> outlier; // per vertex of the mesh; 1: flagged
  std::size_t outliers = 0;  // flagged vertices
  std::size_t tested = 0;    // vertices tested (free, with an edge)
  double inlier_correlation = 0.;
  bool sparse = false; // the noise is on the flagged vertices only
};

// For each vertex, the mean edge length of its connected component (through
// `adjacency`, vertex_adjacency(m), at the positions `points`) over the
// mean edge length of the whole mesh; empty if the mesh has one component
// (every ratio 1). Vertices without an edge get 1.
inline std::vector<double> component_scales(const Csr& adjacency, const std::vector<Vec3>& points)
{
  const std::size_t nv = adjacency.size();
  const std::uint32_t none = std::uint32_t(-1);
  std::vector<std::uint32_t> component(nv, none), stack;
  std::vector<double> lengths;
  std::vector<std::size_t> edges;
  double total_length = 0.;
  std::size_t total_edges = 0;
  for(std::size_t seed = 0; seed < nv; ++seed)
  {
    if(component[seed] != none || adjacency.begin(seed) == adjacency.end(seed))
      continue;
    const std::uint32_t c = std::uint32_t(lengths.size());
    lengths.push_back(0.);
    edges.push_back(0);
    component[seed] = c;
    stack.assign(1, std::uint32_t(seed));
    while(!stack.empty())
    {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      for(std::uint32_t k = adjacency.begin(v); k < adjacency.end(v); ++k)
      {
        const std::uint32_t u = adjacency.items[k];
        if(u > v)
        {
          const double l = norm(points[u] - points[v]);
          lengths[c] += l;
          ++edges[c];
          total_length += l;
          ++total_edges;
        }
        if(component[u] == none)
        {
          component[u] = c;
          stack.push_back(u);
        }
      }
    }
  }
  if(lengths.size() < 2 || !(total_length > 0.))
    return std::vector<double>();
  const double mean = total_length / double(total_edges);
  std::vector<double> scale(nv, 1.);
  for(std::size_t v = 0; v < nv; ++v)
    if(component[v] != none && lengths[component[v]] > 0.)
      scale[v] = lengths[component[v]] / double(edges[component[v]]) / mean;
  return scale;
}

// The test proper, on `input` and `result` in the units they are given in;
// `normals` are the result's area-weighted vertex normals.
inline Sparse_noise_test sparse_noise_test_in_units(const Csr& adjacency, const std::vector<Vec3>& input,
                                                    const std::vector<Vec3>& result, const std::vector<char>& fixed,
                                                    const std::vector<Vec3>& normals)
{
  const std::size_t nv = adjacency.size();
  Sparse_noise_test t;
  t.outlier.assign(nv, 0);
  std::vector<double> along(nv, 0.), magnitudes;
  std::vector<char> tested(nv, 0);
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(fixed[v] || adjacency.begin(v) == adjacency.end(v))
      continue;
    along[v] = dot(input[v] - result[v], normals[v]);
    tested[v] = 1;
    magnitudes.push_back(std::abs(along[v]));
  }
  t.tested = magnitudes.size();
  if(magnitudes.empty())
    return t;
  const std::size_t middle = magnitudes.size() / 2;
  std::nth_element(magnitudes.begin(), magnitudes.begin() + middle, magnitudes.end());
  const double scale = 1.4826 * magnitudes[middle];
  if(!(scale > 0.))
    return t; // half of the vertices did not move: no residual to read
  for(std::size_t v = 0; v < nv; ++v)
    if(tested[v] && std::abs(along[v]) > Sparse_noise_rules::outlier_threshold * scale)
    {
      t.outlier[v] = 1;
      ++t.outliers;
    }
  t.inlier_correlation = residual_edge_correlation(adjacency, result, input,
                                                   [&t, &tested](std::size_t v) { return tested[v] && !t.outlier[v]; });
  t.sparse = t.outliers > 0 && t.inlier_correlation >= Sparse_noise_rules::min_inlier_correlation;
  return t;
}

// The test on `result` (a denoised version of `input`, same mesh `m`, vertex
// order of `m`); `adjacency` is vertex_adjacency(m); vertices with `fixed`
// set or without an edge are neither tested nor flagged. On a mesh of
// several connected components, each vertex's residual is read in units of
// its component's mean edge length over the mesh's (component_scales()): a
// part modelled at a thousandth of the scale of another has a residual a
// thousand times smaller, which in the mesh's units would all fall within
// the threshold and hold the whole part in place as exact. Sequential, in a
// fixed order: the result does not depend on the thread count.
inline Sparse_noise_test sparse_noise_test(const Flat_mesh& m, const Csr& adjacency, const std::vector<Vec3>& input,
                                           const std::vector<Vec3>& result, const std::vector<char>& fixed)
{
  const std::vector<Vec3> normals = area_weighted_vertex_normals(m, result);
  const std::vector<double> scales = component_scales(adjacency, input);
  if(scales.empty())
    return sparse_noise_test_in_units(adjacency, input, result, fixed, normals);
  // the points divided by their component's scale: residuals in its units
  std::vector<Vec3> scaled_input(input.size()), scaled_result(result.size());
  for(std::size_t v = 0; v < input.size(); ++v)
  {
    scaled_input[v] = (1. / scales[v]) * input[v];
    scaled_result[v] = (1. / scales[v]) * result[v];
  }
  return sparse_noise_test_in_units(adjacency, scaled_input, scaled_result, fixed, normals);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
