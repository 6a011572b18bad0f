// Copyright (c) 2026 The intrinsic denoising package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The sample on which the automatic selection chooses its setting on a big
// mesh: a few patches of the mesh, each grown face by face from a seed face
// drawn at random (fixed seed), copied as a mesh of their own. The selection
// reads averages of its residual over the faces (residual_statistics.h), so
// a sample of some ten thousand faces per patch reads the same setting as
// the whole mesh at a fraction of the cost; the setting chosen then runs
// once on the whole mesh.

#ifndef CGAL_PMP_INTERNAL_DENOISING_SELECTION_SAMPLE_H
#define CGAL_PMP_INTERNAL_DENOISING_SELECTION_SAMPLE_H

#include <CGAL/Polygon_mesh_processing/internal/Denoising/automatic/automatic_rules.h>
#include <CGAL/Polygon_mesh_processing/internal/Denoising/mesh/flat_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Denoising {

// A part of a mesh as a mesh of its own: its faces are faces of the whole
// in increasing input index, its vertices those they use, numbered in the
// order the faces first use them.
struct Selection_sample
{
  Flat_mesh mesh;
  std::vector<char> constrained; // by sample vertex
  std::size_t patches = 0;       // the number of patches grown
};

// Grows patches of about `patch_faces` faces each over `whole` (faces
// joined when they share a vertex, breadth first from each seed) until
// `target_faces` faces are taken or every face is. The seeds are faces
// drawn uniformly with a fixed seed, skipping faces already taken, so that
// the sample covers the surface in proportion to its faces and is the same
// on every run and thread count. `constrained` flags the pinned vertices of
// `whole` (empty: none); the sample's vertices on a patch border that are
// interior in the whole mesh are not pinned: the patch is a mesh with a
// border there, as a scan's border is.
inline Selection_sample sample_patches(const Flat_mesh& whole, const std::vector<char>& constrained,
                                       std::size_t target_faces, std::size_t patch_faces)
{
  const std::size_t nf = whole.number_of_faces();
  std::vector<char> taken(nf, 0);
  std::vector<std::uint32_t> queued(nf, 0); // the patch (from 1) that last queued the face
  std::vector<std::uint32_t> faces, queue;
  faces.reserve(std::min(nf, target_faces + patch_faces));
  std::mt19937 engine(1);
  std::uniform_int_distribution<std::size_t> draw(0, nf == 0 ? 0 : nf - 1);
  Selection_sample sample;
  std::size_t misses = 0;
  while(faces.size() < target_faces && faces.size() < nf)
  {
    std::size_t seed = draw(engine);
    if(taken[seed] && ++misses > 64) // most faces taken: the first free one
      seed = std::size_t(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    if(taken[seed])
      continue;
    const std::uint32_t patch = std::uint32_t(++sample.patches);
    const std::size_t end = std::min(faces.size() + patch_faces, target_faces);
    queue.assign(1, std::uint32_t(seed));
    queued[seed] = patch;
    for(std::size_t head = 0; head < queue.size() && faces.size() < end; ++head)
    {
      const std::uint32_t f = queue[head];
      taken[f] = 1;
      faces.push_back(f);
      for(std::uint32_t v : whole.triangles[f])
        for(std::uint32_t i = whole.vertex_face_offsets[v]; i < whole.vertex_face_offsets[v + 1]; ++i)
        {
          const std::uint32_t g = whole.vertex_faces[i];
          if(!taken[g] && queued[g] != patch)
          {
            queued[g] = patch;
            queue.push_back(g);
          }
        }
    }
  }
  std::sort(faces.begin(), faces.end());
  const std::uint32_t unset = std::uint32_t(-1);
  std::vector<std::uint32_t> new_index(whole.number_of_vertices(), unset);
  Flat_mesh& m = sample.mesh;
  m.triangles.reserve(faces.size());
  for(std::uint32_t f : faces)
  {
    std::array<std::uint32_t, 3> t;
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t v = whole.triangles[f][std::size_t(k)];
      if(new_index[v] == unset)
      {
        new_index[v] = std::uint32_t(m.points.size());
        m.points.push_back(whole.points[v]);
        sample.constrained.push_back(constrained.empty() ? 0 : constrained[v]);
      }
      t[std::size_t(k)] = new_index[v];
    }
    m.triangles.push_back(t);
  }
  list_faces_around_vertices(m);
  return sample;
}

// The mesh access of the selection (as Mesh_maps' flat() and constrained())
// for a sample: the selection then runs on the sample as on a mesh.
struct Sample_maps
{
  const Selection_sample* sample;
  template <typename TriangleMesh>
  Flat_mesh flat(const TriangleMesh&, const char*) const
  {
    return sample->mesh;
  }
  template <typename TriangleMesh>
  std::vector<char> constrained(const TriangleMesh&) const
  {
    return sample->constrained;
  }
};

} // namespace Denoising
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif
