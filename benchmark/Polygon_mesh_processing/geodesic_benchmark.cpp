// The paper's figure 2 comparison: exact geodesic paths against square-pattern
// paths, with the same parameters (k = 30, v = 2, r = 4d, sigma_s = sigma_r =
// 0.4), on seeded noisy fandisk (sigma_E = 0.3) and on the synthetic 18-edge
// prism (sigma_E = 0.1). Prints a Markdown table of the seconds of path
// construction and of the whole denoising call, and E_n / E_v, on one thread
// (Sequential_tag) and, with TBB, with Parallel_tag.
//
// Usage: geodesic_benchmark [repetitions]   (default 1; times are the minimum)
//
// "direct fallbacks" counts the geodesic neighbour paths that are direct
// (no geodesic reaches the neighbour in the patch; see geodesic_paths.h).
// "paths" times the path construction alone (square_pattern_paths() or
// geodesic_paths() on neighbourhoods built beforehand); "total" times the
// public intrinsic_denoising() call, which builds face data, neighbourhoods
// and paths and runs the 30 iterations.
//
// A second table splits the geodesic path construction on one thread into
// its phases (more runs with Geodesic_path_options::time_phases; the minimum
// of each phase over the repetitions): the
// patch copies, and the three calls into CGAL's Surface_mesh_shortest_path
// (sequence-tree construction, its deletion, the queries). "CGAL floor"
// is a lower bound of the geodesic total / square-pattern total ratio for any
// implementation that makes these CGAL calls: (CGAL's seconds + the
// square pattern's total minus its path seconds) / the square pattern's
// total, i.e. as if everything else in the geodesic run (patch copies, path
// conversion, and filtering the geodesic forest's 22% more nodes) took no
// more time than in the square-pattern run.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>

#include <denoising_support/synthetic_meshes.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = PMP::internal::Denoising;

template <typename F>
static double seconds(const F& f)
{
  const denoising_support::Stopwatch stopwatch;
  f();
  return stopwatch.seconds();
}

struct Row
{
  double paths = std::numeric_limits<double>::infinity();
  double total = std::numeric_limits<double>::infinity();
  double En = 0., Ev = 0.;
  std::size_t nodes = 0;
  std::size_t paths_built = 0, fallbacks = 0; // geodesic only: neighbour paths, of which direct
  D::Geodesic_path_statistics phases;         // geodesic only: a run with time_phases
  double phased_paths = 0.;                   // the seconds of that run
};

template <typename Tag>
static Row run(const Mesh& reference, const Mesh& noisy, PMP::Intrinsic_path_strategy strategy, int repetitions)
{
  const auto np = CGAL::parameters::path_strategy(strategy)
                      .number_of_iterations(30)
                      .vertex_iterations(2)
                      .relative_neighbor_radius(4.)
                      .sigma_spatial(0.4)
                      .sigma_range(0.4);
  Row row;
  // path construction alone, on the same inputs as the denoiser's
  const D::Mesh_maps<Mesh, decltype(np)> maps(noisy, np);
  const D::Flat_mesh flat = maps.flat(noisy, "geodesic_benchmark");
  D::Face_data fd;
  D::compute_face_data<Tag>(flat, flat.points, fd);
  const D::Csr nb =
      D::geometric_neighborhoods<Tag>(flat, fd.centroids, 4. * D::mean_adjacent_centroid_distance(flat, fd));
  for(int r = 0; r < repetitions; ++r)
  {
    D::Path_forest forest;
    row.paths = (std::min)(row.paths, seconds([&] {
                             D::Geodesic_path_statistics stats;
                             forest = strategy == PMP::Intrinsic_path_strategy::GEODESIC
                                          ? D::geodesic_paths<Tag>(flat, fd, nb, {}, &stats)
                                          : D::square_pattern_paths(flat, fd, nb,
                                                                    D::square_pattern_compact_min_nodes_for_filter());
                             row.paths_built = stats.paths;
                             row.fallbacks = stats.fallbacks;
                           }));
    row.nodes = forest.face.size();
    Mesh denoised = noisy;
    row.total = (std::min)(row.total, seconds([&] { PMP::intrinsic_denoising<Tag>(denoised, np); }));
    row.En = PMP::face_normal_error(denoised, reference);
    row.Ev = PMP::vertex_position_error(denoised, reference);
  }
  if(strategy == PMP::Intrinsic_path_strategy::GEODESIC)
  {
    // each phase's minimum over the repetitions
    D::Geodesic_path_options options;
    options.time_phases = true;
    for(int r = 0; r < repetitions; ++r)
    {
      D::Geodesic_path_statistics s;
      const double t = seconds([&] { D::geodesic_paths<Tag>(flat, fd, nb, options, &s); });
      auto keep_min = [r](double& kept, double v) { kept = r == 0 ? v : (std::min)(kept, v); };
      keep_min(row.phased_paths, t);
      for(double D::Geodesic_path_statistics::*f :
          {&D::Geodesic_path_statistics::patch_seconds, &D::Geodesic_path_statistics::tree_seconds,
           &D::Geodesic_path_statistics::clear_seconds, &D::Geodesic_path_statistics::query_seconds})
        keep_min(row.phases.*f, s.*f);
    }
  }
  return row;
}

