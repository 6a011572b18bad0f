// Uses the installed package: denoises the mesh given on the command line
// (noise added with a fixed seed) with the defaults and checks that the
// result is closer to the input mesh than the noisy one. Exit code 0 if so.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: downstream mesh.off\n";
    return 2;
  }
  Mesh clean;
  if(!CGAL::IO::read_polygon_mesh(argv[1], clean) || clean.is_empty())
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  Mesh mesh = clean;
  PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(1));
  const double noisy = PMP::face_normal_error(mesh, clean);
  const PMP::Intrinsic_denoising_report report = PMP::intrinsic_denoising(mesh);
  const double denoised = PMP::face_normal_error(mesh, clean);
  std::cout << "E_n noisy " << noisy << " degrees, denoised " << denoised << " degrees (" << report.iterations
            << " iterations)\n";
  return denoised < noisy ? 0 : 1;
}
