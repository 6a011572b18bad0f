// File I/O of the command-line tool and the Python module on a big mesh:
// CGAL's bunny00 refined by Loop subdivision (two levels by default: 1.2M
// faces), written to a temporary OFF file, then read back and written again
// with the support code (denoising_support/mesh_file.h: bounded, checked
// reading; atomic writing), best of three runs, next to CGAL's own
// read_polygon_mesh() and write_polygon_mesh() on the same file.
//
// Usage: io_benchmark [LEVELS] [DIR]   (DIR: where the temporary files go,
// default the system's temporary directory)

#include <denoising_support/benchmark_common.h>
#include <denoising_support/mesh_file.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

namespace {

double best_of_three(const std::function<void()>& f)
{
  double best = 1e30;
  for(int i = 0; i < 3; ++i)
  {
    denoising_support::Stopwatch w;
    f();
    best = std::min(best, w.seconds());
  }
  return best;
}

} // namespace

int main(int argc, char** argv)
{
  namespace df = denoising_support;
  const int levels = argc > 1 ? std::atoi(argv[1]) : 2;
  const std::filesystem::path dir = argc > 2 ? std::filesystem::path(argv[2]) : std::filesystem::temp_directory_path();
  df::Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/bunny00.off"), mesh))
  {
    std::fprintf(stderr, "cannot read bunny00.off\n");
    return 1;
  }
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  const double million = double(num_faces(mesh)) / 1e6;
  const std::string file = (dir / "io_benchmark_input.off").string(), out = (dir / "io_benchmark_output.off").string();
  if(const std::string problem = df::write_mesh_file(file, mesh); !problem.empty())
  {
    std::fprintf(stderr, "%s\n", problem.c_str());
    return 1;
  }
  std::printf("bunny00, %d Loop levels: %zu vertices, %zu faces, %.1f MB OFF\n", levels,
              std::size_t(num_vertices(mesh)), std::size_t(num_faces(mesh)),
              double(std::filesystem::file_size(file)) / 1e6);
  std::string problem;
  const double read = best_of_three([&] {
    df::Mesh m;
    problem = df::read_mesh_file(file, m);
  });
  if(!problem.empty())
  {
    std::fprintf(stderr, "%s\n", problem.c_str());
    return 1;
  }
  const double write = best_of_three([&] { problem = df::write_mesh_file(out, mesh); });
  const double cgal_read = best_of_three([&] {
    df::Mesh m;
    CGAL::IO::read_polygon_mesh(file, m);
  });
  const double cgal_write =
      best_of_three([&] { CGAL::IO::write_polygon_mesh(out, mesh, CGAL::parameters::stream_precision(17)); });
  std::printf("| | read (s) | s per million faces | write (s) | s per million faces |\n|---|---|---|---|---|\n");
  std::printf("| mesh_file.h (checked read, atomic write) | %.2f | %.2f | %.2f | %.2f |\n", read, read / million, write,
              write / million);
  std::printf("| CGAL read_polygon_mesh / write_polygon_mesh | %.2f | %.2f | %.2f | %.2f |\n", cgal_read,
              cgal_read / million, cgal_write, cgal_write / million);
  std::filesystem::remove(file);
  std::filesystem::remove(out);
  return 0;
}
