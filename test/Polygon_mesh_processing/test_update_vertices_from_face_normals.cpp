// Tests of update_vertices_from_face_normals() (eq. 10).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/guided_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/vertices/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/update_vertices_from_face_normals.h>

#include <denoising_support/synthetic_meshes.h>

#include "flat_setup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <utility>

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
  M mesh = denoising_support::plane_grid<M>(8);
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
  Mesh mesh = denoising_support::plane_grid<Mesh>(4);
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
  Mesh mesh = denoising_support::plane_grid<Mesh>(3);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", K::Vector_3(0, 0, 1)).first;
  put(fnm, *faces(mesh).begin(), K::Vector_3(std::nan(""), 0, 1));
  const Mesh before = mesh;
  auto v = *vertices(mesh).begin();
  mesh.point(v) = K::Point_3(0, 0, 0.5);
  const K::Point_3 p = mesh.point(v);
  EXPECT_THROW(PMP::update_vertices_from_face_normals(mesh, fnm), std::invalid_argument);
  EXPECT_EQ(mesh.point(v), p);
}

TEST(UpdateVertices, OneStepAtAVertexWithSeveralFacesMatchesEquation10)
{
  // a fan of four faces around a raised centre vertex; targets tilted
  // differently per face: the centre moves by
  //   1/4 sum_j n_j (n_j . (c_j - v)),
  // the mean, not the sum, of its faces' corrections (all computed from the
  // positions before the step)
  Mesh mesh;
  const K::Point_3 centre_at(0.1, -0.05, 0.3);
  auto centre = mesh.add_vertex(centre_at);
  const K::Point_3 rim_at[4] = {{1, 0, 0}, {0, 1, 0.1}, {-1, 0, 0}, {0, -1, -0.1}};
  Mesh::Vertex_index rim[4];
  for(int k = 0; k < 4; ++k)
    rim[k] = mesh.add_vertex(rim_at[k]);
  Mesh::Face_index f[4];
  for(int k = 0; k < 4; ++k)
    f[k] = mesh.add_face(centre, rim[k], rim[(k + 1) % 4]);
  const K::Vector_3 target[4] = {{0.1, 0, 1}, {0, 0.2, 1}, {-0.1, 0.1, 1}, {0.05, -0.2, 1}};
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", K::Vector_3(0, 0, 1)).first;
  K::Vector_3 move = CGAL::NULL_VECTOR;
  for(int k = 0; k < 4; ++k)
  {
    put(fnm, f[k], target[k]);
    const K::Vector_3 n = target[k] / std::sqrt(target[k].squared_length());
    const K::Point_3 c = CGAL::centroid(centre_at, rim_at[k], rim_at[(k + 1) % 4]);
    move = move + (n * (c - centre_at)) * n;
  }
  const K::Point_3 expected = centre_at + move / 4.;
  PMP::update_vertices_from_face_normals(mesh, fnm, CGAL::parameters::vertex_iterations(1).prevent_folds(false));
  EXPECT_NEAR(mesh.point(centre).x(), expected.x(), 1e-15);
  EXPECT_NEAR(mesh.point(centre).y(), expected.y(), 1e-15);
  EXPECT_NEAR(mesh.point(centre).z(), expected.z(), 1e-15);
  // the sum instead of the mean would be 4 times as far
  EXPECT_GT(std::sqrt(move.squared_length()), 1e-3);
}

// ---- Vertex_update::LEAST_SQUARES ------------------------------------------

