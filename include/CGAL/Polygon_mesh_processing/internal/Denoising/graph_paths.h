// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shortest paths in the adjacency graph of the items (faces through shared
// vertices, vertices through edges), inside each neighbourhood: a cheap
// stand-in for geodesic paths, defined for face and vertex signals alike.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GRAPH_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_GRAPH_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/path_forest.h>

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// For each item i, Dijkstra from i over the graph restricted to i and its
// neighbours, with edge lengths the distances between positions; nodes are
// listed in the order they are settled (so parents come first), ties broken
// by item index. A neighbour the restricted graph cannot reach (impossible
// for neighbourhoods grown by geometric_neighborhoods()) hangs from i.
template <typename Adjacency>
Path_forest shortest_graph_paths(const std::vector<Vec3>& positions, const Adjacency& adjacent, const Csr& neighbors)
{
  const std::size_t n = positions.size();
  Path_forest forest;
  forest.offsets.assign(n + 1, 0);
  forest.face.reserve(neighbors.items.size());
  forest.parent.reserve(neighbors.items.size());
  std::vector<std::uint32_t> stamp(n, std::uint32_t(-1)), local(n, 0);
  std::vector<double> dist(n, 0.);
  std::vector<std::int32_t> pred(n, Path_forest::root);
  std::vector<char> settled(n, 0);
  typedef std::pair<double, std::uint32_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::uint32_t mark = std::uint32_t(i);
    for(std::uint32_t k = neighbors.begin(i); k < neighbors.end(i); ++k)
    {
      const std::uint32_t j = neighbors.items[k];
      stamp[j] = mark;
      dist[j] = std::numeric_limits<double>::infinity();
      settled[j] = 0;
      pred[j] = -2; // unreached
    }
    stamp[i] = mark;
    dist[i] = 0.;
    settled[i] = 0;
    const std::uint32_t base = std::uint32_t(forest.face.size());
    heap.push(Entry(0., mark));
    while(!heap.empty())
    {
      const Entry top = heap.top();
      heap.pop();
      const std::uint32_t a = top.second;
      if(settled[a] || top.first > dist[a])
        continue;
      settled[a] = 1;
      if(a != mark)
      {
        local[a] = std::uint32_t(forest.face.size()) - base;
        forest.face.push_back(a);
        forest.parent.push_back(pred[a] == -1 ? Path_forest::root : std::int32_t(local[pred[a]]));
      }
      adjacent(a, [&](std::uint32_t g) {
        if(stamp[g] != mark || settled[g] || g == a)
          return;
        const double d = dist[a] + norm(positions[g] - positions[a]);
        if(d < dist[g])
        {
          dist[g] = d;
          pred[g] = a == mark ? -1 : std::int32_t(a);
          heap.push(Entry(d, g));
        }
      });
    }
    for(std::uint32_t k = neighbors.begin(i); k < neighbors.end(i); ++k)
    {
      const std::uint32_t j = neighbors.items[k];
      if(!settled[j])
      {
        forest.face.push_back(j);
        forest.parent.push_back(Path_forest::root);
      }
    }
    forest.offsets[i + 1] = std::uint32_t(forest.face.size());
  }
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
