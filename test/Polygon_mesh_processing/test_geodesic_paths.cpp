// Tests of the exact geodesic paths (internal/Denoising/paths/geodesic_paths.h) and
// of intrinsic_denoising() with Intrinsic_path_strategy::GEODESIC.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <denoising_support/synthetic_meshes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = PMP::internal::Denoising;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
using denoising_support::P3;
using denoising_support::Soup_builder;

namespace {

// Flat arrays of a mesh, as the denoiser sees it.
struct Flat
{
  D::Flat_mesh mesh;
  D::Face_data faces;
  double d = 0.;

  template <typename M>
  explicit Flat(const M& m)
  {
    const D::Mesh_maps<M, CGAL::parameters::Default_named_parameters> maps(m, CGAL::parameters::default_values());
    mesh = maps.flat(m, "test");
    init();
  }
  explicit Flat(const D::Flat_mesh& m) : mesh(m) { init(); }
  void init()
  {
    D::compute_face_data<CGAL::Sequential_tag>(mesh, mesh.points, faces);
    d = D::mean_adjacent_centroid_distance(mesh, faces);
  }
  D::Csr neighbors(double relative_radius) const
  {
    return D::geometric_neighborhoods<CGAL::Sequential_tag>(mesh, faces.centroids, relative_radius * d);
  }
};

// Flat mesh straight from a soup (no CGAL mesh in between).
D::Flat_mesh flat_from_soup(const Soup_builder& s)
{
  D::Flat_mesh m;
  for(const P3& p : s.points)
    m.points.push_back({p[0], p[1], p[2]});
  for(const auto& t : s.triangles)
    m.triangles.push_back({std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  D::list_faces_around_vertices(m);
  return m;
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Faces of a planar (2D) triangulation whose interior the segment a -> b
// crosses over a length above `relative_tolerance` of the segment, in the order
// the segment meets them: clipping of the segment by the three half-planes of
// each triangle, independent of any mesh traversal.
std::vector<std::uint32_t> faces_crossed_by_segment(const std::vector<std::array<double, 2>>& pts,
                                                    const std::vector<std::array<std::uint32_t, 3>>& tris,
                                                    const std::array<double, 2>& a, const std::array<double, 2>& b,
                                                    double relative_tolerance = 1e-9)
{
  std::vector<std::pair<double, std::uint32_t>> hits;
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  for(std::uint32_t f = 0; f < tris.size(); ++f)
  {
    double t0 = 0., t1 = 1.;
    const auto& t = tris[f];
    const double orient = cross2(pts[t[1]][0] - pts[t[0]][0], pts[t[1]][1] - pts[t[0]][1], pts[t[2]][0] - pts[t[0]][0],
                                 pts[t[2]][1] - pts[t[0]][1]);
    for(int k = 0; k < 3 && t0 < t1; ++k)
    {
      const auto& p = pts[t[k]];
      const auto& q = pts[t[(k + 1) % 3]];
      // inside: orient * cross(q - p, x - p) >= 0, x = a + s (b - a)
      const double c0 = orient * cross2(q[0] - p[0], q[1] - p[1], a[0] - p[0], a[1] - p[1]);
      const double c1 = orient * cross2(q[0] - p[0], q[1] - p[1], dx, dy);
      if(c1 == 0.)
      {
        if(c0 < 0.)
          t1 = -1.;
      }
      else if(c1 > 0.)
        t0 = (std::max)(t0, -c0 / c1);
      else
        t1 = (std::min)(t1, -c0 / c1);
    }
    if(t1 - t0 > relative_tolerance)
      hits.emplace_back(0.5 * (t0 + t1), f);
  }
  std::sort(hits.begin(), hits.end());
  std::vector<std::uint32_t> out;
  for(const auto& h : hits)
    out.push_back(h.second);
  return out;
}

std::string to_string(const std::vector<std::uint32_t>& v)
{
  std::string s;
  for(std::uint32_t x : v)
    s += std::to_string(x) + " ";
  return s;
}

// Checks the structure of a geodesic path forest against the neighbourhoods:
// parents before children, every neighbour weighted exactly once, nothing
// else weighted, every unweighted node has a child (it lies on a path).
void expect_consistent_forest(const D::Path_forest& f, const D::Csr& nb)
{
  ASSERT_EQ(f.number_of_faces(), nb.size());
  ASSERT_EQ(f.weighted.size(), f.face.size());
  for(std::size_t i = 0; i < nb.size(); ++i)
  {
    const std::uint32_t b = f.offsets[i], e = f.offsets[i + 1];
    std::multiset<std::uint32_t> weighted;
    std::vector<char> has_child(e - b, 0);
    for(std::uint32_t k = b; k < e; ++k)
    {
      const std::int32_t p = f.parent[k];
      ASSERT_TRUE(p == D::Path_forest::root || (p >= 0 && std::uint32_t(p) < k - b)) << "face " << i;
      if(p != D::Path_forest::root)
        has_child[p] = 1;
      if(f.is_weighted(k))
        weighted.insert(f.face[k]);
    }
    for(std::uint32_t k = b; k < e; ++k)
      if(!f.is_weighted(k))
      {
        EXPECT_TRUE(has_child[k - b]) << "face " << i << ": a path-only node ends no path";
      }
    const std::multiset<std::uint32_t> expected(nb.items.begin() + nb.begin(i), nb.items.begin() + nb.end(i));
    EXPECT_EQ(weighted, expected) << "face " << i;
  }
}

// Faces from the root to node k of face i's tree.
std::vector<std::uint32_t> chain(const D::Path_forest& f, std::size_t i, std::uint32_t k)
{
  std::vector<std::uint32_t> c;
  for(std::int32_t local = std::int32_t(k - f.offsets[i]); local != D::Path_forest::root;
      local = f.parent[f.offsets[i] + local])
    c.push_back(f.face[f.offsets[i] + local]);
  c.push_back(std::uint32_t(i));
  std::reverse(c.begin(), c.end());
  return c;
}

// A grid of n x n cells on [0, 1]^2 (two triangles per cell), each interior
// vertex moved by up to `jitter` cell sizes (deterministic), with its 2D layout.
struct Planar_grid
{
  std::vector<std::array<double, 2>> pts;
  std::vector<std::array<std::uint32_t, 3>> tris;
  D::Flat_mesh flat;

  Planar_grid(int n, double jitter)
  {
    Soup_builder s;
    auto at = [&](int i, int j) -> P3 {
      double x = double(i) / n, y = double(j) / n;
      if(i > 0 && j > 0 && i < n && j < n)
      {
        x += jitter / n * std::sin(12.9898 * i + 78.233 * j);
        y += jitter / n * std::cos(39.3468 * i + 11.135 * j);
      }
      return {x, y, 0.};
    };
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
      {
        s.add_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), {0., 0., 1.});
        s.add_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), {0., 0., 1.});
      }
    flat = flat_from_soup(s);
    for(const auto& p : flat.points)
      pts.push_back({p[0], p[1]});
    tris = flat.triangles;
  }
};

void check_flat_paths(const Planar_grid& g, double relative_radius, std::size_t& checked, std::size_t& with_vertex)
{
  Flat f(g.flat);
  const D::Csr nb = f.neighbors(relative_radius);
  D::Geodesic_patch_solver solver(f.mesh, f.faces, 1);
  D::Geodesic_path path;
  for(std::uint32_t i = 0; i < f.mesh.number_of_faces(); ++i)
  {
    ASSERT_TRUE(solver.set_source(i, nb.items.begin() + nb.begin(i), nb.items.begin() + nb.end(i)));
    for(std::uint32_t k = nb.begin(i); k < nb.end(i); ++k)
    {
      const std::uint32_t j = nb.items[k];
      ASSERT_TRUE(solver.path_to(j, path)) << i << " -> " << j;
      const D::Vec3 ci = f.faces.centroids[i], cj = f.faces.centroids[j];
      const auto expected = faces_crossed_by_segment(g.pts, g.tris, {ci[0], ci[1]}, {cj[0], cj[1]});
      ASSERT_EQ(path.faces, expected) << i << " -> " << j << ": geodesic " << to_string(path.faces) << ", segment "
                                      << to_string(expected);
      // the geodesic is the segment: its length, and its points lie on it
      const double len = D::norm(cj - ci);
      EXPECT_NEAR(path.length(), len, 1e-12 * len);
      for(const D::Vec3& p : path.points)
        EXPECT_LT(D::norm(D::cross(p - ci, cj - ci)) / len, 1e-12);
      ++checked;
      with_vertex += path.vertex_passages > 0;
    }
  }
}

} // namespace

