// The bad-input corpus: one test per kind of messy input, each asserting the
// documented outcome (README, "Robustness"; Doxygen of the public functions),
// and a summary line of how many cases behave as documented.
//
// A case is a function returning "" when the outcome is the documented one,
// otherwise what went wrong.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/update_vertices_from_face_normals.h>

#include <denoising_support/mesh_file.h>
#include <denoising_support/synthetic_meshes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef Mesh::Vertex_index V;
typedef Mesh::Face_index F;

namespace {

// ---- the corpus cases --------------------------------------------------------

// Each case is a function returning "" if the input behaves as documented,
// else a message naming the check that failed; the test fails with it. (CTest
// runs every test in a process of its own, so there is no summary test: it
// would run every case a second time.)
#define BAD_INPUT_CASE(NAME)                                                                                           \
  std::string NAME();                                                                                                  \
  TEST(BadInputCorpus, NAME)                                                                                           \
  {                                                                                                                    \
    const std::string problem = NAME();                                                                                \
    EXPECT_TRUE(problem.empty()) << problem;                                                                           \
  }                                                                                                                    \
  std::string NAME()

// Returns from the case with a message unless `cond`.
#define REQUIRE(cond)                                                                                                  \
  do                                                                                                                   \
  {                                                                                                                    \
    if(!(cond))                                                                                                        \
      return std::string(__FILE__ ":") + std::to_string(__LINE__) + ": " #cond;                                        \
  } while(false)

// ---- helpers ---------------------------------------------------------------

std::vector<K::Point_3> positions(const Mesh& mesh)
{
  std::vector<K::Point_3> p;
  for(auto v : mesh.vertices())
    p.push_back(mesh.point(v));
  return p;
}

// Bitwise comparison that also accepts NaN == NaN.
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }
bool same_positions(const std::vector<K::Point_3>& a, const std::vector<K::Point_3>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!same(a[i].x(), b[i].x()) || !same(a[i].y(), b[i].y()) || !same(a[i].z(), b[i].z()))
      return false;
  return true;
}

bool all_finite(const Mesh& mesh)
{
  for(auto v : mesh.vertices())
  {
    const K::Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

double max_abs_z(const Mesh& mesh)
{
  double h = 0;
  for(auto v : mesh.vertices())
    h = (std::max)(h, std::abs(mesh.point(v).z()));
  return h;
}

// Runs f; returns the message of the std::invalid_argument it throws, or
// "<no exception>" / "<other exception>".
template <typename Function>
std::string invalid_argument_of(Function f)
{
  try
  {
    f();
  }
  catch(const std::invalid_argument& e)
  {
    return e.what();
  }
  catch(...)
  {
    return "<other exception>";
  }
  return "<no exception>";
}

bool contains(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// Calls every public function that modifies a mesh or writes a map on `mesh`,
// each on its own copy, and checks that each throws std::invalid_argument
// whose message contains `what`, and leaves its copy, and the face map it was
// given, exactly as they were (the strong guarantee).
std::string every_function_throws_and_leaves_unchanged(const Mesh& mesh, const char* what)
{
  const auto before = positions(mesh);
  std::vector<std::pair<const char*, std::function<void(Mesh&)>>> calls = {
      {"intrinsic_denoising", [](Mesh& m) { PMP::intrinsic_denoising(m); }},
      {"intrinsic_denoising(face_normal_map)",
       [](Mesh& m) {
         auto fnm = m.add_property_map<F, K::Vector_3>("f:out", K::Vector_3(7, 7, 7)).first;
         PMP::intrinsic_denoising(m, CGAL::parameters::face_normal_map(fnm));
       }},
      {"intrinsic_filter_face_normals",
       [](Mesh& m) {
         auto fnm = m.add_property_map<F, K::Vector_3>("f:out", K::Vector_3(7, 7, 7)).first;
         PMP::intrinsic_filter_face_normals(m, fnm);
       }},
      {"update_vertices_from_face_normals",
       [](Mesh& m) {
         auto fnm = m.add_property_map<F, K::Vector_3>("f:target", K::Vector_3(0, 0, 1)).first;
         PMP::update_vertices_from_face_normals(m, fnm);
       }},
      {"add_gaussian_noise", [](Mesh& m) { PMP::add_gaussian_noise(m, 0.3); }},
      {"add_impulsive_noise", [](Mesh& m) { PMP::add_impulsive_noise(m, 0.5, 0.3); }},
      {"face_normal_error", [](Mesh& m) { (void)PMP::face_normal_error(m, m); }},
      {"vertex_position_error", [](Mesh& m) { (void)PMP::vertex_position_error(m, m); }},
  };
  for(auto& call : calls)
  {
    Mesh copy = mesh;
    const std::string message = invalid_argument_of([&] { call.second(copy); });
    if(!contains(message, what))
      return std::string(call.first) + ": expected std::invalid_argument about '" + what + "', got: " + message;
    if(!same_positions(before, positions(copy)))
      return std::string(call.first) + ": the mesh was modified";
    auto out = copy.property_map<F, K::Vector_3>("f:out");
    if(out.second)
      for(auto f : copy.faces())
        if(get(out.first, f) != K::Vector_3(7, 7, 7))
          return std::string(call.first) + ": the face normal map was modified";
  }
  return "";
}

Mesh noisy_plane(int n, unsigned int seed, double sigma = 0.3)
{
  Mesh m = denoising_support::plane_grid<Mesh>(n);
  PMP::add_gaussian_noise(m, sigma, CGAL::parameters::random_seed(seed));
  return m;
}

// A triangle of the plane z = 0, n x n grid of size 1, with noise, with every
// vertex scaled by `s`.
Mesh scaled(const Mesh& m, double s)
{
  Mesh r = m;
  for(auto v : r.vertices())
  {
    const K::Point_3& p = r.point(v);
    r.point(v) = K::Point_3(s * p.x(), s * p.y(), s * p.z());
  }
  return r;
}

const auto few_iterations = CGAL::parameters::number_of_iterations(8);

} // namespace

// ---- the cases -------------------------------------------------------------

// An empty mesh: every public function is a no-op.
BAD_INPUT_CASE(EmptyMeshIsANoOpForEveryFunction)
{
  Mesh m;
  auto fnm = m.add_property_map<F, K::Vector_3>("f:out").first;
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_filter_face_normals(m, fnm); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::update_vertices_from_face_normals(m, fnm); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::add_gaussian_noise(m, 0.3); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::add_impulsive_noise(m, 0.5, 0.3); }) == "<no exception>");
  REQUIRE(PMP::face_normal_error(m, m) == 0.);
  REQUIRE(m.is_empty());
  Polyhedron p;
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(p); }) == "<no exception>");
  return "";
}

