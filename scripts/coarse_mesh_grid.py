"""The best E_n that any small setting of the filter reaches on coarse
irregular meshes with weak noise (the manual's section on the vertex
update): Gaussian noise along the normals at sigma_E 0.05 and 0.1, seed 1,
then the fixed mode with sigma_s = sigma_r in {0.1, 0.2, 0.3, 0.5}, a
radius of 1.5, 2 or 3 d and 1, 2, 3 or 5 iterations (eq. 10, 2 vertex
steps); prints the noisy input's E_n and the best of the grid per input.
usage: PYTHONPATH=build/python python3 scripts/coarse_mesh_grid.py [MESHES_DIR]"""
import os
import sys

import numpy as np

import cgal_intrinsic_denoising as dn

meshes = sys.argv[1] if len(sys.argv) > 1 else "build/cgal_data/data/meshes"
for name in ["b9_mesh.off", "bones.off", "bull.off", "cow.off", "femur.off", "polygon_mesh.off"]:
    V, F = dn.read_mesh(os.path.join(meshes, name))
    V, F = np.asarray(V), np.asarray(F)
    for level in (0.05, 0.1):
        N = np.asarray(dn.add_gaussian_noise(V, F, level, seed=1))
        best = (float("inf"), None)
        for sigma in (0.1, 0.2, 0.3, 0.5):
            for radius in (1.5, 2.0, 3.0):
                for k in (1, 2, 3, 5):
                    R, _ = dn.denoise(N, F, automatic_parameters=False, sigma_spatial=sigma, sigma_range=sigma,
                                      relative_neighbor_radius=radius, number_of_iterations=k)
                    best = min(best, (dn.face_normal_error(np.asarray(R), F, V), (sigma, radius, k)))
        print("%s sigma_E %.2f: noisy %.2f, best %.2f (sigma %.1f, r %.1f d, k %d)"
              % (name, level, dn.face_normal_error(N, F, V), best[0], *best[1]), flush=True)