TEST(GeodesicPaths, FlatPatchPathIsTheStraightSegmentAndItsCrossedFaces)
{
  // an irregular planar mesh: no segment meets a vertex
  std::size_t checked = 0, with_vertex = 0;
  check_flat_paths(Planar_grid(9, 0.25), 4., checked, with_vertex);
  std::printf("jittered grid: %zu paths checked\n", checked);
  EXPECT_GT(checked, 5000u);
}

TEST(GeodesicPaths, FlatRegularGridPathsThroughVerticesSkipTheFacesTheyTouch)
{
  // regular grid: many centroid-to-centroid segments pass exactly through
  // vertices; the faces touched only there are not on the path
  std::size_t checked = 0, with_vertex = 0;
  check_flat_paths(Planar_grid(9, 0.), 4., checked, with_vertex);
  std::printf("regular grid: %zu paths checked, %zu through a vertex (pseudo-source)\n", checked, with_vertex);
  EXPECT_GT(checked, 5000u);
}

TEST(GeodesicPaths, FoldedStripCrossesTheFoldWhereTheUnfoldedLineDoes)
{
  // [0, 2] x [0, 1] folded along x = 1 by 70 degrees: (x, y) -> (1 + (x-1) cos a, y, (x-1) sin a) for x > 1
  const int nu = 16, nv = 8;
  const double a = 70. * 3.14159265358979323846 / 180.;
  auto fold = [&](double x, double y) -> P3 {
    if(x <= 1.)
      return {x, y, 0.};
    return {1. + (x - 1.) * std::cos(a), y, (x - 1.) * std::sin(a)};
  };
  Soup_builder s;
  std::vector<std::array<double, 2>> layout;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double x0 = 2. * i / nu, x1 = 2. * (i + 1) / nu, y0 = double(j) / nv, y1 = double(j + 1) / nv;
      for(const auto& t : {std::array<std::array<double, 2>, 3>{{{x0, y0}, {x1, y0}, {x1, y1}}},
                           std::array<std::array<double, 2>, 3>{{{x0, y0}, {x1, y1}, {x0, y1}}}})
      {
        std::vector<std::size_t> tri;
        for(const auto& p : t)
        {
          const std::size_t id = s.add_point(fold(p[0], p[1]));
          if(id == layout.size())
            layout.push_back(p);
          tri.push_back(id);
        }
        s.triangles.push_back(tri);
      }
    }
  Flat f(flat_from_soup(s));
  const D::Csr nb = f.neighbors(5.);
  D::Geodesic_patch_solver solver(f.mesh, f.faces, 1);
  D::Geodesic_path path;
  std::size_t checked = 0;
  for(std::uint32_t i = 0; i < f.mesh.number_of_faces(); ++i)
  {
    ASSERT_TRUE(solver.set_source(i, nb.items.begin() + nb.begin(i), nb.items.begin() + nb.end(i)));
    auto unfolded_centroid = [&](std::uint32_t g) {
      std::array<double, 2> c = {0., 0.};
      for(std::uint32_t v : f.mesh.triangles[g])
        for(int k = 0; k < 2; ++k)
          c[k] += layout[v][k] / 3.;
      return c;
    };
    const auto ui = unfolded_centroid(i);
    for(std::uint32_t k = nb.begin(i); k < nb.end(i); ++k)
    {
      const std::uint32_t j = nb.items[k];
      const auto uj = unfolded_centroid(j);
      if((ui[0] - 1.) * (uj[0] - 1.) >= 0.)
        continue; // same side of the fold
      ASSERT_TRUE(solver.path_to(j, path)) << i << " -> " << j;
      EXPECT_EQ(path.faces, faces_crossed_by_segment(layout, f.mesh.triangles, ui, uj)) << i << " -> " << j;
      const double len = std::hypot(uj[0] - ui[0], uj[1] - ui[1]);
      EXPECT_NEAR(path.length(), len, 1e-12 * len);
      // the crossing point on the fold line (x = 1, z = 0 in 3D)
      const double y_fold = ui[1] + (1. - ui[0]) * (uj[1] - ui[1]) / (uj[0] - ui[0]);
      std::size_t on_fold = 0;
      for(const D::Vec3& p : path.points)
        if(std::abs(p[0] - 1.) < 1e-12 && std::abs(p[2]) < 1e-12)
        {
          ++on_fold;
          EXPECT_NEAR(p[1], y_fold, 1e-12) << i << " -> " << j;
        }
      EXPECT_EQ(on_fold, 1u) << i << " -> " << j << " y_fold " << y_fold << [&] {
        std::string t;
        for(const D::Vec3& p : path.points)
          t += " (" + std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]) + ")";
        return t + " vertex passages " + std::to_string(path.vertex_passages);
      }();
      // and it is not the 3D chord
      EXPECT_GT(path.length(), D::norm(f.faces.centroids[j] - f.faces.centroids[i]) * (1. + 1e-6));
      ++checked;
    }
  }
  std::printf("folded strip: %zu paths across the fold checked\n", checked);
  EXPECT_GT(checked, 1000u);
}

