// Automatic parameters and stopping rule of intrinsic_denoising(),
// measured against a grid search on a set of seeded noisy inputs.
//
// Usage: auto_parameters_benchmark [--grid] [--wide-grid] [--estimates] [--trace] [--only name]
//                                  [--mesh file.off sigma kind]...
//   default:     per input, E_n of the automatic mode (the denoiser's defaults:
//                intrinsic_denoising(mesh)) with what it chose, and E_n of each
//                classic method with its defaults;
//   --grid:      also the best E_n of a grid search over (sigma, r, k) for the
//                same method and its setting, and the ratio (slow: 35 settings
//                of up to 150 iterations per input);
//   --wide-grid: only, per input, the best E_n of a second grid beyond the
//                first (sigma 1.4 to 10, r 1.2 to 2 d, v 1 or 2, k up to 60)
//                next to the best classic default (use with --only);
//   --estimates: only the noise estimates (noisy and noise-free) per input;
//   --trace:     per grid setting, E_n and the stopping signals per iteration
//                (to stderr), for studying the rule;
//   --only name: one input;
//   --mesh:      instead of the built-in inputs, CGAL data set meshes
//                (meshes/file.off) with Gaussian noise sigma (repeatable).
//
// The grid runs the denoiser's own loop (same setup, same pass, same vertex
// update) and reads E_n after every iteration, so k is searched exactly.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/noise_estimate.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/filter/filter_iterations.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>
#include <denoising_support/classic_method_list.h>
#include <denoising_support/synthetic_meshes.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;
typedef CGAL::Parallel_if_available_tag Tag;

struct Input
{
  std::string name, kind, noise;
  Mesh reference, noisy;
};

static bool load(const char* file, Mesh& m)
{
  return denoising_support::read_triangle_mesh(CGAL::data_file_path(std::string("meshes/") + file), m);
}

struct Extra
{
  std::string file, kind;
  double sigma;
};

static std::vector<Input> make_inputs(const std::string& only, const std::vector<Extra>& extras)
{
  struct Spec
  {
    const char* name;
    const char* kind;
    std::function<bool(Mesh&)> make;
    double sigma;
    double impulsive_fraction; // 0: Gaussian noise on every vertex
  };
  const std::vector<Spec> specs = {
      {"fandisk", "CAD", [](Mesh& m) { return load("fandisk.off", m); }, 0.1, 0.},
      {"fandisk", "CAD", [](Mesh& m) { return load("fandisk.off", m); }, 0.2, 0.},
      {"fandisk", "CAD", [](Mesh& m) { return load("fandisk.off", m); }, 0.3, 0.},
      {"fandisk", "CAD", [](Mesh& m) { return load("fandisk.off", m); }, 0.5, 0.2},
      {"octahedron", "synthetic CAD",
       [](Mesh& m) {
         m = denoising_support::graded_octahedron<Mesh>(17, 1.4);
         return true;
       },
       0.3, 0.},
      {"prism", "synthetic CAD",
       [](Mesh& m) {
         m = denoising_support::benchmark_prism<Mesh>();
         return true;
       },
       0.1, 0.},
      {"cube", "synthetic CAD",
       [](Mesh& m) {
         m = denoising_support::cube<Mesh>(24);
         return true;
       },
       0.2, 0.},
      {"turbine", "CAD", [](Mesh& m) { return load("turbine.off", m); }, 0.2, 0.},
      {"mech-holes-shark", "CAD", [](Mesh& m) { return load("mech-holes-shark.off", m); }, 0.3, 0.},
      {"lion-head", "organic", [](Mesh& m) { return load("lion-head.off", m); }, 0.1, 0.},
      {"bear", "organic", [](Mesh& m) { return load("bear.off", m); }, 0.2, 0.},
      {"camel", "organic", [](Mesh& m) { return load("camel.off", m); }, 0.3, 0.},
      {"bunny00", "organic", [](Mesh& m) { return load("bunny00.off", m); }, 0.2, 0.},
  };
  std::vector<Spec> all = extras.empty() ? specs : std::vector<Spec>();
  for(const Extra& e : extras)
  {
    const std::string file = e.file;
    all.push_back({nullptr, nullptr, [file](Mesh& m) { return load(file.c_str(), m); }, e.sigma, 0.});
  }
  std::vector<Input> inputs;
  for(std::size_t i = 0; i < all.size(); ++i)
  {
    Spec s = all[i];
    const std::size_t x = i + extras.size() - all.size(); // index into extras
    if(s.name == nullptr)
    {
      s.name = extras[x].file.c_str();
      s.kind = extras[x].kind.c_str();
    }
    Input in;
    in.name = s.name;
    in.kind = s.kind;
    char buf[64];
    if(s.impulsive_fraction > 0.)
      std::snprintf(buf, sizeof buf, "impulsive %.0f%%, %.1f", 100. * s.impulsive_fraction, s.sigma);
    else
      std::snprintf(buf, sizeof buf, "Gaussian %.1f", s.sigma);
    in.noise = buf;
    if(!only.empty() && only != in.name && only != in.name + " " + in.noise)
      continue;
    if(!s.make(in.reference))
    {
      std::cerr << "cannot read " << s.name << "\n";
      std::exit(1);
    }
    in.noisy = in.reference;
    if(s.impulsive_fraction > 0.)
      PMP::add_impulsive_noise(in.noisy, s.impulsive_fraction, s.sigma, CGAL::parameters::random_seed(1));
    else
      PMP::add_gaussian_noise(in.noisy, s.sigma, CGAL::parameters::random_seed(1));
    inputs.push_back(std::move(in));
  }
  return inputs;
}