// Vertices without faces only: no face, so nothing to do; they do not move.
BAD_INPUT_CASE(MeshWithoutFacesIsANoOp)
{
  Mesh m;
  m.add_vertex(K::Point_3(0, 0, 0));
  m.add_vertex(K::Point_3(1, 2, 3));
  const auto before = positions(m);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::add_gaussian_noise(m, 0.3); }) == "<no exception>");
  REQUIRE(same_positions(before, positions(m)));
  return "";
}

// A quadrangle among triangles: std::invalid_argument naming the problem,
// from every function, nothing modified.
BAD_INPUT_CASE(NonTriangleFaceThrowsAndLeavesEverythingUnchanged)
{
  Mesh m = noisy_plane(4, 1);
  const V a = m.add_vertex(K::Point_3(2, 0, 0)), b = m.add_vertex(K::Point_3(3, 0, 0)),
          c = m.add_vertex(K::Point_3(3, 1, 0)), d = m.add_vertex(K::Point_3(2, 1, 0));
  REQUIRE(m.add_face(a, b, c, d) != Mesh::null_face());
  return every_function_throws_and_leaves_unchanged(m, "triangle");
}

BAD_INPUT_CASE(NaNCoordinateThrowsAndLeavesEverythingUnchanged)
{
  Mesh m = noisy_plane(5, 2);
  m.point(V(7)) = K::Point_3(0.5, std::numeric_limits<double>::quiet_NaN(), 0);
  return every_function_throws_and_leaves_unchanged(m, "NaN or infinite");
}

BAD_INPUT_CASE(InfiniteCoordinateThrowsAndLeavesEverythingUnchanged)
{
  Mesh m = noisy_plane(5, 3);
  m.point(V(11)) = K::Point_3(0.5, 0.5, -std::numeric_limits<double>::infinity());
  return every_function_throws_and_leaves_unchanged(m, "NaN or infinite");
}

// A Surface_mesh with removed, not yet collected elements: CGAL's index maps
// skip the removed ones, so it is denoised like a collected mesh.
// (Not bitwise like its collected copy: collect_garbage() renumbers the faces
// and the result depends on the face numbering, by a few 1e-3 on this unit
// plane: printed below.)
BAD_INPUT_CASE(SurfaceMeshWithGarbageIsDenoised)
{
  const Mesh flat = [] {
    Mesh f = denoising_support::plane_grid<Mesh>(8);
    f.remove_face(*f.faces().begin());
    f.collect_garbage();
    return f;
  }();
  Mesh m = noisy_plane(8, 4);
  m.remove_face(*m.faces().begin());
  const V isolated = m.add_vertex(K::Point_3(9, 9, 9));
  m.remove_vertex(isolated);
  REQUIRE(m.has_garbage());
  Mesh collected = m;
  collected.collect_garbage();
  const double noisy_En = PMP::face_normal_error(collected, flat);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  PMP::intrinsic_denoising(collected);
  m.collect_garbage();
  REQUIRE(all_finite(m));
  const double En = PMP::face_normal_error(m, flat);
  const auto p = positions(m), q = positions(collected);
  REQUIRE(p.size() == q.size());
  double d = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
    d = (std::max)(d, std::sqrt(CGAL::squared_distance(p[i], q[i])));
  std::printf("garbage: E_n %.2f -> %.3f deg; max difference to the collected copy's result %.3e\n", noisy_En, En, d);
  REQUIRE(En < noisy_En / 10.);
  return "";
}

// A user's face index map that does not number the faces 0..n-1 (here: all
// zero): std::invalid_argument, nothing modified (instead of out-of-bounds
// writes).
BAD_INPUT_CASE(BrokenIndexMapThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = noisy_plane(5, 16);
  auto bad_fim = m.add_property_map<F, std::size_t>("f:bad_index", 0).first;
  auto bad_vim = m.add_property_map<V, std::size_t>("v:bad_index", 1000).first;
  const auto before = positions(m);
  REQUIRE(contains(invalid_argument_of([&] { PMP::intrinsic_denoising(m, CGAL::parameters::face_index_map(bad_fim)); }),
                   "face index map"));
  REQUIRE(contains(
      invalid_argument_of([&] { PMP::add_gaussian_noise(m, 0.3, CGAL::parameters::vertex_index_map(bad_vim)); }),
      "vertex index map"));
  REQUIRE(same_positions(before, positions(m)));
  return "";
}

// Two fans of triangles that share one vertex only (a "bow tie", a
// non-manifold vertex, which Surface_mesh can represent): denoised like any
// mesh, the shared vertex follows the faces of both fans.
BAD_INPUT_CASE(NonManifoldVertexIsDenoised)
{
  Mesh m;
  // two 4 x 4 grids in z = 0 touching at the corner (0, 0, 0)
  std::vector<std::vector<V>> grid(2, std::vector<V>(25));
  const V shared = m.add_vertex(K::Point_3(0, 0, 0));
  for(int g = 0; g < 2; ++g)
    for(int i = 0; i <= 4; ++i)
      for(int j = 0; j <= 4; ++j)
      {
        const double s = g == 0 ? 1. : -1.;
        grid[g][5 * i + j] = (i == 0 && j == 0) ? shared : m.add_vertex(K::Point_3(s * i / 4., s * j / 4., 0));
      }
  for(int g = 0; g < 2; ++g)
    for(int i = 0; i < 4; ++i)
      for(int j = 0; j < 4; ++j)
      {
        const V a = grid[g][5 * i + j], b = grid[g][5 * (i + 1) + j], c = grid[g][5 * (i + 1) + j + 1],
                d = grid[g][5 * i + j + 1];
        REQUIRE(m.add_face(a, b, c) != Mesh::null_face());
        REQUIRE(m.add_face(a, c, d) != Mesh::null_face());
      }
  REQUIRE(m.is_valid(false));
  REQUIRE(!CGAL::is_border(shared, m) || m.degree(shared) > 0); // it exists and has faces
  const Mesh flat = m;
  PMP::add_gaussian_noise(m, 0.2, CGAL::parameters::random_seed(5));
  const double noisy_En = PMP::face_normal_error(m, flat);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m, few_iterations); }) == "<no exception>");
  REQUIRE(all_finite(m));
  REQUIRE(PMP::face_normal_error(m, flat) < noisy_En / 4.);
  return "";
}

