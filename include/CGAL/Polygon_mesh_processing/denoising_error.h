// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The two error metrics of section 5.2 of the intrinsic filter paper:
// E_n (eq. 12) and E_v (eq. 11, Belyaev and Ohtake 2003).

#ifndef CGAL_POLYGON_MESH_PROCESSING_DENOISING_ERROR_H
#define CGAL_POLYGON_MESH_PROCESSING_DENOISING_ERROR_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
  \ingroup PMP_denoising_grp

  \brief E_n of eq. 12: the mean angle, in degrees, between the normals of
  corresponding faces of `denoised` and `reference` (faces correspond by face
  index). A face of zero area counts as an angle of 0 with any normal.

  \tparam TriangleMesh1 a model of `VertexListGraph` and `FaceListGraph`
  \tparam TriangleMesh2 a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters1 a sequence of named parameters
  \tparam NamedParameters2 a sequence of named parameters
  \param denoised the mesh whose face normals are evaluated
  \param reference the mesh it is compared with, for example the noise-free original; face \f$i\f$ of
                   `reference` is compared with face \f$i\f$ of `denoised`
  \param np1 an optional sequence of named parameters for `denoised` among the ones listed below
  \param np2 an optional sequence of named parameters for `reference` among the ones listed below
  \return \f$E_n\f$ in degrees

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
      \cgalParamDescription{for `denoised` in `np1`, for `reference` in `np2`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre both are triangle meshes with the same number of faces and finite
       coordinates; otherwise `std::invalid_argument` is thrown. Returns 0 for
       two empty meshes.
*/
template <typename TriangleMesh1, typename TriangleMesh2,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
double face_normal_error(const TriangleMesh1& denoised, const TriangleMesh2& reference,
                         const NamedParameters1& np1 = parameters::default_values(),
                         const NamedParameters2& np2 = parameters::default_values())
{
  namespace D = internal::Denoising;
  static const char* fname = "face_normal_error()";
  if(num_faces(denoised) != num_faces(reference))
    throw std::invalid_argument(std::string(fname) + ": the meshes have different numbers of faces (" +
                                std::to_string(num_faces(denoised)) + " and " + std::to_string(num_faces(reference)) +
                                ").");
  if(num_faces(denoised) == 0)
    return 0.;
  const D::Flat_mesh a = D::Mesh_maps<TriangleMesh1, NamedParameters1>(denoised, np1).flat(denoised, fname);
  const D::Flat_mesh b = D::Mesh_maps<TriangleMesh2, NamedParameters2>(reference, np2).flat(reference, fname);
  D::Face_data fa, fb;
  D::compute_face_data<CGAL::Sequential_tag>(a, a.points, fa);
  D::compute_face_data<CGAL::Sequential_tag>(b, b.points, fb);
  return D::mean_angle_degrees(fa.normals, fb.normals);
}

/*!
  \ingroup PMP_denoising_grp

  \brief E_v of eq. 11 (Belyaev and Ohtake 2003):
  \f[ E_v = \sqrt{\frac{1}{3A(M')}\sum_{P'\in M'} A(P')\,\mathrm{dist}(P', M)^2} \f]
  with \f$M'\f$ = `denoised`, \f$M\f$ = `reference`, \f$A(P')\f$ the area of
  the faces around vertex \f$P'\f$, \f$A(M')\f$ the area of \f$M'\f$ and the
  distance to the closest point of \f$M\f$ found with an AABB tree. In the
  meshes' length unit.

  \tparam TriangleMesh1 a model of `VertexListGraph` and `FaceListGraph`
  \tparam TriangleMesh2 a model of `VertexListGraph` and `FaceListGraph`
  \tparam NamedParameters1 a sequence of named parameters
  \tparam NamedParameters2 a sequence of named parameters
  \param denoised the mesh whose vertices are measured (\f$M'\f$)
  \param reference the mesh to whose surface the distances are measured (\f$M\f$); it need not have the
                   vertices or faces of `denoised`
  \param np1 an optional sequence of named parameters for `denoised` among the ones listed below
  \param np2 an optional sequence of named parameters for `reference` among the ones listed below
  \return \f$E_v\f$ in the meshes' length unit

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
      \cgalParamDescription{for `denoised` in `np1`, for `reference` in `np2`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre both are triangle meshes with finite coordinates, and `reference` has
       a face if `denoised` has one; otherwise `std::invalid_argument` is
       thrown. Returns 0 if `denoised` has no area.
*/
template <typename TriangleMesh1, typename TriangleMesh2,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
double vertex_position_error(const TriangleMesh1& denoised, const TriangleMesh2& reference,
                             const NamedParameters1& np1 = parameters::default_values(),
                             const NamedParameters2& np2 = parameters::default_values())
{
  namespace D = internal::Denoising;
  static const char* fname = "vertex_position_error()";
  if(num_faces(denoised) == 0)
    return 0.;
  if(num_faces(reference) == 0)
    throw std::invalid_argument(std::string(fname) + ": the reference mesh has no face.");
  const D::Flat_mesh a = D::Mesh_maps<TriangleMesh1, NamedParameters1>(denoised, np1).flat(denoised, fname);
  const D::Flat_mesh b = D::Mesh_maps<TriangleMesh2, NamedParameters2>(reference, np2).flat(reference, fname);

  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  std::vector<K::Triangle_3> triangles;
  triangles.reserve(b.number_of_faces());
  auto point = [](const D::Vec3& p) { return K::Point_3(p[0], p[1], p[2]); };
  for(const auto& t : b.triangles)
    triangles.emplace_back(point(b.points[t[0]]), point(b.points[t[1]]), point(b.points[t[2]]));
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();

  D::Face_data fa;
  D::compute_face_data<CGAL::Sequential_tag>(a, a.points, fa);
  std::vector<double> vertex_area(a.number_of_vertices(), 0.);
  double total_area = 0.;
  for(std::size_t f = 0; f < a.number_of_faces(); ++f)
  {
    total_area += fa.areas[f];
    for(std::uint32_t v : a.triangles[f])
      vertex_area[v] += fa.areas[f];
  }
  if(!(total_area > 0.))
    return 0.;
  double sum = 0.;
  for(std::size_t v = 0; v < a.number_of_vertices(); ++v)
    if(vertex_area[v] > 0.)
      sum += vertex_area[v] * tree.squared_distance(point(a.points[v]));
  return std::sqrt(sum / (3. * total_area));
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