static D::Flat_mesh flat(const Mesh& m)
{
  return D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters>(m, CGAL::parameters::default_values())
      .flat(m, "benchmark");
}

// E_n (degrees) of `points` on the connectivity of `m` against reference normals
static double normal_error(const D::Flat_mesh& m, const std::vector<D::Vec3>& points,
                           const std::vector<D::Vec3>& reference_normals)
{
  D::Face_data fd;
  D::compute_face_data<CGAL::Sequential_tag>(m, points, fd);
  return D::mean_angle_degrees(fd.normals, reference_normals);
}

struct Grid_best
{
  double En = 1e30, sigma = 0., radius = 0.;
  unsigned int k = 0, v = 2;
};

struct Grid
{
  std::vector<double> sigmas, radii;
  std::vector<unsigned int> vertex_iterations;
  unsigned int kmax;
};

// The grid of --grid: sigma_s = sigma_r in {0.2, ..., 1.4}, r in {2, ..., 8} d,
// k = 1..150, v = 2.
static Grid standard_grid() { return {{0.2, 0.3, 0.4, 0.5, 0.7, 1.0, 1.4}, {2., 3., 4., 6., 8.}, {2}, 150}; }

// The grid of --wide-grid: where the standard grid stops (its best settings on
// the curved inputs are at its largest sigma and smallest radius), wider
// kernels on smaller radii, and one or two vertex iterations; k = 1..60.
static Grid wide_grid() { return {{1.4, 2., 3., 5., 10.}, {1.2, 1.5, 2.}, {1, 2}, 60}; }

// The grid search: sigma_s = sigma_r in `sigmas`, r in `radii` (in d),
// v in `vertex_iterations`, k = 1..kmax. Returns the best setting.
static Grid_best grid_search(const Input& in, bool trace, const Grid& grid = standard_grid())
{
  const unsigned int kmax = grid.kmax;
  const D::Flat_mesh ref = flat(in.reference);
  Grid_best best;
  for(double r : grid.radii)
  {
    const D::Mesh_maps<Mesh, CGAL::parameters::Default_named_parameters> maps(in.noisy,
                                                                              CGAL::parameters::default_values());
    const auto np = CGAL::parameters::relative_neighbor_radius(r);
    D::Intrinsic_setup base = D::make_intrinsic_setup<Tag>(in.noisy, D::read_filter_options(np), maps, "grid");
    const double L = D::mean_edge_length(base.mesh);
    // the setup may renumber faces (not vertices): reference normals in its order
    D::Face_data ref_fd;
    D::compute_face_data<CGAL::Sequential_tag>(base.mesh, ref.points, ref_fd);
    for(unsigned int v : grid.vertex_iterations)
      for(double sigma : grid.sigmas)
      {
        D::Intrinsic_kernel kernel = base.kernel;
        kernel.sigma_spatial = kernel.sigma_range = sigma;
        std::vector<D::Vec3> points = base.mesh.points;
        const std::vector<D::Vec3> input_points = points;
        std::vector<D::Vec3> previous;
        const std::vector<char> fixed(points.size(), 0);
        D::Fold_safeguard guard;
        guard.enabled = true;
        guard.reference = &base.input_faces.normals;
        D::iterate_filter<Tag>(
            base, kernel, base.input_faces, points, fixed, v, guard, kmax,
            [&](unsigned int k, const std::vector<D::Vec3>& p, std::vector<D::Vec3>& filtered) {
              const double En = normal_error(base.mesh, p, ref_fd.normals);
              if(En < best.En)
                best = {En, sigma, r, k, v};
              if(trace)
              {
                double disp = 0., change = 0.;
                for(std::size_t x = 0; x < p.size(); ++x)
                  disp += D::squared_norm(p[x] - input_points[x]);
                disp = std::sqrt(disp / double(p.size())) / L;
                if(!previous.empty())
                {
                  for(std::size_t f = 0; f < filtered.size(); ++f)
                    change += std::atan2(D::norm(D::cross(filtered[f], previous[f])), D::dot(filtered[f], previous[f]));
                  change = change / double(filtered.size()) * (180. / 3.14159265358979323846);
                }
                std::fprintf(stderr, "%s | %s | r %.0f s %.2f k %2u | En %.3f | disp %.4f | change %.4f\n",
                             in.name.c_str(), in.noise.c_str(), r, sigma, k, En, disp, change);
              }
              previous = filtered;
              return true;
            });
      }
  }
  return best;
}

