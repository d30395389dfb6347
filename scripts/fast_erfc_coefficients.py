#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The polynomial of src_fix/lib/common/fast_erfc.h (needs mpmath: Debian's python3-mpmath).

erfc(x) = t exp(-x^2 + g(s)) for x >= 0, t = 2/(2 + x), s = 2t - 1; g(s) = ln(erfc(x)/t) + x^2
is expanded in Chebyshev polynomials from its values at 60 Chebyshev nodes in 50-digit
arithmetic, cut after KEPT terms and rewritten in powers of s (the header's Horner rule). Prints
the coefficients (constant term first), the sum of the dropped Chebyshev coefficients (a bound
on the cut's relative error in erfc) and the sum of the powers' |coefficients| (their rounding
in Horner's rule is that many ulp at most: no cancellation).

    scripts/fast_erfc_coefficients.py
"""
import mpmath as mp

NODES, KEPT = 60, 22


def g(s):
    t = (s + 1) / 2
    if t == 0:
        return mp.log(1 / (2 * mp.sqrt(mp.pi)))  # x -> inf: ln((2 + x)/(2 x sqrt(pi)))
    x = 2 / t - 2
    return mp.log(mp.erfc(x) / t) + x * x


def main():
    mp.mp.dps = 50
    angle = [mp.pi * (k + mp.mpf(1) / 2) / NODES for k in range(NODES)]
    values = [g(mp.cos(a)) for a in angle]
    c = [2 * mp.fsum(v * mp.cos(j * a) for v, a in zip(values, angle)) / NODES
         for j in range(NODES)]
    c[0] /= 2
    # T_j in powers of s: T_0 = 1, T_1 = s, T_j = 2 s T_(j-1) - T_(j-2).
    cheb = [[mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]]
    while len(cheb) < KEPT:
        a, b = [mp.mpf(0)] + [2 * x for x in cheb[-1]], cheb[-2]
        cheb.append([x - (b[k] if k < len(b) else 0) for k, x in enumerate(a)])
    power = [mp.mpf(0)] * KEPT
    for j in range(KEPT):
        for k, x in enumerate(cheb[j]):
            power[k] += c[j] * x
    for a in power:
        print(repr(float(a)) + ",")
    print("dropped:", mp.nstr(mp.fsum(abs(x) for x in c[KEPT:]), 3),
          " sum of |power coefficients|:", mp.nstr(mp.fsum(abs(x) for x in power), 4))


if __name__ == "__main__":
    main()