TEST(GeodesicPaths, ForestIsAPrefixTreeOfTheGeodesicPaths)
{
  Mesh mesh = denoising_support::graded_octahedron<Mesh>(10);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(4));
  Flat f(mesh);
  const D::Csr nb = f.neighbors(4.);
  D::Geodesic_path_statistics stats;
  const D::Path_forest forest = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, {}, &stats);
  expect_consistent_forest(forest, nb);
  EXPECT_EQ(stats.paths, nb.items.size());
  EXPECT_EQ(stats.fallbacks, 0u);
  EXPECT_EQ(stats.failed_patches, 0u);
  EXPECT_TRUE(forest.step.empty()); // unit steps by default
  // each weighted node's chain of faces is the geodesic to its face, on the
  // same patch (default rings) as the forest's
  D::Geodesic_patch_solver solver(f.mesh, f.faces, D::Geodesic_path_options().patch_rings);
  D::Geodesic_path path;
  std::size_t path_nodes = 0, longer_than_direct = 0;
  for(std::uint32_t i = 0; i < f.mesh.number_of_faces(); ++i)
  {
    ASSERT_TRUE(solver.set_source(i, nb.items.begin() + nb.begin(i), nb.items.begin() + nb.end(i)));
    for(std::uint32_t k = forest.offsets[i]; k < forest.offsets[i + 1]; ++k)
    {
      if(!forest.is_weighted(k))
        continue;
      ASSERT_TRUE(solver.path_to(forest.face[k], path));
      ASSERT_EQ(chain(forest, i, k), path.faces) << i << " -> " << forest.face[k];
      path_nodes += path.faces.size() - 1;
      longer_than_direct += path.faces.size() > 2;
    }
  }
  std::printf("noisy octahedron: %zu paths, %zu nodes for %zu path steps, %zu through a vertex\n", stats.paths,
              forest.face.size(), path_nodes, stats.vertex_passages);
  EXPECT_LT(forest.face.size(), path_nodes); // prefixes are shared
  EXPECT_GT(longer_than_direct, stats.paths / 2);
}

TEST(GeodesicPaths, PhaseTimingLeavesTheForestAsItIs)
{
  Mesh mesh = denoising_support::graded_octahedron<Mesh>(8);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(5));
  Flat f(mesh);
  const D::Csr nb = f.neighbors(4.);
  D::Geodesic_path_statistics plain, timed;
  const D::Path_forest a = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, {}, &plain);
  D::Geodesic_path_options o;
  o.time_phases = true;
  const D::Path_forest b = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, o, &timed);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.face, b.face);
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_EQ(a.weighted, b.weighted);
  EXPECT_EQ(plain.paths, timed.paths);
  EXPECT_EQ(plain.fallbacks, timed.fallbacks);
  // off: nothing timed; on: every phase ran (hundreds of patches and queries)
  EXPECT_EQ(plain.patch_seconds + plain.tree_seconds + plain.clear_seconds + plain.query_seconds, 0.);
  EXPECT_GT(timed.patch_seconds, 0.);
  EXPECT_GT(timed.tree_seconds, 0.);
  EXPECT_GT(timed.clear_seconds, 0.);
  EXPECT_GT(timed.query_seconds, 0.);
}

