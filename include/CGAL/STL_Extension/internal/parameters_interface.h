// Extension of CGAL's closed list of named parameters.
//
// CGAL 5.5 keeps every named parameter in one guard-less file that
// <CGAL/Named_function_parameters.h> includes three times (tag enums, the
// chaining member functions, the free functions of CGAL::parameters). This
// header has the same path, so, with this package's include directory before
// CGAL's (the normal -I order, CGAL's directory being a system one), it is the
// one found: it pulls in CGAL's own list with #include_next and then appends
// the denoising package's parameters. The package's additions are listed in
// exactly one place: internal/Denoising/core/parameters_list.h.
//
// No include guard on purpose: like the file it extends, it is included once
// per expansion of CGAL_add_named_parameter.

// CGAL's list first, then the package's: the order matters
// clang-format off
#include_next <CGAL/STL_Extension/internal/parameters_interface.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/core/parameters_list.h>
// clang-format on

#ifndef CGAL_PMP_DENOISING_NAMED_PARAMETERS_ADDED
#define CGAL_PMP_DENOISING_NAMED_PARAMETERS_ADDED 1
#endif
