#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Exact resistance between `ehigh` and `0` of a SPICE netlist written by write_spice_netlist.

An independent reference for ill-conditioned networks (doc/methods/conduction_network.md, Accuracy).
Every R value is read as an exact decimal (Fraction); nodes are eliminated one at a time by
the star-mesh transform (Kron reduction): node k with total conductance d_k adds
g_ik * g_jk / d_k between each pair of its neighbours. Rational arithmetic makes it exact;
minimum-degree order keeps the fill small (a 2D packing of ~400 nodes takes a few minutes).

The printed values are 1/g to 17 significant digits, a relative perturbation below 1e-16 of
each conductance; R moves by at most as much (R is monotone in every g and scales as 1/g),
so the result is the double-precision network's R to ~1e-16.

Usage: kron_exact.py net.cir   -> prints R in ohm
"""
import sys
from fractions import Fraction


def read_netlist(path):
    adj = {}
    with open(path) as f:
        next(f)  # the title line
        for line in f:
            tok = line.split()
            if not tok or not tok[0].upper().startswith("R"):
                continue  # comments (floating edges), the source, .op, .end
            a, b, g = tok[1], tok[2], 1 / Fraction(tok[3])
            for x, y in ((a, b), (b, a)):
                adj.setdefault(x, {})
                adj[x][y] = adj[x].get(y, 0) + g
    return adj


def component(adj, root):
    seen, todo = {root}, [root]
    while todo:
        for j in adj[todo.pop()]:
            if j not in seen:
                seen.add(j)
                todo.append(j)
    return seen


def resistance(adj, high="ehigh", low="0"):
    keep = component(adj, high)
    if low not in keep:
        return float("inf")
    adj = {k: v for k, v in adj.items() if k in keep}
    while len(adj) > 2:
        k = min((n for n in adj if n not in (high, low)), key=lambda n: (len(adj[n]), n))
        nb = adj.pop(k)
        d = sum(nb.values())
        items = sorted(nb.items())
        for i, _ in items:
            del adj[i][k]
        for x, (i, gi) in enumerate(items):
            for j, gj in items[x + 1:]:
                add = gi * gj / d
                adj[i][j] = adj[i].get(j, 0) + add
                adj[j][i] = adj[j].get(i, 0) + add
    return 1 / adj[high][low]


if __name__ == "__main__":
    r = resistance(read_netlist(sys.argv[1]))
    print(f"{float(r):.17g}")
