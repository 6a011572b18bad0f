// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// [SRML07] Sun, Rosin, Martin, Langbein: "Fast and effective
// feature-preserving mesh denoising", IEEE TVCG 13(5), 2007. A classic method
// of the paper's Table 1.

#ifndef CGAL_POLYGON_MESH_PROCESSING_FAST_FEATURE_PRESERVING_DENOISING_H
#define CGAL_POLYGON_MESH_PROCESSING_FAST_FEATURE_PRESERVING_DENOISING_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/classic/classic_methods.h>

#include <CGAL/tags.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

namespace internal {
namespace Denoising {

// One pass of Sun et al.'s normal filter: out[i] = normalised sum over j in
// {i} + N_i of f(n_i . n_j) n_j, with f(x) = (x - T)^2 above T and 0 below.
// A degenerate face keeps its zero normal.
template <typename ConcurrencyTag>
void thresholded_normal_pass(const Csr& neighbors, const std::vector<Vec3>& n, double threshold, std::vector<Vec3>& out)
{
  out.resize(n.size());
  for_each_chunk<ConcurrencyTag>(n.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const double self = 1. - threshold;
      Vec3 sum = (self * self) * n[i];
      for(std::uint32_t k = neighbors.begin(i); k < neighbors.end(i); ++k)
      {
        const Vec3& nj = n[neighbors.items[k]];
        const double x = dot(n[i], nj) - threshold;
        if(x > 0.)
          sum = sum + (x * x) * nj;
      }
      const double len = norm(sum);
      out[i] = len > 0. ? (1. / len) * sum : n[i];
    }
  });
}

} // namespace Denoising
} // namespace internal

/*!
  \ingroup PMP_denoising_grp

  \brief denoises `tmesh` by the method of Sun, Rosin, Martin and Langbein
  (2007) [SRML07]: face normals filtered with a threshold weight, then the
  vertices updated to fit them.

  `number_of_iterations` times, every face normal becomes
  \f[ n'_i = \frac{\sum_{j \in N_i \cup \{i\}} f(n_i\cdot n_j)\, n_j}{\|\sum_j f(n_i\cdot n_j)\, n_j\|}, \qquad
      f(x) = \begin{cases} (x - T)^2 & x > T \\ 0 & \text{otherwise,} \end{cases} \f]
  with \f$N_i\f$ the faces sharing a vertex (or an edge) with face \f$i\f$;
  face \f$i\f$ itself takes part with weight \f$(1-T)^2\f$. After each
  pass, the vertices follow the filtered normals by `vertex_iterations` steps
  of the paper's vertex update (eq. 10 of the intrinsic filter paper, see
  `update_vertices_from_face_normals()`).

  The mesh is read once and written once, at the end: if an exception is
  thrown, `tmesh` is left unchanged.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to denoise; its vertex points are overwritten with the result
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{normal_threshold}
      \cgalParamDescription{\f$T\f$: neighbours with \f$n_i\cdot n_j \le T\f$ get no weight (larger: sharper features
                            kept, less smoothing)}
      \cgalParamType{double in [0, 1)}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{use_vertex_neighborhood}
      \cgalParamDescription{if `true`, \f$N_i\f$ is the faces sharing a vertex with face \f$i\f$; if `false`, an edge}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{\f$n_1\f$, the number of normal filtering passes}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`20`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_iterations}
      \cgalParamDescription{\f$n_2\f$, the vertex update steps after each pass}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`10`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_update}
      \cgalParamDescription{`Vertex_update::PAPER` (eq. 10) or `Vertex_update::LEAST_SQUARES` (each step a global one,
                            see `update_vertices_from_face_normals()`)}
      \cgalParamType{`CGAL::Polygon_mesh_processing::Vertex_update`}
      \cgalParamDefault{`Vertex_update::PAPER`}
    \cgalParamNEnd
    \cgalParamNBegin{relax_along_surface}
      \cgalParamDescription{if `true`, after the last iteration each vertex is moved along the surface only, as in
                            `intrinsic_denoising()`: toward the centroid of its faces in the directions they leave
                            free, at most half as far from the result as the denoising moved it from the input;
                            border and constrained vertices stay, and no face turns over against the result}
      \cgalParamType{bool}
      \cgalParamDefault{`false` (the method as published)}
    \cgalParamNEnd
    \cgalParamNBegin{face_normal_map}
      \cgalParamDescription{if given, receives the filtered normals of the last pass}
      \cgalParamType{a model of `WritablePropertyMap` with face descriptors as keys and `GeomTraits::Vector_3` as values}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{a property map telling which vertices never move}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `bool` as values}
      \cgalParamDefault{no vertex is constrained}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map, geom_traits}
      \cgalParamDescription{as for `intrinsic_denoising()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates and \f$0 \le T < 1\f$;
       otherwise `std::invalid_argument` is thrown. An empty mesh is left as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
void fast_feature_preserving_denoising(TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static const char* fname = "fast_feature_preserving_denoising()";
  if(faces(tmesh).empty())
    return;
  const double threshold = choose_parameter(get_parameter(np, internal_np::normal_threshold), 0.5);
  const bool vertex_ring = choose_parameter(get_parameter(np, internal_np::use_vertex_neighborhood), true);
  D::require_unit_interval(threshold, fname, "normal_threshold");

  D::Classic_setup<TriangleMesh, NamedParameters> setup(tmesh, np, fname);
  const D::Csr neighbors = D::topological_face_neighbors(setup.mesh, vertex_ring ? 1 : 2);
  auto filter = [&](const D::Face_data& fd, std::vector<D::Vec3>& out) {
    D::thresholded_normal_pass<ConcurrencyTag>(neighbors, fd.normals, threshold, out);
  };
  D::run_normal_filtering<ConcurrencyTag>(tmesh, np, setup, filter);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
