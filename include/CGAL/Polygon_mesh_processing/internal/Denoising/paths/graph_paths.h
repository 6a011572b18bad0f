// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shortest paths in the adjacency graph of the items (faces through shared
// vertices, vertices through edges), inside each neighbourhood: a cheap
// stand-in for geodesic paths, defined for face and vertex signals alike.

#ifndef CGAL_PMP_INTERNAL_DENOISING_GRAPH_PATHS_H
#define CGAL_PMP_INTERNAL_DENOISING_GRAPH_PATHS_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/paths/path_forest.h>

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
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename Adjacency>
Path_forest shortest_graph_paths(const std::vector<Vec3>& positions, const Adjacency& adjacent, const Csr& neighbors)
{
  const std::size_t n = positions.size();
  typedef std::pair<double, std::uint32_t> Entry;
  struct Scratch
  {
    std::vector<std::uint32_t> stamp, local;
    std::vector<double> dist;
    std::vector<std::int32_t> pred;
    std::vector<char> settled;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  };
  Path_forest forest;
  build_lists<ConcurrencyTag, Path_node>(
      n, forest.offsets,
      [n] {
        return Scratch{std::vector<std::uint32_t>(n, std::uint32_t(-1)),
                       std::vector<std::uint32_t>(n, 0),
                       std::vector<double>(n, 0.),
                       std::vector<std::int32_t>(n, Path_forest::root),
                       std::vector<char>(n, 0),
                       {}};
      },
      [&](std::size_t i, Scratch& s, std::vector<Path_node>& out) {
        const std::uint32_t mark = std::uint32_t(i);
        for(std::uint32_t k = neighbors.begin(i); k < neighbors.end(i); ++k)
        {
          const std::uint32_t j = neighbors.items[k];
          s.stamp[j] = mark;
          s.dist[j] = std::numeric_limits<double>::infinity();
          s.settled[j] = 0;
        }
        s.stamp[i] = mark;
        s.dist[i] = 0.;
        s.settled[i] = 0;
        const std::size_t base = out.size();
        s.heap.push(Entry(0., mark));
        while(!s.heap.empty())
        {
          const Entry top = s.heap.top();
          s.heap.pop();
          const std::uint32_t a = top.second;
          if(s.settled[a] || top.first > s.dist[a])
            continue;
          s.settled[a] = 1;
          if(a != mark)
          {
            s.local[a] = std::uint32_t(out.size() - base);
            out.push_back(Path_node{a, s.pred[a] == -1 ? Path_forest::root : std::int32_t(s.local[s.pred[a]])});
          }
          adjacent(a, [&](std::uint32_t g) {
            if(s.stamp[g] != mark || s.settled[g] || g == a)
              return;
            const double d = s.dist[a] + norm(positions[g] - positions[a]);
            if(d < s.dist[g])
            {
              s.dist[g] = d;
              s.pred[g] = a == mark ? -1 : std::int32_t(a);
              s.heap.push(Entry(d, g));
            }
          });
        }
        for(std::uint32_t k = neighbors.begin(i); k < neighbors.end(i); ++k)
          if(!s.settled[neighbors.items[k]])
            out.push_back(Path_node{neighbors.items[k], Path_forest::root});
      },
      [&forest](const std::vector<Path_node>& chunk) { forest.append_nodes(chunk); });
  return forest;
}

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
