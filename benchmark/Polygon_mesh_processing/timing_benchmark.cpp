// Timing of the intrinsic denoiser on seeded noisy fandisk (sigma_E = 0.3,
// seed 1): each stage and the whole denoise (k = 30, r = 4d), with one thread
// (Sequential_tag) and with TBB (Parallel_tag) when available.
//
// Usage: timing_benchmark [Google Benchmark flags]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = PMP::internal::Denoising;

static const Mesh& noisy_fandisk()
{
  static const Mesh mesh = [] {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), m) || m.is_empty())
    {
      std::cerr << "cannot read fandisk.off (install libcgal-demo)\n";
      std::exit(1);
    }
    PMP::add_gaussian_noise(m, 0.3, CGAL::parameters::random_seed(1));
    return m;
  }();
  return mesh;
}

template <typename Tag>
static void BM_whole_denoise(benchmark::State& state)
{
  for(auto _ : state)
  {
    state.PauseTiming();
    Mesh m = noisy_fandisk();
    state.ResumeTiming();
    PMP::intrinsic_denoising<Tag>(m, CGAL::parameters::automatic_parameters(false)); // the fixed k = 30 loop
    benchmark::DoNotOptimize(m.points().data());
  }
  state.counters["faces"] = double(num_faces(noisy_fandisk()));
}

struct Stages
{
  D::Flat_mesh mesh;
  D::Face_data faces;
  double d;
  D::Csr neighbors;
  D::Path_forest paths;
  Stages()
  {
    const Mesh& m = noisy_fandisk();
    mesh = D::make_flat_mesh(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m), get(CGAL::face_index, m), "");
    D::compute_face_data<CGAL::Sequential_tag>(mesh, mesh.points, faces);
    d = D::mean_adjacent_centroid_distance(mesh, faces);
    D::reorder_faces_for_locality<CGAL::Sequential_tag>(mesh, faces); // as intrinsic_denoising() does
    neighbors = D::geometric_neighborhoods<CGAL::Sequential_tag>(mesh, faces.centroids, 4 * d);
    paths = D::square_pattern_paths(mesh, faces, neighbors, D::square_pattern_compact_min_nodes_for_filter());
  }
};
static const Stages& stages()
{
  static const Stages s;
  return s;
}

template <typename Tag>
static void BM_neighborhoods(benchmark::State& state)
{
  const Stages& s = stages();
  for(auto _ : state)
    benchmark::DoNotOptimize(D::geometric_neighborhoods<Tag>(s.mesh, s.faces.centroids, 4 * s.d));
  state.counters["neighbours/face"] = double(s.neighbors.items.size()) / double(s.mesh.number_of_faces());
}

static void BM_square_pattern_paths(benchmark::State& state)
{
  const Stages& s = stages();
  for(auto _ : state)
    benchmark::DoNotOptimize(
        D::square_pattern_paths(s.mesh, s.faces, s.neighbors, D::square_pattern_compact_min_nodes_for_filter()));
}

template <typename Tag>
static void BM_filter_pass(benchmark::State& state)
{
  const Stages& s = stages();
  D::Intrinsic_kernel kernel;
  std::vector<D::Vec3> out;
  for(auto _ : state)
  {
    D::intrinsic_filter_pass<Tag>(s.paths, s.faces.normals, s.faces.areas, kernel, out);
    benchmark::DoNotOptimize(out.data());
  }
}

template <typename Tag>
static void BM_vertex_update(benchmark::State& state)
{
  const Stages& s = stages();
  std::vector<D::Vec3> points = s.mesh.points, centroids, next;
  const std::vector<char> fixed;
  for(auto _ : state)
  {
    D::update_vertices<Tag>(s.mesh, points, s.faces.normals, fixed, 2, centroids, next);
    benchmark::DoNotOptimize(points.data());
  }
}

BENCHMARK(BM_neighborhoods<CGAL::Sequential_tag>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_square_pattern_paths)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_filter_pass<CGAL::Sequential_tag>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_vertex_update<CGAL::Sequential_tag>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_whole_denoise<CGAL::Sequential_tag>)->Unit(benchmark::kMillisecond);
#ifdef CGAL_LINKED_WITH_TBB
BENCHMARK(BM_neighborhoods<CGAL::Parallel_tag>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_filter_pass<CGAL::Parallel_tag>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_vertex_update<CGAL::Parallel_tag>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_whole_denoise<CGAL::Parallel_tag>)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

BENCHMARK_MAIN();
