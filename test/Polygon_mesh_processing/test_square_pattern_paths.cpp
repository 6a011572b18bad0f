// Tests of section 4: regions by areal coordinates, order, square-pattern parents.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include "flat_setup.h"
#include <denoising_support/synthetic_meshes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

TEST(SquarePattern, ParentRanksFollowThePaper)
{
  // node 1 hangs from face i (rank 0); 2..4 from 1; 5..9 from 4; 10..16 from 9
  EXPECT_EQ(D::square_pattern_parent_rank(1), 0u);
  for(unsigned k : {2u, 3u, 4u})
    EXPECT_EQ(D::square_pattern_parent_rank(k), 1u) << k;
  for(unsigned k = 5; k <= 9; ++k)
    EXPECT_EQ(D::square_pattern_parent_rank(k), 4u) << k;
  for(unsigned k = 10; k <= 16; ++k)
    EXPECT_EQ(D::square_pattern_parent_rank(k), 9u) << k;
  EXPECT_EQ(D::square_pattern_parent_rank(17), 16u);
  // the paper's examples: 8 -> 4 -> 1 -> i and 16 -> 9 -> 4 -> 1 -> i
  EXPECT_EQ(D::square_pattern_parent_rank(8), 4u);
  EXPECT_EQ(D::square_pattern_parent_rank(16), 9u);
  EXPECT_EQ(D::square_pattern_parent_rank(9), 4u);
}

TEST(SquarePattern, SixRegionsBySignsOfArealCoordinates)
{
  EXPECT_EQ(D::areal_region(0.2, 0.3, 0.5), -1); // inside
  EXPECT_EQ(D::areal_region(0., 0.5, 0.5), -1);  // on an edge counts as inside
  std::set<int> seen;
  for(auto l : {std::array<double, 3>{-1, 1, 1}, {-1, -1, 3}, {1, -1, 1}, {3, -1, -1}, {1, 1, -1}, {-1, 3, -1}})
  {
    const int r = D::areal_region(l[0], l[1], l[2]);
    EXPECT_GE(r, 0);
    EXPECT_LT(r, 6);
    seen.insert(r);
  }
  EXPECT_EQ(seen.size(), 6u);
}

TEST(SquarePattern, EachSignPatternHasItsRegion)
{
  // the regions run around the triangle in order: beyond the edge opposite
  // vertex 0, beyond vertex 2, beyond the edge opposite vertex 1, beyond
  // vertex 0, beyond the edge opposite vertex 2, beyond vertex 1 (the trees
  // list their nodes region after region in this order)
  EXPECT_EQ(D::areal_region(-1, 1, 1), 0);  // (-,+,+)
  EXPECT_EQ(D::areal_region(-1, -1, 3), 1); // (-,-,+)
  EXPECT_EQ(D::areal_region(1, -1, 1), 2);  // (+,-,+)
  EXPECT_EQ(D::areal_region(3, -1, -1), 3); // (+,-,-)
  EXPECT_EQ(D::areal_region(1, 1, -1), 4);  // (+,+,-)
  EXPECT_EQ(D::areal_region(-1, 3, -1), 5); // (-,+,-)
}

// Face 0 is the triangle (0,0,0), (1,0,0), (0,1,0); faces 1.. are tiny
// triangles around chosen centroids (the neighbourhood is given by hand).
struct Hand_built
{
  D::Flat_mesh mesh;
  D::Face_data faces;
  D::Csr neighbors;

  explicit Hand_built(const std::vector<D::Vec3>& centroids)
  {
    mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles.push_back({0, 1, 2});
    for(const D::Vec3& c : centroids)
    {
      const std::uint32_t b = std::uint32_t(mesh.points.size());
      const double e = 1e-3;
      mesh.points.push_back({c[0] - e, c[1] - e, c[2]});
      mesh.points.push_back({c[0] + 2 * e, c[1] - e, c[2]});
      mesh.points.push_back({c[0] - e, c[1] + 2 * e, c[2]});
      mesh.triangles.push_back({b, b + 1, b + 2});
    }
    D::compute_face_data<CGAL::Sequential_tag>(mesh, mesh.points, faces);
    neighbors.offsets.assign(mesh.number_of_faces() + 1, std::uint32_t(centroids.size()));
    neighbors.offsets[0] = 0;
    for(std::uint32_t j = 1; j <= centroids.size(); ++j)
      neighbors.items.push_back(j);
  }
};