TEST(GeodesicPaths, StepLengthsSumToTheGeodesicLength)
{
  Planar_grid g(8, 0.25);
  Flat f(g.flat);
  // one neighbour per face: the face of farthest centroid within 4d, so each
  // tree is one path; the patch (i, j and rings around them) then needs 3
  // rings to hold the segment between them
  const D::Csr all = f.neighbors(4.);
  D::Csr one;
  one.offsets.push_back(0);
  for(std::size_t i = 0; i < all.size(); ++i)
  {
    std::uint32_t best = all.items[all.begin(i)];
    for(std::uint32_t k = all.begin(i); k < all.end(i); ++k)
      if(D::norm(f.faces.centroids[all.items[k]] - f.faces.centroids[i]) >
         D::norm(f.faces.centroids[best] - f.faces.centroids[i]))
        best = all.items[k];
    one.items.push_back(best);
    one.offsets.push_back(std::uint32_t(one.items.size()));
  }
  D::Geodesic_path_options o;
  o.step_length = true;
  o.length_unit = f.d;
  o.patch_rings = 3;
  D::Geodesic_path_statistics stats;
  const D::Path_forest forest = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, one, o, &stats);
  ASSERT_EQ(forest.step.size(), forest.face.size());
  EXPECT_EQ(stats.fallbacks, 0u);
  for(std::size_t i = 0; i < one.size(); ++i)
  {
    const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
    ASSERT_GE(e - b, 3u) << i; // the farthest neighbour is a few faces away
    double sum = 0.;
    for(std::uint32_t k = b; k < e; ++k)
    {
      EXPECT_GT(forest.step[k], 0.);
      sum += forest.step[k];
    }
    const double len = D::norm(f.faces.centroids[one.items[i]] - f.faces.centroids[i]) / f.d;
    EXPECT_NEAR(sum, len, 1e-12 * len) << i;
  }
}

TEST(GeodesicPaths, UnreachableNeighbourFallsBackToTheDirectPath)
{
  // two separate grids: face 0's neighbourhood (given by hand) holds faces of both
  Soup_builder s;
  s.add_subdivided_quad({0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, 2, 2, false);
  const std::uint32_t first_other = std::uint32_t(s.triangles.size());
  s.add_subdivided_quad({3., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, 2, 2, false);
  Flat f(flat_from_soup(s));
  const std::uint32_t nf = std::uint32_t(f.mesh.number_of_faces());
  D::Csr nb;
  nb.offsets.assign(nf + 1, std::uint32_t(nf - 1));
  nb.offsets[0] = 0;
  for(std::uint32_t j = 1; j < nf; ++j)
    nb.items.push_back(j);
  D::Geodesic_path_options o;
  o.step_length = true;
  D::Geodesic_path_statistics stats;
  const D::Path_forest forest = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, o, &stats);
  expect_consistent_forest(forest, nb);
  EXPECT_EQ(stats.fallbacks, nf - first_other);
  for(std::uint32_t k = forest.offsets[0]; k < forest.offsets[1]; ++k)
  {
    const std::uint32_t j = forest.face[k];
    if(j < first_other)
      continue;
    EXPECT_EQ(forest.parent[k], D::Path_forest::root) << j; // direct i -> j
    EXPECT_TRUE(forest.is_weighted(k));
    EXPECT_DOUBLE_EQ(forest.step[k], D::norm(f.faces.centroids[j] - f.faces.centroids[0]));
  }
}

TEST(GeodesicPaths, GeodesicsBendAroundTheReflexCornerOfAnLShapedPatch)
{
  // the L-shaped plane domain [0, 2]^2 minus (1, 2)^2, 4 x 4 cells per unit
  // square; every face is a neighbour of every other, so the patch is the
  // whole L. The shortest path between two centroids is the straight segment
  // if it stays in the L, else the two segments through the reflex corner
  // (1, 1): the border vertex there must stay a pseudo-source, while the
  // convex corners (angle pi / 2) are not (see Geodesic_patch_mesh).
  Soup_builder s;
  const int n = 4;
  for(const auto& o : {P3{0., 0., 0.}, P3{1., 0., 0.}, P3{0., 1., 0.}})
    s.add_subdivided_quad(o, {1., 0., 0.}, {0., 1., 0.}, n, n, false);
  Flat f(flat_from_soup(s));
  const std::uint32_t nf = std::uint32_t(f.mesh.number_of_faces());
  ASSERT_EQ(nf, 3u * 2 * n * n);
  std::vector<std::uint32_t> all(nf);
  for(std::uint32_t k = 0; k < nf; ++k)
    all[k] = k;
  D::Geodesic_patch_solver solver(f.mesh, f.faces, 0);
  D::Geodesic_path path;
  const D::Vec3 corner = {1., 1., 0.};
  std::size_t straight = 0, bent = 0;
  for(std::uint32_t i = 0; i < nf; ++i)
  {
    ASSERT_TRUE(solver.set_source(i, all.begin(), all.end()));
    for(std::uint32_t j = 0; j < nf; ++j)
    {
      if(j == i)
        continue;
      ASSERT_TRUE(solver.path_to(j, path)) << i << " -> " << j;
      const D::Vec3 a = f.faces.centroids[i], b = f.faces.centroids[j];
      // does the open segment a b meet the removed square (1, 2)^2? (clip it)
      double t0 = 0., t1 = 1.;
      for(int k = 0; k < 2; ++k)
      {
        const double d = b[k] - a[k];
        if(d == 0.)
        {
          if(!(a[k] > 1.))
            t1 = -1.;
        }
        else
        {
          const double t = (1. - a[k]) / d; // where the coordinate k is 1
          if(d > 0.)
            t0 = (std::max)(t0, t);
          else
            t1 = (std::min)(t1, t);
        }
      }
      const bool around = t1 - t0 > 1e-12;
      const double expected = around ? D::norm(corner - a) + D::norm(b - corner) : D::norm(b - a);
      ASSERT_NEAR(path.length(), expected, 1e-12 * expected) << i << " -> " << j << (around ? " around" : "");
      if(around)
      {
        EXPECT_GT(path.vertex_passages, 0u) << i << " -> " << j;
        ++bent;
      }
      else
        ++straight;
    }
  }
  std::printf("L-shaped patch: %zu straight geodesics, %zu around the reflex corner\n", straight, bent);
  EXPECT_GT(bent, 500u);
  EXPECT_GT(straight, 2000u);
}

// Faces of a flat mesh grouped into the components connected through edges
// (union-find over the shared edges).
std::vector<std::size_t> edge_components(const D::Flat_mesh& m, std::size_t& count)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<std::size_t> root(nf);
  for(std::size_t f = 0; f < nf; ++f)
    root[f] = f;
  auto find = [&](std::size_t x) {
    while(root[x] != x)
      x = root[x] = root[root[x]];
    return x;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first_face;
  for(std::size_t f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::uint32_t a = m.triangles[f][c], b = m.triangles[f][(c + 1) % 3];
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      const auto it = first_face.find(key);
      if(it == first_face.end())
        first_face.emplace(key, f);
      else
        root[find(f)] = find(it->second);
    }
  count = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    root[f] = find(f);
    count += root[f] == f;
  }
  return root;
}

