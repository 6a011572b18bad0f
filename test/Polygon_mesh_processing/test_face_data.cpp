// Tests of flat_mesh.h and face_data.h: the flat copy of a mesh, its edge
// walks and the means over its faces.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include "flat_setup.h"
#include <denoising_support/synthetic_meshes.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// Adds four fins (triangles) on the edge (t[0], t[1]) of face 0 of `m` and
// lists the faces around each vertex again.
void add_fins(D::Flat_mesh& m)
{
  const std::array<std::uint32_t, 3> t = m.triangles[0];
  for(int k = 0; k < 4; ++k)
  {
    m.points.push_back({0.01 * k, 0.02, 0.1 + 0.1 * k});
    m.triangles.push_back({t[0], t[1], std::uint32_t(m.points.size() - 1)});
  }
  D::list_faces_around_vertices(m);
}

// The mean distance d between adjacent centroids and the mean edge length
// are the same, bitwise, with Parallel_tag (values computed in parallel,
// added in order) as with Sequential_tag: on noisy fandisk, and on a grid
// with four fins on one edge, whose faces there have more values than the
// parallel version keeps per face (it must fall back to the sequential sum).
TEST(FaceData, MeansAreTheSameWithEveryConcurrencyTag)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  CGAL::Polygon_mesh_processing::add_gaussian_noise(fandisk, 0.3, CGAL::parameters::random_seed(3));
  const Flat_setup<> noisy(fandisk);
  Flat_setup<> fins(denoising_support::plane_grid<Mesh>(48)); // 4608 faces
  {
    D::Flat_mesh& m = fins.m;
    add_fins(m);
    D::compute_face_data<CGAL::Sequential_tag>(m, m.points, fins.fd);
  }
  for(const Flat_setup<>* s : {&noisy, static_cast<const Flat_setup<>*>(&fins)})
  {
    ASSERT_GT(s->m.number_of_faces(), 4096u); // the parallel version's size
    const double d = D::mean_adjacent_centroid_distance<CGAL::Sequential_tag>(s->m, s->fd);
    const double l = D::mean_edge_length<CGAL::Sequential_tag>(s->m);
    EXPECT_GT(d, 0.);
    EXPECT_GT(l, 0.);
#ifdef CGAL_LINKED_WITH_TBB
    EXPECT_EQ(D::mean_adjacent_centroid_distance<CGAL::Parallel_tag>(s->m, s->fd), d);
    EXPECT_EQ(D::mean_edge_length<CGAL::Parallel_tag>(s->m), l);
#endif
  }
}

// The faces on an edge, found by walking the faces of its first vertex:
// every face on the edge and only those, on a manifold edge (2), a border
// edge (1) and an edge with four fins (5 or 6); the mean edge length counts each
// edge once, bitwise as a sum over the distinct edges in order of first use.
TEST(FlatMesh, EdgeWalksSeeEveryFaceOnAnEdgeOnce)
{
  Flat_setup<> grid(denoising_support::plane_grid<Mesh>(6));
  D::Flat_mesh& m = grid.m;
  const std::array<std::uint32_t, 3> t = m.triangles[0];
  add_fins(m);

  // brute force: the faces of each undirected edge
  const auto key = [](std::uint32_t a, std::uint32_t b) { return std::make_pair((std::min)(a, b), (std::max)(a, b)); };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::set<std::uint32_t>> faces_of;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> first_use;
  for(std::uint32_t f = 0; f < m.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const auto e = key(m.triangles[f][k], m.triangles[f][(k + 1) % 3]);
      if(faces_of[e].empty())
        first_use.push_back(e);
      faces_of[e].insert(f);
    }
  std::size_t counts[4] = {0, 0, 0, 0}; // edges with 1, 2, 3-4, 5 or more faces
  for(const auto& entry : faces_of)
  {
    std::vector<std::uint32_t> walked;
    D::for_each_face_on_edge(m, entry.first.first, entry.first.second, [&](std::uint32_t g) { walked.push_back(g); });
    EXPECT_EQ(std::set<std::uint32_t>(walked.begin(), walked.end()), entry.second);
    EXPECT_EQ(walked.size(), entry.second.size()); // each once
    const std::size_t n = entry.second.size();
    ++counts[n >= 5 ? 3 : n >= 3 ? 2 : n - 1];
    if(n >= 5)
    {
      EXPECT_EQ(entry.first, key(t[0], t[1])); // the edge with the fins
    }
  }
  EXPECT_EQ(counts[3], 1u);
  EXPECT_EQ(counts[2], 0u);
  EXPECT_GT(counts[1], 0u); // interior edges
  EXPECT_GT(counts[0], 0u); // border edges

  // each pair of edge-adjacent faces once, from its lower face
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs, expected;
  for(std::uint32_t f = 0; f < m.triangles.size(); ++f)
    D::for_each_edge_adjacent_face_after(m, f, [&](std::uint32_t g) { EXPECT_TRUE(pairs.insert({f, g}).second); });
  for(const auto& entry : faces_of)
    for(std::uint32_t f : entry.second)
      for(std::uint32_t g : entry.second)
        if(f < g)
          expected.insert({f, g});
  EXPECT_EQ(pairs, expected);

  double sum = 0.;
  for(const auto& e : first_use)
    sum += D::norm(m.points[e.second] - m.points[e.first]);
  EXPECT_EQ(D::mean_edge_length(m), sum / double(first_use.size()));
}