TEST(SquarePattern, HandBuiltNeighbourhoodGivesRegionsOrderAndParents)
{
  // Region beyond the edge opposite vertex 0 (x + y > 1, x > 0, y > 0): six
  // neighbours given out of order, at distances growing with their index in
  // `order`. One neighbour lies inside face 0 (dropped), one above the plane
  // (its projection falls in the same region) and one in another region.
  const std::vector<D::Vec3> centroids = {
      {0.9, 0.9, 0.},     // 1: region A, 3rd closest
      {0.6, 0.6, 0.},     // 2: region A, closest
      {0.2, 0.2, 0.},     // 3: inside face 0 -> dropped
      {1.2, 1.2, 0.},     // 4: region A, 5th
      {0.75, 0.75, 0.05}, // 5: region A after projection, 2nd
      {1.05, 1.05, 0.},   // 6: region A, 4th
      {1.4, 1.4, 0.},     // 7: region A, 6th
      {-0.5, -0.5, 0.}    // 8: beyond vertex 0 (another region)
  };
  Hand_built h(centroids);
  const D::Path_forest forest = D::square_pattern_paths(h.mesh, h.faces, h.neighbors);
  const std::vector<std::int32_t> parent = D::all_parents(forest);
  const std::uint32_t b = forest.offsets[0], e = forest.offsets[1];
  ASSERT_EQ(e - b, 7u); // 8 neighbours, one dropped
  // locate region A's run: the nodes whose face is one of {2,5,1,6,4,7}
  std::vector<std::uint32_t> faces(forest.face.begin() + b, forest.face.begin() + e);
  EXPECT_EQ(std::count(faces.begin(), faces.end(), 3u), 0); // the inside face is gone
  auto pos = std::find(faces.begin(), faces.end(), 2u) - faces.begin();
  ASSERT_LE(pos + 6, std::ptrdiff_t(faces.size()));
  const std::vector<std::uint32_t> expected_order = {2, 5, 1, 6, 4, 7};
  for(int k = 0; k < 6; ++k)
    EXPECT_EQ(faces[pos + k], expected_order[k]) << "rank " << k + 1;
  // parents in the region: 1 -> i, 2,3,4 -> 1, 5,6 -> 4
  const std::vector<int> expected_parent_rank = {0, 1, 1, 1, 4, 4};
  for(int k = 0; k < 6; ++k)
  {
    const std::int32_t p = parent[b + pos + k];
    if(expected_parent_rank[k] == 0)
      EXPECT_EQ(p, D::Path_forest::root) << "rank " << k + 1;
    else
      EXPECT_EQ(p, std::int32_t(pos + expected_parent_rank[k] - 1)) << "rank " << k + 1;
  }
  // the lone neighbour of the other region hangs from face 0
  auto other = std::find(faces.begin(), faces.end(), 8u) - faces.begin();
  ASSERT_LT(other, std::ptrdiff_t(faces.size()));
  EXPECT_EQ(parent[b + other], D::Path_forest::root);
}

// Every face's tree is its kept neighbours region after region (regions 0
// to 5), each region sorted by distance to c_i with ties broken by the input
// index: checked against trees built here with one std::sort per region, on
// noisy fandisk at r = 4d (regions of about 10 nodes, sorted by counting)
// and r = 14d (regions past square_pattern_counting_max nodes, sorted by
// comparisons), and at both radii on a noise-free cube, whose grid has many
// equal distances.
struct Region_counts
{
  std::size_t largest = 0; // nodes of the largest region
  std::size_t ties = 0;    // neighbours at the same distance as the next one in their region
};