// Isolated vertices (no incident face) never move and cause no error.
BAD_INPUT_CASE(IsolatedVerticesDoNotMove)
{
  Mesh m = noisy_plane(6, 6);
  std::vector<V> isolated = {m.add_vertex(K::Point_3(5, 5, 5)), m.add_vertex(K::Point_3(-1, 0, 2))};
  const auto before = positions(m);
  auto fnm = m.add_property_map<F, K::Vector_3>("f:target", K::Vector_3(0, 0, 1)).first;
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m, few_iterations); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::update_vertices_from_face_normals(m, fnm); }) == "<no exception>");
  REQUIRE(invalid_argument_of([&] { PMP::add_gaussian_noise(m, 0.3); }) == "<no exception>");
  REQUIRE(all_finite(m));
  for(V v : isolated)
    REQUIRE(m.point(v) == before[std::size_t(v)]);
  REQUIRE(!same_positions(before, positions(m))); // the others moved
  return "";
}

// A flat plane cut in two along a line of duplicated (coincident, unshared)
// vertices: the halves are denoised independently; a flat input stays flat.
BAD_INPUT_CASE(DuplicatedVerticesAlongASeam)
{
  denoising_support::Soup_builder left, right;
  left.add_subdivided_quad({0., 0., 0.}, {0.5, 0., 0.}, {0., 1., 0.}, 4, 8, false);
  right.add_subdivided_quad({0.5, 0., 0.}, {0.5, 0., 0.}, {0., 1., 0.}, 4, 8, false);
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> triangles;
  for(const auto* s : {&left, &right})
  {
    const std::size_t offset = points.size();
    for(const auto& p : s->points)
      points.emplace_back(p[0], p[1], p[2]);
    for(auto t : s->triangles)
    {
      for(auto& i : t)
        i += offset;
      triangles.push_back(t);
    }
  }
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, m);
  REQUIRE(num_vertices(m) == 2 * 5 * 9);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(max_abs_z(m) < 1e-15);
  const Mesh flat = m;
  PMP::add_gaussian_noise(m, 0.2, CGAL::parameters::random_seed(7));
  const double noisy_En = PMP::face_normal_error(m, flat);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(all_finite(m));
  REQUIRE(PMP::face_normal_error(m, flat) < noisy_En / 4.);
  return "";
}

// Two connected components: each is denoised as if it were alone (the
// neighbourhoods never cross from one to the other).
BAD_INPUT_CASE(SeveralConnectedComponentsAreIndependent)
{
  Mesh a = denoising_support::cube<Mesh>(6);
  PMP::add_gaussian_noise(a, 0.2, CGAL::parameters::random_seed(8));
  const std::size_t n = num_vertices(a);
  // a second copy of the same noisy cube, shifted by 8 (exact in floating
  // point), as vertices n..2n-1
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> triangles;
  for(int copy = 0; copy < 2; ++copy)
  {
    for(auto v : a.vertices())
    {
      const K::Point_3& p = a.point(v);
      points.emplace_back(p.x() + 8. * copy, p.y(), p.z());
    }
    for(auto f : a.faces())
    {
      std::vector<std::size_t> t;
      for(auto v : CGAL::vertices_around_face(halfedge(f, a), a))
        t.push_back(std::size_t(v) + copy * n);
      triangles.push_back(t);
    }
  }
  Mesh both;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, both);
  REQUIRE(num_vertices(both) == 2 * n);
  PMP::intrinsic_denoising(a, few_iterations);
  PMP::intrinsic_denoising(both, few_iterations);
  double d = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3 p = both.point(V(i)), q = both.point(V(i + n)), r = a.point(V(i));
    d = (std::max)({d, std::sqrt(CGAL::squared_distance(p, r)),
                    std::sqrt(CGAL::squared_distance(K::Point_3(q.x() - 8., q.y(), q.z()), r))});
  }
  std::printf("two components vs one alone: max difference %.3e\n", d);
  REQUIRE(d < 1e-12);
  return "";
}

// Faces of zero area (a vertex on the opposite edge, and two coincident
// vertices) get a zero normal: no NaN, no error.
BAD_INPUT_CASE(ZeroAreaFacesProduceNoNaN)
{
  Mesh m = noisy_plane(10, 9, 0.2);
  int collapsed = 0;
  for(auto f : m.faces())
  {
    if(std::size_t(f) % 23 != 0)
      continue;
    auto h = halfedge(f, m);
    const V a = source(h, m), b = target(h, m), c = target(next(h, m), m);
    m.point(c) = CGAL::midpoint(m.point(a), m.point(b));
    ++collapsed;
  }
  m.point(V(40)) = m.point(V(41)); // an edge of length zero
  REQUIRE(collapsed > 3);
  auto fnm = m.add_property_map<F, K::Vector_3>("f:out").first;
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_filter_face_normals(m, fnm); }) == "<no exception>");
  for(auto f : m.faces())
    REQUIRE(std::isfinite(get(fnm, f).squared_length()));
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(all_finite(m));
  return "";
}

// Every vertex at the same point: all faces degenerate; nothing moves.
BAD_INPUT_CASE(FullyCollapsedMeshStaysAsItIs)
{
  Mesh m = denoising_support::plane_grid<Mesh>(3);
  for(auto v : m.vertices())
    m.point(v) = K::Point_3(1, 1, 1);
  const auto before = positions(m);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(same_positions(before, positions(m)));
  return "";
}

