// Tests of update_vertices_from_face_normals() (eq. 10).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/update_vertices_from_face_normals.h>

#include "synthetic_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

TEST(UpdateVertices, OneStepOnOneTriangleMatchesEquation10)
{
  // one triangle, target normal n: each vertex moves by n (n . (c - v))
  Mesh mesh;
  const K::Point_3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto a = mesh.add_vertex(p[0]), b = mesh.add_vertex(p[1]), c = mesh.add_vertex(p[2]);
  auto f = mesh.add_face(a, b, c);
  const K::Vector_3 n = K::Vector_3(1, 0, 1) / std::sqrt(2.);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", n).first;
  put(fnm, f, K::Vector_3(2, 0, 2)); // not unit: normalised by the function
  PMP::update_vertices_from_face_normals(mesh, fnm, CGAL::parameters::vertex_iterations(1));
  const K::Point_3 centroid(1. / 3, 1. / 3, 0);
  int k = 0;
  for(auto v : {a, b, c})
  {
    const K::Vector_3 expected_move = n * (n * (centroid - p[k]));
    const K::Point_3 expected = p[k] + expected_move;
    EXPECT_NEAR(mesh.point(v).x(), expected.x(), 1e-15);
    EXPECT_NEAR(mesh.point(v).y(), expected.y(), 1e-15);
    EXPECT_NEAR(mesh.point(v).z(), expected.z(), 1e-15);
    ++k;
  }
}

template <typename M>
double lift_and_restore()
{
  M mesh = denoising_test::plane_grid<M>(8);
  // lift one interior vertex; the target normals are those of the flat plane
  typename boost::graph_traits<M>::vertex_descriptor lifted;
  for(auto v : vertices(mesh))
  {
    const auto p = get(CGAL::vertex_point, mesh, v);
    if(std::abs(p.x() - 0.5) < 1e-9 && std::abs(p.y() - 0.5) < 1e-9)
    {
      lifted = v;
      put(CGAL::vertex_point, mesh, v, K::Point_3(0.5, 0.5, 0.1));
    }
  }
  std::map<typename boost::graph_traits<M>::face_descriptor, K::Vector_3> normals;
  for(auto f : faces(mesh))
    normals[f] = K::Vector_3(0, 0, 1);
  PMP::update_vertices_from_face_normals(mesh, boost::make_assoc_property_map(normals),
                                         CGAL::parameters::vertex_iterations(1000));
  // eq. 10 only makes faces orthogonal to the normals: the mesh becomes flat,
  // possibly translated along z (the lift is averaged out, not removed)
  double lo = 1e30, hi = -1e30;
  for(auto v : vertices(mesh))
  {
    lo = (std::min)(lo, get(CGAL::vertex_point, mesh, v).z());
    hi = (std::max)(hi, get(CGAL::vertex_point, mesh, v).z());
  }
  return hi - lo;
}

TEST(UpdateVertices, LiftedVertexIsFlattenedOnBothMeshTypes)
{
  const double h_sm = lift_and_restore<Mesh>();
  const double h_poly = lift_and_restore<Polyhedron>();
  EXPECT_LT(h_sm, 1e-4); // height spread, from 0.1
  EXPECT_EQ(h_sm, h_poly);
}

TEST(UpdateVertices, ConstrainedVertexStays)
{
  Mesh mesh = denoising_test::plane_grid<Mesh>(4);
  auto v0 = *vertices(mesh).begin();
  mesh.point(v0) = K::Point_3(mesh.point(v0).x(), mesh.point(v0).y(), 0.3);
  auto pinned = mesh.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
  put(pinned, v0, true);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", K::Vector_3(0, 0, 1)).first;
  PMP::update_vertices_from_face_normals(mesh, fnm, CGAL::parameters::vertex_is_constrained_map(pinned));
  EXPECT_EQ(mesh.point(v0).z(), 0.3);
}

TEST(UpdateVertices, NonFiniteNormalThrowsAndMeshIsUnchanged)
{
  Mesh mesh = denoising_test::plane_grid<Mesh>(3);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", K::Vector_3(0, 0, 1)).first;
  put(fnm, *faces(mesh).begin(), K::Vector_3(std::nan(""), 0, 1));
  const Mesh before = mesh;
  auto v = *vertices(mesh).begin();
  mesh.point(v) = K::Point_3(0, 0, 0.5);
  const K::Point_3 p = mesh.point(v);
  EXPECT_THROW(PMP::update_vertices_from_face_normals(mesh, fnm), std::invalid_argument);
  EXPECT_EQ(mesh.point(v), p);
}