TEST(GeodesicPaths, PrismWithNonMatchingCapSubdivisionFallsBackExactlyAcrossItsCracks)
{
  // hexagonal_prism(n_around, n_up, n_cap) splits each side of a cap's rim
  // into n_cap segments and the matching bottom or top edge of a side into
  // n_around: unless the two are equal, the caps and the sides share only
  // the vertices where both subdivisions meet (T-junctions between them), so
  // the mesh is three surfaces (two caps, one band of sides) touching at
  // vertices. Neighbourhoods grow through shared vertices, but no geodesic
  // on the surface goes from a cap to a side: exactly those neighbours get
  // the direct fallback. This is the 7.9% of fallback paths of the
  // benchmark's prism, hexagonal_prism(12, 40, 18).
  for(int n_cap : {8, 6})
  {
    Mesh mesh = denoising_support::hexagonal_prism<Mesh>(8, 12, n_cap);
    PMP::add_gaussian_noise(mesh, 0.1, CGAL::parameters::random_seed(1));
    Flat f(mesh);
    std::size_t ncomp = 0;
    const std::vector<std::size_t> comp = edge_components(f.mesh, ncomp);
    EXPECT_EQ(ncomp, n_cap == 8 ? 1u : 3u) << n_cap;
    const D::Csr nb = f.neighbors(4.);
    D::Geodesic_patch_solver solver(f.mesh, f.faces, D::Geodesic_path_options().patch_rings);
    D::Geodesic_path path;
    std::size_t across = 0;
    for(std::uint32_t i = 0; i < f.mesh.number_of_faces(); ++i)
    {
      ASSERT_TRUE(solver.set_source(i, nb.items.begin() + nb.begin(i), nb.items.begin() + nb.end(i)));
      for(std::uint32_t k = nb.begin(i); k < nb.end(i); ++k)
      {
        const std::uint32_t j = nb.items[k];
        const bool same = comp[i] == comp[j];
        across += !same;
        ASSERT_EQ(solver.path_to(j, path), same) << "n_cap " << n_cap << ": " << i << " -> " << j;
      }
    }
    D::Geodesic_path_statistics stats;
    D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, {}, &stats);
    EXPECT_EQ(stats.fallbacks, across) << n_cap;
    EXPECT_EQ(stats.failed_patches, 0u) << n_cap;
    if(n_cap == 8)
    {
      EXPECT_EQ(stats.fallbacks, 0u);
    }
    else
    {
      EXPECT_GT(across, nb.items.size() / 20); // the case is exercised
    }
    std::printf("prism (8, 12, %d): %zu edge-connected components, %zu of %zu paths direct\n", n_cap, ncomp,
                stats.fallbacks, stats.paths);
  }
}