static void expect_sorted_regions(const Mesh& mesh, double radius_in_d, Region_counts& counts)
{
  const Flat_setup<> setup(mesh);
  const D::Flat_mesh& m = setup.m;
  const D::Face_data& fd = setup.fd;
  const D::Csr nb = D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, setup.r / 4. * radius_in_d);
  const D::Path_forest forest = D::square_pattern_paths(m, fd, nb, 0); // keeps the region sizes
  ASSERT_EQ(forest.square_regions.size(), m.number_of_faces());
  for(std::size_t i = 0; i < m.number_of_faces(); ++i)
  {
    std::array<std::vector<std::pair<double, std::uint32_t>>, 6> regions;
    const D::Square_pattern_frame frame(m, fd, i);
    for(std::uint32_t k = nb.begin(i); k < nb.end(i); ++k)
    {
      const std::uint32_t j = nb.items[k];
      const int r = frame.region(fd.centroids[j]);
      if(r >= 0)
        regions[r].emplace_back(D::squared_norm(fd.centroids[j] - fd.centroids[i]), j); // input order
    }
    std::vector<std::uint32_t> expected;
    for(int r = 0; r < 6; ++r)
    {
      std::sort(regions[r].begin(), regions[r].end());
      for(std::size_t k = 0; k + 1 < regions[r].size(); ++k)
        counts.ties += regions[r][k].first == regions[r][k + 1].first ? 1 : 0;
      for(const auto& node : regions[r])
        expected.push_back(node.second);
      ASSERT_EQ(forest.square_regions[i][r], regions[r].size()) << "face " << i << " region " << r;
      counts.largest = (std::max)(counts.largest, regions[r].size());
    }
    ASSERT_EQ(std::vector<std::uint32_t>(forest.face.begin() + forest.offsets[i],
                                         forest.face.begin() + forest.offsets[i + 1]),
              expected)
        << "face " << i;
  }
}

TEST(SquarePattern, TreesAreRegionsSortedByDistanceThenInputIndex)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  CGAL::Polygon_mesh_processing::add_gaussian_noise(fandisk, 0.3, CGAL::parameters::random_seed(5));
  Region_counts near, far, cube_near, cube_far;
  expect_sorted_regions(fandisk, 4., near);
  EXPECT_LE(near.largest, D::square_pattern_counting_max); // sorted by counting only
  expect_sorted_regions(fandisk, 14., far);
  EXPECT_GT(far.largest, D::square_pattern_counting_max); // the comparison sort ran too
  // the tie-break, in both sorts
  const Mesh cube = denoising_support::cube<Mesh>(12);
  expect_sorted_regions(cube, 4., cube_near);
  EXPECT_LE(cube_near.largest, D::square_pattern_counting_max);
  EXPECT_GT(cube_near.ties, 0u);
  expect_sorted_regions(cube, 14., cube_far);
  EXPECT_GT(cube_far.largest, D::square_pattern_counting_max);
  EXPECT_GT(cube_far.ties, 0u);
}

TEST(SquarePattern, DegenerateFaceFallsBackToDirectPaths)
{
  Hand_built h({{0.6, 0.6, 0.}, {0.9, 0.9, 0.}, {1.2, 1.2, 0.}});
  h.mesh.points[2] = {2., 0., 0.}; // face 0 becomes a zero-area (collinear) triangle
  D::compute_face_data<CGAL::Sequential_tag>(h.mesh, h.mesh.points, h.faces);
  ASSERT_EQ(D::squared_norm(h.faces.normals[0]), 0.);
  // tilt two neighbours so that their weights matter in the passes below
  h.mesh.points[3 * 1 + 2][2] += 1e-3;
  h.mesh.points[3 * 3 + 1][2] -= 2e-3;
  D::compute_face_data<CGAL::Sequential_tag>(h.mesh, h.mesh.points, h.faces);
  std::vector<std::vector<D::Vec3>> passes;
  for(const std::size_t compact_min_nodes : {std::size_t(0), D::square_pattern_compact_min_nodes})
  {
    const D::Path_forest forest = D::square_pattern_paths(h.mesh, h.faces, h.neighbors, compact_min_nodes);
    EXPECT_EQ(forest.square_regions.empty(), compact_min_nodes != 0);
    const std::vector<std::int32_t> parent = D::all_parents(forest);
    ASSERT_EQ(forest.offsets[1] - forest.offsets[0], 3u);
    for(std::uint32_t k = forest.offsets[0]; k < forest.offsets[1]; ++k)
      EXPECT_EQ(parent[k], D::Path_forest::root);
    D::Intrinsic_kernel kernel;
    kernel.sigma_range = 0.001;
    passes.emplace_back();
    D::intrinsic_filter_pass<CGAL::Sequential_tag>(forest, h.faces.normals, h.faces.areas, kernel, passes.back());
    passes.emplace_back();
    D::intrinsic_filter_pass_generic<CGAL::Sequential_tag>(forest, h.faces.normals, h.faces.areas, kernel,
                                                           passes.back());
  }
  // the same normals from every form and kernel (the AVX2 kernel on region
  // sizes takes this face's parents one per node)
  ASSERT_EQ(passes.size(), 4u);
  for(std::size_t p = 1; p < passes.size(); ++p)
    EXPECT_EQ(passes[p], passes[0]) << "pass " << p;
}

