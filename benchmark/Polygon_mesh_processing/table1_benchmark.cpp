// Reproduction of Table 1 of "Mesh denoising via generalized intrinsic filter
// on 2D manifold": E_n (degrees) and E_v (mesh units) of every method of the
// table on seeded noisy models, each method tuned per model by a small grid
// search (the best E_n wins; its setting is printed).
//
// Usage: table1_benchmark [--out FILE] [--models a,b,..] [--methods a,b,..] [--verbose]
//                         [--meshes DIR] [--report DIR]
//   --out FILE      also write the Markdown report to FILE
//   --meshes DIR    write per model DIR/<model>/{noisy,reference,<method>}.off (the
//                   best setting's output) and <method>_errors.txt (per-face
//                   normal error in degrees, one a line, face order of the OFF)
//   --report DIR    write per model the comparison page DIR/<model>.html (meshes,
//                   linked cameras, heat map, E_n/E_v/seconds table) and DIR/<model>.csv
//   --models        a subset of: octahedron,fandisk,prism,bunny (default: all)
//   --methods       a subset of: FDC03,JDD03,SRML07,ZFAT11,HS13,ZDZ15,ours (default: all)
//   --verbose       every grid setting's errors on stderr
//
// Models and noise (Gaussian along vertex normals, sigma_E relative to the
// mean edge length, seed 1):
//   octahedron: graded_octahedron(17, 1.4) (non-uniform sampling), sigma_E 0.3
//   fandisk:    CGAL's meshes/fandisk.off, sigma_E 0.3
//   prism:      benchmark_prism() (18 edges, 7776 faces), sigma_E 0.1
//   bunny:      CGAL's meshes/bunny00.off, sigma_E 0.2
// Single thread (Sequential_tag). The grids are listed in make_methods().

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/add_noise.h>
#include <CGAL/Polygon_mesh_processing/bilateral_mesh_denoising.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/denoising_error.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/guided_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/intrinsic_denoising.h>
#include <CGAL/Polygon_mesh_processing/l0_denoising.h>
#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <denoising_support/benchmark_common.h>

#include <denoising_support/comparison_report.h>
#include <denoising_support/synthetic_meshes.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

struct Model
{
  std::string name;
  Mesh reference;
  double sigma_E;
  bool large; // the bunny: small grids
  double paper_En[7], paper_Ev[7];
  double paper_Ev_scale;                                                 // the paper's E_v unit (1e-3, 1e-2, 1e-4)
  std::array<double, 3> view_dir{{1., 0.6, 1.4}}, view_up{{0., 1., 0.}}; // camera of the figures
  double heat_max = 15.; // degrees drawn full red in the page's heat map
};

typedef std::vector<double> Setting;

struct Method
{
  std::string name;
  std::function<void(Mesh&, const Setting&)> run;
  std::function<std::string(const Setting&)> describe;
  std::vector<Setting> grid, large_grid; // large_grid: for the bunny
};

struct Result
{
  double En = 1e30, Ev = 0., seconds = 0.;
  Setting setting;
  Mesh output; // kept only with --meshes or --report
};

// the cartesian product of per-parameter value lists
std::vector<Setting> product(const std::vector<std::vector<double>>& values)
{
  std::vector<Setting> out(1);
  for(const auto& list : values)
  {
    std::vector<Setting> next;
    for(const Setting& s : out)
      for(double v : list)
      {
        next.push_back(s);
        next.back().push_back(v);
      }
    out.swap(next);
  }
  return out;
}

std::string format(const char* fmt, const Setting& s)
{
  char buf[256];
  switch(s.size())
  {
  case 1:
    std::snprintf(buf, sizeof(buf), fmt, s[0]);
    break;
  case 2:
    std::snprintf(buf, sizeof(buf), fmt, s[0], s[1]);
    break;
  case 3:
    std::snprintf(buf, sizeof(buf), fmt, s[0], s[1], s[2]);
    break;
  case 4:
    std::snprintf(buf, sizeof(buf), fmt, s[0], s[1], s[2], s[3]);
    break;
  default:
    std::snprintf(buf, sizeof(buf), fmt, s[0], s[1], s[2], s[3], s[4]);
    break;
  }
  return buf;
}

unsigned u(double x) { return unsigned(x + 0.5); }