namespace {

// The unit normals of `clean` by face.
std::map<Mesh::Face_index, K::Vector_3> clean_normals(const Mesh& clean)
{
  std::map<Mesh::Face_index, K::Vector_3> n;
  for(auto f : faces(clean))
  {
    auto h = halfedge(f, clean);
    const K::Point_3 &a = clean.point(source(h, clean)), &b = clean.point(target(h, clean)),
                     &c = clean.point(target(next(h, clean), clean));
    const K::Vector_3 v = CGAL::cross_product(b - a, c - a);
    n[f] = v / std::sqrt(v.squared_length());
  }
  return n;
}

double mean_angle_to(const Mesh& mesh, const std::map<Mesh::Face_index, K::Vector_3>& target)
{
  const auto n = clean_normals(mesh);
  double sum = 0.;
  for(auto f : faces(mesh))
    sum += std::acos((std::max)(-1., (std::min)(1., n.at(f) * target.at(f)))) * 180. / 3.14159265358979323846;
  return sum / double(num_faces(mesh));
}

// Copy of `clean` with Gaussian noise along the vertex normals, seed 1.
Mesh noisy_copy(const Mesh& clean, double sigma)
{
  Mesh m = clean;
  PMP::add_gaussian_noise(m, sigma, CGAL::parameters::random_seed(1));
  return m;
}

} // namespace