TEST(SquarePattern, FandiskForestIsWellFormed)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), mesh));
  auto vim = get(CGAL::vertex_index, mesh);
  auto fim = get(CGAL::face_index, mesh);
  const D::Flat_mesh m = D::make_flat_mesh(mesh, get(CGAL::vertex_point, mesh), vim, fim, "test");
  D::Face_data fd;
  D::compute_face_data<CGAL::Sequential_tag>(m, m.points, fd);
  const double d = D::mean_adjacent_centroid_distance(m, fd);
  EXPECT_GT(d, 0.);
  const D::Csr nb = D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, 4 * d);
  const D::Path_forest forest = D::square_pattern_paths(m, fd, nb);
  const std::vector<std::int32_t> parent = D::all_parents(forest);
  std::size_t dropped = 0, total = 0;
  for(std::size_t i = 0; i < m.number_of_faces(); ++i)
  {
    const std::uint32_t b = forest.offsets[i], e = forest.offsets[i + 1];
    total += nb.end(i) - nb.begin(i);
    dropped += (nb.end(i) - nb.begin(i)) - (e - b);
    for(std::uint32_t k = b; k < e; ++k)
    {
      ASSERT_NE(forest.face[k], i);
      ASSERT_LT(parent[k], std::int32_t(k - b)); // parents come first
      // every node is a neighbour within the radius
      ASSERT_LE(D::norm(fd.centroids[forest.face[k]] - fd.centroids[i]), 4 * d * (1 + 1e-12));
    }
  }
  // dropped neighbours (inside face i): well under one dropped neighbour per face; about 60 neighbours at 4d
  EXPECT_LT(double(dropped) / m.number_of_faces(), 1.);
  EXPECT_GT(double(total) / m.number_of_faces(), 30.);
  EXPECT_LT(double(total) / m.number_of_faces(), 120.);
}

// The renumbering of faces along the Morton curve (reorder_faces_for_locality)
// and the face-by-face construction (square_pattern_paths_within) give, face
// for face, the same trees (same nodes in the same order, same parents) and
// bitwise the same filtered normals as the plain construction in input
// order; checked on noisy fandisk and on a noise-free cube, whose regular
// grid has many ties in distance.
template <typename Tag>
static void expect_renumbering_changes_nothing(const Mesh& mesh)
{
  const Flat_setup<Tag> setup(mesh);
  const D::Flat_mesh& m = setup.m;
  const D::Face_data& fd = setup.fd;
  const double r = setup.r;
  const D::Path_forest plain = D::square_pattern_paths<Tag>(m, fd, D::geometric_neighborhoods<Tag>(m, fd.centroids, r));

  D::Flat_mesh rm = m;
  D::Face_data rfd = fd;
  D::reorder_faces_for_locality<Tag>(rm, rfd);
  ASSERT_EQ(rm.input_face.size(), m.number_of_faces());
  std::size_t moved = 0;
  for(std::size_t f = 0; f < rm.number_of_faces(); ++f)
    moved += rm.input_face[f] != f ? 1 : 0;
  EXPECT_GT(moved, 0u); // the test would prove nothing with the identity
  const D::Path_forest renumbered = D::square_pattern_paths_within<Tag>(rm, rfd, r);

  ASSERT_EQ(renumbered.face.size(), plain.face.size());
  const std::vector<std::int32_t> renumbered_parent = D::all_parents(renumbered), plain_parent = D::all_parents(plain);
  for(std::size_t f = 0; f < rm.number_of_faces(); ++f)
  {
    const std::uint32_t g = rm.input_face[f];
    ASSERT_EQ(renumbered.offsets[f + 1] - renumbered.offsets[f], plain.offsets[g + 1] - plain.offsets[g]) << f;
    for(std::uint32_t k = 0; k < plain.offsets[g + 1] - plain.offsets[g]; ++k)
    {
      EXPECT_EQ(rm.input_face[renumbered.face[renumbered.offsets[f] + k]], plain.face[plain.offsets[g] + k]);
      EXPECT_EQ(renumbered_parent[renumbered.offsets[f] + k], plain_parent[plain.offsets[g] + k]);
    }
  }
  D::Intrinsic_kernel kernel;
  std::vector<D::Vec3> a, b;
  D::intrinsic_filter_pass<Tag>(plain, fd.normals, fd.areas, kernel, a);
  D::intrinsic_filter_pass<Tag>(renumbered, rfd.normals, rfd.areas, kernel, b);
  const std::vector<D::Vec3> b_in_input_order = rm.in_input_order(b);
  std::size_t different = 0;
  for(std::size_t f = 0; f < a.size(); ++f)
    different += a[f] != b_in_input_order[f] ? 1 : 0;
  EXPECT_EQ(different, 0u);
}

