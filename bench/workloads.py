#!/usr/bin/python3
"""Inputs for tools/performance.sh, written deterministically (no randomness), and the
Python + NumPy peer that grades the same class files.

  workloads.py class-set SET.yaml                 20 depth_at_pixel problems × 3 answers
  workloads.py gen-set SET.yaml                   the plane-method exercise with ranges wide enough
                                                  for 100 000 distinct variants (for `generate`)
  workloads.py class DIR KEY.json N               N answer files (KEY.json: `frustum solve --format json`)
  workloads.py peer SET.yaml KEY.json DIR OUT.csv [c|python]
                                                  the NumPy peer: parse every file, grade, write a gradebook;
                                                  its YAML read by PyYAML's C loader (c, the default) or by
                                                  its own Python loader (python: what yaml.safe_load gives)
  workloads.py together JSON                      runs the argument vectors of a JSON list at once
                                                  (no shell), each one's output discarded
  workloads.py scene FILE N                       a render scene of about N small triangles
  workloads.py mesh FILE N                        an edge_visibility problem: a closed torus of about N faces
"""
import csv
import json
import math
import os
import sys


def class_set(path):
    # The class of bench/grade_bench.cpp: twenty triangles, each asked normal, plane and z.
    s = "problems:\n"
    for i in range(20):
        s += (f"  - id: p{i}\n    kind: depth_at_pixel\n    given:\n"
              f"      triangle: [[0, 0, {6 + i % 3}], [{3 + i % 4}, 0, 9], [0, 3, 9]]\n"
              f"      pixel: [1, 1]\n    ask: [normal, plane, z]\n")
    with open(path, "w") as f:
        f.write(s)


def gen_set(path):
    # The plane-method exercise of the lecture (unit normal, plane, z at a pixel), each problem
    # drawing its triangle's coordinates from ranges wide enough for a 100 000-variant run (the
    # lecture's own set, with the default redraw, holds about 13 500 distinct variants).
    coord = "{range: [-20, 20]}"
    depth = "{range: [1, 40]}"
    tri = f"[[{coord}, {coord}, {depth}], [{coord}, {coord}, {depth}], [{coord}, {coord}, {depth}]]"
    s = ("title: \"Generate benchmark: the plane method\"\nproblems:\n"
         "  - id: unit-normal\n    kind: normal\n"
         "    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9], cross: [AC, AB]}\n"
         f"    vary: {{A: [{coord}, {coord}, {depth}], B: [{coord}, {coord}, {depth}], "
         f"C: [{coord}, {coord}, {depth}]}}\n"
         "    ask: [normal, unit_normal]\n")
    for pid, ask in (("plane", "[plane]"), ("pixel-z", "[normal, unit_normal, plane, z, inside]")):
        s += (f"  - id: {pid}\n    kind: depth_at_pixel\n"
              "    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}\n"
              f"    vary: {{triangle: {tri}, pixel: [{{range: [-5, 5]}}, {{range: [-5, 5]}}]}}\n"
              f"    ask: {ask}\n")
    with open(path, "w") as f:
        f.write(s)


def key_of(key_json):
    with open(key_json) as f:
        solved = json.load(f)
    return {p["id"]: {k: p["answers"][k]["value"] for k in ("normal", "plane", "z")} for p in solved["problems"]}


def write_class(directory, key_json, n):
    # Decimals as students type them; one z in five off by 0.5 (the C++ benchmark's class).
    key = key_of(key_json)
    os.makedirs(directory, exist_ok=True)
    for s in range(n):
        lines = [f"student: s{s:05d}", "answers:"]
        for i, (pid, a) in enumerate(key.items()):
            z = a["z"] + (0.5 if (s + i) % 5 == 0 else 0.0)
            nrm = ", ".join(f"{v:.6f}" for v in a["normal"])
            pln = ", ".join(f"{v:.6f}" for v in a["plane"])
            lines.append(f"  {pid}: {{normal: [{nrm}], plane: [{pln}], z: {z:.6f}}}")
        with open(os.path.join(directory, f"s{s:05d}.yaml"), "w") as f:
            f.write("\n".join(lines) + "\n")