// Needles: a column of the grid squeezed to width 1e-9 (aspect ratio 1e8).
BAD_INPUT_CASE(NeedleFacesProduceNoNaN)
{
  Mesh m = denoising_support::plane_grid<Mesh>(10);
  for(auto v : m.vertices())
  {
    const K::Point_3& p = m.point(v);
    if(p.x() > 0.45 && p.x() < 0.55)
      m.point(v) = K::Point_3(0.4 + 1e-9, p.y(), p.z());
  }
  const Mesh flat = m;
  PMP::add_gaussian_noise(m, 0.2, CGAL::parameters::random_seed(10));
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(all_finite(m));
  return "";
}

// A single triangle: no neighbour, its normal stays, nothing moves.
BAD_INPUT_CASE(SingleTriangleDoesNotMove)
{
  Mesh m;
  m.add_face(m.add_vertex(K::Point_3(0, 0, 0)), m.add_vertex(K::Point_3(1, 0, 0)), m.add_vertex(K::Point_3(0, 1, 0.5)));
  const auto before = positions(m);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  double d = 0;
  for(std::size_t i = 0; i < before.size(); ++i)
    d = (std::max)(d, std::sqrt(CGAL::squared_distance(before[i], m.point(V(i)))));
  REQUIRE(d < 1e-15);
  return "";
}

// An open mesh: border faces have one-sided neighbourhoods and still work;
// border vertices stay finite and the noise goes down.
BAD_INPUT_CASE(BorderFacesAreDenoised)
{
  const Mesh flat = denoising_support::plane_grid<Mesh>(20);
  Mesh m = noisy_plane(20, 11);
  const double noisy_En = PMP::face_normal_error(m, flat);
  REQUIRE(invalid_argument_of([&] { PMP::intrinsic_denoising(m); }) == "<no exception>");
  REQUIRE(all_finite(m));
  // E_n over the border faces only
  double border_before = 0, border_after = 0;
  int count = 0;
  Mesh noisy = noisy_plane(20, 11);
  for(auto f : m.faces())
  {
    if(!CGAL::is_border(opposite(halfedge(f, m), m), m) && !CGAL::is_border(opposite(next(halfedge(f, m), m), m), m) &&
       !CGAL::is_border(opposite(prev(halfedge(f, m), m), m), m))
      continue;
    const K::Vector_3 up(0, 0, 1);
    border_before += std::acos((std::min)(1., PMP::compute_face_normal(f, noisy) * up));
    border_after += std::acos((std::min)(1., PMP::compute_face_normal(f, m) * up));
    ++count;
  }
  std::printf("border faces (%d): mean angle to the true normal %.2f -> %.2f deg\n", count,
              border_before / count * 180 / CGAL_PI, border_after / count * 180 / CGAL_PI);
  REQUIRE(count > 40);
  REQUIRE(border_after < border_before / 3.);
  REQUIRE(PMP::face_normal_error(m, flat) < noisy_En / 10.);
  return "";
}

// Constrained vertices never move, border vertices among them.
BAD_INPUT_CASE(ConstrainedBorderVerticesNeverMove)
{
  Mesh m = noisy_plane(12, 12);
  auto pinned = m.add_property_map<V, bool>("v:pinned", false).first;
  for(auto h : m.halfedges())
    if(m.is_border(h))
      put(pinned, target(h, m), true);
  const auto before = positions(m);
  PMP::intrinsic_denoising(m, CGAL::parameters::vertex_is_constrained_map(pinned));
  auto fnm = m.add_property_map<F, K::Vector_3>("f:target", K::Vector_3(0.3, 0, 1)).first;
  PMP::update_vertices_from_face_normals(m, fnm, CGAL::parameters::vertex_is_constrained_map(pinned));
  for(auto v : m.vertices())
    if(get(pinned, v))
      REQUIRE(m.point(v) == before[std::size_t(v)]);
  REQUIRE(!same_positions(before, positions(m)));
  return "";
}

// Coordinates scaled by 1e-6 and 1e6: the result is the scaled result (the
// algorithm is scale-free) up to rounding, relative 1e-9.
BAD_INPUT_CASE(TinyAndHugeScalesGiveTheScaledResult)
{
  const Mesh noisy = [] {
    Mesh c = denoising_support::cube<Mesh>(6);
    PMP::add_gaussian_noise(c, 0.3, CGAL::parameters::random_seed(13));
    return c;
  }();
  Mesh unit = noisy;
  PMP::intrinsic_denoising(unit);
  for(double s : {1e-6, 1e6})
  {
    Mesh m = scaled(noisy, s);
    PMP::intrinsic_denoising(m);
    double d = 0;
    for(auto v : m.vertices())
    {
      const K::Point_3 &p = m.point(v), &q = unit.point(v);
      d = (std::max)(d, std::sqrt(CGAL::squared_distance(K::Point_3(p.x() / s, p.y() / s, p.z() / s), q)));
    }
    std::printf("scale %.0e: max |result / s - unit result| = %.3e (cube of side 2)\n", s, d);
    REQUIRE(d < 2e-9);
  }
  return "";
}

// A NaN target normal for update_vertices_from_face_normals(): error, mesh unchanged.
BAD_INPUT_CASE(NaNTargetNormalThrowsAndLeavesTheMeshUnchanged)
{
  Mesh m = noisy_plane(5, 14);
  auto fnm = m.add_property_map<F, K::Vector_3>("f:target", K::Vector_3(0, 0, 1)).first;
  put(fnm, F(3), K::Vector_3(std::nan(""), 0, 1));
  const auto before = positions(m);
  REQUIRE(contains(invalid_argument_of([&] { PMP::update_vertices_from_face_normals(m, fnm); }), "NaN"));
  REQUIRE(same_positions(before, positions(m)));
  return "";
}