TEST(GeodesicPaths, ZeroAreaFaceIsLeftOutOfThePatchesAndGetsDirectPaths)
{
  // a plane grid whose edge (a, b) is split by its midpoint m on one side,
  // closed by the zero-area face (a, b, m)
  Soup_builder s;
  const int n = 6;
  const P3 up = {0., 0., 1.};
  std::size_t cap = 0;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const P3 p00 = {double(i), double(j), 0.}, p10 = {i + 1., double(j), 0.}, p11 = {i + 1., j + 1., 0.},
               p01 = {double(i), j + 1., 0.};
      if(i == 2 && j == 2)
      {
        // diagonal (p00, p11) split by m on the side of the lower triangle
        const P3 m = {i + 0.5, j + 0.5, 0.};
        s.add_triangle(p00, p10, m, up);
        s.add_triangle(m, p10, p11, up);
        cap = s.triangles.size();
        s.triangles.push_back({s.add_point(p00), s.add_point(m), s.add_point(p11)}); // zero area
        s.add_triangle(p00, p11, p01, up);
      }
      else
      {
        s.add_triangle(p00, p10, p11, up);
        s.add_triangle(p00, p11, p01, up);
      }
    }
  Mesh mesh = s.to_mesh<Mesh>();
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  ASSERT_EQ(num_faces(mesh), s.triangles.size());
  Flat f(flat_from_soup(s));
  ASSERT_EQ(D::squared_norm(f.faces.normals[cap]), 0.);
  const D::Csr nb = f.neighbors(3.);
  D::Geodesic_path_statistics stats;
  const D::Path_forest forest = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, {}, &stats);
  expect_consistent_forest(forest, nb);
  std::size_t cap_as_neighbour = 0;
  for(std::uint32_t k = 0; k < nb.items.size(); ++k)
    cap_as_neighbour += nb.items[k] == cap;
  ASSERT_GT(cap_as_neighbour, 0u);
  EXPECT_EQ(stats.failed_patches, 1u); // the cap's own patch
  EXPECT_EQ(stats.fallbacks, cap_as_neighbour + (nb.end(cap) - nb.begin(cap)));
  // no path passes through the cap
  for(std::size_t i = 0; i < forest.number_of_faces(); ++i)
    for(std::uint32_t k = forest.offsets[i]; k < forest.offsets[i + 1]; ++k)
      if(forest.face[k] == cap)
      {
        EXPECT_EQ(forest.parent[k], D::Path_forest::root);
      }
  // and the denoiser gives finite, unit normals
  PMP::add_gaussian_noise(mesh, 0.2, CGAL::parameters::random_seed(2));
  auto normals = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:filtered").first;
  PMP::intrinsic_filter_face_normals(mesh, normals,
                                     CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC));
  for(auto fi : faces(mesh))
    if(std::size_t(fi) != cap)
    {
      EXPECT_NEAR(normals[fi].squared_length(), 1., 1e-12) << fi;
    }
  PMP::intrinsic_denoising(mesh, CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC));
  for(auto v : vertices(mesh))
    EXPECT_TRUE(std::isfinite(mesh.point(v).x() + mesh.point(v).y() + mesh.point(v).z()));
}

TEST(GeodesicDenoising, NoiseFreeCubeKeepsItsEdges)
{
  Mesh cube = denoising_support::cube<Mesh>(12);
  const Mesh reference = cube;
  PMP::intrinsic_denoising(cube, CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC));
  const double En = PMP::face_normal_error(cube, reference), Ev = PMP::vertex_position_error(cube, reference);
  std::printf("noise-free cube, geodesic paths: E_n %.3e deg, E_v %.3e\n", En, Ev);
  // a geodesic crossing an edge has a large d^s, so faces across the edge get
  // (almost) no weight; rounding an edge would give E_n of degrees
  EXPECT_LT(En, 1e-3);
  EXPECT_LT(Ev, 1e-5);
}

