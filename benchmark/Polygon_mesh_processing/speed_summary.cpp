// Speed summary of the intrinsic denoiser, printed as Markdown
// tables; every row is measured in this run.
//
// 1. Methods on seeded noisy fandisk (sigma_E 0.3, seed 1), 1 and 2 threads:
//    intrinsic_denoising() with its defaults and with the two documented fast
//    settings, this package's SRML07 (fast_feature_preserving_denoising) and
//    ZFAT11 (bilateral_normal_denoising) with their defaults, and, if the
//    optional target meshsdfilter_benchmark was built (Debian's
//    libmeshsdfilter-dev), MeshSDFilter's denoiser, run as a child process.
// 2. Stages (flat copy, neighbourhoods, paths, one pass, one vertex update)
//    and whole denoise with 1 and 2 threads (Sequential_tag, Parallel_tag with
//    TBB limited to 2) on CGAL's fandisk and bunny00 refined by 0, 1 and 2
//    steps of Loop subdivision; each size runs in its own child process, so
//    its peak memory is its own.
// 3. Memory: per size, a child process that only builds the noisy mesh and
//    denoises it (2 threads, k of the stage table): resident size before the
//    denoise, the denoise's peak (VmHWM reset just before it) and the
//    process's peak (getrusage).
//
// 4. Linearity on one shape: fandisk refined by 0 to 3 Loop steps (13k to
//    829k faces, same noise, k 20), whole denoise with 2 threads and its
//    seconds per face and iteration, beside the mean neighbourhood size
//    (the bunny family of table 2 gains neighbours per face as subdivision
//    makes its irregular triangles regular, which table 4 keeps apart).
//
// Usage: speed_summary [max_faces]      all tables (sizes up to max_faces)
//        speed_summary --fast-grid      the grid the fast settings come from
//        speed_summary --size i         one row pair of table 2 (child)
//        speed_summary --memory i       one row of table 3 (child)
//        speed_summary --family i       one row of table 4 (child)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <sys/resource.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = PMP::internal::Denoising;

template <typename F>
static double seconds(const F& f, int repeat = 1)
{
  double best = 1e30;
  for(int r = 0; r < repeat; ++r)
  {
    const denoising_support::Stopwatch watch;
    f();
    best = (std::min)(best, watch.seconds());
  }
  return best;
}

struct Row
{
  double flat, reorder, neighborhoods, paths, pass, update, whole, En, mean_neighbors, max_neighbors;
};

template <typename Tag>
static Row measure(const Mesh& noisy, const Mesh& reference, unsigned int k)
{
  Row row;
  const int rep = num_faces(noisy) < 100000 ? 5 : 1;
  D::Flat_mesh m;
  D::Face_data fd;
  row.flat = seconds(
      [&] {
        m = D::make_flat_mesh(noisy, get(CGAL::vertex_point, noisy), get(CGAL::vertex_index, noisy),
                              get(CGAL::face_index, noisy), "speed_summary");
        D::compute_face_data<Tag>(m, m.points, fd);
      },
      rep);
  const double d = D::mean_adjacent_centroid_distance(m, fd);
  row.reorder = seconds([&] { D::reorder_faces_for_locality<Tag>(m, fd); }); // as intrinsic_denoising() does
  D::Csr nb;
  row.neighborhoods = seconds([&] { nb = D::geometric_neighborhoods<Tag>(m, fd.centroids, 4 * d); }, rep);
  row.mean_neighbors = double(nb.items.size()) / double(m.number_of_faces());
  row.max_neighbors = 0;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    row.max_neighbors = (std::max)(row.max_neighbors, double(nb.end(f) - nb.begin(f)));
  D::Path_forest forest;
  row.paths = seconds(
      [&] { forest = D::square_pattern_paths<Tag>(m, fd, nb, D::square_pattern_compact_min_nodes_for_filter()); }, rep);
  D::Intrinsic_kernel kernel;
  std::vector<D::Vec3> out, points = m.points, c, next;
  row.pass = seconds([&] { D::intrinsic_filter_pass<Tag>(forest, fd.normals, fd.areas, kernel, out); }, rep);
  row.update = seconds([&] { D::update_vertices<Tag>(m, points, out, {}, 2, c, next); }, rep);
  Mesh result;
  row.whole = seconds(
      [&] {
        result = noisy;
        PMP::intrinsic_denoising<Tag>(result, CGAL::parameters::number_of_iterations(k).automatic_parameters(false));
      },
      num_faces(noisy) < 100000 ? 3 : 1);
  row.En = PMP::face_normal_error(result, reference);
  return row;
}