// The methods in the order of the paper's table, with their grids. Spatial
// sigmas and radii of the classic methods are relative to the mesh (see each
// function's documentation), so one grid serves every model.
std::vector<Method> make_methods()
{
  std::vector<Method> m;
  // FDC03: sigma_c (x mean edge length), sigma_s (x mean edge length; 0 = the
  // paper's adaptive choice), iterations
  m.push_back({"FDC03",
               [](Mesh& mesh, const Setting& s) {
                 auto np = CGAL::parameters::sigma_spatial(s[0]).number_of_iterations(u(s[2]));
                 if(s[1] > 0.)
                   PMP::bilateral_mesh_denoising(mesh, np.sigma_range(s[1]));
                 else
                   PMP::bilateral_mesh_denoising(mesh, np);
               },
               [](const Setting& s) {
                 return s[1] > 0. ? format("sigma_c=%.2gl sigma_s=%.2gl iter=%.0f", s)
                                  : format("sigma_c=%.2gl sigma_s=adaptive(%.0f) iter=%.0f", s);
               },
               product({{0.7, 1., 1.5, 2.}, {0., 0.2, 0.3, 0.6}, {1., 2., 3., 6.}}),
               product({{0.7, 1.}, {0., 0.2, 0.3}, {2., 3.}})});
  // JDD03: sigma_f, sigma_g (x mean edge length)
  m.push_back({"JDD03",
               [](Mesh& mesh, const Setting& s) {
                 PMP::non_iterative_denoising(mesh, CGAL::parameters::sigma_spatial(s[0]).sigma_range(s[1]));
               },
               [](const Setting& s) { return format("sigma_f=%.2gl sigma_g=%.2gl", s); },
               product({{1., 1.5, 2., 3., 4.}, {0.3, 0.5, 1., 2.}}), product({{1., 1.5, 2.}, {1., 2., 3.}})});
  // SRML07: T, n1 (normal iterations), n2 (vertex iterations)
  m.push_back({"SRML07",
               [](Mesh& mesh, const Setting& s) {
                 PMP::fast_feature_preserving_denoising(
                     mesh,
                     CGAL::parameters::normal_threshold(s[0]).number_of_iterations(u(s[1])).vertex_iterations(u(s[2])));
               },
               [](const Setting& s) { return format("T=%.2g n1=%.0f n2=%.0f", s); },
               product({{0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}, {10., 20., 40., 80., 160.}, {10.}}),
               product({{0.3, 0.5, 0.7}, {5., 10., 20.}, {10.}})});
  // ZFAT11 (local): sigma_s (x d), sigma_r, iterations; 10 vertex iterations
  m.push_back({"ZFAT11",
               [](Mesh& mesh, const Setting& s) {
                 PMP::bilateral_normal_denoising(
                     mesh, CGAL::parameters::sigma_spatial(s[0]).sigma_range(s[1]).number_of_iterations(u(s[2])));
               },
               [](const Setting& s) { return format("sigma_s=%.2gd sigma_r=%.2g iter=%.0f", s); },
               product({{1., 2.}, {0.2, 0.35, 0.5}, {10., 20., 40., 80., 160.}}),
               product({{1.}, {0.5, 0.7, 1.}, {5., 10., 20.}})});
  // HS13: lambda factor (lambda = c l^2 gamma), alpha factor
  m.push_back({"HS13",
               [](Mesh& mesh, const Setting& s) {
                 PMP::l0_denoising(mesh, CGAL::parameters::l0_weight(s[0]).regularization_weight(s[1]));
               },
               [](const Setting& s) { return format("lambda=%.3g l^2 gamma, alpha0=%.2g gamma", s); },
               product({{0.03, 0.1, 0.3, 0.6, 1.15}, {0.1}}), product({{0.03, 0.1}, {0.1}})});
  // ZDZ15: radius (x d), sigma_r, iterations; sigma_s = d, 10 vertex iterations
  m.push_back({"ZDZ15",
               [](Mesh& mesh, const Setting& s) {
                 PMP::guided_normal_denoising(
                     mesh,
                     CGAL::parameters::relative_neighbor_radius(s[0]).sigma_range(s[1]).number_of_iterations(u(s[2])));
               },
               [](const Setting& s) { return format("r=%.2gd sigma_r=%.2g iter=%.0f", s); },
               product({{2.}, {0.1, 0.2, 0.35, 0.5}, {10., 20., 40., 80., 160.}}),
               product({{2.}, {0.5, 0.7, 1.}, {3., 5., 10.}})});
  // ours (intrinsic_denoising, square-pattern paths): sigma_s = sigma_r, r (x d), k; v = 2
  m.push_back({"ours",
               [](Mesh& mesh, const Setting& s) {
                 PMP::intrinsic_denoising(mesh, CGAL::parameters::sigma_spatial(s[0])
                                                    .sigma_range(s[0])
                                                    .relative_neighbor_radius(s[1])
                                                    .number_of_iterations(u(s[2]))
                                                    .vertex_iterations(2));
               },
               [](const Setting& s) { return format("sigma=%.2g r=%.2gd k=%.0f v=2", s); },
               [] {
                 std::vector<Setting> g = product({{0.4, 0.5, 0.6, 0.8}, {4.}, {30.}});
                 for(const Setting& s : product({{0.4, 0.5, 0.6, 0.8}, {5.}, {50., 75., 100., 150.}}))
                   g.push_back(s);
                 return g;
               }(),
               product({{0.8, 1.2, 1.6}, {2., 3.}, {5., 10., 20.}})});
  return m;
}

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ','))
    out.push_back(item);
  return out;
}