int main(int argc, char** argv)
{
  const int repetitions = argc > 1 ? (std::max)(1, std::atoi(argv[1])) : 1;
  struct Model
  {
    std::string name;
    Mesh reference;
    double sigma_E;
  };
  std::vector<Model> models;
  struct Phases
  {
    std::string name;
    Row square, geodesic;
  };
  std::vector<Phases> phases;
  {
    Mesh fandisk;
    if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk) || fandisk.is_empty())
    {
      std::cerr << "error: cannot read meshes/fandisk.off of CGAL's data set\n";
      return 1;
    }
    models.push_back({"fandisk", fandisk, 0.3});
    models.push_back({"hexagonal prism", denoising_support::benchmark_prism<Mesh>(), 0.1});
  }
  std::printf("Geodesic vs square-pattern paths (paper figure 2): k = 30, v = 2, r = 4d, sigma_s = sigma_r = 0.4,\n"
              "Gaussian noise seed 1; times: minimum of %d run(s)\n\n",
              repetitions);
  std::printf(
      "| model | faces | noisy E_n | threads | strategy | path nodes | direct fallbacks | paths (s) | total (s) "
      "| total / square | E_n (deg) | E_v |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Model& m : models)
  {
    Mesh noisy = m.reference;
    PMP::add_gaussian_noise(noisy, m.sigma_E, CGAL::parameters::random_seed(1));
    const double noisy_En = PMP::face_normal_error(noisy, m.reference);
    auto print = [&](const char* threads, const Row& square, const Row& geodesic) {
      for(int k = 0; k < 2; ++k)
      {
        const Row& r = k == 0 ? square : geodesic;
        const std::string fallbacks =
            k == 0 ? std::string("-") : std::to_string(r.fallbacks) + " / " + std::to_string(r.paths_built);
        std::printf("| %s σ_E=%.1f | %zu | %.2f | %s | %s | %zu | %s | %.2f | %.2f | %.2f | %.3f | %.3e |\n",
                    m.name.c_str(), m.sigma_E, std::size_t(num_faces(noisy)), noisy_En, threads,
                    k == 0 ? "square pattern" : "geodesic", r.nodes, fallbacks.c_str(), r.paths, r.total,
                    r.total / square.total, r.En, r.Ev);
      }
      std::fflush(stdout);
    };
    {
      const Row square =
          run<CGAL::Sequential_tag>(m.reference, noisy, PMP::Intrinsic_path_strategy::SQUARE_PATTERN, repetitions);
      const Row geodesic =
          run<CGAL::Sequential_tag>(m.reference, noisy, PMP::Intrinsic_path_strategy::GEODESIC, repetitions);
      print("1", square, geodesic);
      phases.push_back({m.name, square, geodesic});
    }
#ifdef CGAL_LINKED_WITH_TBB
    {
      const Row square =
          run<CGAL::Parallel_tag>(m.reference, noisy, PMP::Intrinsic_path_strategy::SQUARE_PATTERN, repetitions);
      const Row geodesic =
          run<CGAL::Parallel_tag>(m.reference, noisy, PMP::Intrinsic_path_strategy::GEODESIC, repetitions);
      print("TBB", square, geodesic);
    }
#endif
  }
  std::printf(
      "\nWhere the geodesic path time goes, 1 thread (runs with time_phases, minimum of each phase; seconds):\n\n"
      "| model | paths | patch copies | CGAL tree construction | CGAL tree deletion | CGAL queries | other "
      "| CGAL total | square total | square paths | CGAL floor of the ratio |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Phases& p : phases)
  {
    const D::Geodesic_path_statistics& s = p.geodesic.phases;
    const double cgal = s.tree_seconds + s.clear_seconds + s.query_seconds;
    const double other = p.geodesic.phased_paths - cgal - s.patch_seconds;
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f |\n", p.name.c_str(),
                p.geodesic.phased_paths, s.patch_seconds, s.tree_seconds, s.clear_seconds, s.query_seconds, other, cgal,
                p.square.total, p.square.paths, (cgal + p.square.total - p.square.paths) / p.square.total);
  }
  return 0;
}
