// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [ZFAT11] Zheng, Fu, Au, Tai: "Bilateral normal filtering for mesh
// denoising", IEEE TVCG 17(10), 2011, local scheme. A classic method of the
// paper's Table 1, and a special case of the intrinsic filter (direct paths,
// phi = face centroid, psi = face normal, n = m = 2).

#ifndef CGAL_POLYGON_MESH_PROCESSING_BILATERAL_NORMAL_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_BILATERAL_NORMAL_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

#include <CGAL/tags.h>

#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by the local scheme of bilateral normal filtering of
  Zheng, Fu, Au and Tai (2011) [ZFAT11].

  `number_of_iterations` times, every face normal becomes
  \f[ n'_i = \frac{1}{K_i}\sum_{j \in N_i \cup \{i\}} A_j\, W_s(\|c_i - c_j\|)\, W_r(\|n_i - n_j\|)\, n_j,
      \qquad W(x) = e^{-x^2/2\sigma^2}, \f]
  (\f$K_i\f$ normalises the result), with \f$N_i\f$ the faces sharing a
  vertex with face \f$i\f$, or, if a radius is given, the geometric
  neighbourhood of `intrinsic_denoising()`. This is the intrinsic filter with
  direct paths \f$\{i, j\}\f$, \f$\varphi\f$ = centroid, \f$\psi\f$ = normal and
  \f$n = m = 2\f$, and it is computed by the same engine. After each pass the
  vertices follow the filtered normals by `vertex_iterations` steps of eq. 10
  (see `update_vertices_from_face_normals()`).

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
      \cgalParamDefault{`1` (the paper's \f$\sigma_s = d\f$)}
    \cgalParamNEnd
    \cgalParamNBegin{sigma_range}
      \cgalParamDescription{\f$\sigma_r\f$, on the normal difference \f$\|n_i - n_j\|\f$}
      \cgalParamType{double}
      \cgalParamDefault{`0.35`}
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
    \cgalParamNBegin{neighbor_radius, relative_neighbor_radius}
      \cgalParamDescription{if one is given, \f$N_i\f$ is the geometric neighbourhood of that radius (absolute, or in
                            multiples of \f$d\f$) instead of the faces sharing a vertex}
      \cgalParamType{double}
      \cgalParamDefault{unused}
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
void bilateral_normal_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::is_default_parameter;
  static const char* fname = "bilateral_normal_denoising()";
  if(faces(tmesh).empty())
    return;
  const D::Classic_sigmas sigmas = D::read_classic_sigmas(np, fname, 1., 0.35);
  const double relative_sigma_s = sigmas.spatial, sigma_r = sigmas.range;

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  D::Face_data input;
  const double d = setup.template input_faces<ConcurrencyTag>(input);
  const bool geometric = !is_default_parameter<NamedParameters, internal_np::neighbor_radius_t>::value ||
                         !is_default_parameter<NamedParameters, internal_np::relative_neighbor_radius_t>::value;
  const D::Csr neighbors = geometric ? D::geometric_neighborhoods<ConcurrencyTag>(setup.mesh, input.centroids,
                                                                                  D::read_radius(np, fname, d, 1.))
                                     : D::topological_face_neighbors(setup.mesh, 1);
  const D::Path_forest direct = D::direct_paths(neighbors);
  const double sigma_s = relative_sigma_s * (d > 0. ? d : 1.);
  auto filter = [&](const D::Face_data& fd, std::vector<D::Vec3>& out) {
    D::bilateral_normal_pass<ConcurrencyTag>(direct, fd, fd.normals, sigma_s, sigma_r, out);
  };
  D::run_normal_filtering<ConcurrencyTag>(tmesh, np, setup, filter);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
