"""Writes the strip tessellation of a plane used by the manual's sliver
pictures: 20 x 200 cells of width 1 and height 0.05, each split along a
diagonal into two slivers of aspect ratio 20 (the mesh of the test
IrregularMeshes.ScrambledSliverPatchComesBackFlat).
usage: python3 sliver_plane.py OUT.off"""
import sys

columns, rows, height = 20, 200, 0.05
with open(sys.argv[1], "w") as out:
    out.write("OFF\n%d %d 0\n" % ((columns + 1) * (rows + 1), 2 * columns * rows))
    for i in range(columns + 1):
        for j in range(rows + 1):
            out.write("%g %g 0\n" % (i, j * height))
    at = lambda i, j: i * (rows + 1) + j
    for i in range(columns):
        for j in range(rows):
            out.write("3 %d %d %d\n" % (at(i, j), at(i + 1, j), at(i + 1, j + 1)))
            out.write("3 %d %d %d\n" % (at(i, j), at(i + 1, j + 1), at(i, j + 1)))