TEST(SquarePattern, RenumberedFacesGiveTheSameTreesAndNormals)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  CGAL::Polygon_mesh_processing::add_gaussian_noise(fandisk, 0.3, CGAL::parameters::random_seed(3));
  expect_renumbering_changes_nothing<CGAL::Sequential_tag>(fandisk);
  expect_renumbering_changes_nothing<CGAL::Sequential_tag>(denoising_support::cube<Mesh>(12));
#ifdef CGAL_LINKED_WITH_TBB
  expect_renumbering_changes_nothing<CGAL::Parallel_tag>(fandisk);
#endif
}

// Path_forest::parents() on square-pattern region sizes gives the parents
// of square_pattern_parent_rank(), region after region, for regions shorter
// than, as long as and longer than the values it writes for every region
// (Square_pattern_parent_table::width) and than its table; six zero sizes
// hang every node from the root (degenerate face).
TEST(SquarePattern, ParentsFromRegionSizes)
{
  const std::uint32_t w = D::Square_pattern_parent_table::width, t = D::Square_pattern_parent_table::size;
  const std::vector<std::array<std::uint32_t, 6>> cases = {{3, 0, 7, 1, 0, 12},
                                                           {0, 0, 0, 0, 0, 0},
                                                           {w - 1, w, w + 1, 1, 0, 2},
                                                           {t + 5, 2, 0, 0, 0, w + 3},
                                                           {0, 0, 0, 0, 0, 5}};
  D::Path_forest forest;
  forest.offsets = {0};
  for(const auto& sizes : cases)
  {
    std::uint32_t count = 0;
    for(std::uint32_t s : sizes)
      count += s;
    if(count == 0)
      count = 9; // six zero sizes with nodes: a degenerate face
    forest.offsets.push_back(forest.offsets.back() + count);
    forest.square_regions.push_back(sizes);
  }
  forest.face.assign(forest.offsets.back(), 0u);
  const std::vector<std::int32_t> parent = D::all_parents(forest);
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    std::vector<std::int32_t> expected;
    std::int32_t start = 0;
    for(std::uint32_t size : cases[i])
    {
      for(std::uint32_t k = 1; k <= size; ++k)
      {
        const std::uint32_t pk = D::square_pattern_parent_rank(k);
        expected.push_back(pk == 0 ? D::Path_forest::root : start + std::int32_t(pk) - 1);
      }
      start += std::int32_t(size);
    }
    if(expected.empty())
      expected.assign(forest.offsets[i + 1] - forest.offsets[i], D::Path_forest::root);
    const std::vector<std::int32_t> got(parent.begin() + forest.offsets[i], parent.begin() + forest.offsets[i + 1]);
    EXPECT_EQ(got, expected) << "case " << i;
  }
}

