// libFuzzer harness: the bytes are a mesh file in the format FUZZ_FORMAT
// ("off", "obj", "ply" or "stl": one executable each) given to the
// command-line program's path (support/include/denoising_support/mesh_file.h):
// read and validate, then denoise. Documented outcomes only: a one-line
// message for a bad file, or a denoised mesh with finite coordinates. Anything
// else (a crash, a sanitizer report, an exception escaping, a NaN) is a bug.

#include <denoising_support/mesh_file.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#ifndef FUZZ_FORMAT
#define FUZZ_FORMAT "off"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::istringstream in(bytes);
  denoising_support::Mesh mesh;
  const std::string problem = denoising_support::read_mesh(in, FUZZ_FORMAT, size, mesh);
  if(!problem.empty())
  {
    if(problem.find('\n') != std::string::npos || !mesh.is_empty())
      std::abort();
    return 0;
  }
  // a valid mesh: denoising must succeed and give finite coordinates
  if(num_faces(mesh) > 2000)
    return 0; // keep each input fast; the size does not change the code paths
  const std::string failure = denoising_support::denoise(mesh, CGAL::parameters::number_of_iterations(3));
  if(!failure.empty())
  {
    std::fprintf(stderr, "denoising a valid mesh failed: %s\n", failure.c_str());
    std::abort();
  }
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
    {
      std::fprintf(stderr, "denoising produced a non-finite coordinate\n");
      std::abort();
    }
  }
  return 0;
}
