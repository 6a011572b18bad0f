// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Loops over index ranges, sequential or parallel according to a CGAL
// concurrency tag. Every loop body of the package writes only to slots of its
// own indices, so the results are the same for one thread and for many.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PARALLEL_H
#define CGAL_PMP_INTERNAL_DENOISING_PARALLEL_H

#include <CGAL/tags.h>

#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// Calls body(begin, end) on sub-ranges covering [0, n). A body may allocate
// scratch memory once per call: calls are per chunk, not per index.
template <typename ConcurrencyTag, typename Body>
void for_each_chunk(std::size_t n, const Body& body, std::size_t grain = 256)
{
  if(n == 0)
    return;
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
  (void)grain;
  body(std::size_t(0), n);
#else
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&body](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  }
  else
  {
    body(std::size_t(0), n);
  }
#endif
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
