#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""ASCII STL of a race built the stock LIGGGHTS way: a cylinder band about the z axis.

usage: make_ring_stl.py --radius R --height H (--segments N | --max-error E)
                        --normal in|out [--name NAME] -o FILE

The band is a polygon of N flat facets (2 triangles each, one row, z in [-H/2, H/2]).
A flat facet lies inside the circle at its middle and on it at its edges, so the distance
from the axis to the surface varies by the sagitta s = Rv (1 - cos(pi/N)) along a facet.
The vertices are put on the radius Rv = 2 R / (1 + cos(pi/N)) so that the surface is
R + s/2 at the edges and R - s/2 at the facet middles: the faceting error is +-s/2 about R.
--max-error E picks the smallest N with s/2 <= E. --normal tells which side the balls are
on (out: an inner ring, balls outside; in: an outer ring, balls inside); LIGGGHTS takes
contacts on both sides, the normal only keeps the file tidy.
Prints N, the triangle count, s/2 and the smallest triangle angle (LIGGGHTS warns below
0.5 degrees and stops below 0.018 degrees).
"""
import argparse
import math
import sys


def segments_for(radius, max_error):
    n = 3
    while True:
        rv = 2 * radius / (1 + math.cos(math.pi / n))
        if rv * (1 - math.cos(math.pi / n)) / 2 <= max_error:
            return n
        n = max(n + 1, int(n * 1.01))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--radius', type=float, required=True, help='surface radius R (m)')
    ap.add_argument('--height', type=float, required=True, help='band height H along z (m)')
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument('--segments', type=int, help='number of facets N around')
    g.add_argument('--max-error', type=float, help='largest |surface radius - R| allowed (m)')
    ap.add_argument('--normal', choices=('in', 'out'), required=True)
    ap.add_argument('--name', default='ring')
    ap.add_argument('-o', '--output', required=True)
    a = ap.parse_args()
    if a.radius <= 0 or a.height <= 0:
        sys.exit('ERROR: --radius and --height must be positive')
    n = a.segments if a.segments else segments_for(a.radius, a.max_error)
    if n < 3:
        sys.exit('ERROR: --segments must be at least 3')
    c = math.cos(math.pi / n)
    rv = 2 * a.radius / (1 + c)
    half_err = rv * (1 - c) / 2
    z0, z1 = -a.height / 2, a.height / 2
    pts = [(rv * math.cos(2 * math.pi * k / n), rv * math.sin(2 * math.pi * k / n))
           for k in range(n)]
    sign = 1.0 if a.normal == 'out' else -1.0
    with open(a.output, 'w') as f:
        f.write('solid %s\n' % a.name)
        for k in range(n):
            (x0, y0), (x1, y1) = pts[k], pts[(k + 1) % n]
            phi = 2 * math.pi * (k + 0.5) / n
            nx, ny = sign * math.cos(phi), sign * math.sin(phi)
            quad = [((x0, y0, z0), (x1, y1, z0), (x1, y1, z1)),
                    ((x0, y0, z0), (x1, y1, z1), (x0, y0, z1))]
            for tri in quad:
                if sign < 0:  # counter-clockwise seen from the side the normal points to
                    tri = (tri[0], tri[2], tri[1])
                f.write('  facet normal %.9e %.9e 0.0\n    outer loop\n' % (nx, ny))
                for v in tri:
                    f.write('      vertex %.12e %.12e %.12e\n' % v)
                f.write('    endloop\n  endfacet\n')
        f.write('endsolid %s\n' % a.name)
    width = 2 * rv * math.sin(math.pi / n)
    min_angle = math.degrees(math.atan2(min(width, a.height), max(width, a.height)))
    print('%s: R = %.6g m, H = %.4g m, N = %d facets around, %d triangles, vertex radius %.9g m,'
          ' faceting error +-%.3g m, angle between facets %.4g deg, smallest triangle angle'
          ' %.3g deg' % (a.output, a.radius, a.height, n, 2 * n, rv, half_err, 360.0 / n,
                         min_angle))


if __name__ == '__main__':
    main()