// The forest with its parents kept as region sizes (compact: the default
// where the AVX2 kernel runs, else for large forests; forced here) and the one with a parent per node are the same
// trees, and every filter pass (dispatched, generic, SSE2, AVX2) gives
// bitwise the same normals on both; the sequential and parallel builds agree.
TEST(SquarePattern, CompactForestGivesTheSameTreesAndPasses)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  CGAL::Polygon_mesh_processing::add_gaussian_noise(fandisk, 0.3, CGAL::parameters::random_seed(7));
  const Flat_setup<> setup(fandisk);
  const D::Flat_mesh& m = setup.m;
  const D::Face_data& fd = setup.fd;
  const double r = setup.r;
  const D::Path_forest stored =
      D::square_pattern_paths_within<CGAL::Sequential_tag>(m, fd, r, D::square_pattern_compact_min_nodes);
  const D::Path_forest compact = D::square_pattern_paths_within<CGAL::Sequential_tag>(m, fd, r, 0);
  // the setup's choice keeps the region sizes exactly where the AVX2 kernel
  // runs; the paths' own default stores parents below the memory threshold
  EXPECT_EQ(
      D::square_pattern_paths_within<CGAL::Sequential_tag>(m, fd, r, D::square_pattern_compact_min_nodes_for_filter())
          .square_regions.empty(),
      !D::filter_pass_prefers_square_regions());
  EXPECT_TRUE(D::square_pattern_paths_within<CGAL::Sequential_tag>(m, fd, r).square_regions.empty());
  ASSERT_TRUE(stored.square_regions.empty());
  ASSERT_EQ(compact.square_regions.size(), m.number_of_faces());
  EXPECT_TRUE(compact.parent.empty());
  EXPECT_EQ(compact.offsets, stored.offsets);
  EXPECT_EQ(compact.face, stored.face);
  EXPECT_EQ(D::all_parents(compact), stored.parent);
  EXPECT_GT(stored.face.size(), 30u * m.number_of_faces());
#ifdef CGAL_LINKED_WITH_TBB
  const D::Path_forest parallel = D::square_pattern_paths_within<CGAL::Parallel_tag>(m, fd, r, 0);
  EXPECT_EQ(parallel.face, stored.face);
  EXPECT_EQ(D::all_parents(parallel), stored.parent);
#endif
  D::Intrinsic_kernel kernel;
  kernel.sigma_range = 0.3;
  std::vector<std::pair<std::string, std::array<std::vector<D::Vec3>, 2>>> passes;
  const D::Path_forest* forests[2] = {&stored, &compact};
  for(int f = 0; f < 2; ++f)
  {
    const D::Path_forest& forest = *forests[f];
    passes.resize(4);
    passes[0].first = "dispatched";
    D::intrinsic_filter_pass<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, passes[0].second[f]);
    passes[1].first = "generic";
    D::intrinsic_filter_pass_generic<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, passes[1].second[f]);
#ifdef CGAL_PMP_DENOISING_SSE2
    passes[2].first = "SSE2";
    passes[2].second[f].resize(forest.number_of_faces());
    D::intrinsic_filter_pass_l1_sse2<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, passes[2].second[f]);
#endif
#ifdef CGAL_PMP_DENOISING_AVX2
    if(D::cpu_has_avx2())
    {
      passes[3].first = "AVX2";
      passes[3].second[f].resize(forest.number_of_faces());
      D::intrinsic_filter_pass_l1_avx2<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, passes[3].second[f]);
    }
#endif
  }
  for(const auto& p : passes)
  {
    EXPECT_EQ(p.second[0].size(), p.second[1].size()) << p.first;
    std::size_t different = 0;
    for(std::size_t i = 0; i < p.second[0].size() && i < p.second[1].size(); ++i)
      different += p.second[0][i] != p.second[1][i] ? 1 : 0;
    EXPECT_EQ(different, 0u) << p.first;
  }
  EXPECT_EQ(passes[0].second[0].size(), m.number_of_faces());
  // step lengths (eq. 4) follow the same parents
  D::Path_forest stored_steps = stored, compact_steps = compact;
  D::set_step_lengths(stored_steps, fd.centroids, 1.);
  D::set_step_lengths(compact_steps, fd.centroids, 1.);
  EXPECT_EQ(stored_steps.step, compact_steps.step);
}

