"""Writes examples/shapes/icosahedron.obj and .stl: a regular icosahedron of circumradius 1 (mm in
the examples: `mesh_scale = 1e-3` makes it 1 mm), corners (0, +-1, +-phi) and their cyclic
permutations over sqrt(1 + phi^2), faces counter-clockwise seen from outside. Numbers are written
in Python's shortest round-trip form, so the files hold the doubles computed here exactly.

    python3 tools/icosahedron_mesh.py [OUT_DIR]   (default: examples/shapes)
"""
import itertools
import math
import os
import sys


def icosahedron():
    phi = (1 + math.sqrt(5)) / 2
    a, b = 1 / math.sqrt(1 + phi * phi), phi / math.sqrt(1 + phi * phi)
    vertices = []
    for s, t in itertools.product((1, -1), (1, -1)):
        vertices += [(0, s * a, t * b), (s * a, t * b, 0), (t * b, 0, s * a)]
    edge2 = 4 * a * a  # squared edge length, (2a)^2

    def d2(i, j):
        return sum((p - q) ** 2 for p, q in zip(vertices[i], vertices[j]))

    faces = []
    for i, j, k in itertools.combinations(range(len(vertices)), 3):
        if all(abs(d2(p, q) - edge2) < 1e-9 for p, q in ((i, j), (j, k), (k, i))):
            n = normal(vertices[i], vertices[j], vertices[k])
            centre = [sum(c) / 3 for c in zip(vertices[i], vertices[j], vertices[k])]
            faces.append((i, j, k) if sum(x * y for x, y in zip(n, centre)) > 0 else (i, k, j))
    assert len(faces) == 20
    return vertices, faces


def normal(p, q, r):
    u = [y - x for x, y in zip(p, q)]
    v = [y - x for x, y in zip(p, r)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(x * x for x in n))
    return [x / length for x in n]


def text(x):
    return repr(float(x)) if x != 0 else "0"


def main(out_dir):
    vertices, faces = icosahedron()
    with open(os.path.join(out_dir, "icosahedron.obj"), "w") as f:
        f.write("# A regular icosahedron of circumradius 1 (tools/icosahedron_mesh.py)\n")
        for v in vertices:
            f.write("v " + " ".join(text(x) for x in v) + "\n")
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
    with open(os.path.join(out_dir, "icosahedron.stl"), "w") as f:
        f.write("solid icosahedron of circumradius 1 (tools/icosahedron_mesh.py)\n")
        for face in faces:
            p = [vertices[i] for i in face]
            f.write("  facet normal " + " ".join(text(x) for x in normal(*p)) + "\n    outer loop\n")
            for v in p:
                f.write("      vertex " + " ".join(text(x) for x in v) + "\n")
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid icosahedron\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "examples", "shapes"))
