// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Entry point for the package's named parameters. Include this (all public
// headers of the package do) rather than <CGAL/Named_function_parameters.h>.
// The enumerations some of them take are in denoising_types.h.

#ifndef CGAL_PMP_INTERNAL_DENOISING_NAMED_PARAMETERS_H
#define CGAL_PMP_INTERNAL_DENOISING_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#ifndef CGAL_PMP_DENOISING_NAMED_PARAMETERS_ADDED
#error "The denoising package's named parameters are missing: CGAL's \
<CGAL/STL_Extension/internal/parameters_interface.h> was found before the \
package's own. Put the package's include directory before CGAL's (-I, not \
-isystem) on the include path."
#endif

// the enumerations the named parameters take
#include <CGAL/Polygon_mesh_processing/denoising_types.h>

#endif
