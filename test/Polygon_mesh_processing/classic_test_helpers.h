// Shared checks of the classic denoisers: one test file per public
// header calls them with its function and its measured bounds.

#ifndef DENOISING_TEST_CLASSIC_TEST_HELPERS_H
#define DENOISING_TEST_CLASSIC_TEST_HELPERS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>

#include <denoising_support/synthetic_meshes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace classic_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace PMP = CGAL::Polygon_mesh_processing;

template <typename M>
std::vector<K::Point_3> positions(const M& mesh)
{
  std::vector<K::Point_3> p;
  for(auto v : vertices(mesh))
    p.push_back(get(CGAL::vertex_point, mesh, v));
  return p;
}

inline double max_distance(const std::vector<K::Point_3>& a, const std::vector<K::Point_3>& b)
{
  double d = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    d = (std::max)(d, std::sqrt(CGAL::squared_distance(a[i], b[i])));
  return d;
}

struct Errors
{
  double before, after;
};

// E_n of a 30 x 30 plane with Gaussian noise (sigma_E 0.3, seed 7), before and
// after `denoise(mesh)`.
template <typename Denoise>
Errors noisy_plane(const char* name, const Denoise& denoise)
{
  Mesh plane = denoising_support::plane_grid<Mesh>(30);
  const Mesh reference = plane;
  PMP::add_gaussian_noise(plane, 0.3, CGAL::parameters::random_seed(7));
  const double before = PMP::face_normal_error(plane, reference);
  denoise(plane);
  const double after = PMP::face_normal_error(plane, reference);
  std::printf("%s, noisy plane: E_n %.3f -> %.3f deg (factor %.1f)\n", name, before, after, before / after);
  return {before, after};
}

// E_n and E_v of a noise-free 12 x 12 cube after `denoise(mesh)`.
template <typename Denoise>
Errors noise_free_cube(const char* name, const Denoise& denoise)
{
  Mesh cube = denoising_support::cube<Mesh>(12);
  const Mesh reference = cube;
  denoise(cube);
  const Errors e = {PMP::face_normal_error(cube, reference), PMP::vertex_position_error(cube, reference)};
  std::printf("%s, noise-free cube: E_n %.3e deg, E_v %.3e\n", name, e.before, e.after);
  return e;
}

// The largest distance between the results on a Surface_mesh and on a
// Polyhedron_3 of the same noisy graded octahedron.
template <typename Denoise>
double surface_mesh_vs_polyhedron(const Denoise& denoise)
{
  Mesh sm = denoising_support::graded_octahedron<Mesh>(9, 1.4);
  Polyhedron poly = denoising_support::graded_octahedron<Polyhedron>(9, 1.4);
  PMP::add_gaussian_noise(sm, 0.3, CGAL::parameters::random_seed(3));
  PMP::add_gaussian_noise(poly, 0.3, CGAL::parameters::random_seed(3));
  EXPECT_EQ(max_distance(positions(sm), positions(poly)), 0.);
  const auto before = positions(sm);
  denoise(sm);
  denoise(poly);
  EXPECT_GT(max_distance(before, positions(sm)), 1e-3); // it did something
  return max_distance(positions(sm), positions(poly));
}

// Pins every 7th vertex of a noisy plane; checks that they stay and that the
// others move.
template <typename Denoise>
void constrained_vertices_do_not_move(const Denoise& denoise)
{
  Mesh mesh = denoising_support::plane_grid<Mesh>(12);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(2));
  auto pinned = mesh.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
  for(auto v : vertices(mesh))
    put(pinned, v, std::size_t(v) % 7 == 0);
  const auto before = positions(mesh);
  denoise(mesh, pinned);
  const auto after = positions(mesh);
  double pinned_move = 0., free_move = 0.;
  for(auto v : vertices(mesh))
  {
    const double d = std::sqrt(CGAL::squared_distance(before[std::size_t(v)], after[std::size_t(v)]));
    (get(pinned, v) ? pinned_move : free_move) = (std::max)(get(pinned, v) ? pinned_move : free_move, d);
  }
  EXPECT_EQ(pinned_move, 0.);
  EXPECT_GT(free_move, 1e-3);
}

// Sequential_tag and Parallel_tag give the same positions on a noisy fandisk-
// sized mesh (a graded octahedron of 8 x 33^2 faces, above the parallel grain).
template <typename Sequential, typename Parallel>
double parallel_vs_sequential(const Sequential& sequential, const Parallel& parallel)
{
  Mesh a = denoising_support::graded_octahedron<Mesh>(33, 1.4);
  PMP::add_gaussian_noise(a, 0.3, CGAL::parameters::random_seed(5));
  Mesh b = a;
  sequential(a);
  parallel(b);
  return max_distance(positions(a), positions(b));
}

} // namespace classic_test

#endif
