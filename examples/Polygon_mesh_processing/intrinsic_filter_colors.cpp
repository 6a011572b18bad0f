// Filters a noisy per-vertex colour with the general intrinsic filter and its
// presets, and prints, per filter, how much noise is left on each side of a
// colour edge and how sharp the edge stays: the filter is not only for normals.
//
// Usage: intrinsic_filter_colors
//   A 40 x 40 plane grid coloured red for x < 0.5 and blue beyond, with seeded
//   Gaussian noise (sigma 0.15 per channel).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/intrinsic_filter.h>

#include <denoising_support/synthetic_meshes.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index V;
typedef std::array<double, 3> Color;
namespace PMP = CGAL::Polygon_mesh_processing;

// Noise left (RMS distance to the true colour, over vertices at least 0.1 from
// the edge) and edge contrast (distance between the mean colours of the two
// one-cell strips along the edge; 1.13 when perfectly sharp).
static void report(const char* name, const Mesh& mesh, Mesh::Property_map<V, Color> color)
{
  const Color red = {0.9, 0.1, 0.1}, blue = {0.1, 0.1, 0.9};
  double noise = 0;
  int n_noise = 0, n_left = 0, n_right = 0;
  Color left = {0, 0, 0}, right = {0, 0, 0};
  for(V v : vertices(mesh))
  {
    const double x = mesh.point(v).x();
    const Color& c = color[v];
    const Color& truth = x < 0.5 ? red : blue;
    if(std::abs(x - 0.5) > 0.1)
    {
      for(int k = 0; k < 3; ++k)
        noise += (c[k] - truth[k]) * (c[k] - truth[k]);
      ++n_noise;
    }
    else if(x < 0.5 && x > 0.5 - 0.03)
    {
      for(int k = 0; k < 3; ++k)
        left[k] += c[k];
      ++n_left;
    }
    else if(x >= 0.5 && x < 0.5 + 0.03)
    {
      for(int k = 0; k < 3; ++k)
        right[k] += c[k];
      ++n_right;
    }
  }
  double contrast = 0;
  for(int k = 0; k < 3; ++k)
    contrast += std::pow(left[k] / n_left - right[k] / n_right, 2);
  std::printf("| %-34s | %.4f | %.3f |\n", name, std::sqrt(noise / n_noise), std::sqrt(contrast));
}

int main()
{
  Mesh mesh = denoising_support::plane_grid<Mesh>(40);
  auto noisy = mesh.add_property_map<V, Color>("v:noisy").first;
  auto out = mesh.add_property_map<V, Color>("v:out").first;
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0., 0.15);
  for(V v : vertices(mesh))
  {
    const bool is_red = mesh.point(v).x() < 0.5;
    noisy[v] = {(is_red ? 0.9 : 0.1) + noise(rng), 0.1 + noise(rng), (is_red ? 0.1 : 0.9) + noise(rng)};
  }
  const double r = 0.08; // neighbourhood radius, about 3 cells
  std::printf("| filter (3 iterations, r = %.2f)    | noise left (RMS) | edge contrast |\n|---|---|---|\n", r);
  report("noisy input", mesh, noisy);
  auto run = [&](const char* name, const auto& np) {
    PMP::intrinsic_filter(mesh, noisy, out, np.neighbor_radius(r).number_of_iterations(3));
    report(name, mesh, out);
  };
  run("Gaussian (bilateral, sigma_r = 1e3)", PMP::bilateral_filter_parameters(0.04, 1e3));
  run("bilateral (eq. 5)", PMP::bilateral_filter_parameters(0.04, 0.3));
  run("geodesic (eq. 6)", PMP::geodesic_filter_parameters(0.3));
  run("propagation (eq. 7)", PMP::propagation_filter_parameters(0.3, 0.3));
  run("intrinsic, L1 (n = m = 1)", CGAL::parameters::sigma_spatial(0.5).sigma_range(0.5));
  return 0;
}
