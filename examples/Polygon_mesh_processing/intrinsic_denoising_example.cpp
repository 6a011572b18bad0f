// Denoises a mesh with the intrinsic filter (square-pattern paths) and, when a
// noise-free reference is given, prints the errors E_n and E_v.
//
// Usage: intrinsic_denoising_example [input [reference]]
//   Without arguments: CGAL's fandisk with seeded Gaussian noise
//   (sigma_E = 0.3, seed 1) is written to ./fandisk_noisy.off and denoised,
//   with fandisk itself as the reference.
// The result is written next to the input, as <input stem>_denoised.off.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

static bool read_mesh(const std::string& path, Mesh& mesh)
{
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
  {
    std::cerr << "error: cannot read a non-empty polygon mesh from '" << path << "'\n";
    return false;
  }
  return true;
}

// Writes to a temporary file first, so no half-written output is ever left.
static bool write_mesh(const std::string& path, const Mesh& mesh)
{
  // keep the extension last: it selects the file format
  const std::size_t dot = path.find_last_of('.');
  const std::string tmp = path + ".tmp" + (dot == std::string::npos ? std::string(".off") : path.substr(dot));
  if(!CGAL::IO::write_polygon_mesh(tmp, mesh, CGAL::parameters::stream_precision(17)) ||
     std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    std::cerr << "error: cannot write '" << path << "'\n";
    return false;
  }
  return true;
}

int main(int argc, char** argv)
{
  std::string input, reference_path;
  Mesh noisy, reference;
  if(argc > 1)
  {
    input = argv[1];
    if(argc > 2)
      reference_path = argv[2];
    if(!read_mesh(input, noisy))
      return 1;
  }
  else
  {
    reference_path = CGAL::data_file_path("meshes/fandisk.off");
    if(!read_mesh(reference_path, noisy))
      return 1;
    PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
    input = "fandisk_noisy.off";
    if(!write_mesh(input, noisy))
      return 1;
    std::cout << "noisy input: fandisk + Gaussian noise sigma_E = 0.3 (seed 1), written to " << input << "\n";
  }
  if(!reference_path.empty() && !read_mesh(reference_path, reference))
    return 1;

  Mesh denoised = noisy;
  const auto start = std::chrono::steady_clock::now();
  try
  {
    PMP::intrinsic_denoising<CGAL::Parallel_if_available_tag>(denoised);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << "denoised " << num_faces(denoised) << " faces in " << seconds
            << " s (square-pattern paths, 30 iterations, r = 4d, sigma_s = sigma_r = 0.4)\n";
  if(!reference_path.empty())
  {
    try
    {
      std::cout << "E_n (degrees): noisy " << PMP::face_normal_error(noisy, reference) << ", denoised "
                << PMP::face_normal_error(denoised, reference) << "\n";
      std::cout << "E_v: noisy " << PMP::vertex_position_error(noisy, reference) << ", denoised "
                << PMP::vertex_position_error(denoised, reference) << "\n";
    }
    catch(const std::exception& e)
    {
      std::cerr << "error: cannot compare with the reference: " << e.what() << "\n";
      return 1;
    }
  }
  const std::size_t dot = input.find_last_of('.');
  const std::string output = (dot == std::string::npos ? input : input.substr(0, dot)) + "_denoised.off";
  if(!write_mesh(output, denoised))
    return 1;
  std::cout << "output: " << output << "\n";
  return 0;
}