// Non-positive or non-finite parameters: error, mesh and maps unchanged.
BAD_INPUT_CASE(InvalidParametersThrowAndLeaveEverythingUnchanged)
{
  Mesh m = noisy_plane(5, 15);
  const auto before = positions(m);
  auto fnm = m.add_property_map<F, K::Vector_3>("f:out", K::Vector_3(7, 7, 7)).first;
  const double nan = std::nan("");
  REQUIRE(contains(invalid_argument_of([&] { PMP::intrinsic_denoising(m, CGAL::parameters::sigma_range(0.)); }),
                   "sigma_range"));
  REQUIRE(contains(invalid_argument_of([&] {
                     PMP::intrinsic_denoising(m, CGAL::parameters::neighbor_radius(nan).face_normal_map(fnm));
                   }),
                   "neighbor_radius"));
  REQUIRE(contains(
      invalid_argument_of([&] { PMP::intrinsic_filter_face_normals(m, fnm, CGAL::parameters::sigma_spatial(-1.)); }),
      "sigma_spatial"));
  REQUIRE(contains(invalid_argument_of([&] { PMP::add_gaussian_noise(m, -1.); }), "noise level"));
  REQUIRE(contains(invalid_argument_of([&] { PMP::add_impulsive_noise(m, 2., 0.3); }), "fraction"));
  REQUIRE(same_positions(before, positions(m)));
  for(auto f : m.faces())
    REQUIRE(get(fnm, f) == K::Vector_3(7, 7, 7));
  return "";
}

// ---- mesh files (the command-line entry, denoising_support/mesh_file.h) --

namespace {

std::string read_off_text(const std::string& text, Mesh& m)
{
  std::istringstream in(text);
  return denoising_support::read_mesh(in, "off", text.size(), m);
}

} // namespace

// Truncated, malformed or unusable OFF data: a one-line message, no mesh.
BAD_INPUT_CASE(MalformedOffDataIsRejectedWithAOneLineMessage)
{
  const char* bad[] = {
      "",                                                    // empty file
      "OFF\n",                                               // header only
      "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n",                   // truncated vertices
      "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n",   // truncated faces
      "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",          // index out of range
      "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",       // not a number
      "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",         // negative face size
      "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n",        // NaN coordinate
      "OFF\n3 1 0\n0 0 0\n1 0 0\ninf 1 0\n3 0 1 2\n",        // infinite coordinate
      "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", // a quad
      "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",                   // no face
      "OFF\n2000000000 1 0\n0 0 0\n",                        // absurd vertex count
      "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", // absurd face count
      "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n",          // repeated vertex in a face
      "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", // absurd face size
      "\x7f"
      "ELF\x02\x01\x01\x00 binary garbage",
  };
  for(const char* text : bad)
  {
    Mesh m;
    const std::string message = read_off_text(text, m);
    if(message.empty())
      return std::string("accepted: ") + text;
    if(message.find('\n') != std::string::npos)
      return "message on several lines: " + message;
    if(!m.is_empty())
      return std::string("mesh left non-empty for: ") + text;
  }
  Mesh good;
  REQUIRE(read_off_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", good).empty());
  REQUIRE(num_faces(good) == 1);
  // a non-manifold edge (three triangles on edge 0-1) is split by
  // orient_polygon_soup(): read, with the three faces
  Mesh split;
  REQUIRE(read_off_text("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n", split).empty());
  REQUIRE(num_faces(split) == 3);
  return "";
}

namespace {

std::string read_text(const std::string& text, const char* format, Mesh& m,
                      std::vector<std::string>* warnings = nullptr)
{
  std::istringstream in(text);
  return denoising_support::read_mesh(in, format, text.size(), m, warnings);
}

// Each of `bad` in `format`: a one-line message, no mesh; returns "" or what
// went wrong.
std::string check_rejected(const char* format, const std::vector<std::string>& bad)
{
  for(const std::string& text : bad)
  {
    Mesh m;
    const std::string message = read_text(text, format, m);
    if(message.empty())
      return std::string("accepted (") + format + "): " + text;
    if(message.find('\n') != std::string::npos)
      return "message on several lines: " + message;
    if(!m.is_empty())
      return std::string("mesh left non-empty for (") + format + "): " + text;
  }
  return "";
}

// Little-endian binary helpers for the binary PLY and STL cases.
void put_u32(std::string& s, std::uint32_t v)
{
  for(int i = 0; i < 4; ++i)
    s.push_back(char((v >> (8 * i)) & 0xff));
}
void put_f32(std::string& s, float f)
{
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(s, v);
}
// A binary STL of `triangles` (9 coordinates each), announcing `announced`.
std::string binary_stl(const std::vector<std::array<float, 9>>& triangles, std::uint32_t announced)
{
  std::string s(80, ' ');
  put_u32(s, announced);
  for(const auto& t : triangles)
  {
    for(int k = 0; k < 3; ++k)
      put_f32(s, 0.f);
    for(float c : t)
      put_f32(s, c);
    s.push_back('\0');
    s.push_back('\0');
  }
  return s;
}

const char* const ply_header_ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n";

} // namespace

// OBJ, PLY and STL: every count bounded by the data, finite coordinates,
// indices in range; a one-line message naming the line or element, no mesh.
BAD_INPUT_CASE(MalformedObjPlyStlDataIsRejectedWithAOneLineMessage)
{
  const float nan = std::nanf("");
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  REQUIRE(check_rejected("obj", {"", "garbage\x7f\x01", tri,               // no face
                                 "v 0 0 0\nv 1 0 0\nf 1 2 3\n",            // truncated (index 3 missing)
                                 tri + "f 1 2 7\n",                        // out of range
                                 tri + "f 1 2 -9\n",                       // before the first vertex
                                 tri + "f 1 2 0\n",                        // zero index
                                 tri + "f 1 2 x\n",                        // not a number
                                 "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", // NaN
                                 "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", // infinite
                                 "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",     // two coordinates
                                 tri + "f 1 2\n",                          // two vertices
                                 tri + "f 1 2 99999999999999999999999\n",  // huge index
                                 tri + "f 1 1 2\n"})                       // a vertex twice
              .empty());
  const std::string ply_body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  REQUIRE(check_rejected("ply", {"", "ply\n", std::string("ply\nformat ascii 1.0\n") + "element vertex 3\n",
                                 std::string(ply_header_ascii) + "0 0 0\n1 0 0\n",                    // truncated
                                 std::string(ply_header_ascii) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",    // out of range
                                 std::string(ply_header_ascii) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",  // NaN
                                 std::string(ply_header_ascii) + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", // not a number
                                 std::string(ply_header_ascii) + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n",  // huge list
                                 std::string("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\n"
                                             "property float y\nproperty float z\nend_header\n0 0 0\n"), // huge count
                                 std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                             "property float y\nend_header\n") +
                                     ply_body,                                        // no z
                                 std::string("ply\nformat ebcdic 1.0\nend_header\n"), // unknown format
                                 std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                                             "property float x\nproperty float y\nproperty float z\n"
                                             "end_header\n\x01\x02")}) // truncated binary
              .empty());
  const std::vector<std::array<float, 9>> one = {{0, 0, 0, 1, 0, 0, 0, 1, 0}};
  REQUIRE(check_rejected("stl", {"", "garbage bytes, neither ascii nor binary",
                                 binary_stl(one, 2) + std::string(10, '\0'),     // announces 2, holds 1.2
                                 binary_stl({{0, 0, 0, 1, 0, 0, 0, nan, 0}}, 1), // NaN
                                 "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n", // truncated
                                 "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"
                                 "endfacet\nendsolid x\n", // two vertices
                                 "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 inf 0\n"
                                 "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n"}) // infinite
              .empty());
  // the messages name where: a line, an element, a triangle
  Mesh m;
  REQUIRE(contains(read_text(tri + "f 1 2 7\n", "obj", m), "line 4"));
  REQUIRE(
      contains(read_text(std::string(ply_header_ascii) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "ply", m), "vertex 1"));
  REQUIRE(contains(read_text(binary_stl({{0, 0, 0, 1, 0, 0, 0, nan, 0}}, 1), "stl", m), "triangle 0"));
  return "";
}