// --fast-grid: whole denoise of noisy fandisk (sigma_E 0.3, seed 1) with 2
// threads over a grid of settings; prints every setting with its time (best
// of 2, the mesh copy included) and E_n, fastest first, for choosing the documented fast settings.
static int fast_grid(const Mesh& fandisk)
{
  Mesh noisy = fandisk;
  PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  typedef CGAL::Parallel_tag Tag;
#else
  typedef CGAL::Sequential_tag Tag;
#endif
  struct Entry
  {
    double r, sigma;
    unsigned int k, v;
    double sec, En;
  };
  std::vector<Entry> entries;
  for(double r : {1.5, 2., 2.5, 3., 4.})
    for(double sigma : {0.3, 0.4, 0.5, 0.6, 0.8})
      for(unsigned int k : {3u, 4u, 5u, 6u, 8u, 10u, 12u, 15u, 20u})
        for(unsigned int v : {1u, 2u, 3u, 5u})
        {
          Mesh result;
          const auto run = [&] {
            result = noisy;
            PMP::intrinsic_denoising<Tag>(result, CGAL::parameters::number_of_iterations(k)
                                                      .vertex_iterations(v)
                                                      .sigma_spatial(sigma)
                                                      .sigma_range(sigma)
                                                      .relative_neighbor_radius(r));
          };
          const double sec = seconds(run, 2);
          const double En = PMP::face_normal_error(result, fandisk);
          entries.push_back({r, sigma, k, v, sec, En});
          std::fprintf(stderr, "r=%gd sigma=%.2f k=%u v=%u: %.4f s, E_n %.3f\n", r, sigma, k, v, sec, En);
        }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.sec < b.sec; });
  double best_En = 1e30;
  std::printf("| r (d) | sigma_s = sigma_r | k | v | seconds (2 threads) | E_n (deg) |\n|---|---|---|---|---|---|\n");
  for(const Entry& e : entries)
    if(e.En < best_En) // the Pareto front: no faster setting is as accurate
    {
      best_En = e.En;
      std::printf("| %g | %.2f | %u | %u | %.4f | %.3f |\n", e.r, e.sigma, e.k, e.v, e.sec, e.En);
    }
  return 0;
}

// The two fast settings of the manual (found by --fast-grid).
struct Fast_setting
{
  const char* name;
  double relative_radius, sigma;
  unsigned int k, v;
};
static const Fast_setting fast_settings[] = {{"intrinsic, fast", 2., 0.6, 10, 2},
                                             {"intrinsic, fast (better)", 2., 0.6, 15, 2}};

static double process_peak_mib()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.; // kilobytes on Linux
}

static bool read_mesh(const char* name, Mesh& m)
{
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path(name), m) || m.is_empty())
  {
    std::cerr << "cannot read " << name << " of CGAL's data set (install libcgal-demo)\n";
    return false;
  }
  return true;
}

struct Input
{
  std::string name;
  Mesh reference;
  unsigned int k;
};

// The input of size index i (0: fandisk, 1: bunny00, 2, 3: bunny00 with 1, 2
// Loop steps); false if unreadable.
static bool make_input(int i, Input& in)
{
  if(i == 0)
  {
    in = {"fandisk", Mesh(), 30};
    return read_mesh("meshes/fandisk.off", in.reference);
  }
  in = {"bunny00", Mesh(), 20};
  if(!read_mesh("meshes/bunny00.off", in.reference))
    return false;
  if(i > 1)
  {
    CGAL::Subdivision_method_3::Loop_subdivision(in.reference, CGAL::parameters::number_of_iterations(i - 1));
    in.name += " + Loop x" + std::to_string(i - 1);
  }
  return true;
}
static const int number_of_sizes = 4;