def peer(key_json, directory, out_csv, loader_name="c"):
    # What a course's own script would do: read each file, compare in bulk with NumPy
    # (normal up to a positive multiple, plane up to a non-zero multiple, z with rtol 1e-2),
    # write one gradebook line per student. yaml.safe_load, the call a plain script makes, uses
    # the Python loader; the C loader (libyaml, which Frustum uses too) must be asked for.
    import numpy as np
    import yaml
    if loader_name == "python":
        loader = yaml.SafeLoader
    else:
        loader = yaml.CSafeLoader  # python3-yaml is built with libyaml on Debian
    key = key_of(key_json)
    ids = list(key)
    kn = np.array([key[i]["normal"] for i in ids], float)
    kp = np.array([key[i]["plane"] for i in ids], float)
    kz = np.array([key[i]["z"] for i in ids], float)
    kn /= np.linalg.norm(kn, axis=1, keepdims=True)
    kp /= np.linalg.norm(kp, axis=1, keepdims=True)
    with open(out_csv, "w", newline="") as out:
        w = csv.writer(out)
        w.writerow(["student", "score", "max"])
        for name in sorted(os.listdir(directory)):
            with open(os.path.join(directory, name)) as f:
                doc = yaml.load(f, Loader=loader)
            ans = doc["answers"]
            n = np.array([ans[i]["normal"] for i in ids], float)
            p = np.array([ans[i]["plane"] for i in ids], float)
            z = np.array([ans[i]["z"] for i in ids], float)
            n /= np.linalg.norm(n, axis=1, keepdims=True)
            p /= np.linalg.norm(p, axis=1, keepdims=True)
            ok_n = np.abs(np.einsum("ij,ij->i", n, kn) - 1) < 1e-4
            ok_p = np.abs(np.abs(np.einsum("ij,ij->i", p, kp)) - 1) < 1e-4
            ok_z = np.abs(z - kz) <= 1e-2 * np.maximum(np.abs(kz), 1)
            w.writerow([doc["student"], int(ok_n.sum() + ok_p.sum() + ok_z.sum()), 3 * len(ids)])


def scene(path, n):
    # A grid of k × k cells, two small triangles each (a few pixels on a 1920 × 1080 image), all
    # in front of the camera and inside the view volume: transform, clip and fill all run.
    k = max(1, int(math.sqrt(n / 2)))
    h = round(2.0 / k, 6)
    rep = f"repeat: {{from: [0, 0, 0], to: [{k - 1}, {k - 1}, 0], step: [{h}, {h}, 0]}}"
    with open(path, "w") as f:
        f.write("scene:\n  viewport: {width: 1920, height: 1080}\n"
                "  camera: {eye: [0, 0, 3], center: [0, 0, 0], up: [0, 1, 0]}\n"
                "  perspective: {fovy: 60, aspect: 16/9, near: 1/2, far: 10}\n"
                "  objects:\n"
                f"    - triangle: [[-1, -1, 0], [{h - 1}, -1, 0.1], [-1, {h - 1}, -0.1]]\n      {rep}\n"
                f"    - triangle: [[{h - 1}, -1, 0.1], [{h - 1}, {h - 1}, 0], [-1, {h - 1}, -0.1]]\n      {rep}\n")


def mesh(path, n):
    # A torus of u × v quads split into triangles (2uv faces), counter-clockwise seen from outside.
    u = max(3, int(math.sqrt(n / 2)))
    v = max(3, n // (2 * u))
    R, r = 3.0, 1.0
    verts = []
    for i in range(u):
        a = 2 * math.pi * i / u
        for j in range(v):
            b = 2 * math.pi * j / v
            verts.append([round((R + r * math.cos(b)) * math.cos(a), 4), round((R + r * math.cos(b)) * math.sin(a), 4),
                          round(r * math.sin(b), 4)])
    faces = []
    for i in range(u):
        for j in range(v):
            a, b = i * v + j, ((i + 1) % u) * v + j
            c, d = ((i + 1) % u) * v + (j + 1) % v, i * v + (j + 1) % v
            faces += [[a, b, c], [a, c, d]]
    with open(path, "w") as f:
        f.write("problems:\n  - id: torus\n    kind: edge_visibility\n    given:\n      mesh:\n        vertices:\n")
        f.writelines(f"          - {p}\n" for p in verts)
        f.write("        faces:\n")
        f.writelines(f"          - {t}\n" for t in faces)
        f.write("      eye: [2, -9, 7]\n    ask: [faces, edges]\n")


def together(commands):
    """Runs the commands (argument vectors, no shell) at once, their output discarded, and
    fails unless every one succeeds."""
    import subprocess
    running = [subprocess.Popen(c, stdout=subprocess.DEVNULL) for c in commands]
    if any(p.wait() != 0 for p in running):
        sys.exit("a command run together failed")


if __name__ == "__main__":
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "class-set":
        class_set(args[0])
    elif cmd == "gen-set":
        gen_set(args[0])
    elif cmd == "class":
        write_class(args[0], args[1], int(args[2]))
    elif cmd == "peer":
        peer(args[1], args[2], args[3], *(args[4:5] or ["c"]))
    elif cmd == "scene":
        scene(args[0], int(args[1]))
    elif cmd == "mesh":
        mesh(args[0], int(args[1]))
    elif cmd == "together":  # together JSON: a list of argument vectors
        together(__import__("json").loads(args[0]))
    else:
        sys.exit(__doc__)