// E_n of the classic methods with their defaults on `in`, in the order of
// the table's columns (classic_names).
static std::vector<double> classic_errors(const Input& in)
{
  std::vector<double> errors;
  for(const auto& method : denoising_support::classic_methods<CGAL::Sequential_tag, Mesh>())
  {
    Mesh m = in.noisy;
    method.run(m, false);
    errors.push_back(PMP::face_normal_error(m, in.reference));
  }
  return errors;
}

int main(int argc, char** argv)
{
  bool estimates_only = false, trace = false, grid = false, wide = false;
  std::string only;
  std::vector<Extra> extras;
  for(int i = 1; i < argc; ++i)
  {
    if(std::strcmp(argv[i], "--grid") == 0)
      grid = true;
    else if(std::strcmp(argv[i], "--wide-grid") == 0)
      wide = true;
    else if(std::strcmp(argv[i], "--estimates") == 0)
      estimates_only = true;
    else if(std::strcmp(argv[i], "--trace") == 0)
      trace = true;
    else if(std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
    else if(std::strcmp(argv[i], "--mesh") == 0 && i + 3 < argc)
    {
      extras.push_back({argv[i + 1], argv[i + 3], std::atof(argv[i + 2])});
      i += 3;
    }
    else
    {
      std::cerr << "usage: auto_parameters_benchmark [--grid] [--wide-grid] [--estimates] [--trace] [--only name] "
                   "[--mesh file.off sigma kind]...\n";
      return 2;
    }
  }
  const std::vector<Input> inputs = make_inputs(only, extras);
  if(wide)
  {
    std::printf("| input | noise | wide grid best E_n | at (sigma, r/d, k, v) | best classic default E_n (method) "
                "|\n|---|---|---|---|---|\n");
    for(const Input& in : inputs)
    {
      const Grid_best g = grid_search(in, trace, wide_grid());
      const std::vector<double> classic = classic_errors(in);
      const std::size_t best = std::size_t(std::min_element(classic.begin(), classic.end()) - classic.begin());
      const double best_En = classic[best];
      std::printf("| %s | %s | %.3f | (%.1f, %.1f, %u, %u) | %.3f (%s) |\n", in.name.c_str(), in.noise.c_str(), g.En,
                  g.sigma, g.radius, g.k, g.v, best_En,
                  denoising_support::classic_methods<CGAL::Sequential_tag, Mesh>()[best].name);
      std::fflush(stdout);
    }
    return 0;
  }
  if(estimates_only)
  {
    std::printf("| input | kind | noise | faces | estimate q25 | q50 | noise-free q25 | q50 | estimate | median "
                "adjacent L1 normal difference |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for(const Input& in : inputs)
    {
      const D::Flat_mesh a = flat(in.noisy), b = flat(in.reference);
      const auto e25 = D::estimate_noise<Tag>(a, 0.25, 1.), e50 = D::estimate_noise<Tag>(a, 0.5, 1.);
      const auto c25 = D::estimate_noise<Tag>(b, 0.25, 1.), c50 = D::estimate_noise<Tag>(b, 0.5, 1.);
      D::Face_data fd;
      D::compute_face_data<Tag>(a, a.points, fd);
      std::vector<double> diffs;
      for(std::size_t f = 0; f < a.number_of_faces(); ++f)
        D::Face_vertex_adjacency{a}(std::uint32_t(f), [&](std::uint32_t g) {
          if(g > f)
          {
            const D::Vec3 d = fd.normals[g] - fd.normals[f];
            diffs.push_back(std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]));
          }
        });
      std::nth_element(diffs.begin(), diffs.begin() + diffs.size() / 2, diffs.end());
      std::printf("| %s | %s | %s | %zu | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", in.name.c_str(),
                  in.kind.c_str(), in.noise.c_str(), a.number_of_faces(), e25.relative_noise, e50.relative_noise,
                  c25.relative_noise, c50.relative_noise, D::estimate_noise<Tag>(a).relative_noise,
                  diffs[diffs.size() / 2]);
    }
    return 0;
  }
  std::printf("| input | kind | noise | faces | noisy E_n | auto E_n | residual RMS | - | candidates (sigma/r/k, kept "
              "starred) | estimate-rule E_n | sigma | r (d) | k | stop | auto s | fixed defaults E_n |"
              "%s FDC03 | JDD03 | SRML07 | ZFAT11 | HS13 | ZDZ15 | best classic | auto / best classic |\n",
              grid ? " grid best E_n | at (sigma, r, k) | auto / grid |" : "");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s---|---|---|---|---|---|---|---|\n",
              grid ? "---|---|---|" : "");
  for(const Input& in : inputs)
  {
    Mesh a = in.noisy;
    const denoising_support::Stopwatch watch;
    const PMP::Intrinsic_denoising_report r = PMP::intrinsic_denoising<Tag>(a);
    const double seconds = watch.seconds();
    const double auto_En = PMP::face_normal_error(a, in.reference);
    const char* stop = r.stop_reason == PMP::Intrinsic_stop_reason::NOISE_LEVEL_REACHED   ? "noise level"
                       : r.stop_reason == PMP::Intrinsic_stop_reason::CONVERGED           ? "converged"
                       : r.stop_reason == PMP::Intrinsic_stop_reason::RESIDUAL_CORRELATED ? "residual"
                                                                                          : "limit";
    // the selection's candidates: sigma / r / iterations, the kept one starred
    std::string schedule;
    for(std::size_t c = 0; c < r.candidates.size(); ++c)
    {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s%.1f/%.0fd/%u", c == r.chosen_candidate ? "*" : "", r.candidates[c].sigma,
                    r.candidates[c].relative_neighbor_radius, r.candidates[c].iterations);
      schedule += (c > 0 ? " " : "") + std::string(buf);
    }
    // what the rule of a given kernel gives (sigma from the noise estimate)
    std::string first;
    {
      Mesh f = in.noisy;
      const D::Flat_mesh fm = flat(in.noisy);
      const double sigma = D::automatic_choice(D::estimate_noise<Tag>(fm).relative_noise).kernel.sigma_spatial;
      PMP::intrinsic_denoising<Tag>(f, CGAL::parameters::sigma_spatial(sigma).sigma_range(sigma));
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3f", PMP::face_normal_error(f, in.reference));
      first = buf;
    }
    std::printf("| %s | %s | %s | %zu | %.3f | **%.3f** | %.3f | %.3f | %s | %s | %.3f | %.2f | %u | %s | %.2f |",
                in.name.c_str(), in.kind.c_str(), in.noise.c_str(), std::size_t(num_faces(a)),
                PMP::face_normal_error(in.noisy, in.reference), auto_En, r.noise_level, 0., schedule.c_str(),
                first.c_str(), r.sigma_spatial, r.relative_neighbor_radius, r.iterations, stop, seconds);
    Mesh fixed = in.noisy;
    PMP::intrinsic_denoising<Tag>(fixed, CGAL::parameters::automatic_parameters(false));
    std::printf(" %.3f |", PMP::face_normal_error(fixed, in.reference));
    std::fflush(stdout);
    if(grid)
    {
      const Grid_best g = grid_search(in, trace);
      std::printf(" %.3f | (%.2f, %.0f, %u) | %.3f |", g.En, g.sigma, g.radius, g.k, auto_En / g.En);
    }
    const std::vector<double> classic = classic_errors(in);
    for(const double En : classic)
      std::printf(" %.3f |", En);
    const double best_classic = *std::min_element(classic.begin(), classic.end());
    std::printf(" %.3f | %.3f |\n", best_classic, auto_En / best_classic);
    std::fflush(stdout);
  }
  return 0;
}