static Mesh noisy_copy(const Mesh& reference)
{
  Mesh noisy = reference;
  PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
  return noisy;
}

static int size_rows(int i)
{
  Input in;
  if(!make_input(i, in))
    return 1;
  const Mesh noisy = noisy_copy(in.reference);
  auto print = [&](const char* threads, const Row& r) {
    std::printf(
        "| %s | %zu | %s | %.4f | %.4f | %.4f | %.1f, %.0f | %.4f | %.4f | %.5f | %.3f | %u | %.3e | %.3f | %.0f |\n",
        in.name.c_str(), (std::size_t)num_faces(noisy), threads, r.flat, r.reorder, r.neighborhoods, r.mean_neighbors,
        r.max_neighbors, r.paths, r.pass, r.update, r.whole, in.k, r.whole / (double(num_faces(noisy)) * in.k), r.En,
        process_peak_mib());
    std::fflush(stdout);
  };
  print("1", measure<CGAL::Sequential_tag>(noisy, in.reference, in.k));
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  print("2", measure<CGAL::Parallel_tag>(noisy, in.reference, in.k));
#endif
  return 0;
}

static int memory_row(int i)
{
  Input in;
  if(!make_input(i, in))
    return 1;
  Mesh mesh = noisy_copy(in.reference);
  in.reference = Mesh(); // only the mesh being denoised stays
  in.reference.collect_garbage();
  const double before = denoising_support::status_mib("VmRSS:");
  {
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5";
  } // resets VmHWM to the current size
  const double t = seconds([&] {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    PMP::intrinsic_denoising<CGAL::Parallel_tag>(
        mesh, CGAL::parameters::number_of_iterations(in.k).automatic_parameters(false));
#else
    PMP::intrinsic_denoising<CGAL::Sequential_tag>(
        mesh, CGAL::parameters::number_of_iterations(in.k).automatic_parameters(false));
#endif
  });
  std::printf("| %s | %zu | %u | %.3f | %.0f | %.0f | %.0f | %.0f |\n", in.name.c_str(), (std::size_t)num_faces(mesh),
              in.k, t, before, denoising_support::status_mib("VmHWM:"),
              denoising_support::status_mib("VmHWM:") - before, process_peak_mib());
  std::fflush(stdout);
  return 0;
}