TEST(UpdateVerticesLeastSquares, StepSolvesItsNormalEquations)
{
  // After one step without the safeguard, the gradient of
  //   sum_f sum_{edges (a,b) of f} (n_f . (x_a - x_b))^2 + alpha sum_v |F_v| |x_v - p_v|^2
  // vanishes at every free vertex: half of it at v is
  //   sum_{f around v} n_f (n_f . (3 x_v - x_a - x_b - x_c)) + alpha |F_v| (x_v - p_v),
  // computed here from the mesh (a, b, c the corners of f). A wrong matrix,
  // right-hand side or solver fails this.
  const Mesh clean = denoising_support::graded_octahedron<Mesh>(6);
  const Mesh noisy = noisy_copy(clean, 0.3);
  auto target = clean_normals(clean);
  Mesh mesh = noisy;
  PMP::update_vertices_from_face_normals(
      mesh, boost::make_assoc_property_map(target),
      CGAL::parameters::vertex_iterations(1).prevent_folds(false).vertex_update(PMP::Vertex_update::LEAST_SQUARES));
  const double alpha = 0.05;
  double worst = 0., scale = 0.;
  for(auto v : vertices(mesh))
  {
    K::Vector_3 g = CGAL::NULL_VECTOR;
    std::size_t faces_around = 0;
    for(auto f : CGAL::faces_around_target(halfedge(v, mesh), mesh))
    {
      const K::Vector_3& n = target.at(f);
      K::Vector_3 s = 3. * (mesh.point(v) - CGAL::ORIGIN);
      for(auto u : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        s = s - (mesh.point(u) - CGAL::ORIGIN);
      g = g + (n * s) * n;
      ++faces_around;
    }
    g = g + alpha * double(faces_around) * (mesh.point(v) - noisy.point(v));
    worst = (std::max)(worst, std::sqrt(g.squared_length()));
    scale = (std::max)(scale, std::sqrt((mesh.point(v) - noisy.point(v)).squared_length()));
  }
  std::printf("largest gradient %.3g, largest move %.3g\n", worst, scale);
  EXPECT_GT(scale, 1e-3);         // the step moved
  EXPECT_LT(worst, 1e-4 * scale); // and it is the minimiser (measured: 1e-5)
}

TEST(UpdateVerticesLeastSquares, RecoversFromTrueNormalsFasterThanEquation10)
{
  // With the noise-free normals as targets, one global step removes most of
  // the normal error, one step of eq. 10 much less. Measured: noisy 6.5,
  // eq. 10 2.1, least squares 0.33 degrees.
  const Mesh clean = denoising_support::cube<Mesh>(12);
  const Mesh noisy = noisy_copy(clean, 0.3);
  auto target = clean_normals(clean);
  Mesh paper = noisy, global = noisy;
  const auto map = boost::make_assoc_property_map(target);
  PMP::update_vertices_from_face_normals(paper, map, CGAL::parameters::vertex_iterations(1));
  PMP::update_vertices_from_face_normals(
      global, map, CGAL::parameters::vertex_iterations(1).vertex_update(PMP::Vertex_update::LEAST_SQUARES));
  const double e_noisy = mean_angle_to(noisy, target), e_paper = mean_angle_to(paper, target),
               e_global = mean_angle_to(global, target);
  std::printf("E_n: noisy %.3f, eq. 10 %.3f, least squares %.3f degrees\n", e_noisy, e_paper, e_global);
  EXPECT_LT(e_global, 0.25 * e_paper);
  EXPECT_LT(e_global, 0.1 * e_noisy);
}

namespace {

// A plane grid with its centre vertex lifted by 0.1 and its first vertex
// pinned, after `steps` steps of `update` toward the plane's normals: the
// height spread of the result, and whether the pinned vertex stayed.
std::pair<double, bool> flatten_lifted_grid(PMP::Vertex_update update, unsigned int steps)
{
  Mesh mesh = denoising_support::plane_grid<Mesh>(8);
  auto pinned = mesh.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
  Mesh::Vertex_index lifted, corner = *vertices(mesh).begin();
  for(auto v : vertices(mesh))
    if(std::abs(mesh.point(v).x() - 0.5) < 1e-9 && std::abs(mesh.point(v).y() - 0.5) < 1e-9)
      lifted = v;
  mesh.point(lifted) = K::Point_3(0.5, 0.5, 0.1);
  const K::Point_3 corner_at = mesh.point(corner);
  put(pinned, corner, true);
  auto fnm = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:n", K::Vector_3(0, 0, 1)).first;
  PMP::update_vertices_from_face_normals(
      mesh, fnm, CGAL::parameters::vertex_iterations(steps).vertex_is_constrained_map(pinned).vertex_update(update));
  double lo = 1e30, hi = -1e30;
  for(auto v : vertices(mesh))
  {
    lo = (std::min)(lo, mesh.point(v).z());
    hi = (std::max)(hi, mesh.point(v).z());
  }
  return {hi - lo, mesh.point(corner) == corner_at};
}

} // namespace

TEST(UpdateVerticesLeastSquares, LiftedVertexIsFlattenedAndConstrainedVertexStays)
{
  // measured after 20 steps: least squares 1.7e-4, eq. 10 2.3e-3
  const auto global = flatten_lifted_grid(PMP::Vertex_update::LEAST_SQUARES, 20);
  const auto paper = flatten_lifted_grid(PMP::Vertex_update::PAPER, 20);
  std::printf("height spread after 20 steps: least squares %.3g, eq. 10 %.3g\n", global.first, paper.first);
  EXPECT_TRUE(global.second);
  EXPECT_LT(global.first, 5e-4);
  EXPECT_LT(global.first, 0.1 * paper.first);
}

TEST(UpdateVerticesLeastSquares, SameResultForAnyThreadCount)
{
  // over 2048 vertices, so that the dot products add several blocks
  const Mesh clean = denoising_support::cube<Mesh>(24);
  ASSERT_GT(num_vertices(clean), 3000u);
  const Mesh noisy = noisy_copy(clean, 0.5);
  auto target = clean_normals(clean);
  const auto map = boost::make_assoc_property_map(target);
  Mesh seq = noisy, par = noisy;
  const auto np = CGAL::parameters::vertex_iterations(3).vertex_update(PMP::Vertex_update::LEAST_SQUARES);
  PMP::update_vertices_from_face_normals<CGAL::Sequential_tag>(seq, map, np);
  PMP::update_vertices_from_face_normals<CGAL::Parallel_if_available_tag>(par, map, np);
  for(auto v : vertices(seq))
    ASSERT_EQ(seq.point(v), par.point(v));
}

TEST(UpdateVerticesLeastSquares, ClassicNormalFiltersTakeTheSameParameter)
{
  // SRML07, ZFAT11 and ZDZ15 with vertex_update(LEAST_SQUARES): a different
  // result from eq. 10's, finite, and closer to the clean cube than the noisy
  // input (mean angle to the clean normals)
  const Mesh clean = denoising_support::cube<Mesh>(8);
  const Mesh noisy = noisy_copy(clean, 0.2);
  const auto target = clean_normals(clean);
  const double e_noisy = mean_angle_to(noisy, target);
  const auto ls = CGAL::parameters::vertex_update(PMP::Vertex_update::LEAST_SQUARES);
  const std::vector<std::pair<const char*, std::function<void(Mesh&, bool)>>> methods = {
      {"SRML07",
       [&](Mesh& m, bool global) {
         global ? PMP::fast_feature_preserving_denoising(m, ls) : PMP::fast_feature_preserving_denoising(m);
       }},
      {"ZFAT11",
       [&](Mesh& m, bool global) {
         global ? PMP::bilateral_normal_denoising(m, ls) : PMP::bilateral_normal_denoising(m);
       }},
      {"ZDZ15",
       [&](Mesh& m, bool global) { global ? PMP::guided_normal_denoising(m, ls) : PMP::guided_normal_denoising(m); }}};
  for(const auto& method : methods)
  {
    Mesh paper = noisy, global = noisy;
    method.second(paper, false);
    method.second(global, true);
    bool differs = false, finite = true;
    for(auto v : vertices(global))
    {
      differs = differs || global.point(v) != paper.point(v);
      finite = finite && std::isfinite(global.point(v).x()) && std::isfinite(global.point(v).y()) &&
               std::isfinite(global.point(v).z());
    }
    const double e_paper = mean_angle_to(paper, target), e_global = mean_angle_to(global, target);
    std::printf("%s: noisy %.3f, eq. 10 %.3f, least squares %.3f degrees\n", method.first, e_noisy, e_paper, e_global);
    EXPECT_TRUE(differs) << method.first;
    EXPECT_TRUE(finite) << method.first;
    EXPECT_LT(e_global, e_noisy) << method.first;
  }
}

// ---- Tangential relaxation (the automatic mode's last step) ---------------

namespace {

// A plane grid whose interior vertices are moved along the plane by a seeded
// jitter (`jittered`, as the denoiser might leave them) and, for the input,
// also off it by `lift` (what the denoiser removed).
struct Jittered_plane
{
  D::Flat_mesh m;
  std::vector<D::Vec3> exact, jittered, input;
  double h = 0.;
  Jittered_plane(int n, double jitter, double lift) : m(Flat_setup<>(denoising_support::plane_grid<Mesh>(n)).m)
  {
    exact = m.points;
    h = 1. / n;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    jittered = exact;
    input = exact;
    for(std::size_t v = 0; v < exact.size(); ++v)
    {
      const D::Vec3 p = exact[v];
      const bool interior = p[0] > 1e-9 && p[0] < 1. - 1e-9 && p[1] > 1e-9 && p[1] < 1. - 1e-9;
      const double dx = u(rng), dy = u(rng), dz = u(rng) < 0. ? -1. : 1.;
      if(!interior)
        continue;
      jittered[v] = {p[0] + jitter * h * dx, p[1] + jitter * h * dy, 0.};
      input[v] = {jittered[v][0], jittered[v][1], dz * lift * h};
    }
  }
  double mean_distance_to_exact(const std::vector<D::Vec3>& p) const
  {
    double s = 0.;
    for(std::size_t v = 0; v < p.size(); ++v)
      s += std::sqrt(D::squared_norm(p[v] - exact[v]));
    return s / double(p.size());
  }
};

} // namespace

// Vertices moved along a plane come back toward an even sampling; they stay
// in the plane, border and held vertices stay, and none ends farther from
// where it started than half of its distance to the input.
TEST(TangentialRelaxation, EvensOutAJitteredPlaneWithinItsCap)
{
  const Jittered_plane c(12, 0.25, 0.4);
  std::vector<D::Vec3> p = c.jittered;
  std::vector<char> held(p.size(), 0);
  const std::size_t pinned = 12 * 13 / 2 + 6; // an interior vertex
  held[pinned] = 1;
  D::Fold_safeguard guard;
  D::Face_data input_faces;
  D::compute_face_data<CGAL::Sequential_tag>(c.m, c.input, input_faces);
  guard.reference = &input_faces.normals;
  const std::size_t moved = D::relax_tangentially<CGAL::Sequential_tag>(c.m, c.input, p, held, guard);
  EXPECT_GT(moved, 0u);
  const double before = c.mean_distance_to_exact(c.jittered), after = c.mean_distance_to_exact(p);
  std::cout << "jittered plane: mean distance to the even grid " << before << " -> " << after << " (h " << c.h << "), "
            << moved << " vertices moved\n";
  EXPECT_LT(after, 0.8 * before);
  for(std::size_t v = 0; v < p.size(); ++v)
  {
    EXPECT_EQ(p[v][2], 0.) << v;
    const double cap = 0.5 * std::sqrt(D::squared_norm(c.input[v] - c.jittered[v]));
    EXPECT_LE(std::sqrt(D::squared_norm(p[v] - c.jittered[v])), cap * (1. + 1e-12)) << v;
    if(c.input[v] == c.jittered[v]) // border: nothing removed there, nothing moves
    {
      EXPECT_EQ(p[v], c.jittered[v]) << v;
    }
  }
  EXPECT_EQ(p[pinned], c.jittered[pinned]);
  // the same for any number of threads
  std::vector<D::Vec3> q = c.jittered;
  D::relax_tangentially<CGAL::Parallel_if_available_tag>(c.m, c.input, q, held, guard);
  for(std::size_t v = 0; v < p.size(); ++v)
    ASSERT_EQ(p[v], q[v]) << v;
}

// On a cube, a vertex of a face moves in its face's plane, one of an edge
// along the edge, a corner not at all: the faces around a vertex leave it
// only the directions along which they are flat.
TEST(TangentialRelaxation, CreaseVerticesMoveAlongTheCreaseAndCornersStay)
{
  const D::Flat_mesh m = Flat_setup<>(denoising_support::cube<Mesh>(6)).m;
  const std::vector<D::Vec3> exact = m.points;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1., 1.);
  std::vector<D::Vec3> start = exact, input = exact;
  const auto on_side = [](double x) { return std::abs(std::abs(x) - 1.) < 1e-9; };
  for(std::size_t v = 0; v < exact.size(); ++v)
  {
    D::Vec3 p = exact[v];
    for(int i = 0; i < 3; ++i)
      if(!on_side(p[i])) // a free coordinate: jitter it along the surface
        p[i] += 0.05 * u(rng);
    start[v] = p;
    input[v] = p + D::Vec3{0.1, 0.1, 0.1}; // the denoiser moved every vertex by about 0.17
  }
  std::vector<D::Vec3> p = start;
  D::Fold_safeguard guard;
  guard.enabled = false;
  const std::size_t moved = D::relax_tangentially<CGAL::Sequential_tag>(m, input, p, std::vector<char>(), guard);
  EXPECT_GT(moved, 0u);
  std::size_t corners = 0, creases = 0;
  for(std::size_t v = 0; v < p.size(); ++v)
  {
    int fixed_coordinates = 0;
    for(int i = 0; i < 3; ++i)
      if(on_side(exact[v][i]))
      {
        ++fixed_coordinates;
        EXPECT_NEAR(p[v][i], exact[v][i], 1e-12) << v; // stays on its face (faces)
      }
    if(fixed_coordinates == 3)
    {
      ++corners;
      EXPECT_EQ(p[v], start[v]) << v;
    }
    if(fixed_coordinates == 2)
      ++creases;
  }
  EXPECT_EQ(corners, 8u);
  EXPECT_GT(creases, 0u);
}
