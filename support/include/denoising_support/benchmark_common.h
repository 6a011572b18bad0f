// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the benchmarks share: reading a triangle mesh of CGAL's data set,
// timing with a wall-clock stopwatch, memory figures of the process and the
// quantiles of their summaries.

#ifndef DENOISING_SUPPORT_BENCHMARK_COMMON_H
#define DENOISING_SUPPORT_BENCHMARK_COMMON_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace denoising_support {

// Reads `path` into `mesh`; false unless it is read and is a non-empty
// triangle mesh.
template <typename Mesh>
bool read_triangle_mesh(const std::string& path, Mesh& mesh)
{
  return CGAL::IO::read_polygon_mesh(path, mesh) && !CGAL::is_empty(mesh) && CGAL::is_triangle_mesh(mesh);
}

// Wall-clock seconds since construction or the last restart().
class Stopwatch
{
public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
  std::chrono::steady_clock::time_point start_;
};

// The q-quantile of `v` by nearest rank (the smallest value with at least a
// fraction q of the values at or below it; q = 0: the smallest); 0 if empty.
inline double quantile(std::vector<double> v, double q)
{
  if(v.empty())
    return 0.;
  std::sort(v.begin(), v.end());
  const std::size_t k = std::min(v.size() - 1, std::size_t(std::ceil(q * double(v.size()))) - (q > 0. ? 1 : 0));
  return v[k];
}

// A field of /proc/self/status in MiB ("VmRSS:", "VmHWM:", ...); 0 where
// there is no such file or field.
inline double status_mib(const char* key)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t len = std::strlen(key);
  while(std::getline(status, line))
    if(line.compare(0, len, key) == 0)
      return std::atof(line.c_str() + len) / 1024.;
  return 0.;
}

} // namespace denoising_support

#endif
