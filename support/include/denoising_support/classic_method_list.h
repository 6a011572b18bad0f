// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The six classic methods of the paper's Table 1 at their defaults, in one
// list: the command-line tool and the benchmarks take them from here.

#ifndef DENOISING_SUPPORT_CLASSIC_METHOD_LIST_H
#define DENOISING_SUPPORT_CLASSIC_METHOD_LIST_H

#include <CGAL/Polygon_mesh_processing/bilateral_mesh_denoising.h>
#include <CGAL/Polygon_mesh_processing/bilateral_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/fast_feature_preserving_denoising.h>
#include <CGAL/Polygon_mesh_processing/guided_normal_denoising.h>
#include <CGAL/Polygon_mesh_processing/l0_denoising.h>
#include <CGAL/Polygon_mesh_processing/non_iterative_denoising.h>

#include <array>
#include <string>

namespace denoising_support {

template <typename Mesh>
struct Classic_method
{
  const char* name;     // the citation key of Table 1
  const char* function; // the package's function
  // the function at its defaults; with `relax`, a normal-filtering method
  // (filters_normals) ends with the relaxation along the surface
  // (named parameter relax_along_surface), the others ignore it
  void (*run)(Mesh&, bool relax);
  bool filters_normals;
};

// In the order of the paper's Table 1.
template <typename ConcurrencyTag, typename Mesh>
const std::array<Classic_method<Mesh>, 6>& classic_methods()
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  static const std::array<Classic_method<Mesh>, 6> list = {{
      {"FDC03", "bilateral_mesh_denoising", [](Mesh& m, bool) { PMP::bilateral_mesh_denoising<ConcurrencyTag>(m); },
       false},
      {"JDD03", "non_iterative_denoising", [](Mesh& m, bool) { PMP::non_iterative_denoising<ConcurrencyTag>(m); },
       false},
      {"SRML07", "fast_feature_preserving_denoising",
       [](Mesh& m, bool relax) {
         PMP::fast_feature_preserving_denoising<ConcurrencyTag>(m, CGAL::parameters::relax_along_surface(relax));
       },
       true},
      {"ZFAT11", "bilateral_normal_denoising",
       [](Mesh& m, bool relax) {
         PMP::bilateral_normal_denoising<ConcurrencyTag>(m, CGAL::parameters::relax_along_surface(relax));
       },
       true},
      {"HS13", "l0_denoising", [](Mesh& m, bool) { PMP::l0_denoising<ConcurrencyTag>(m); }, false},
      {"ZDZ15", "guided_normal_denoising",
       [](Mesh& m, bool relax) {
         PMP::guided_normal_denoising<ConcurrencyTag>(m, CGAL::parameters::relax_along_surface(relax));
       },
       true},
  }};
  return list;
}

// The method named `name` (its citation key), or nullptr.
template <typename ConcurrencyTag, typename Mesh>
const Classic_method<Mesh>* find_classic_method(const std::string& name)
{
  for(const Classic_method<Mesh>& method : classic_methods<ConcurrencyTag, Mesh>())
    if(name == method.name)
      return &method;
  return nullptr;
}

} // namespace denoising_support

#endif
