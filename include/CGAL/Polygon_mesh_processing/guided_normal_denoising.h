// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [ZDZ*15] Zhang, Deng, Zhang, Bouaziz, Liu: "Guided mesh normal filtering",
// Computer Graphics Forum 34(7), 2015. A classic method of the paper's
// Table 1: a joint bilateral normal filter whose range kernel reads guidance
// normals taken from the most consistent patch around each face.

#ifndef CGAL_POLYGON_MESH_PROCESSING_GUIDED_NORMAL_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_GUIDED_NORMAL_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic_methods.h>

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

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by guided mesh normal filtering, Zhang, Deng, Zhang,
  Bouaziz and Liu (2015) [ZDZ15].

  `number_of_iterations` times: a guidance normal \f$g_i\f$ is computed for
  every face from the current normals (the mean normal of the most consistent
  patch containing the face: the patch of face \f$j\f$ is \f$j\f$ and the faces
  sharing a vertex with it; its consistency is the largest normal difference
  in it times the largest normal jump across one of its edges relative to the
  sum of those jumps), then every face normal becomes the joint bilateral
  average
  \f[ n'_i = \frac{1}{K_i}\sum_{j \in N_i \cup \{i\}} A_j\, W_s(\|c_i - c_j\|)\, W_r(\|g_i - g_j\|)\, n_j,
      \qquad W(x) = e^{-x^2/2\sigma^2}, \f]
  over the geometric neighbourhood \f$N_i\f$ (faces connected to \f$i\f$
  whose centroid is within the radius of \f$c_i\f$). This is the intrinsic
  filter's engine with direct paths, \f$\varphi\f$ = centroid and \f$\psi\f$
  = guidance. After each pass the vertices follow the filtered normals by
  `vertex_iterations` steps of eq. 10 (see `update_vertices_from_face_normals()`).

  The mesh is read once and written once, at the end: if an exception is
  thrown, `tmesh` is left unchanged.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{sigma_spatial}
      \cgalParamDescription{\f$\sigma_s\f$, as a multiple of \f$d\f$, the mean distance between the centroids of
                            edge-adjacent faces of the input}
      \cgalParamType{double}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_range}
      \cgalParamDescription{\f$\sigma_r\f$, on the guidance difference \f$\|g_i - g_j\|\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.35`}
    \cgalParamNEnd
    \cgalParamNBegin{relative_neighbor_radius}
      \cgalParamDescription{the radius of \f$N_i\f$ as a multiple of \f$d\f$; ignored if `neighbor_radius` gives it
                            absolutely}
      \cgalParamType{double}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of normal filtering passes}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`20`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_iterations}
      \cgalParamDescription{the vertex update steps after each pass}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`10`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_update}
      \cgalParamDescription{`Vertex_update::PAPER` (eq. 10) or `Vertex_update::LEAST_SQUARES` (each step a global one,
                            see `update_vertices_from_face_normals()`)}
      \cgalParamType{`CGAL::Polygon_mesh_processing::Vertex_update`}
      \cgalParamDefault{`Vertex_update::PAPER`}
    \cgalParamNEnd
    \cgalParamNBegin{relax_along_surface, face_normal_map, vertex_is_constrained_map, vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `fast_feature_preserving_denoising()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates; the sigmas and the
       radius are positive and finite. Otherwise `std::invalid_argument` is
       thrown. An empty mesh is left as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
void guided_normal_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static const char* fname = "guided_normal_denoising()";
  if(faces(tmesh).empty())
    return;
  const double relative_sigma_s = choose_parameter(get_parameter(np, internal_np::sigma_spatial), 1.);
  const double sigma_r = choose_parameter(get_parameter(np, internal_np::sigma_range), 0.35);
  D::require_positive(relative_sigma_s, fname, "sigma_spatial");
  D::require_positive(sigma_r, fname, "sigma_range");

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  D::Face_data input;
  const double d = setup.template input_faces<ConcurrencyTag>(input);
  const double radius = D::read_radius(np, fname, d, 2.);
  const D::Csr neighbors = D::geometric_neighborhoods<ConcurrencyTag>(setup.mesh, input.centroids, radius);
  const D::Path_forest direct = D::direct_paths(neighbors);
  const D::Csr ring = D::topological_face_neighbors(setup.mesh, 1);
  const D::Csr edge_neighbors = D::topological_face_neighbors(setup.mesh, 2);
  const double sigma_s = relative_sigma_s * (d > 0. ? d : 1.);

  std::vector<D::Vec3> guidance, patch_mean;
  std::vector<double> consistency;
  auto filter = [&](const D::Face_data& fd, std::vector<D::Vec3>& out) {
    D::guidance_normals<ConcurrencyTag>(ring, edge_neighbors, fd, guidance, consistency, patch_mean);
    D::bilateral_normal_pass<ConcurrencyTag>(direct, fd, guidance, sigma_s, sigma_r, out);
  };
  D::run_normal_filtering<ConcurrencyTag>(tmesh, np, setup, filter);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
