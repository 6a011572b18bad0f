#!/usr/bin/env python3
"""Checks that the internal headers include only their own stage or earlier ones.

internal/Denoising/ holds the pipeline of the package as stage folders, in
this order; a header of a stage may include headers of its own stage and of
the stages before it, never of a later one. The driver (intrinsic_denoiser.h,
at the top of the folder) and the public headers may include any stage.
Also checks that no header under include/ is over 500 lines.
Usage: check_stage_includes.py [ROOT]; exits with 1 and one line per
violation, 0 otherwise. With --self-test, checks instead that a tree with a
backward include, a missing header and a long header is refused.
"""
import pathlib
import re
import sys
import tempfile

STAGES = ["core", "mesh", "neighborhoods", "paths", "weights", "vertices", "filter", "automatic", "classic"]
MAX_LINES = 500
INTERNAL = "include/CGAL/Polygon_mesh_processing/internal/Denoising"
INCLUDE = re.compile(r"#include <CGAL/Polygon_mesh_processing/internal/Denoising/([^>]+)>")


def check(root):
    """The violations in the tree at `root`, one line each."""
    internal = root / INTERNAL
    problems = []
    for folder in sorted(p for p in internal.iterdir() if p.is_dir()):
        if folder.name not in STAGES:
            problems.append(f"{folder}: not a stage ({', '.join(STAGES)})")
    for header in sorted(internal.glob("*/*.h")):
        stage = STAGES.index(header.parent.name) if header.parent.name in STAGES else -1
        for number, line in enumerate(header.read_text().splitlines(), 1):
            m = INCLUDE.search(line)
            if not m:
                continue
            target = m.group(1)
            target_stage = target.split("/")[0]
            if "/" not in target or target_stage not in STAGES:
                problems.append(f"{header}:{number}: includes {target}, which is not in a stage folder")
            elif STAGES.index(target_stage) > stage:
                problems.append(f"{header}:{number}: stage {header.parent.name} includes the later stage {target}")
            elif not (internal / target).exists():
                problems.append(f"{header}:{number}: includes {target}, which does not exist")
    for header in sorted((root / "include").rglob("*.h")):
        lines = len(header.read_text().splitlines())
        if lines > MAX_LINES:
            problems.append(f"{header}: {lines} lines (at most {MAX_LINES})")
    return problems


def self_test():
    """0 if a tree with three known faults gets exactly those three reported."""
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for stage in ("mesh", "paths"):
            (root / INTERNAL / stage).mkdir(parents=True)
        prefix = "#include <CGAL/Polygon_mesh_processing/internal/Denoising/"
        (root / INTERNAL / "paths/a.h").write_text(prefix + "mesh/b.h>\n")
        (root / INTERNAL / "mesh/b.h").write_text(prefix + "paths/a.h>\n" + prefix + "mesh/gone.h>\n")
        (root / INTERNAL / "mesh/long.h").write_text("//\n" * (MAX_LINES + 1))
        problems = check(root)
        expected = ["later stage paths/a.h", "gone.h, which does not exist", f"{MAX_LINES + 1} lines"]
        found = [any(e in p for p in problems) for e in expected]
        if all(found) and len(problems) == len(expected):
            print("self-test: the three faults were reported")
            return 0
        print("self-test failed:", problems)
        return 1


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    problems = check(root)
    for p in problems:
        print(p)
    sys.exit(1 if problems else 0)