// Renumbering the vertices after the faces: a permutation (not the identity
// on fandisk), every face keeps its corners (as input vertices) and every
// vertex its incident faces, and values go back to input order.
TEST(SquarePattern, RenumberedVerticesKeepTheMesh)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  Flat_setup<> setup(fandisk);
  D::Flat_mesh& m = setup.m;
  D::reorder_faces_for_locality<CGAL::Sequential_tag>(m, setup.fd);
  D::Flat_mesh r = m;
  D::reorder_vertices_for_locality(r);
  const std::size_t nv = m.number_of_vertices();
  ASSERT_EQ(r.input_vertex.size(), nv);
  std::vector<std::uint32_t> sorted = r.input_vertex;
  std::sort(sorted.begin(), sorted.end());
  std::size_t moved = 0;
  for(std::size_t v = 0; v < nv; ++v)
  {
    ASSERT_EQ(sorted[v], v);
    moved += r.input_vertex[v] != v ? 1 : 0;
    EXPECT_EQ(r.points[v], m.points[r.input_vertex[v]]);
    const std::uint32_t iv = r.input_vertex[v];
    ASSERT_EQ(r.vertex_face_offsets[v + 1] - r.vertex_face_offsets[v],
              m.vertex_face_offsets[iv + 1] - m.vertex_face_offsets[iv]);
    for(std::uint32_t k = 0; k < r.vertex_face_offsets[v + 1] - r.vertex_face_offsets[v]; ++k)
      EXPECT_EQ(r.vertex_faces[r.vertex_face_offsets[v] + k], m.vertex_faces[m.vertex_face_offsets[iv] + k]);
  }
  EXPECT_GT(moved, nv / 2);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      EXPECT_EQ(r.input_vertex[r.triangles[f][k]], m.triangles[f][k]);
  EXPECT_EQ(r.vertex_values_in_input_order(r.points), m.points);
}

// A geometric neighbourhood holds at most max_neighbors_within() faces: on
// fandisk none comes near the cap, so the paper's neighbourhoods are
// unchanged. A plane grid joined with a copy of itself at a thousandth of
// the scale: the radius (4d, d from both) takes in the whole copy around
// each of its faces, and there the search halves the squared radius until
// the neighbourhood fits: a subset of the full one, at most the cap. The
// faces of the large part keep their neighbourhoods, and the square-pattern
// forest searched face by face follows the capped neighbourhoods.
TEST(SquarePattern, NeighbourhoodsAreCappedWhereFacesAreFarSmallerThanAverage)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  const Flat_setup<> single(fandisk);
  const std::size_t single_cap = D::max_neighbors_within(single.r, single.fd);
  const D::Csr single_nb = D::geometric_neighborhoods<CGAL::Sequential_tag>(single.m, single.fd.centroids, single.r);
  std::size_t largest = 0;
  for(std::size_t f = 0; f < single_nb.size(); ++f)
    largest = std::max<std::size_t>(largest, single_nb.end(f) - single_nb.begin(f));
  EXPECT_LT(8 * largest, single_cap); // far from the cap

  const Mesh grid = denoising_support::plane_grid<Mesh>(50);
  const Mesh both = denoising_support::with_scaled_copy(grid, 0.001, 5.);
  ASSERT_EQ(num_faces(both), 2 * num_faces(grid));
  const Flat_setup<> setup(both);
  const std::size_t nf = num_faces(grid);
  const std::size_t cap = D::max_neighbors_within(setup.r, setup.fd);
  EXPECT_GE(cap, 256u);
  EXPECT_LT(cap, nf / 4);
  const D::Csr full = D::geometric_neighborhoods<CGAL::Parallel_if_available_tag>(setup.m, setup.fd.centroids, setup.r);
  const D::Csr capped =
      D::geometric_neighborhoods<CGAL::Parallel_if_available_tag>(setup.m, setup.fd.centroids, setup.r, cap);
  std::size_t capped_faces = 0;
  for(std::size_t f = 0; f < 2 * nf; ++f)
  {
    const std::vector<std::uint32_t> a(full.items.begin() + full.begin(f), full.items.begin() + full.end(f));
    const std::vector<std::uint32_t> b(capped.items.begin() + capped.begin(f), capped.items.begin() + capped.end(f));
    ASSERT_LE(b.size(), cap) << f;
    if(a.size() <= cap)
    {
      ASSERT_EQ(a, b) << f;
      continue;
    }
    ASSERT_GE(f, nf); // only the small copy's faces
    ++capped_faces;
    EXPECT_GT(b.size(), 0u);
    const std::set<std::uint32_t> in_full(a.begin(), a.end());
    for(std::uint32_t g : b)
      ASSERT_TRUE(in_full.count(g) == 1) << f;
  }
  EXPECT_GT(capped_faces, nf / 2);

  const D::Path_forest within = D::square_pattern_paths_within<CGAL::Sequential_tag>(setup.m, setup.fd, setup.r);
  const D::Path_forest from_capped = D::square_pattern_paths<CGAL::Sequential_tag>(setup.m, setup.fd, capped);
  ASSERT_EQ(within.face, from_capped.face);
  ASSERT_EQ(within.offsets, from_capped.offsets);
}

