// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The internals of guided_normal_denoising() (ZDZ15): the guidance normals
// taken from the most consistent patch around each face.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GUIDANCE_NORMALS_H
#define CGAL_PMP_INTERNAL_DENOISING_GUIDANCE_NORMALS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// max_{a, b in patch} ||n_a - n_b||^2, the same value as trying every pair
// but without doing so where the patch is large (the faces around a vertex
// of high valence, as in a fan of slivers): the normals are taken from the
// farthest from their mean c, and since ||n_a - n_b|| <= |n_a - c| +
// |n_b - c|, the pairs are abandoned once that bound (with a margin for
// rounding) cannot exceed the largest difference found.
inline double largest_squared_normal_difference(const std::vector<std::uint32_t>& patch, const std::vector<Vec3>& n,
                                                std::vector<std::pair<double, std::uint32_t>>& by_distance)
{
  Vec3 c = {0., 0., 0.};
  for(std::uint32_t a : patch)
    c = c + n[a];
  c = (1. / double(patch.size())) * c;
  by_distance.clear();
  for(std::uint32_t a : patch)
    by_distance.emplace_back(norm(n[a] - c), a);
  std::sort(by_distance.begin(), by_distance.end(),
            [](const std::pair<double, std::uint32_t>& x, const std::pair<double, std::uint32_t>& y) {
              return x.first > y.first;
            });
  const auto out_of_reach = [](double bound, double best) { return bound * bound * (1. + 1e-9) <= best; };
  double best = 0.;
  for(std::size_t x = 0; x + 1 < by_distance.size(); ++x)
  {
    if(out_of_reach(by_distance[x].first + by_distance[x + 1].first, best))
      break;
    for(std::size_t y = x + 1; y < by_distance.size(); ++y)
    {
      if(out_of_reach(by_distance[x].first + by_distance[y].first, best))
        break;
      best = (std::max)(best, squared_norm(n[by_distance[x].second] - n[by_distance[y].second]));
    }
  }
  return best;
}

// Guidance normals of Zhang et al. 2015. The patch P_j of a face j is j and
// the faces sharing a vertex with it (`ring`). Its consistency is
//   H(P) = D(P) R(P),   D(P) = max_{a, b in P} ||n_a - n_b||,
//   R(P) = max_e phi(e) / (eps + sum_e phi(e)),  phi(e) = ||n_a - n_b||
// over the edges e = (a, b) between two faces of P. The guidance of face i is
// the normalised area-weighted mean normal of the patch of least H among the
// patches P_j containing i (j = i or j in ring(i)).
template <typename ConcurrencyTag>
void guidance_normals(const Csr& ring, const Csr& edge_neighbors, const Face_data& fd, std::vector<Vec3>& guidance,
                      std::vector<double>& consistency, std::vector<Vec3>& patch_mean)
{
  const std::size_t nf = fd.normals.size();
  const std::vector<Vec3>& n = fd.normals;
  consistency.resize(nf);
  patch_mean.resize(nf);
  guidance.resize(nf);
  const double eps = 1e-9;
  const std::size_t large_patch = 64;
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    std::vector<std::uint32_t> patch, sorted_patch;
    std::vector<std::pair<double, std::uint32_t>> by_distance;
    for(std::size_t j = b; j < e; ++j)
    {
      patch.assign(1, std::uint32_t(j));
      patch.insert(patch.end(), ring.items.begin() + ring.begin(j), ring.items.begin() + ring.end(j));
      // a patch holds about 13 faces on a regular mesh, but thousands around
      // a vertex of high valence: there the pairs are pruned and the faces of
      // the patch found by binary search
      const bool large = patch.size() > large_patch;
      double max_difference = 0.;
      if(large)
      {
        sorted_patch = patch;
        std::sort(sorted_patch.begin(), sorted_patch.end());
        max_difference = largest_squared_normal_difference(patch, n, by_distance);
      }
      else
        for(std::size_t x = 0; x < patch.size(); ++x)
          for(std::size_t y = x + 1; y < patch.size(); ++y)
            max_difference = (std::max)(max_difference, squared_norm(n[patch[x]] - n[patch[y]]));
      const auto in_patch = [&](std::uint32_t c) {
        return large ? std::binary_search(sorted_patch.begin(), sorted_patch.end(), c)
                     : std::find(patch.begin(), patch.end(), c) != patch.end();
      };
      double max_edge = 0., sum_edge = 0.;
      Vec3 mean = {0., 0., 0.};
      for(std::size_t x = 0; x < patch.size(); ++x)
      {
        const std::uint32_t a = patch[x];
        mean = mean + fd.areas[a] * n[a];
        for(std::uint32_t k = edge_neighbors.begin(a); k < edge_neighbors.end(a); ++k)
        {
          const std::uint32_t c = edge_neighbors.items[k];
          if(c > a && in_patch(c))
          {
            const double phi = norm(n[a] - n[c]);
            max_edge = (std::max)(max_edge, phi);
            sum_edge += phi;
          }
        }
      }
      consistency[j] = std::sqrt(max_difference) * max_edge / (eps + sum_edge);
      const double len = norm(mean);
      patch_mean[j] = len > 0. ? (1. / len) * mean : n[j];
    }
  });
  for_each_chunk<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      std::size_t best = i;
      for(std::uint32_t k = ring.begin(i); k < ring.end(i); ++k)
        if(consistency[ring.items[k]] < consistency[best])
          best = ring.items[k];
      guidance[i] = patch_mean[best];
    }
  });
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
