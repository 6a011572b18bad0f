// Tests of the automatic selection on a sample of a big mesh
// (selection_sample.h, the named parameter selection_sample_faces): the
// sample is made of patches of the mesh, the same on every run; the result
// is the setting chosen on the sample run once on the whole mesh; sparse
// noise and meshes below the threshold are selected on the whole mesh.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_selection.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/selection_sample.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/mesh_access.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "data_meshes.h"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;

const Mesh& fandisk() { return data_mesh("meshes/fandisk.off"); }

D::Flat_mesh flat_of(const Mesh& m)
{
  return D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(m, CGAL::parameters::default_values())
      .flat(m, "test");
}

std::size_t different_points(const Mesh& a, const Mesh& b)
{
  std::size_t different = 0;
  for(auto v : vertices(a))
    different += a.point(v) == b.point(v) ? 0 : 1;
  return different;
}

// Fandisk (12,946 faces) sampled with 3,000 faces: above three times the
// sample, so the selection runs on it.
constexpr std::size_t sample_faces = 3000;

} // namespace

// The sample is `target` faces of the mesh, each once, with their vertices
// and orientation, in patches of at most `patch` faces that are connected
// through shared vertices; pinned vertices stay pinned; two runs give the
// same sample.
TEST(SelectionSample, PatchesAreConnectedPartsOfTheMesh)
{
  const D::Flat_mesh whole = flat_of(fandisk());
  std::vector<char> constrained(whole.number_of_vertices(), 0);
  for(std::size_t v = 0; v < constrained.size(); v += 7)
    constrained[v] = 1;
  const std::size_t target = 3000, patch = 600;
  const D::Selection_sample s = D::sample_patches(whole, constrained, target, patch);
  const D::Flat_mesh& m = s.mesh;
  ASSERT_EQ(m.number_of_faces(), target);
  EXPECT_GE(s.patches, target / patch);
  ASSERT_EQ(s.constrained.size(), m.number_of_vertices());

  // every sample face is a face of the whole, once, its corners in order
  std::map<std::array<double, 3>, std::uint32_t> index_of; // fandisk's points are distinct
  const auto key = [](const D::Vec3& p) { return std::array<double, 3>{p[0], p[1], p[2]}; };
  for(std::uint32_t v = 0; v < whole.number_of_vertices(); ++v)
    index_of[key(whole.points[v])] = v;
  ASSERT_EQ(index_of.size(), whole.number_of_vertices());
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> face_of;
  for(std::uint32_t f = 0; f < whole.number_of_faces(); ++f)
    face_of[whole.triangles[f]] = f;
  std::vector<std::uint32_t> whole_vertex(m.number_of_vertices());
  for(std::uint32_t v = 0; v < m.number_of_vertices(); ++v)
  {
    whole_vertex[v] = index_of.at(key(m.points[v]));
    EXPECT_EQ(s.constrained[v], constrained[whole_vertex[v]]);
  }
  std::set<std::uint32_t> faces;
  for(const auto& t : m.triangles)
  {
    const auto f = face_of.find({whole_vertex[t[0]], whole_vertex[t[1]], whole_vertex[t[2]]});
    ASSERT_NE(f, face_of.end());
    EXPECT_TRUE(faces.insert(f->second).second);
  }
  // the faces around each vertex are listed
  ASSERT_EQ(m.vertex_face_offsets.size(), m.number_of_vertices() + 1);
  EXPECT_EQ(m.vertex_faces.size(), 3 * m.number_of_faces());

  // connected parts: at most s.patches components through shared vertices
  std::vector<std::uint32_t> parent(m.number_of_faces());
  for(std::uint32_t f = 0; f < parent.size(); ++f)
    parent[f] = f;
  auto root = [&](std::uint32_t f) {
    while(parent[f] != f)
      f = parent[f] = parent[parent[f]];
    return f;
  };
  for(std::uint32_t v = 0; v < m.number_of_vertices(); ++v)
    for(std::uint32_t i = m.vertex_face_offsets[v] + 1; i < m.vertex_face_offsets[v + 1]; ++i)
      parent[root(m.vertex_faces[i])] = root(m.vertex_faces[m.vertex_face_offsets[v]]);
  std::set<std::uint32_t> components;
  for(std::uint32_t f = 0; f < parent.size(); ++f)
    components.insert(root(f));
  EXPECT_LE(components.size(), s.patches);

  const D::Selection_sample again = D::sample_patches(whole, constrained, target, patch);
  EXPECT_EQ(again.mesh.triangles, m.triangles);
  ASSERT_EQ(again.mesh.points.size(), m.points.size());
  for(std::size_t v = 0; v < m.points.size(); ++v)
    EXPECT_EQ(key(again.mesh.points[v]), key(m.points[v]));
  EXPECT_EQ(again.patches, s.patches);
}

