// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Loops over index ranges, sequential or parallel according to a CGAL
// concurrency tag. Every loop body of the package writes only to slots of its
// own indices, so the results are the same for one thread and for many.

#ifndef CGAL_PMP_INTERNAL_DENOISING_PARALLEL_H
#define CGAL_PMP_INTERNAL_DENOISING_PARALLEL_H

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

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

// Gives the pages of freed heap blocks back to the system (glibc; elsewhere
// nothing). The chunks of build_lists grow by reallocation in every thread's
// heap, and once freed their pages would stay resident for the rest of the
// process: on 1.2M faces that is 200 MiB of the square-pattern build (RSS
// after it 731 MiB, 534 MiB after this), which the filter iterations then
// add to.
inline void release_free_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// Builds a list of records for each item 0..n-1, in parallel chunks, and
// hands the chunks in item order to `append(chunk)`, freeing each one right
// after, so that the records exist about once in memory; fills offsets (size
// n + 1; std::length_error if the lists total 2^32 entries or more).
// `make_scratch()` makes the scratch state of one chunk (allocated
// once per chunk); `fill(i, scratch, out)` appends item i's records to `out`.
// A chunk holds at least `min_chunk_size` items and at least n / 64 (so
// there are at most about 64 chunks): few chunks by default, since a chunk's
// scratch may be as large as the mesh; a slow fill with a small scratch takes
// a small minimum, which balances the threads' loads better.
template <typename ConcurrencyTag, typename Record, typename MakeScratch, typename Fill, typename Append>
void build_lists(std::size_t n, std::vector<std::uint32_t>& offsets, const MakeScratch& make_scratch, const Fill& fill,
                 const Append& append, std::size_t min_chunk_size = 2048)
{
  const std::size_t chunk_size = (std::max)((std::max)(min_chunk_size, std::size_t(1)), n / 64 + 1);
  const std::size_t nchunks = (n + chunk_size - 1) / chunk_size;
  const std::size_t sample = 64; // items whose records size the rest of their chunk
  std::vector<std::vector<Record>> chunks(nchunks);
  offsets.assign(n + 1, 0);
  for_each_chunk<ConcurrencyTag>(
      nchunks,
      [&](std::size_t cb, std::size_t ce) {
        auto scratch = make_scratch();
        for(std::size_t c = cb; c < ce; ++c)
        {
          std::vector<Record>& out = chunks[c];
          const std::size_t first = c * chunk_size, last = (std::min)(n, (c + 1) * chunk_size);
          for(std::size_t i = first; i < last; ++i)
          {
            const std::size_t before = out.size();
            fill(i, scratch, out);
            offsets[i + 1] = std::uint32_t(out.size() - before);
            if(i == first + sample - 1 && last - first > 2 * sample)
              out.reserve(out.size() / sample * (last - first) / 8 * 9); // one allocation, 1/8 to spare
          }
        }
      },
      1);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(offsets[i + 1] > (std::numeric_limits<std::uint32_t>::max)() - offsets[i])
      throw std::length_error("more than 2^32 list entries (paths or neighbours) for this mesh and radius");
    offsets[i + 1] += offsets[i];
  }
  for(auto& c : chunks)
  {
    append(c);
    std::vector<Record>().swap(c);
  }
  release_free_memory();
}

// The same, appending the records to `records`.
template <typename ConcurrencyTag, typename Record, typename MakeScratch, typename Fill>
void build_lists(std::size_t n, std::vector<std::uint32_t>& offsets, std::vector<Record>& records,
                 const MakeScratch& make_scratch, const Fill& fill)
{
  records.clear();
  build_lists<ConcurrencyTag, Record>(n, offsets, make_scratch, fill,
                                      [&records, &offsets](const std::vector<Record>& chunk) {
                                        if(records.capacity() < offsets.back())
                                          records.reserve(offsets.back()); // exact: the counts are known by now
                                        records.insert(records.end(), chunk.begin(), chunk.end());
                                      });
}

// The mean of the values that terms(f, add) gives for every face f (one
// call add(x) per value), added in the order of the faces and of the calls,
// as one sequential loop would. With Parallel_tag the values are computed in
// parallel (at most 3 per face kept) and only added in order, so the result
// is bitwise the same; a face with more than 3 values (a non-manifold edge)
// makes the whole computation sequential. Returns 0 if there is no value.
template <typename ConcurrencyTag, typename Terms>
double mean_of_face_terms(std::size_t n, const Terms& terms)
{
  double sum = 0.;
  std::size_t count = 0;
  const auto add = [&sum, &count](double x) {
    sum += x;
    ++count;
  };
  bool in_order = !std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value || n < 4096;
  if(!in_order)
  {
    std::vector<std::array<double, 3>> values(n);
    std::vector<unsigned char> counts(n);
    for_each_chunk<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
      for(std::size_t f = b; f < e; ++f)
      {
        unsigned int c = 0;
        terms(f, [&](double x) {
          if(c < 3)
            values[f][c] = x;
          ++c;
        });
        counts[f] = static_cast<unsigned char>((std::min)(c, 4u));
      }
    });
    in_order = std::find(counts.begin(), counts.end(), static_cast<unsigned char>(4)) != counts.end();
    if(!in_order)
      for(std::size_t f = 0; f < n; ++f)
        for(unsigned int c = 0; c < counts[f]; ++c)
          add(values[f][c]);
  }
  if(in_order)
    for(std::size_t f = 0; f < n; ++f)
      terms(f, add);
  return count == 0 ? 0. : sum / double(count);
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
