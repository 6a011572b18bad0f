// Denoises one noisy mesh with the two path strategies of the intrinsic
// filter, exact geodesic paths and the paper's square pattern (figure 2), with
// the same parameters, and prints per strategy E_n, E_v and the seconds of
// path construction and of filtering.
//
// Usage: geodesic_vs_square_pattern [clean_mesh [report.html]]
//   The clean mesh (default: CGAL's fandisk) gets seeded Gaussian noise
//   (sigma_E = 0.3, seed 1) and serves as the reference of E_n and E_v.
//   With report.html, also writes the comparison page (comparison_report.h) of
//   the noisy mesh, both results and the reference, and report.csv.
//
// "Paths" is the time of a call with zero iterations (reading the mesh, face
// data, neighbourhoods and paths); "filtering" is the rest of the full call
// (30 normal passes and vertex updates).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/comparison_report.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

template <typename F>
static double seconds(const F& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? std::string(argv[1]) : CGAL::data_file_path("meshes/fandisk.off");
  Mesh reference;
  if(!CGAL::IO::read_polygon_mesh(path, reference) || reference.is_empty())
  {
    std::cerr << "error: cannot read a non-empty polygon mesh from '" << path << "'\n";
    return 1;
  }
  Mesh noisy = reference;
  try
  {
    PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
    std::cout << path << ": " << num_faces(noisy) << " faces, Gaussian noise sigma_E = 0.3 (seed 1): E_n "
              << PMP::face_normal_error(noisy, reference) << " deg, E_v "
              << PMP::vertex_position_error(noisy, reference) << "\n";
    std::cout << "parameters: k = 30, v = 2, r = 4d, sigma_s = sigma_r = 0.4, Parallel_if_available_tag\n\n";
    denoising_support::Report report;
    report.title = path + ", noise sigma_E 0.3 (seed 1): exact geodesic paths against the square pattern "
                          "(k = 30, v = 2, r = 4d, sigma = 0.4)";
    report.entries.push_back(denoising_support::make_entry("noisy", noisy, &reference));
    report.entries.back().En = PMP::face_normal_error(noisy, reference);
    report.entries.back().Ev = PMP::vertex_position_error(noisy, reference);
    std::printf("%-15s %10s %10s %12s %14s\n", "strategy", "E_n (deg)", "E_v", "paths (s)", "filtering (s)");
    for(const auto strategy : {PMP::Intrinsic_path_strategy::GEODESIC, PMP::Intrinsic_path_strategy::SQUARE_PATTERN})
    {
      const auto common = CGAL::parameters::path_strategy(strategy)
                              .vertex_iterations(2)
                              .relative_neighbor_radius(4.)
                              .sigma_spatial(0.4)
                              .sigma_range(0.4);
      const auto np = common.number_of_iterations(30);
      Mesh setup_only = noisy, denoised = noisy;
      const double t_paths = seconds([&] {
        PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(setup_only, common.number_of_iterations(0));
      });
      const double t_total = seconds([&] { PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(denoised, np); });
      const char* name = strategy == PMP::Intrinsic_path_strategy::GEODESIC ? "geodesic paths" : "square pattern";
      report.entries.push_back(denoising_support::make_entry(name, denoised, &reference));
      report.entries.back().En = PMP::face_normal_error(denoised, reference);
      report.entries.back().Ev = PMP::vertex_position_error(denoised, reference);
      report.entries.back().seconds = t_total;
      std::printf("%-15s %10.3f %10.3e %12.2f %14.2f\n",
                  strategy == PMP::Intrinsic_path_strategy::GEODESIC ? "geodesic" : "square pattern",
                  PMP::face_normal_error(denoised, reference), PMP::vertex_position_error(denoised, reference), t_paths,
                  t_total - t_paths);
    }
    if(argc > 2)
    {
      report.entries.push_back(denoising_support::make_entry("reference", reference, &reference));
      report.entries.back().En = 0.;
      report.entries.back().Ev = 0.;
      const std::string problem = denoising_support::write_report(argv[2], report);
      if(!problem.empty())
      {
        std::cerr << "error: " << problem << "\n";
        return 1;
      }
      std::cout << "\nreport: " << argv[2] << "\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