bool selected(const std::vector<std::string>& list, const std::string& name)
{
  if(list.empty())
    return true;
  for(const std::string& s : list)
    if(s == name)
      return true;
  return false;
}

} // namespace

int main(int argc, char** argv)
{
  std::string out_file, mesh_dir, report_dir;
  std::vector<std::string> model_list, method_list;
  bool verbose = false;
  for(int i = 1; i < argc; ++i)
  {
    if(std::strcmp(argv[i], "--out") == 0 && i + 1 < argc)
      out_file = argv[++i];
    else if(std::strcmp(argv[i], "--models") == 0 && i + 1 < argc)
      model_list = split(argv[++i]);
    else if(std::strcmp(argv[i], "--methods") == 0 && i + 1 < argc)
      method_list = split(argv[++i]);
    else if(std::strcmp(argv[i], "--meshes") == 0 && i + 1 < argc)
      mesh_dir = argv[++i];
    else if(std::strcmp(argv[i], "--report") == 0 && i + 1 < argc)
      report_dir = argv[++i];
    else if(std::strcmp(argv[i], "--verbose") == 0)
      verbose = true;
    else
    {
      std::cerr << "usage: table1_benchmark [--out FILE] [--models a,b] [--methods a,b] [--verbose] [--meshes DIR] "
                   "[--report DIR]\n";
      return 2;
    }
  }

  // the paper's Table 1: FDC03 JDD03 SRML07 ZFAT11 HS13 ZDZ15 ours
  std::vector<Model> models;
  auto load = [](const char* file, Mesh& mesh) {
    const std::string path = CGAL::data_file_path(file);
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
    {
      std::cerr << "cannot read " << path << " (install libcgal-demo)\n";
      return false;
    }
    return true;
  };
  if(selected(model_list, "octahedron"))
    models.push_back({"octahedron",
                      denoising_support::graded_octahedron<Mesh>(17, 1.4),
                      0.3,
                      false,
                      {12.81, 10.65, 6.85, 5.27, 3.33, 3.36, 2.03},
                      {28.02, 14.70, 10.71, 6.28, 10.81, 4.90, 2.91},
                      1e-3});
  if(selected(model_list, "fandisk"))
  {
    Mesh m;
    if(!load("meshes/fandisk.off", m))
      return 1;
    models.push_back({"fandisk",
                      m,
                      0.3,
                      false,
                      {9.73, 9.82, 4.04, 3.35, 5.53, 2.62, 2.27},
                      {18.14, 15.10, 11.02, 8.72, 18.79, 6.29, 6.35},
                      1e-3});
  }
  if(selected(model_list, "prism"))
    models.push_back({"prism",
                      denoising_support::benchmark_prism<Mesh>(),
                      0.1,
                      false,
                      {4.98, 4.48, 3.29, 3.87, 0.71, 0.87, 0.46},
                      {11.89, 10.46, 7.45, 7.9, 3.42, 4.09, 2.77},
                      1e-2});
  if(selected(model_list, "prism"))
  {
    models.back().view_dir = {{1.4, 0.9, 0.9}}; // the prism's axis is z
    models.back().view_up = {{0., 0., 1.}};
    models.back().heat_max = 5.; // errors are small on the prism: a finer colour scale
  }
  if(selected(model_list, "bunny"))
  {
    Mesh m;
    if(!load("meshes/bunny00.off", m))
      return 1;
    models.push_back({"bunny",
                      m,
                      0.2,
                      true,
                      {6.93, 5.81, 5.89, 5.68, 7.21, 5.35, 5.11},
                      {18.36, 9.24, 9.98, 9.35, 10.65, 7.61, 7.26},
                      1e-4});
  }

  const std::vector<Method> all_methods = make_methods();
  std::vector<std::size_t> method_index; // into the paper's columns
  for(std::size_t k = 0; k < all_methods.size(); ++k)
    if(selected(method_list, all_methods[k].name))
      method_index.push_back(k);

  // results[model][method]
  std::vector<std::vector<Result>> results(models.size(), std::vector<Result>(all_methods.size()));
  std::vector<double> noisy_En(models.size()), noisy_Ev(models.size());
  const denoising_support::Stopwatch stopwatch;
  for(std::size_t mi = 0; mi < models.size(); ++mi)
  {
    const Model& model = models[mi];
    Mesh noisy = model.reference;
    PMP::add_gaussian_noise(noisy, model.sigma_E, CGAL::parameters::random_seed(1));
    noisy_En[mi] = PMP::face_normal_error(noisy, model.reference);
    noisy_Ev[mi] = PMP::vertex_position_error(noisy, model.reference);
    for(std::size_t k : method_index)
    {
      const Method& method = all_methods[k];
      const std::vector<Setting>& grid = model.large ? method.large_grid : method.grid;
      Result& best = results[mi][k];
      for(const Setting& s : grid)
      {
        Mesh out = noisy;
        const denoising_support::Stopwatch watch;
        method.run(out, s);
        const double sec = watch.seconds();
        const double En = PMP::face_normal_error(out, model.reference);
        if(verbose)
          std::fprintf(stderr, "%s %s [%s]: E_n %.3f E_v %.4e %.2f s\n", model.name.c_str(), method.name.c_str(),
                       method.describe(s).c_str(), En, PMP::vertex_position_error(out, model.reference), sec);
        if(En < best.En)
        {
          best.En = En;
          best.Ev = PMP::vertex_position_error(out, model.reference);
          best.seconds = sec;
          best.setting = s;
          if(!mesh_dir.empty() || !report_dir.empty())
            best.output = out;
        }
      }
      std::fprintf(stderr, "%s %s: best E_n %.3f [%s] (%zu settings, %.0f s so far)\n", model.name.c_str(),
                   method.name.c_str(), best.En, method.describe(best.setting).c_str(), grid.size(),
                   stopwatch.seconds());
    }
    if(!mesh_dir.empty() || !report_dir.empty())
    {
      std::vector<std::pair<std::string, const Result*>> shown; // noisy, methods, reference
      Result noisy_result, reference_result;
      noisy_result.En = noisy_En[mi];
      noisy_result.Ev = noisy_Ev[mi];
      noisy_result.seconds = std::numeric_limits<double>::quiet_NaN();
      noisy_result.output = noisy;
      reference_result.En = 0.;
      reference_result.Ev = 0.;
      reference_result.seconds = std::numeric_limits<double>::quiet_NaN();
      reference_result.output = model.reference;
      shown.emplace_back("noisy", &noisy_result);
      for(std::size_t k : method_index)
        shown.emplace_back(all_methods[k].name, &results[mi][k]);
      shown.emplace_back("reference", &reference_result);
      denoising_support::Report report;
      char title[256];
      std::snprintf(title, sizeof(title),
                    "%s, Gaussian noise sigma_E %.1f (seed 1): best setting of each method by E_n", model.name.c_str(),
                    model.sigma_E);
      report.title = title;
      report.view_dir = model.view_dir;
      report.view_up = model.view_up;
      report.heat_max = model.heat_max;
      for(const auto& item : shown)
      {
        report.entries.push_back(denoising_support::make_entry(item.first, item.second->output, &model.reference));
        report.entries.back().En = item.second->En;
        report.entries.back().Ev = item.second->Ev;
        report.entries.back().seconds = item.second->seconds;
      }
      if(!mesh_dir.empty())
      {
        const std::string dir = mesh_dir + "/" + model.name;
        std::filesystem::create_directories(dir);
        for(std::size_t e = 0; e < shown.size(); ++e)
        {
          if(!CGAL::IO::write_polygon_mesh(dir + "/" + shown[e].first + ".off", shown[e].second->output,
                                           CGAL::parameters::stream_precision(17)))
          {
            std::cerr << "cannot write " << dir << "/" << shown[e].first << ".off\n";
            return 1;
          }
          std::ofstream err(dir + "/" + shown[e].first + "_errors.txt");
          for(float x : report.entries[e].face_errors)
            err << x << "\n";
        }
      }
      if(!report_dir.empty())
      {
        std::filesystem::create_directories(report_dir);
        const std::string error = denoising_support::write_report(report_dir + "/" + model.name + ".html", report);
        if(!error.empty())
        {
          std::cerr << error << "\n";
          return 1;
        }
      }
    }
  }

  std::ostringstream md;
  char buf[512];
  md << "## Table 1, measured (best of each method's grid by E_n; seed 1; one thread)\n\n";
  md << "| Model | Error |";
  for(std::size_t k : method_index)
    md << " " << all_methods[k].name << " |";
  md << " noisy |\n|---|---|";
  for(std::size_t k = 0; k < method_index.size() + 1; ++k)
    md << "---|";
  md << "\n";
  for(std::size_t mi = 0; mi < models.size(); ++mi)
  {
    const Model& model = models[mi];
    // best per row in bold
    double bestEn = 1e30, bestEv = 1e30;
    for(std::size_t k : method_index)
    {
      bestEn = (std::min)(bestEn, results[mi][k].En);
      bestEv = (std::min)(bestEv, results[mi][k].Ev);
    }
    std::snprintf(buf, sizeof(buf), "| %s (%zu faces, sigma_E %.1f) | E_n (deg) |", model.name.c_str(),
                  (std::size_t)num_faces(model.reference), model.sigma_E);
    md << buf;
    for(std::size_t k : method_index)
    {
      const double v = results[mi][k].En;
      std::snprintf(buf, sizeof(buf), v == bestEn ? " **%.3f** |" : " %.3f |", v);
      md << buf;
    }
    std::snprintf(buf, sizeof(buf), " %.3f |\n", noisy_En[mi]);
    md << buf;
    std::snprintf(buf, sizeof(buf), "| | E_v (x%.0e) |", model.paper_Ev_scale);
    md << buf;
    for(std::size_t k : method_index)
    {
      const double v = results[mi][k].Ev;
      std::snprintf(buf, sizeof(buf), v == bestEv ? " **%.2f** |" : " %.2f |", v / model.paper_Ev_scale);
      md << buf;
    }
    std::snprintf(buf, sizeof(buf), " %.2f |\n", noisy_Ev[mi] / model.paper_Ev_scale);
    md << buf;
    md << "| | seconds |";
    for(std::size_t k : method_index)
    {
      std::snprintf(buf, sizeof(buf), " %.2f |", results[mi][k].seconds);
      md << buf;
    }
    md << " |\n";
  }

  md << "\n## The paper's Table 1 (same columns; E_v is in the model's length unit and the paper's models were scaled "
        "differently, so compare its E_v only within a table)\n\n";
  md << "| Model | Error |";
  for(std::size_t k : method_index)
    md << " " << all_methods[k].name << " |";
  md << "\n|---|---|";
  for(std::size_t k = 0; k < method_index.size(); ++k)
    md << "---|";
  md << "\n";
  for(const Model& model : models)
  {
    md << "| " << model.name << " | E_n |";
    for(std::size_t k : method_index)
    {
      std::snprintf(buf, sizeof(buf), " %.2f |", model.paper_En[k]);
      md << buf;
    }
    std::snprintf(buf, sizeof(buf), "\n| | E_v (x%.0e) |", model.paper_Ev_scale);
    md << buf;
    for(std::size_t k : method_index)
    {
      std::snprintf(buf, sizeof(buf), " %.2f |", model.paper_Ev[k]);
      md << buf;
    }
    md << "\n";
  }

  md << "\n## Best setting per method and model (l: mean edge length, d: mean distance of adjacent centroids)\n\n";
  md << "| Model | Method | setting | grid size |\n|---|---|---|---|\n";
  for(std::size_t mi = 0; mi < models.size(); ++mi)
    for(std::size_t k : method_index)
    {
      const Method& method = all_methods[k];
      md << "| " << models[mi].name << " | " << method.name << " | " << method.describe(results[mi][k].setting) << " | "
         << (models[mi].large ? method.large_grid : method.grid).size() << " |\n";
    }
  std::snprintf(buf, sizeof(buf), "\nTotal run time: %.0f s\n", stopwatch.seconds());
  md << buf;

  std::cout << md.str();
  if(!out_file.empty())
  {
    std::ofstream f(out_file);
    f << md.str();
  }
  return 0;
}
