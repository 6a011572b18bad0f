// Speed summary of the intrinsic denoiser (issue 5): per stage and whole
// denoise, with 1 thread (Sequential_tag) and 2 threads (Parallel_tag, TBB
// limited to 2), on seeded noisy meshes from ~13k to ~1.2M faces: CGAL's
// fandisk, and CGAL's bunny00 refined by 0, 1 and 2 steps of Loop
// subdivision. Prints a Markdown table; each row is measured in this run.
//
// Usage: speed_summary [max_faces]   (default: all sizes)
//
// Peak memory is the process's peak resident size (VmHWM) after the row's
// runs; sizes run in increasing order, so it is the peak of the largest mesh
// so far.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace D = PMP::internal::Denoising;

static double peak_rss_mib()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::atof(line.c_str() + 6) / 1024.;
  return 0.;
}

template <typename F>
static double seconds(const F& f, int repeat = 1)
{
  double best = 1e30;
  for(int r = 0; r < repeat; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = (std::min)(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

struct Row
{
  double flat, neighborhoods, paths, pass, update, whole, En, mean_neighbors, max_neighbors;
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
  D::Csr nb;
  row.neighborhoods = seconds([&] { nb = D::geometric_neighborhoods<Tag>(m, fd.centroids, 4 * d); }, rep);
  row.mean_neighbors = double(nb.items.size()) / double(m.number_of_faces());
  row.max_neighbors = 0;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    row.max_neighbors = (std::max)(row.max_neighbors, double(nb.end(f) - nb.begin(f)));
  D::Path_forest forest;
  row.paths = seconds([&] { forest = D::square_pattern_paths<Tag>(m, fd, nb); }, rep);
  D::Intrinsic_kernel kernel;
  std::vector<D::Vec3> out, points = m.points, c, next;
  row.pass = seconds([&] { D::intrinsic_filter_pass<Tag>(forest, fd.normals, fd.areas, kernel, out); }, rep);
  row.update = seconds([&] { D::update_vertices<Tag>(m, points, out, {}, 2, c, next); }, rep);
  Mesh result;
  row.whole = seconds(
      [&] {
        result = noisy;
        PMP::intrinsic_denoising<Tag>(result, CGAL::parameters::number_of_iterations(k));
      },
      num_faces(noisy) < 100000 ? 3 : 1);
  row.En = PMP::face_normal_error(result, reference);
  return row;
}

int main(int argc, char** argv)
{
  const std::size_t max_faces = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : std::size_t(-1);
  struct Input
  {
    std::string name;
    Mesh reference;
    unsigned int k;
  };
  std::vector<Input> inputs;
  Mesh fandisk, bunny;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk) ||
     !CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/bunny00.off"), bunny))
  {
    std::cerr << "cannot read CGAL's data set (install libcgal-demo)\n";
    return 1;
  }
  inputs.push_back({"fandisk", fandisk, 30});
  inputs.push_back({"bunny00", bunny, 20});
  for(int level = 1; level <= 2; ++level)
  {
    Mesh b = inputs.back().reference;
    CGAL::Subdivision_method_3::Loop_subdivision(b, CGAL::parameters::number_of_iterations(1));
    inputs.push_back({"bunny00 + Loop x" + std::to_string(level), b, 20});
  }

  std::printf("| mesh | faces | threads | flat copy + face data (s) | neighbourhoods r=4d (s) | neighbours / face (mean, max) | square-pattern paths (s) "
              "| one filter pass (s) | one vertex update, v=2 (s) | whole denoise (s) | k | s / face / iteration "
              "| E_n (deg) | peak RSS (MiB) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Input& in : inputs)
  {
    if(num_faces(in.reference) > max_faces)
      continue;
    Mesh noisy = in.reference;
    PMP::add_gaussian_noise(noisy, 0.3, CGAL::parameters::random_seed(1));
    auto print = [&](const char* threads, const Row& r) {
      std::printf("| %s | %zu | %s | %.4f | %.4f | %.1f, %.0f | %.4f | %.4f | %.5f | %.3f | %u | %.3e | %.3f | %.0f |\n",
                  in.name.c_str(), (std::size_t)num_faces(noisy), threads, r.flat, r.neighborhoods, r.mean_neighbors,
                  r.max_neighbors, r.paths, r.pass,
                  r.update, r.whole, in.k, r.whole / (double(num_faces(noisy)) * in.k), r.En, peak_rss_mib());
      std::fflush(stdout);
    };
    print("1", measure<CGAL::Sequential_tag>(noisy, in.reference, in.k));
#ifdef CGAL_LINKED_WITH_TBB
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
      print("2", measure<CGAL::Parallel_tag>(noisy, in.reference, in.k));
    }
#endif
  }
  return 0;
}
