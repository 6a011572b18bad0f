// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [ZDZ*15] Zhang, Deng, Zhang, Bouaziz, Liu: "Guided mesh normal filtering",
// Computer Graphics Forum 34(7), 2015. A classic method of the paper's
// Table 1: a joint bilateral normal filter whose range kernel reads guidance
// normals taken from the most consistent patch around each face.

#ifndef CGAL_POLYGON_MESH_PROCESSING_GUIDED_NORMAL_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_GUIDED_NORMAL_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/guidance_normals.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

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
  static const char* fname = "guided_normal_denoising()";
  if(faces(tmesh).empty())
    return;
  const D::Classic_sigmas sigmas = D::read_classic_sigmas(np, fname, 1., 0.35);
  const double relative_sigma_s = sigmas.spatial, sigma_r = sigmas.range;

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
