// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_UPDATE_VERTICES_FROM_FACE_NORMALS_H
#define CGAL_POLYGON_MESH_PROCESSING_UPDATE_VERTICES_FROM_FACE_NORMALS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/vertex_update.h>

#include <CGAL/tags.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
  \ingroup PMP_denoising_grp

  \brief moves the vertices of `tmesh` so that its faces become orthogonal to
  the given face normals: the vertex update of eq. 10 of the intrinsic filter
  paper, from Sun et al. 2007,
  \f[ v^{(t+1)} = v^{(t)} + \frac{1}{|F_v|}\sum_{j\in F_v} n_j\,\big(n_j\cdot(c_j^{(t)} - v^{(t)})\big), \f]
  with \f$F_v\f$ the faces incident to \f$v\f$ and \f$c_j^{(t)}\f$ the centroid
  of face \f$j\f$ at step \f$t\f$ (the paper's right-hand side \f$\bar v_j\f$ is
  read as \f$\bar v_i\f$, the vertex being moved). All vertices move at once
  from the previous step's positions.

  Every normal-filtering denoiser of the package ends with this update.

  With `vertex_update(Vertex_update::LEAST_SQUARES)` each step is global
  instead: the vertices move to the minimiser of
  \f[ \sum_f \sum_{(a,b)\ \mathrm{edge\ of}\ f} \big(n_f\cdot(x_a - x_b)\big)^2 + \alpha \sum_v |F_v|\,|x_v - v^{(t)}|^2, \f]
  the misfit of which eq. 10 is a local descent step, plus a weak pull
  (\f$\alpha = 0.05\f$) to the positions before the step, which fixes what
  the misfit leaves free (a translation or scaling of the whole mesh). The
  sparse system is solved by preconditioned conjugate gradients without
  storing its matrix. Where the target normals are right this recovers the
  surface in far fewer steps than eq. 10 (on CGAL's `b9_mesh.off` with noise
  \f$\sigma_E = 0.05\f$ and its noise-free normals as targets, E_n after one
  step: 0.25 degrees against 1.53 with eq. 10); where they are wrong it fits
  the error as faithfully.

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
          `CGAL::Parallel_if_available_tag`; the result does not depend on it.
  \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
  \tparam FaceNormalMap a model of `ReadablePropertyMap` with face descriptors
          as keys and `GeomTraits::Vector_3` as values: the target normals. They
          are normalised before use; a zero vector leaves its face without
          influence.
  \tparam NamedParameters a sequence of named parameters
  \param tmesh the triangle mesh to update
  \param normals the target face normals
  \param np an optional sequence of named parameters among the ones below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_iterations}
      \cgalParamDescription{the number of steps \f$t\f$}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`2`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_update}
      \cgalParamDescription{`Vertex_update::PAPER` (eq. 10) or `Vertex_update::LEAST_SQUARES` (global steps, above)}
      \cgalParamType{`CGAL::Polygon_mesh_processing::Vertex_update`}
      \cgalParamDefault{`Vertex_update::PAPER`}
    \cgalParamNEnd
    \cgalParamNBegin{prevent_folds}
      \cgalParamDescription{if `true`, each step is restricted so that no face comes to point against its orientation
                            before the step or at the start of the call, or against its target normal (if it agreed
                            with it before): the vertices of such a face get their move halved, up to 4 times, then
                            stay in place. `false` gives eq. 10 exactly.}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{a property map telling which vertices never move}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `bool` as values}
      \cgalParamDefault{no vertex is constrained}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadWritePropertyMap` with vertex descriptors as keys and `GeomTraits::Point_3` as values}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDescription{a property map associating to each vertex an index from 0 to `num_vertices(tmesh) - 1`}
      \cgalParamType{a model of `ReadablePropertyMap` with vertex descriptors as keys and `std::size_t` as values}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face an index from 0 to `num_faces(tmesh) - 1`}
      \cgalParamType{a model of `ReadablePropertyMap` with face descriptors as keys and `std::size_t` as values}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `tmesh` is a triangle mesh with finite coordinates and index maps that
       number vertices and faces from 0 to \f$n-1\f$, and `normals` are finite;
       otherwise `std::invalid_argument` is thrown and `tmesh` is left
       unchanged. Isolated and constrained vertices never move.
  An empty mesh is left as it is.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename FaceNormalMap,
          typename NamedParameters = parameters::Default_named_parameters>
void update_vertices_from_face_normals(TriangleMesh& tmesh, const FaceNormalMap& normals,
                                       const NamedParameters& np = parameters::default_values())
{
  namespace D = internal::Denoising;
  static const char* fname = "update_vertices_from_face_normals()";
  if(faces(tmesh).empty())
    return;
  const D::Mesh_maps<TriangleMesh, NamedParameters> maps(tmesh, np);
  const unsigned int iterations =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_iterations), 2u);

  D::Flat_mesh m = maps.flat(tmesh, fname);
  std::vector<D::Vec3> n(m.number_of_faces());
  for(auto f : faces(tmesh))
  {
    const auto& v = get(normals, f);
    D::Vec3 q = {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
    const double len = D::norm(q);
    if(!std::isfinite(len))
      throw std::invalid_argument(std::string(fname) + ": a face normal has a NaN or infinite coordinate.");
    n[get(maps.fim, f)] = len > 0. ? (1. / len) * q : D::Vec3{0., 0., 0.};
  }
  D::Fold_safeguard guard;
  guard.enabled = parameters::choose_parameter(parameters::get_parameter(np, internal_np::prevent_folds), true);
  D::Least_squares_recovery recovery = D::make_vertex_recovery(
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_update), Vertex_update::PAPER));
  std::vector<D::Vec3> centroids, next;
  D::update_vertices<ConcurrencyTag>(m, m.points, n, maps.constrained(tmesh), iterations, centroids, next, &guard,
                                     &recovery);
  maps.write_points(tmesh, m.points);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
