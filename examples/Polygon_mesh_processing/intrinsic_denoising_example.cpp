// Reads a triangle mesh, denoises it with the defaults of intrinsic_denoising()
// (the automatic mode) and writes the result.
//
// Usage: intrinsic_denoising_example [input [output]]
//   Without an input: CGAL's fandisk with seeded Gaussian noise (sigma_E = 0.3).
//   The output defaults to denoised.off in the working directory.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <stdexcept>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  const std::string output = argc > 2 ? argv[2] : "denoised.off";

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a readable triangle mesh\n";
    return 1;
  }
  if(argc <= 1)
    PMP::add_gaussian_noise(mesh, 0.3, CGAL::parameters::random_seed(1));

  try
  {
    PMP::intrinsic_denoising(mesh);
  }
  catch(const std::invalid_argument& e) // e.g. a non-finite coordinate
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }

  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "error: cannot write " << output << "\n";
    return 1;
  }
  std::cout << "denoised " << num_faces(mesh) << " faces, written to " << output << "\n";
  return 0;
}
