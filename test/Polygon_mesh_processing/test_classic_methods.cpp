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
