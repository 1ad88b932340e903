#!/usr/bin/env python3
"""Fails when a file includes a layer above its own (docs: CONTRIBUTING.md, "The layers").

The solver's directories, bottom to top; a file may include its own directory and any below it.
grader/ sits on the solver, app/ on everything; bench/, tests/ and fuzz/ may include anything.
"""
import pathlib
import re
import sys

LAYERS = [
    "solver/core",        # scalars, Exact, vectors and matrices
    "solver/util",        # expressions, diagnostics, words, work budgets, exact formatting
    "solver/numeric",     # precisions, condition estimates, ranged arithmetic
    "solver/geometry",    # predicates, normals, plane depth, facing
    "solver/viewing",     # conventions, transforms, projections
    "solver/clipping",
    "solver/raster",
    "solver/derivation",  # steps as data, values, renderers, languages
    "solver/visibility",
    "solver/input",       # YAML documents and given readers
    "solver/problem",     # kinds' interface, registry, sets, solving runs, variants
    "solver/steps",       # building blocks shared by kinds
    "solver/kinds",       # one file or file pair per kind
    "solver/accuracy",    # speed against error of the numeric backends
    "grader",
    "server",             # frustum serve: handlers, sessions, stores, grading workers
    "app",
]


def layer_of(path):
    for i, layer in enumerate(LAYERS):
        if path == layer or path.startswith(layer + "/"):
            return i
    return None


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    include = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
    bad = []
    for path in sorted(root.glob("solver/**/*.[ch]pp")) + sorted(root.glob("grader/**/*.[ch]pp")) \
            + sorted(root.glob("server/**/*.[ch]pp")) + sorted(root.glob("app/**/*.[ch]pp")):
        rel = path.relative_to(root).as_posix()
        own = layer_of(rel)
        if own is None:
            bad.append(f"{rel}: not in any layer")
            continue
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = include.match(line)
            if not m:
                continue
            target = layer_of(m.group(1))
            if target is None:
                if not (root / m.group(1)).exists() and not (path.parent / m.group(1)).exists():
                    continue
                bad.append(f"{rel}:{n}: includes {m.group(1)}, which is in no layer")
            elif target > own:
                bad.append(f"{rel}:{n}: includes {m.group(1)} ({LAYERS[target]} is above {LAYERS[own]})")
    for line in bad:
        print(line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