TEST(GeodesicDenoising, NoisyPrismIsDenoisedAndDiffersFromSquarePattern)
{
  Mesh reference = denoising_support::hexagonal_prism<Mesh>(8, 16, 8);
  Mesh noisy = reference;
  PMP::add_gaussian_noise(noisy, 0.1, CGAL::parameters::random_seed(1));
  Mesh geodesic = noisy, square = noisy;
  PMP::intrinsic_denoising(geodesic, CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC));
  PMP::intrinsic_denoising(square);
  const double En0 = PMP::face_normal_error(noisy, reference), Eng = PMP::face_normal_error(geodesic, reference),
               Ens = PMP::face_normal_error(square, reference);
  std::printf("noisy prism: E_n noisy %.3f, geodesic %.3f, square pattern %.3f deg\n", En0, Eng, Ens);
  EXPECT_LT(Eng, En0 / 3.);
  EXPECT_NE(Eng, Ens);
}

TEST(GeodesicDenoising, StepLengthOptionChangesTheFilter)
{
  Mesh mesh = denoising_support::graded_octahedron<Mesh>(8);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(6));
  auto a = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:a").first;
  auto b = mesh.add_property_map<Mesh::Face_index, K::Vector_3>("f:b").first;
  const auto np = CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC);
  PMP::intrinsic_filter_face_normals(mesh, a, np);
  PMP::intrinsic_filter_face_normals(mesh, b, np.use_step_length(true));
  double diff = 0.;
  for(auto f : faces(mesh))
    diff += std::sqrt((a[f] - b[f]).squared_length());
  EXPECT_GT(diff / num_faces(mesh), 1e-4);
}

TEST(GeodesicDenoising, SurfaceMeshAndPolyhedronAgree)
{
  Mesh sm = denoising_support::hexagonal_prism<Mesh>(8, 12, 6);
  Polyhedron poly = denoising_support::hexagonal_prism<Polyhedron>(8, 12, 6);
  PMP::add_gaussian_noise(sm, 0.2, CGAL::parameters::random_seed(3));
  PMP::add_gaussian_noise(poly, 0.2, CGAL::parameters::random_seed(3));
  const auto np = CGAL::parameters::path_strategy(PMP::Intrinsic_path_strategy::GEODESIC).number_of_iterations(5);
  // the same forests
  const D::Mesh_maps<Mesh, decltype(np)> msm(sm, np);
  const D::Mesh_maps<Polyhedron, decltype(np)> mpoly(poly, np);
  const D::Intrinsic_setup ssm =
      D::make_intrinsic_setup<CGAL::Sequential_tag>(sm, D::read_filter_options(np), msm, "test");
  const D::Intrinsic_setup spoly =
      D::make_intrinsic_setup<CGAL::Sequential_tag>(poly, D::read_filter_options(np), mpoly, "test");
  EXPECT_EQ(ssm.paths.offsets, spoly.paths.offsets);
  EXPECT_EQ(ssm.paths.face, spoly.paths.face);
  EXPECT_EQ(ssm.paths.parent, spoly.paths.parent);
  EXPECT_EQ(ssm.paths.weighted, spoly.paths.weighted);
  // the same result
  PMP::intrinsic_denoising(sm, np);
  PMP::intrinsic_denoising(poly, np);
  std::vector<K::Point_3> a, b;
  for(auto v : vertices(sm))
    a.push_back(sm.point(v));
  for(auto v : vertices(poly))
    b.push_back(v->point());
  ASSERT_EQ(a.size(), b.size());
  double d = 0.;
  for(std::size_t k = 0; k < a.size(); ++k)
    d = (std::max)(d, std::sqrt(CGAL::squared_distance(a[k], b[k])));
  EXPECT_LE(d, 1e-12);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(GeodesicPaths, ParallelEqualsSequential)
{
  Mesh mesh = denoising_support::graded_octahedron<Mesh>(12);
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(8));
  Flat f(mesh);
  const D::Csr nb = f.neighbors(4.);
  D::Geodesic_path_options o;
  o.step_length = true;
  const D::Path_forest a = D::geodesic_paths<CGAL::Sequential_tag>(f.mesh, f.faces, nb, o);
  const D::Path_forest b = D::geodesic_paths<CGAL::Parallel_tag>(f.mesh, f.faces, nb, o);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.face, b.face);
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_EQ(a.weighted, b.weighted);
  EXPECT_EQ(a.step, b.step);
}
#endif