// Neighbourhoods on a tessellation with fans: a cylinder whose caps are
// fans of 240 slivers around one vertex each (fan_cylinder()). The faces'
// lists of geometric_neighborhoods() come from Face_fan_search, which tests
// the faces around each vertex once per search; they must be those of the
// plain search that tests every face sharing a vertex with each face
// reached (Face_vertex_adjacency), in the same order, at several radii, with
// and without the cap on their size, in the input order and along the
// Morton curve, and the square-pattern forest searched face by face must
// follow them. Fandisk is checked too.
static void expect_same_lists(const D::Csr& a, const D::Csr& b)
{
  ASSERT_EQ(a.offsets, b.offsets);
  ASSERT_EQ(a.items, b.items);
}

static void expect_fan_search_is_the_plain_search(const D::Flat_mesh& m, const D::Face_data& fd, double r)
{
  for(double scale : {0.5, 1., 3.})
  {
    const double radius = scale * r;
    const D::Csr plain =
        D::geometric_neighborhoods<CGAL::Sequential_tag>(fd.centroids, D::Face_vertex_adjacency{m}, radius);
    expect_same_lists(D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, radius), plain);
    expect_same_lists(D::geometric_neighborhoods<CGAL::Parallel_if_available_tag>(m, fd.centroids, radius), plain);
    const std::size_t cap = 300;
    expect_same_lists(
        D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, radius, cap),
        D::geometric_neighborhoods<CGAL::Sequential_tag>(fd.centroids, D::Face_vertex_adjacency{m}, radius, cap));
    const D::Path_forest within = D::square_pattern_paths_within<CGAL::Sequential_tag>(m, fd, radius);
    const D::Path_forest from_lists = D::square_pattern_paths<CGAL::Sequential_tag>(
        m, fd,
        D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, radius, D::max_neighbors_within(radius, fd)));
    ASSERT_EQ(within.face, from_lists.face);
    ASSERT_EQ(within.offsets, from_lists.offsets);
  }
}

TEST(SquarePattern, FanSearchGivesTheListsOfThePlainSearch)
{
  const Mesh cylinder = denoising_support::fan_cylinder<Mesh>(240);
  ASSERT_EQ(num_faces(cylinder), 960u);
  Mesh noisy = cylinder;
  CGAL::Polygon_mesh_processing::add_gaussian_noise(noisy, 0.2, CGAL::parameters::random_seed(3));
  for(const Mesh* mesh : {&cylinder, static_cast<const Mesh*>(&noisy)})
  {
    const Flat_setup<> setup(*mesh);
    std::uint32_t largest_fan = 0;
    for(std::size_t v = 0; v < setup.m.number_of_vertices(); ++v)
      largest_fan = std::max(largest_fan, setup.m.vertex_face_offsets[v + 1] - setup.m.vertex_face_offsets[v]);
    ASSERT_EQ(largest_fan, 240u);
    expect_fan_search_is_the_plain_search(setup.m, setup.fd, setup.r);

    D::Flat_mesh rm = setup.m;
    D::Face_data rfd = setup.fd;
    D::reorder_faces_for_locality<CGAL::Sequential_tag>(rm, rfd);
    expect_fan_search_is_the_plain_search(rm, rfd, setup.r);
  }

  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  const Flat_setup<> f(fandisk);
  expect_same_lists(
      D::geometric_neighborhoods<CGAL::Sequential_tag>(f.m, f.fd.centroids, f.r),
      D::geometric_neighborhoods<CGAL::Sequential_tag>(f.fd.centroids, D::Face_vertex_adjacency{f.m}, f.r));
}
