#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""ASCII STL of a race's groove built the stock LIGGGHTS way: a patch of the torus swept about z
by the groove's curvature-centre circle (the 3D bearing's race, doc/methods/bearing_3d.md).

usage: make_groove_stl.py --side inner|outer --centre-radius RHO --centre-z Z --groove RC
                          --angle DEG --half-width DEG --max-error E -o FILE

The patch spans the contact angles DEG +- half-width across the groove, all around. Facets are
flat: the surface lies within E of the torus (the chords' sagittas, R (1 - cos(step/2)) in
each direction, at most E). Prints the facet counts and the error reached.
"""
import argparse
import math


def steps(radius, span, max_error):
    """The number of chords over `span` (rad) of a circle of `radius` with sagitta <= max_error."""
    step = 2 * math.acos(max(-1.0, 1 - max_error / radius))
    return max(1, math.ceil(span / step))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--side", choices=("inner", "outer"), required=True)
    ap.add_argument("--centre-radius", type=float, required=True)
    ap.add_argument("--centre-z", type=float, default=0.0)
    ap.add_argument("--groove", type=float, required=True)
    ap.add_argument("--angle", type=float, default=0.0)
    ap.add_argument("--half-width", type=float, default=30.0)
    ap.add_argument("--max-error", type=float, required=True)
    ap.add_argument("-o", required=True)
    a = ap.parse_args()
    s = -1.0 if a.side == "inner" else 1.0  # the surface is on the axis side of the circle (inner)
    a0, hw = math.radians(a.angle), math.radians(a.half_width)
    rho_min = a.centre_radius - a.groove if a.side == "inner" else a.centre_radius
    n_phi = steps(rho_min, 2 * math.pi, a.max_error)
    n_th = steps(a.groove, 2 * hw, a.max_error)

    def point(i, j):
        phi = 2 * math.pi * i / n_phi
        th = a0 - hw + 2 * hw * j / n_th
        rho = a.centre_radius + s * a.groove * math.cos(th)
        return (rho * math.cos(phi), rho * math.sin(phi), a.centre_z + s * a.groove * math.sin(th))

    with open(a.o, "w") as f:
        f.write(f"solid {a.side}\n")
        for i in range(n_phi):
            for j in range(n_th):
                p00, p10 = point(i, j), point(i + 1, j)
                p01, p11 = point(i, j + 1), point(i + 1, j + 1)
                for tri in ((p00, p10, p11), (p00, p11, p01)):
                    # The normal toward the balls (the curvature centres' side), the vertices
                    # counter-clockwise seen from it.
                    u = [tri[1][k] - tri[0][k] for k in range(3)]
                    w = [tri[2][k] - tri[0][k] for k in range(3)]
                    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]]
                    ln = math.sqrt(sum(x * x for x in n))
                    n = [x / ln for x in n]
                    c = [sum(v[k] for v in tri) / 3 for k in range(3)]
                    rc = math.hypot(c[0], c[1])
                    toward = [a.centre_radius * c[0] / rc - c[0],
                              a.centre_radius * c[1] / rc - c[1], a.centre_z - c[2]]
                    if sum(n[k] * toward[k] for k in range(3)) < 0:
                        tri = (tri[0], tri[2], tri[1])
                        n = [-x for x in n]
                    f.write(" facet normal %.9e %.9e %.9e\n  outer loop\n" % tuple(n))
                    for v in tri:
                        f.write("   vertex %.12e %.12e %.12e\n" % v)
                    f.write("  endloop\n endfacet\n")
        f.write(f"endsolid {a.side}\n")
    print(f"{a.side}: {n_phi} x {n_th} facets, {2 * n_phi * n_th} triangles, surface within "
          f"{a.max_error:g} m of the torus")


if __name__ == "__main__":
    main()
