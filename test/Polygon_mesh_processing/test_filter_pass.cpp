// Tests of normal_filter_pass.h: the SIMD kernels against the generic engine.

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
#include <set>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// The vector kernels of the paper's case (n = m = 1: SSE2, and AVX2 where
// the processor has it) give bitwise the filtered normals of the generic
// engine, with and without the self term; and their two- and four-lane exps
// are bitwise the scalar one, down to the flush to 0.
TEST(FilterPass, VectorKernelEqualsGenericEngine)
{
  Mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  CGAL::Polygon_mesh_processing::add_gaussian_noise(fandisk, 0.3, CGAL::parameters::random_seed(5));
  const Flat_setup<> setup(fandisk);
  const D::Face_data& fd = setup.fd;
  const D::Path_forest forest = D::square_pattern_paths_within<CGAL::Sequential_tag>(setup.m, fd, setup.r);
  for(bool self : {false, true})
    for(double sigma : {0.2, 0.4, 1.3})
    {
      D::Intrinsic_kernel kernel;
      kernel.include_self = self;
      kernel.sigma_spatial = sigma;
      kernel.sigma_range = 0.5 * sigma;
      std::vector<D::Vec3> fast, generic;
      D::intrinsic_filter_pass<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, fast);
      D::intrinsic_filter_pass_generic<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel, generic);
      // each vector kernel on its own, whichever the dispatch picks
      std::vector<std::pair<const char*, std::vector<D::Vec3>>> kernels;
      kernels.emplace_back("dispatched", fast);
#ifdef CGAL_PMP_DENOISING_SSE2
      kernels.emplace_back("SSE2", std::vector<D::Vec3>(forest.number_of_faces()));
      D::intrinsic_filter_pass_l1_sse2<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel,
                                                             kernels.back().second);
#endif
#ifdef CGAL_PMP_DENOISING_AVX2
      if(D::cpu_has_avx2())
      {
        kernels.emplace_back("AVX2", std::vector<D::Vec3>(forest.number_of_faces()));
        D::intrinsic_filter_pass_l1_avx2<CGAL::Sequential_tag>(forest, fd.normals, fd.areas, kernel,
                                                               kernels.back().second);
      }
#endif
      for(const auto& k : kernels)
      {
        ASSERT_EQ(k.second.size(), generic.size());
        std::size_t different = 0;
        for(std::size_t f = 0; f < generic.size(); ++f)
          different += k.second[f] != generic[f] ? 1 : 0;
        EXPECT_EQ(different, 0u) << k.first << " self " << self << " sigma " << sigma;
      }
    }
#ifdef CGAL_PMP_DENOISING_SSE2
  const D::Exp_table& table = D::Exp_table::instance();
  std::size_t different = 0, tried = 0;
  for(double x = -720.; x <= 0.; x += 0.0137)
    for(double y : {x, x - 1e-9, -0., std::nextafter(-707., 0.), -707., -1e300})
    {
      double lanes[2];
      _mm_storeu_pd(lanes, D::exp_nonpositive_2(_mm_set_pd(x, y), table));
      different += (lanes[0] != D::exp_nonpositive(y, table)) + (lanes[1] != D::exp_nonpositive(x, table));
      tried += 2;
    }
  EXPECT_EQ(different, 0u) << "of " << tried;
#endif
#ifdef CGAL_PMP_DENOISING_AVX2
  if(D::cpu_has_avx2())
  {
    std::size_t different4 = 0, tried4 = 0;
    for(double x = -720.; x <= 0.; x += 0.0137)
    {
      const double in[4] = {x, x - 1e-9, std::nextafter(-707., 0.), x < -360. ? -1e300 : -0.};
      double lanes[4];
      D::exp_nonpositive_4(in, lanes, table);
      for(int l = 0; l < 4; ++l)
        different4 += lanes[l] != D::exp_nonpositive(in[l], table);
      tried4 += 4;
    }
    EXPECT_EQ(different4, 0u) << "of " << tried4;
  }
#endif
}
