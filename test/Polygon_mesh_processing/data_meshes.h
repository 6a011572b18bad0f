// Meshes of CGAL's data set for the tests, each read once.

#ifndef DENOISING_TEST_DATA_MESHES_H
#define DENOISING_TEST_DATA_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <map>
#include <stdexcept>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Data_mesh;

// The data set's mesh `name` (for instance "meshes/fandisk.off"), read on
// the first call; throws if it cannot be read or is empty.
inline const Data_mesh& data_mesh(const std::string& name)
{
  static std::map<std::string, Data_mesh> meshes;
  const auto found = meshes.find(name);
  if(found != meshes.end())
    return found->second;
  Data_mesh m;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path(name), m) || m.is_empty())
    throw std::runtime_error("cannot read " + name);
  return meshes.emplace(name, std::move(m)).first->second;
}

#endif