// The same triangle pair in every format, ASCII and binary: the same mesh.
BAD_INPUT_CASE(ObjPlyStlReadTheSameMesh)
{
  // a square of two triangles: 4 vertices, 2 faces
  const std::vector<std::array<float, 3>> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const int t[2][3] = {{0, 1, 2}, {0, 2, 3}};
  std::string obj = "# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -4 -2 -1\n";
  std::string ply_ascii = "ply\nformat ascii 1.0\ncomment square\nelement vertex 4\nproperty float x\n"
                          "property float y\nproperty float z\nproperty uchar red\nelement face 2\n"
                          "property list uchar int vertex_indices\nend_header\n"
                          "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n3 0 1 2\n3 0 2 3\n";
  std::string ply_big = "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\n"
                        "property double y\nproperty double z\nelement face 2\n"
                        "property list uchar uint vertex_indices\nend_header\n";
  for(const auto& q : p)
    for(float c : q)
    {
      double d = c;
      unsigned char b[8];
      std::memcpy(b, &d, 8);
      for(int i = 7; i >= 0; --i) // this test runs on little-endian machines
        ply_big.push_back(char(b[i]));
    }
  for(const auto& f : t)
  {
    ply_big.push_back(char(3));
    for(int v : f)
      for(int i = 3; i >= 0; --i)
        ply_big.push_back(char((std::uint32_t(v) >> (8 * i)) & 0xff));
  }
  std::vector<std::array<float, 9>> triangles;
  std::string stl_ascii = "solid square\n";
  for(const auto& f : t)
  {
    std::array<float, 9> tr;
    stl_ascii += "facet normal 0 0 1\nouter loop\n";
    for(int c = 0; c < 3; ++c)
    {
      stl_ascii += "vertex " + std::to_string(p[f[c]][0]) + " " + std::to_string(p[f[c]][1]) + " " +
                   std::to_string(p[f[c]][2]) + "\n";
      for(int k = 0; k < 3; ++k)
        tr[3 * c + k] = p[f[c]][k];
    }
    stl_ascii += "endloop\nendfacet\n";
    triangles.push_back(tr);
  }
  stl_ascii += "endsolid square\n";
  // a degenerate triangle is dropped, with a warning
  triangles.push_back({0, 0, 0, 0, 0, 0, 1, 1, 0});
  const std::string stl_binary = binary_stl(triangles, 3);
  const std::pair<const char*, std::string> files[] = {
      {"obj", obj}, {"ply", ply_ascii}, {"ply", ply_big}, {"stl", stl_ascii}, {"stl", stl_binary}};
  for(const auto& file : files)
  {
    Mesh m;
    std::vector<std::string> warnings;
    const std::string problem = read_text(file.second, file.first, m, &warnings);
    if(!problem.empty())
      return std::string(file.first) + ": " + problem;
    REQUIRE(num_vertices(m) == 4);
    REQUIRE(num_faces(m) == 2);
    double area = 0.;
    for(auto f : m.faces())
      area += std::sqrt(CGAL::squared_area(m.point(source(halfedge(f, m), m)), m.point(target(halfedge(f, m), m)),
                                           m.point(target(next(halfedge(f, m), m), m))));
    REQUIRE(std::abs(area - 1.) < 1e-12);
    REQUIRE(warnings.size() == (file.second == stl_binary ? 1u : 0u));
  }
  return "";
}