// Fandisk refined by i Loop steps, denoised with 2 threads (fixed defaults,
// k 20; best of 3 runs, 2 from 200,000 faces on).
static int family_row(int i)
{
  Mesh reference;
  if(!read_mesh("meshes/fandisk.off", reference))
    return 1;
  if(i > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(reference, CGAL::parameters::number_of_iterations(i));
  const Mesh noisy = noisy_copy(reference);
  const unsigned int k = 20;
  const std::size_t n = num_faces(noisy);
  double mean_neighbors = 0.;
  {
    const auto np = CGAL::parameters::default_values();
    const D::Mesh_maps<Mesh, decltype(np)> maps(noisy, np);
    const D::Flat_mesh m = maps.flat(noisy, "speed_summary");
    D::Face_data fd;
    D::compute_face_data<CGAL::Sequential_tag>(m, m.points, fd);
    const double d = D::mean_adjacent_centroid_distance(m, fd);
    const D::Csr nb = D::geometric_neighborhoods<CGAL::Sequential_tag>(m, fd.centroids, 4 * d);
    mean_neighbors = double(nb.items.size()) / double(n);
  }
  Mesh result;
  const double t = seconds(
      [&] {
        result = noisy;
#ifdef CGAL_LINKED_WITH_TBB
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        PMP::intrinsic_denoising<CGAL::Parallel_tag>(
            result, CGAL::parameters::number_of_iterations(k).automatic_parameters(false));
#else
        PMP::intrinsic_denoising<CGAL::Sequential_tag>(
            result, CGAL::parameters::number_of_iterations(k).automatic_parameters(false));
#endif
      },
      n < 200000 ? 3 : 2);
  const double En = PMP::face_normal_error(result, reference);
  std::printf("| fandisk + Loop x%d | %zu | %.1f | %.3f | %u | %.3e | %.3f |\n", i, n, mean_neighbors, t, k,
              t / (double(n) * k), En);
  std::fflush(stdout);
  return 0;
}

// Wall and CPU seconds of f (best wall of `repeat` runs, CPU of that run).
template <typename F>
static std::pair<double, double> wall_and_cpu(const F& f, int repeat)
{
  std::pair<double, double> best(1e30, 0.);
  for(int r = 0; r < repeat; ++r)
  {
    const std::clock_t c0 = std::clock();
    const denoising_support::Stopwatch watch;
    f();
    const double wall = watch.seconds();
    if(wall < best.first)
      best = {wall, double(std::clock() - c0) / CLOCKS_PER_SEC};
  }
  return best;
}

static void methods_table(const std::string& self)
{
  Mesh reference;
  if(!read_mesh("meshes/fandisk.off", reference))
    return;
  const Mesh noisy = noisy_copy(reference);
  std::printf(
      "| method (fandisk, sigma_E 0.3, seed 1) | parameters | threads | seconds (wall, best of 5) | CPU seconds | "
      "E_n (deg) |\n|---|---|---|---|---|---|\n");
  auto row = [&](const char* name, const std::string& params, auto&& run) {
    for(int threads = 1; threads <= 2; ++threads)
    {
      Mesh result;
      std::pair<double, double> t;
#ifdef CGAL_LINKED_WITH_TBB
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#else
      if(threads == 2)
        break;
#endif
      t = wall_and_cpu(
          [&] {
            result = noisy;
            run(result, threads);
          },
          5);
      std::printf("| %s | %s | %d | %.4f | %.4f | %.3f |\n", name, params.c_str(), threads, t.first, t.second,
                  PMP::face_normal_error(result, reference));
      std::fflush(stdout);
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  typedef CGAL::Parallel_tag Par;
#else
  typedef CGAL::Sequential_tag Par;
#endif
  row("intrinsic_denoising", "fixed defaults (automatic_parameters(false): r 4d, sigma 0.4, k 30, v 2)",
      [](Mesh& m, int threads) {
        const auto np = CGAL::parameters::automatic_parameters(false);
        if(threads == 1)
          PMP::intrinsic_denoising<CGAL::Sequential_tag>(m, np);
        else
          PMP::intrinsic_denoising<Par>(m, np);
      });
  row("intrinsic_denoising", "automatic (the default; noise estimate, stopping rule)", [](Mesh& m, int threads) {
    if(threads == 1)
      PMP::intrinsic_denoising<CGAL::Sequential_tag>(m);
    else
      PMP::intrinsic_denoising<Par>(m);
  });
  for(const Fast_setting& f : fast_settings)
  {
    char params[128];
    std::snprintf(params, sizeof params, "r %gd, sigma %.2f, k %u, v %u", f.relative_radius, f.sigma, f.k, f.v);
    row(f.name, params, [&f](Mesh& m, int threads) {
      const auto np = CGAL::parameters::relative_neighbor_radius(f.relative_radius)
                          .sigma_spatial(f.sigma)
                          .sigma_range(f.sigma)
                          .number_of_iterations(f.k)
                          .vertex_iterations(f.v);
      if(threads == 1)
        PMP::intrinsic_denoising<CGAL::Sequential_tag>(m, np);
      else
        PMP::intrinsic_denoising<Par>(m, np);
    });
  }
  row("SRML07 (fast_feature_preserving_denoising)", "defaults (T 0.5, k 20, v 10)", [](Mesh& m, int threads) {
    if(threads == 1)
      PMP::fast_feature_preserving_denoising<CGAL::Sequential_tag>(m);
    else
      PMP::fast_feature_preserving_denoising<Par>(m);
  });
  row("ZFAT11 (bilateral_normal_denoising)", "defaults (sigma_s d, sigma_r 0.35, k 20, v 10)",
      [](Mesh& m, int threads) {
        if(threads == 1)
          PMP::bilateral_normal_denoising<CGAL::Sequential_tag>(m);
        else
          PMP::bilateral_normal_denoising<Par>(m);
      });
  // MeshSDFilter, if its optional benchmark was built next to this program
  const std::string dir = self.substr(0, self.find_last_of('/') + 1);
  const std::string sdf = dir + "meshsdfilter_benchmark";
  if(std::ifstream(sdf).good())
  {
    std::fflush(stdout);
    if(std::system((sdf + " --row").c_str()) != 0)
      std::printf("| MeshSDFilter | (its benchmark failed) | | | | |\n");
  }
  else
    std::printf("| MeshSDFilter | not built (needs Debian's libmeshsdfilter-dev) | | | | |\n");
  std::fflush(stdout);
}

int main(int argc, char** argv)
{
  const std::string self = argv[0];
  if(argc > 2 && std::string(argv[1]) == "--size")
    return size_rows(std::atoi(argv[2]));
  if(argc > 2 && std::string(argv[1]) == "--memory")
    return memory_row(std::atoi(argv[2]));
  if(argc > 2 && std::string(argv[1]) == "--family")
    return family_row(std::atoi(argv[2]));
  if(argc > 1 && std::string(argv[1]) == "--fast-grid")
  {
    Mesh fandisk;
    return read_mesh("meshes/fandisk.off", fandisk) ? fast_grid(fandisk) : 1;
  }
  const std::size_t max_faces = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : std::size_t(-1);
  const std::size_t faces_of_size[number_of_sizes] = {12946, 75408, 301632, 1206528};

  std::printf("### Methods on noisy fandisk\n\n");
  methods_table(self);

  std::printf("\n### Stages and sizes (each size in its own process)\n\n");
  std::printf(
      "| mesh | faces | threads | flat copy + face data (s) | Morton reorder (s) | neighbourhoods r=4d (s) | "
      "neighbours / face (mean, "
      "max) | square-pattern paths (s) | one filter pass (s) | one vertex update, v=2 (s) | whole denoise (s) | k "
      "| s / face / iteration | E_n (deg) | process peak RSS (MiB) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for(int i = 0; i < number_of_sizes; ++i)
    if(faces_of_size[i] <= max_faces && std::system((self + " --size " + std::to_string(i)).c_str()) != 0)
      std::printf("| (size %d failed) |\n", i);

  std::printf("\n### Memory of the whole denoise (2 threads, each size in its own process)\n\n");
  std::printf(
      "| mesh | faces | k | seconds | RSS before (MiB) | peak during denoise (MiB) | denoise's own peak (MiB) | "
      "process peak (MiB) |\n|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for(int i = 0; i < number_of_sizes; ++i)
    if(faces_of_size[i] <= max_faces && std::system((self + " --memory " + std::to_string(i)).c_str()) != 0)
      std::printf("| (size %d failed) |\n", i);

  std::printf("\n### Linearity on one shape (fandisk refined by Loop subdivision, 2 threads, each size in its own "
              "process)\n\n");
  std::printf("| mesh | faces | neighbours / face at r=4d | whole denoise (s) | k | s / face / iteration | E_n (deg) "
              "|\n|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  const std::size_t family_faces[4] = {12946, 51784, 207136, 828544};
  for(int i = 0; i < 4; ++i)
    if(family_faces[i] <= max_faces && std::system((self + " --family " + std::to_string(i)).c_str()) != 0)
      std::printf("| (fandisk + Loop x%d failed) |\n", i);
  return 0;
}
