// Tests of face_normal_error() (E_n, eq. 12) and vertex_position_error() (E_v, eq. 11).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/denoising_error.h>

#include <denoising_support/synthetic_meshes.h>

#include <gtest/gtest.h>

#include <cmath>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

TEST(DenoisingError, IdenticalMeshesHaveZeroError)
{
  const Mesh a = denoising_support::cube<Mesh>(4);
  EXPECT_EQ(PMP::face_normal_error(a, a), 0.);
  EXPECT_EQ(PMP::vertex_position_error(a, a), 0.);
}

TEST(DenoisingError, TiltedPlaneGivesItsAngle)
{
  const Mesh flat = denoising_support::plane_grid<Mesh>(10);
  Mesh tilted = flat;
  const double slope = 0.25;
  for(auto v : vertices(tilted))
  {
    const auto p = tilted.point(v);
    tilted.point(v) = K::Point_3(p.x(), p.y(), slope * p.x());
  }
  const double expected = std::atan(slope) * 180. / 3.14159265358979323846;
  EXPECT_NEAR(PMP::face_normal_error(tilted, flat), expected, 1e-10);
  // mixed mesh types
  const Polyhedron flat_poly = denoising_support::plane_grid<Polyhedron>(10);
  EXPECT_NEAR(PMP::face_normal_error(tilted, flat_poly), expected, 1e-10);
}

TEST(DenoisingError, TranslatedPlaneGivesItsOffset)
{
  // every vertex at distance h from the (larger) reference plane: E_v = h,
  // since the vertex areas add up to 3 A(M')
  const Mesh reference = denoising_support::plane_grid<Mesh>(10, 2.);
  Mesh lifted = denoising_support::plane_grid<Mesh>(10, 1.);
  const double h = 0.0125;
  for(auto v : vertices(lifted))
  {
    const auto p = lifted.point(v);
    lifted.point(v) = K::Point_3(p.x() + 0.5, p.y() + 0.5, h);
  }
  EXPECT_NEAR(PMP::vertex_position_error(lifted, reference), h, 1e-12);
}

TEST(DenoisingError, AreaWeightsOfEquation11)
{
  // two triangles of the reference plane z = 0, one vertex of the evaluated
  // copy lifted by h: only that vertex contributes, weighted by its ring area.
  const Mesh reference = denoising_support::plane_grid<Mesh>(1);
  Mesh m = reference;
  // lift the vertex (1, 1): it belongs to one of the two triangles (area 1/2)
  const double h = 0.1;
  for(auto v : vertices(m))
    if(m.point(v) == K::Point_3(1, 1, 0))
      m.point(v) = K::Point_3(1, 1, h);
  // areas of m: the triangle with (1,1,h) grows slightly; compute them directly
  double total = 0, ring = 0;
  for(auto f : faces(m))
  {
    auto hf = halfedge(f, m);
    const auto &a = m.point(source(hf, m)), &b = m.point(target(hf, m)), &c = m.point(target(next(hf, m), m));
    const double area = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) / 2;
    total += area;
    for(auto v : {source(hf, m), target(hf, m), target(next(hf, m), m)})
      if(m.point(v) == K::Point_3(1, 1, h))
        ring += area;
  }
  EXPECT_NEAR(PMP::vertex_position_error(m, reference), std::sqrt(ring * h * h / (3 * total)), 1e-14);
}

TEST(DenoisingError, MismatchedMeshesThrow)
{
  const Mesh a = denoising_support::cube<Mesh>(3), b = denoising_support::cube<Mesh>(4);
  EXPECT_THROW(PMP::face_normal_error(a, b), std::invalid_argument);
  const Mesh empty;
  EXPECT_THROW(PMP::vertex_position_error(a, empty), std::invalid_argument);
  EXPECT_EQ(PMP::face_normal_error(empty, empty), 0.);
}