// OFF with more face lines than its header says: read as the header says,
// with a warning naming the count.
BAD_INPUT_CASE(OffTrailingFacesAreCountedInAWarning)
{
  Mesh m;
  std::vector<std::string> warnings;
  REQUIRE(read_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n# end\n", "off", m, &warnings).empty());
  REQUIRE(num_faces(m) == 1);
  REQUIRE(warnings.size() == 1);
  REQUIRE(contains(warnings[0], "1 line after the 1 faces"));
  return "";
}

// Writing: through a temporary file and a rename; never over the input.
BAD_INPUT_CASE(OutputIsAtomicAndNeverOverwritesTheInput)
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("denoising_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string input = (dir / "in.off").string();
  {
    std::ofstream out(input);
    out << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  Mesh m;
  REQUIRE(denoising_support::read_mesh_file(input, m).empty());
  REQUIRE(denoising_support::output_path(input) == (dir / "in_denoised.off").string());
  REQUIRE(denoising_support::output_path("a.b/c") == "a.b/c_denoised.off");
  // refuses to write over the input
  REQUIRE(contains(denoising_support::write_mesh_file(input, m, input), "refusing"));
  // an unwritable place: an error, and no temporary file left
  REQUIRE(!denoising_support::write_mesh_file((dir / "missing" / "x.off").string(), m).empty());
  // a normal write: the output holds the mesh, no temporary file is left
  const std::string output = denoising_support::output_path(input);
  REQUIRE(denoising_support::write_mesh_file(output, m, input).empty());
  Mesh back;
  REQUIRE(denoising_support::read_mesh_file(output, back).empty());
  REQUIRE(num_faces(back) == 1);
  std::size_t files = 0;
  for(const auto& entry : fs::directory_iterator(dir))
    files += entry.is_regular_file();
  fs::remove_all(dir);
  REQUIRE(files == 2);
  REQUIRE(contains(denoising_support::read_mesh_file((dir / "nope.off").string(), back), "cannot open"));
  return "";
}

namespace {

// The faces of `mesh` as a soup (vertex indices, each face from its halfedge).
std::vector<std::vector<std::size_t>> polygons_of(const Mesh& mesh)
{
  std::vector<std::vector<std::size_t>> polygons;
  for(auto f : faces(mesh))
  {
    polygons.emplace_back();
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(std::size_t(v));
  }
  return polygons;
}

// An open surface as a soup: the n x n grid of vertices, two triangles a cell.
std::vector<std::vector<std::size_t>> grid_polygons(std::size_t n)
{
  std::vector<std::vector<std::size_t>> grid;
  for(std::size_t i = 0; i + 1 < n; ++i)
    for(std::size_t j = 0; j + 1 < n; ++j)
    {
      const std::size_t a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      grid.push_back({a, b, d});
      grid.push_back({a, d, c});
    }
  return grid;
}

} // namespace

// The readers' manifold test (is_oriented_manifold_soup()) answers as CGAL's
// is_polygon_soup_a_polygon_mesh() on soups of every kind it must tell
// apart: closed and open surfaces, faces removed from them (pinched
// vertices: two fans at one vertex), faces flipped or repeated, bowties,
// two closed fans sharing a vertex, random triangles on a few vertices.
TEST(MeshFile, ManifoldSoupTestAgreesWithCgal)
{
  typedef std::vector<std::vector<std::size_t>> Polygons;
  auto agree = [](const Polygons& p, std::size_t nv, const std::string& what) {
    const bool cgal = PMP::is_polygon_soup_a_polygon_mesh(p),
               ours = denoising_support::is_oriented_manifold_soup(p, nv);
    EXPECT_EQ(ours, cgal) << what;
    return cgal;
  };
  // a closed surface, an open one (an n x n grid) and two closed fans at one vertex
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  const Polygons closed = polygons_of(fandisk);
  const std::size_t n = 12;
  const Polygons grid = grid_polygons(n);
  const Polygons two_tetrahedra = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2},
                                   {0, 4, 5}, {0, 5, 6}, {0, 6, 4}, {4, 6, 5}};
  const Polygons bowtie = {{0, 1, 2}, {0, 3, 4}};
  const Polygons quads = {{0, 1, 2, 3}, {3, 2, 4, 5}};
  EXPECT_TRUE(agree(closed, num_vertices(fandisk), "fandisk"));
  EXPECT_TRUE(agree(grid, n * n, "grid"));
  EXPECT_TRUE(agree(quads, 6, "two quads"));
  EXPECT_FALSE(agree(two_tetrahedra, 7, "two tetrahedra at a vertex"));
  EXPECT_FALSE(agree(bowtie, 5, "bowtie"));
  std::mt19937 random(7);
  std::size_t yes = 0, no = 0;
  for(int trial = 0; trial < 400; ++trial)
  {
    const bool on_grid = trial % 2 == 0;
    Polygons p = on_grid ? grid : closed;
    const std::size_t nv = on_grid ? n * n : num_vertices(fandisk);
    const int kind = (trial / 2) % 4;
    if(kind == 0) // faces removed
      for(int k = 0; k < 1 + trial % 40; ++k)
        p.erase(p.begin() + std::ptrdiff_t(random() % p.size()));
    else if(kind == 1) // a face flipped
    {
      std::vector<std::size_t>& f = p[random() % p.size()];
      std::reverse(f.begin(), f.end());
    }
    else if(kind == 2) // a face repeated
      p.push_back(p[random() % p.size()]);
    else // a face glued to a far vertex
      p.push_back({p[random() % p.size()][0], nv, nv + 1});
    const bool ok = agree(p, nv + 2, "trial " + std::to_string(trial));
    yes += ok;
    no += !ok;
  }
  for(int trial = 0; trial < 300; ++trial) // random triangles on 6 vertices
  {
    Polygons p;
    for(int k = 0; k < 1 + trial % 8; ++k)
    {
      std::size_t a = random() % 6, b = random() % 6, c = random() % 6;
      if(a != b && b != c && a != c)
        p.push_back({a, b, c});
    }
    const bool ok = agree(p, 6, "random " + std::to_string(trial));
    yes += ok;
    no += !ok;
  }
  // both answers occur often enough for the agreement to mean something
  EXPECT_GT(yes, 50u);
  EXPECT_GT(no, 50u);
}

