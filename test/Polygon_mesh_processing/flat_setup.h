// A mesh as the denoiser sees it before the paths, for the tests of the
// internal stages.

#ifndef DENOISING_TEST_FLAT_SETUP_H
#define DENOISING_TEST_FLAT_SETUP_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/face_data.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/flat_mesh.h>

namespace D = CGAL::Polygon_mesh_processing::internal::Denoising;

// A mesh as the denoiser sees it before the paths: its flat copy, the face
// data and the paper's radius r = 4d.
template <typename Tag = CGAL::Sequential_tag,
          typename Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>>
struct Flat_setup
{
  D::Flat_mesh m;
  D::Face_data fd;
  double r = 0.;
  explicit Flat_setup(const Mesh& mesh)
      : m(D::make_flat_mesh(mesh, get(CGAL::vertex_point, mesh), get(CGAL::vertex_index, mesh),
                            get(CGAL::face_index, mesh), "test"))
  {
    D::compute_face_data<Tag>(m, m.points, fd);
    r = 4. * D::mean_adjacent_centroid_distance(m, fd);
  }
};

#endif