// With selection_sample_faces below a third of the mesh, the selection runs
// on the sample and its setting once on the whole mesh: the result is the
// plain run of that kernel, radius and count from the input, relaxed along
// the surface; it removes noise, the same with one thread as with several.
TEST(SelectionSample, TheSettingChosenOnTheSampleRunsOnTheWholeMesh)
{
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
  Mesh m = noisy;
  const PMP::Intrinsic_denoising_report r = PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(
      m, CGAL::parameters::selection_sample_faces(sample_faces));
  EXPECT_EQ(r.selection_sample_faces, sample_faces);
  EXPECT_GE(r.selection_sample_patches, D::Sample_rules::patches);
  ASSERT_EQ(r.candidates.size(), D::Selection_rules::number_of_candidates);
  ASSERT_GT(r.iterations, 0u);
  EXPECT_GT(r.relaxed_vertices, 0u);

  Mesh plain = noisy;
  PMP::intrinsic_denoising(plain, CGAL::parameters::sigma_spatial(r.sigma_spatial)
                                      .sigma_range(r.sigma_range)
                                      .relative_neighbor_radius(r.relative_neighbor_radius)
                                      .number_of_iterations(r.iterations)
                                      .stop_when_converged(false)
                                      .relax_along_surface(true));
  EXPECT_EQ(different_points(plain, m), 0u);

  Mesh sequential = noisy;
  const PMP::Intrinsic_denoising_report s = PMP::intrinsic_denoising<CGAL::Sequential_tag>(
      sequential, CGAL::parameters::selection_sample_faces(sample_faces));
  EXPECT_EQ(different_points(sequential, m), 0u);
  EXPECT_EQ(s.iterations, r.iterations);

  Mesh whole = noisy;
  const PMP::Intrinsic_denoising_report w = PMP::intrinsic_denoising(whole);
  EXPECT_EQ(w.selection_sample_faces, 0u); // 12,946 faces: below three times the default sample
  const double noisy_En = PMP::face_normal_error(noisy, fandisk()), sampled_En = PMP::face_normal_error(m, fandisk()),
               whole_En = PMP::face_normal_error(whole, fandisk());
  std::cout << "fandisk, sigma_E 0.3: E_n noisy " << noisy_En << ", selection on " << sample_faces << " faces "
            << sampled_En << " (sigma " << r.sigma_range << ", r " << r.relative_neighbor_radius << " d, k "
            << r.iterations << "), on the whole mesh " << whole_En << " (sigma " << w.sigma_range << ", r "
            << w.relative_neighbor_radius << " d, k " << w.iterations << ")\n";
  EXPECT_LT(sampled_En, 0.5 * noisy_En);
}

// Below three times the sample the selection runs on the whole mesh, and
// the result is the default's bit for bit; selection_sample_faces(0) never
// samples.
TEST(SelectionSample, NoSampleBelowTheThresholdOrWithZero)
{
  Mesh noisy = fandisk();
  PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
  Mesh a = noisy, b = noisy, c = noisy;
  const PMP::Intrinsic_denoising_report ra = PMP::intrinsic_denoising(a);
  const PMP::Intrinsic_denoising_report rb =
      PMP::intrinsic_denoising(b, CGAL::parameters::selection_sample_faces(num_faces(noisy) / 3 + 1));
  const PMP::Intrinsic_denoising_report rc = PMP::intrinsic_denoising(c, CGAL::parameters::selection_sample_faces(0));
  EXPECT_EQ(ra.selection_sample_faces, 0u);
  EXPECT_EQ(rb.selection_sample_faces, 0u);
  EXPECT_EQ(rc.selection_sample_faces, 0u);
  EXPECT_EQ(different_points(a, b), 0u);
  EXPECT_EQ(different_points(a, c), 0u);
  Mesh d = noisy;
  const PMP::Intrinsic_denoising_report rd =
      PMP::intrinsic_denoising(d, CGAL::parameters::selection_sample_faces(num_faces(noisy) / 3 - 1));
  EXPECT_GT(rd.selection_sample_faces, 0u); // just above the threshold: sampled
}

// Sparse (impulsive) noise: the outliers are vertices of their own, so once
// the sample shows sparse noise the selection runs again on the whole mesh;
// the result is the selection's on the whole mesh.
TEST(SelectionSample, SparseNoiseIsSelectedOnTheWholeMesh)
{
  Mesh noisy = fandisk();
  PMP::add_impulsive_noise(noisy, 0.1, 1.0, CGAL::parameters::random_seed(1));
  Mesh m = noisy, whole = noisy;
  const PMP::Intrinsic_denoising_report r =
      PMP::intrinsic_denoising(m, CGAL::parameters::selection_sample_faces(sample_faces));
  const PMP::Intrinsic_denoising_report w =
      PMP::intrinsic_denoising(whole, CGAL::parameters::selection_sample_faces(0));
  EXPECT_GT(w.outlier_vertices, 0u);
  EXPECT_EQ(r.selection_sample_faces, 0u);
  EXPECT_EQ(r.outlier_vertices, w.outlier_vertices);
  EXPECT_EQ(different_points(m, whole), 0u);
}