// The readers' mesh builder (build_oriented_manifold_mesh()) gives the mesh
// CGAL's polygon_soup_to_polygon_mesh() gives, index for index and link for
// link (every halfedge's target, next, prev and face, every vertex's and
// face's halfedge), on every manifold soup of the kinds above: closed and
// open surfaces, with faces removed (holes, pinched borders), flipped
// faces repaired by orient_polygon_soup(), quads, isolated vertices.
TEST(MeshFile, DirectBuildIsCgalsBuild)
{
  typedef std::vector<std::vector<std::size_t>> Polygons;
  std::size_t compared = 0;
  auto same = [&compared](const Polygons& polygons, std::size_t nv, const std::string& what) {
    if(!denoising_support::is_oriented_manifold_soup(polygons, nv))
      return;
    std::vector<K::Point_3> points;
    for(std::size_t v = 0; v < nv; ++v)
      points.emplace_back(double(v), double(v * v % 7), 0.5 * double(v % 3));
    Mesh ours, cgal;
    denoising_support::build_oriented_manifold_mesh(points, polygons, ours);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, cgal);
    ASSERT_EQ(ours.num_vertices(), cgal.num_vertices()) << what;
    ASSERT_EQ(ours.num_halfedges(), cgal.num_halfedges()) << what;
    ASSERT_EQ(ours.num_faces(), cgal.num_faces()) << what;
    EXPECT_TRUE(ours.is_valid(false)) << what;
    std::size_t different = 0;
    for(auto h : halfedges(cgal))
      different += ours.target(h) != cgal.target(h) || ours.next(h) != cgal.next(h) || ours.prev(h) != cgal.prev(h) ||
                   ours.face(h) != cgal.face(h);
    for(auto v : vertices(cgal))
      different += ours.halfedge(v) != cgal.halfedge(v) || ours.point(v) != cgal.point(v);
    for(auto f : faces(cgal))
      different += ours.halfedge(f) != cgal.halfedge(f);
    EXPECT_EQ(different, 0u) << what;
    ++compared;
  };
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  const Polygons closed = polygons_of(fandisk);
  const std::size_t n = 12;
  const Polygons grid = grid_polygons(n);
  same(closed, num_vertices(fandisk), "fandisk");
  same(grid, n * n, "grid");
  same({{0, 1, 2, 3}, {3, 2, 4, 5}}, 6, "two quads");
  std::mt19937 random(11);
  for(int trial = 0; trial < 200; ++trial)
  {
    const bool on_grid = trial % 2 == 0;
    Polygons p = on_grid ? grid : closed;
    std::shuffle(p.begin(), p.end(), random); // faces in another order
    const std::size_t nv = on_grid ? n * n : num_vertices(fandisk);
    for(int k = 0; k < trial % 30; ++k) // faces removed
      p.erase(p.begin() + std::ptrdiff_t(random() % p.size()));
    std::size_t count = nv + 2; // two isolated vertices
    if(trial % 3 == 0)          // a face flipped, then the soup oriented again (it may add vertices)
    {
      std::vector<std::size_t>& f = p[random() % p.size()];
      std::reverse(f.begin(), f.end());
      std::vector<K::Point_3> points(count);
      PMP::orient_polygon_soup(points, p);
      count = points.size();
    }
    same(p, count, "trial " + std::to_string(trial));
  }
  EXPECT_GT(compared, 100u);
}

// The OFF reader's number scanner (off_text::numbers()) reads every line as
// the string stream of CGAL's OFF scanner does: the same numbers, bit for
// bit, up to the same first word that is not one, on lines of random words
// among plain numbers and the words the two could read differently.
TEST(MeshFile, OffNumberScannerAgreesWithTheStream)
{
  const char* words[] = {"1",        "-2.5", "+3",   "1e5",    "1e999",
                         "1e-400",   "nan",  "inf",  "-inf",   ".5",
                         "-.5",      "5.",   "0x10", "abc",    "1,2",
                         "\t",       "\r",   "--1",  "-",      ".",
                         "7e-3",     "-0",   "3e",   "1.5e+2", "12345678901234567890",
                         "4.9e-324", "0.1"};
  std::mt19937 random(3);
  std::vector<double> fast;
  std::size_t lines_with_numbers = 0;
  for(int trial = 0; trial < 5000; ++trial)
  {
    std::string line;
    for(int k = 0; k < 1 + trial % 7; ++k)
      line += std::string(k ? " " : "") + words[random() % (sizeof(words) / sizeof(words[0]))];
    denoising_support::off_text::numbers(line, fast);
    std::vector<double> stream;
    std::istringstream in(line);
    double d;
    while(in >> CGAL::IO::iformat(d))
      stream.push_back(d);
    ASSERT_EQ(fast.size(), stream.size()) << "'" << line << "'";
    for(std::size_t i = 0; i < fast.size(); ++i)
      ASSERT_TRUE(same(fast[i], stream[i])) << "'" << line << "' word " << i;
    lines_with_numbers += !fast.empty();
  }
  EXPECT_GT(lines_with_numbers, 1000u);
}

// The OFF writer: what it writes reads back bit for bit (coordinates in the
// shortest form that round-trips, extreme and denormal values included),
// faces and their vertex order kept, removed vertices skipped and the
// others renumbered.
TEST(MeshFile, OffWriterRoundTripsBitForBit)
{
  Mesh m;
  const double values[] = {0.1, -1e-310, 1.7976931348623157e308, 3.141592653589793, -0., 2.5e-8, 123456789.125};
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i < 7; ++i)
    v.push_back(m.add_vertex(K::Point_3(values[i], values[(i + 3) % 7], values[(i + 5) % 7])));
  const auto unused = m.add_vertex(K::Point_3(9, 9, 9));
  v.push_back(m.add_vertex(K::Point_3(1, 2, 3)));
  m.add_face(v[0], v[1], v[2]);
  m.add_face(v[0], v[2], v[3]);
  m.add_face(v[4], v[5], v[6]);
  m.add_face(v[4], v[6], v[7]);
  m.remove_vertex(unused); // a hole in the vertex numbering
  std::ostringstream out;
  ASSERT_TRUE(denoising_support::write_off_text(out, m));
  std::istringstream in(out.str());
  Mesh back;
  ASSERT_EQ(denoising_support::read_mesh(in, "off", out.str().size(), back), "");
  ASSERT_EQ(num_vertices(back), 8u);
  ASSERT_EQ(num_faces(back), 4u);
  std::vector<K::Point_3> a, b;
  for(auto x : vertices(m))
    a.push_back(m.point(x));
  for(auto x : vertices(back))
    b.push_back(back.point(x));
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i)
    for(int c = 0; c < 3; ++c)
      EXPECT_EQ(std::memcmp(&a[i][c], &b[i][c], sizeof(double)), 0) << i << " " << c;
  auto corners = [](const Mesh& mesh) {
    std::vector<std::size_t> ids;
    for(auto f : faces(mesh))
      for(auto x : vertices_around_face(halfedge(f, mesh), mesh))
        ids.push_back(std::size_t(x));
    return ids;
  };
  const std::vector<std::size_t> written = corners(back);
  // the input's corners, renumbered past the removed vertex (index 7)
  std::vector<std::size_t> expected = corners(m);
  for(std::size_t& x : expected)
    x -= x > 7 ? 1 : 0;
  EXPECT_EQ(written, expected);
}
