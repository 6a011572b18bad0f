// The automatic mode on big meshes against the fixed setting: a mesh of
// CGAL's data set refined by Loop subdivision (bunny00 twice by default:
// 1.2M faces), seeded Gaussian noise along the vertex normals (sigma_E 0.3
// by default, seed 1), denoised with 2 threads by the fixed setting (k 30), by the
// automatic mode (the default: above Selection_rules' sample threshold it
// chooses on a sample of patches) and by the automatic mode on the whole
// mesh (selection_sample_faces(0)). Each run is a child process of its
// own, so that its peak memory is its own; the call's peak is VmHWM reset
// just before the call, less the resident size before it.
//
// Usage: big_mesh_benchmark [MESH [LEVELS [SIGMA_E]]]   all three runs, one table row each
//        big_mesh_benchmark --run MODE MESH LEVELS SIGMA_E   one run (child)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

template <typename NamedParameters>
void denoise(Mesh& mesh, const NamedParameters& np, PMP::Intrinsic_denoising_report& report)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  report = PMP::intrinsic_denoising<CGAL::Parallel_tag>(mesh, np);
#else
  report = PMP::intrinsic_denoising<CGAL::Sequential_tag>(mesh, np);
#endif
}

int run(const std::string& mode, const std::string& name, int levels, double sigma)
{
  Mesh reference;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path(name), reference) || !CGAL::is_triangle_mesh(reference))
  {
    std::fprintf(stderr, "cannot read %s as a triangle mesh\n", name.c_str());
    return 1;
  }
  if(levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(reference, CGAL::parameters::number_of_iterations(levels));
  Mesh mesh = reference;
  PMP::add_gaussian_noise(mesh, sigma, CGAL::parameters::random_seed(1));
  const double noisy_En = PMP::face_normal_error(mesh, reference);
  const double before = denoising_support::status_mib("VmRSS:");
  {
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5";
  } // VmHWM back to the current size
  PMP::Intrinsic_denoising_report report;
  const denoising_support::Stopwatch watch;
  if(mode == "fixed")
    denoise(mesh, CGAL::parameters::automatic_parameters(false), report);
  else if(mode == "auto")
    denoise(mesh, CGAL::parameters::default_values(), report);
  else if(mode == "whole")
    denoise(mesh, CGAL::parameters::selection_sample_faces(0), report);
  else
  {
    std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
    return 1;
  }
  const double seconds = watch.seconds();
  const double call_peak = denoising_support::status_mib("VmHWM:") - before;
  std::printf("| %s x%d, %.2g | %zu | %s | %.2f | %.0f | %.3f | %.3f | %.1f / %.1fd / %u |\n", name.c_str(), levels,
              sigma, std::size_t(num_faces(mesh)), mode.c_str(), seconds, call_peak, noisy_En,
              PMP::face_normal_error(mesh, reference), report.sigma_range, report.relative_neighbor_radius,
              report.iterations);
  std::fflush(stdout);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 6 && std::strcmp(argv[1], "--run") == 0)
    return run(argv[2], argv[3], std::atoi(argv[4]), std::atof(argv[5]));
  const std::string name = argc > 1 ? argv[1] : "meshes/bunny00.off";
  const int levels = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string sigma = argc > 3 ? argv[3] : "0.3";
  std::printf("| mesh, sigma_E | faces | run | seconds | call peak (MiB) | noisy E_n | E_n | sigma / r / k |\n"
              "|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  int status = 0;
  for(const char* mode : {"fixed", "auto", "whole"})
  {
    const std::string command =
        std::string("\"") + argv[0] + "\" --run " + mode + " \"" + name + "\" " + std::to_string(levels) + " " + sigma;
    if(std::system(command.c_str()) != 0)
      status = 1;
  }
  return status;
}
