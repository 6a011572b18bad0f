// Denoises a mesh with the intrinsic filter (square-pattern paths) in its
// default, automatic mode: the noise level is estimated, sigma_s, sigma_r and
// r are derived from it and a stopping rule ends the iterations. Prints what
// was chosen (the returned report) and, when a noise-free reference is given,
// the errors E_n and E_v.
//
// Usage: denoise_and_report [input [reference]]
//   Without arguments: CGAL's fandisk with seeded Gaussian noise
//   (sigma_E = 0.3, seed 1) is written to ./fandisk_noisy.off and denoised,
//   with fandisk itself as the reference.
// The result is written next to the input, as <input stem>_denoised.off,
// through a temporary file and a rename (never over the input).
// An unreadable, truncated or malformed file, a mesh that is not a triangle
// mesh or has non-finite coordinates: one line on stderr and exit code 1.

#include <denoising_support/mesh_file.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>

#include <chrono>
#include <iostream>
#include <string>

typedef denoise_file::Mesh Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

// One line on std::cerr, exit code 1.
static int fail(const std::string& message)
{
  std::cerr << "error: " << message << "\n";
  return 1;
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
    const std::string problem = denoise_file::read_mesh_file(input, noisy);
    if(!problem.empty())
      return fail(problem);
  }
  else
  {
    reference_path = CGAL::data_file_path("meshes/fandisk.off");
    const std::string problem = denoise_file::read_mesh_file(reference_path, noisy);
    if(!problem.empty())
      return fail(problem);
    PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
    input = "fandisk_noisy.off";
    const std::string written = denoise_file::write_mesh_file(input, noisy);
    if(!written.empty())
      return fail(written);
    std::cout << "noisy input: fandisk + Gaussian noise sigma_E = 0.3 (seed 1), written to " << input << "\n";
  }
  if(!reference_path.empty())
  {
    const std::string problem = denoise_file::read_mesh_file(reference_path, reference);
    if(!problem.empty())
      return fail("reference " + problem);
  }

  Mesh denoised = noisy;
  const auto start = std::chrono::steady_clock::now();
  PMP::Intrinsic_denoising_report report;
  const std::string problem =
      denoise_file::denoise<CGAL::Parallel_if_available_tag>(denoised, CGAL::parameters::default_values(), &report);
  if(!problem.empty())
    return fail(problem);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << "denoised " << num_faces(denoised) << " faces in " << seconds
            << " s (square-pattern paths, default parameters)\n"
            << denoise_file::describe(report);
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
      return fail(std::string("cannot compare with the reference: ") + e.what());
    }
  }
  const std::string output = denoise_file::output_path(input);
  const std::string written = denoise_file::write_mesh_file(output, denoised, input);
  if(!written.empty())
    return fail(written);
  std::cout << "output: " << output << "\n";
  return 0;
}
