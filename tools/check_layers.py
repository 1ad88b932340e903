#!/usr/bin/env python3
"""Fails when a file includes a layer its own layer may not use (docs: CONTRIBUTING.md, "The layers").

The layers are a graph: USES says which layers each may use directly, and a layer may use
whatever those may use. The solver's directories form a chain (each uses the one below it),
but for solver/raster_fast, a branch over solver/raster that only server/ (and app/ through it)
uses; above the solver, one folder per job. bench/, tests/ and fuzz/ may include anything.
"""
import pathlib
import re
import sys

USES = {
    "solver/core": [],                          # scalars, Exact, vectors and matrices
    "solver/util": ["solver/core"],             # expressions, diagnostics, words, budgets
    "solver/numeric": ["solver/util"],          # precisions, condition estimates, ranges
    "solver/geometry": ["solver/numeric"],      # predicates, normals, plane depth, facing
    "solver/viewing": ["solver/geometry"],      # conventions, transforms, projections
    "solver/clipping": ["solver/viewing"],
    "solver/raster": ["solver/clipping"],       # the teaching pipeline: rasterizer, z-buffer, …
    "solver/raster_fast": ["solver/raster"],    # frustum render at speed: bands, strips, PNG
    "solver/derivation": ["solver/raster"],     # steps as data, typesetting, languages
    "solver/visibility": ["solver/derivation"],
    "solver/input": ["solver/visibility"],      # YAML documents and given readers
    "solver/problem": ["solver/input"],         # kinds' interface, registry, sets, variants
    "solver/shared": ["solver/problem"],        # what several kinds share
    "solver/kinds": ["solver/shared"],          # one file or file pair per kind
    "solver/accuracy": ["solver/kinds"],        # speed against error of the backends
    "grader": ["solver/kinds"],                 # judging one answer file
    "report": ["grader"],                       # what a grading says, in every format
    "batch": ["report"],                        # a class: isolation, transactions, gradebooks
    "export": ["batch"],                        # platform questions, LMS gradebooks, paper
    "server": ["batch", "export", "solver/raster_fast"],  # frustum serve: handlers and stores
    "app": ["server", "solver/accuracy"],       # the command line
}


def reachable(layer):
    seen, todo = set(), [layer]
    while todo:
        for used in USES[todo.pop()]:
            if used not in seen:
                seen.add(used)
                todo.append(used)
    return seen


def layer_of(path):
    best = None
    for layer in USES:
        if (path == layer or path.startswith(layer + "/")) and (best is None or len(layer) > len(best)):
            best = layer
    return best


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    include = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
    bad = []
    paths = [p for layer in USES for p in sorted((root / layer).glob("**/*.[ch]pp"))
             if layer_of(p.relative_to(root).as_posix()) == layer]
    for path in paths:
        rel = path.relative_to(root).as_posix()
        own = layer_of(rel)
        allowed = reachable(own) | {own}
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = include.match(line)
            if not m:
                continue
            target = layer_of(m.group(1))
            if target is None:
                if not (root / m.group(1)).exists() and not (path.parent / m.group(1)).exists():
                    continue
                bad.append(f"{rel}:{n}: includes {m.group(1)}, which is in no layer")
            elif target not in allowed:
                bad.append(f"{rel}:{n}: includes {m.group(1)} ({own} may not use {target})")
    for line in bad:
        print(line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
