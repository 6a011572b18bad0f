// What every classic method of the paper's Table 1 must do, whatever its
// filter: the same result on Surface_mesh and Polyhedron_3, constrained
// vertices kept, the same result with every concurrency tag, an empty mesh
// left empty. One typed suite over the six methods; what is particular to a
// method (its figures, its parameters, its hand-checked weights) is tested in
// the file of its header.

#include <CGAL/Polygon_mesh_processing/bilateral_mesh_denoising.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/guided_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/l0_denoising.h>
#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include "classic_test_helpers.h"

using namespace classic_test;

// One type per method: run<Tag>(mesh, named parameters).
#define CLASSIC_METHOD(Type, function)                                                                                 \
  struct Type                                                                                                          \
  {                                                                                                                    \
    template <typename Tag = CGAL::Sequential_tag, typename M,                                                         \
              typename NP = CGAL::parameters::Default_named_parameters>                                                \
    static void run(M& mesh, const NP& np = CGAL::parameters::default_values())                                        \
    {                                                                                                                  \
      PMP::function<Tag>(mesh, np);                                                                                    \
    }                                                                                                                  \
  };
CLASSIC_METHOD(FDC03, bilateral_mesh_denoising)
CLASSIC_METHOD(JDD03, non_iterative_denoising)
CLASSIC_METHOD(SRML07, fast_feature_preserving_denoising)
CLASSIC_METHOD(ZFAT11, bilateral_normal_denoising)
CLASSIC_METHOD(HS13, l0_denoising)
CLASSIC_METHOD(ZDZ15, guided_normal_denoising)
#undef CLASSIC_METHOD

template <typename Method>
class ClassicMethod : public ::testing::Test
{
};
typedef ::testing::Types<FDC03, JDD03, SRML07, ZFAT11, HS13, ZDZ15> Classic_methods;
TYPED_TEST_SUITE(ClassicMethod, Classic_methods);

TYPED_TEST(ClassicMethod, SurfaceMeshAndPolyhedronGiveTheSameResult)
{
  EXPECT_LE(surface_mesh_vs_polyhedron([](auto& m) { TypeParam::run(m); }), 1e-12);
}

TYPED_TEST(ClassicMethod, ConstrainedVerticesDoNotMove)
{
  constrained_vertices_do_not_move(
      [](Mesh& m, auto pinned) { TypeParam::run(m, CGAL::parameters::vertex_is_constrained_map(pinned)); });
}

#ifdef CGAL_LINKED_WITH_TBB
// (HS13's solver is sequential and ignores the tag: its case checks that.)
TYPED_TEST(ClassicMethod, ParallelEqualsSequential)
{
  EXPECT_EQ(parallel_vs_sequential([](Mesh& m) { TypeParam::template run<CGAL::Sequential_tag>(m); },
                                   [](Mesh& m) { TypeParam::template run<CGAL::Parallel_tag>(m); }),
            0.);
}
#endif

TYPED_TEST(ClassicMethod, EmptyMeshIsLeftEmpty)
{
  Mesh empty;
  TypeParam::run(empty);
  EXPECT_TRUE(empty.is_empty());
}

// The normal-filtering methods (filter the face normals, then eq. 10) can end
// with the intrinsic filter's relaxation along the surface. Off by default
// (the published methods); when asked for, on a graded octahedron with
// depth-scan noise (partly along the surface, which eq. 10 cannot undo): it
// moves vertices, each by at most half its distance from the input, none
// constrained, turns no face against the unrelaxed result, lowers E_n and
// does not depend on the concurrency tag.
template <typename Method>
class NormalFilteringMethod : public ::testing::Test
{
};
typedef ::testing::Types<SRML07, ZFAT11, ZDZ15> Normal_filtering_methods;
TYPED_TEST_SUITE(NormalFilteringMethod, Normal_filtering_methods);

TYPED_TEST(NormalFilteringMethod, RelaxesAlongTheSurfaceOnlyWhenAsked)
{
  const Mesh reference = denoising_support::graded_octahedron<Mesh>(20, 1.4);
  Mesh noisy = reference;
  PMP::add_depth_scan_noise(noisy, 0.3, CGAL::parameters::random_seed(3));
  auto pinned = noisy.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
  for(auto v : vertices(noisy))
    put(pinned, v, std::size_t(v) % 11 == 0);
  const auto constrained = CGAL::parameters::vertex_is_constrained_map(pinned);

  Mesh plain = noisy, unrelaxed = noisy, relaxed = noisy;
  TypeParam::run(plain, constrained);
  TypeParam::run(unrelaxed, constrained.relax_along_surface(false));
  TypeParam::run(relaxed, constrained.relax_along_surface(true));
  EXPECT_EQ(max_distance(positions(plain), positions(unrelaxed)), 0.);

  std::size_t moved = 0, beyond_cap = 0, pinned_moved = 0, turned = 0;
  for(auto v : vertices(noisy))
  {
    const double d = std::sqrt(CGAL::squared_distance(relaxed.point(v), plain.point(v)));
    const double cap = 0.5 * std::sqrt(CGAL::squared_distance(noisy.point(v), plain.point(v)));
    moved += d > 0. ? 1 : 0;
    beyond_cap += d <= cap * (1. + 1e-9) ? 0 : 1;
    pinned_moved += get(pinned, v) && d > 0. ? 1 : 0;
  }
  for(auto f : faces(noisy))
    turned += PMP::compute_face_normal(f, relaxed) * PMP::compute_face_normal(f, plain) > 0. ? 0 : 1;
  EXPECT_GT(moved, num_vertices(noisy) / 2);
  EXPECT_EQ(beyond_cap, 0u);
  EXPECT_EQ(pinned_moved, 0u);
  EXPECT_EQ(turned, 0u);
  const double e_plain = PMP::face_normal_error(plain, reference),
               e_relaxed = PMP::face_normal_error(relaxed, reference);
  std::printf("depth-scan noise: E_n %.3f without, %.3f with the relaxation along the surface (%zu vertices)\n",
              e_plain, e_relaxed, moved);
  EXPECT_LT(e_relaxed, e_plain);

#ifdef CGAL_LINKED_WITH_TBB
  Mesh parallel = noisy;
  TypeParam::template run<CGAL::Parallel_tag>(parallel, constrained.relax_along_surface(true));
  EXPECT_EQ(max_distance(positions(relaxed), positions(parallel)), 0.);
#endif
}
