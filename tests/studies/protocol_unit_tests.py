#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""studies/protocol.py without a run: the draw (case i the same whatever N; the laws the
space declares, against scipy's distributions by a Kolmogorov-Smirnov test), the 95 % intervals
(against Wilson's closed form, Wilson 1927), what the user's run.json leaves out (every defect
key the deck writes into run.json, read from in.bearing's deck_files line) and the scoring of
answers written here (size within 15 %, the interval's coverage, the place's error modulo the
ball spacing and across 0/360 deg).
Usage: protocol_unit_tests.py SOURCE_DIR"""
import math
import os
import re
import sys

failed = []


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg)
    if not cond:
        failed.append(msg)


def main():
    src = sys.argv[1]
    sys.path.insert(0, os.path.join(src, "studies"))
    import protocol
    from scipy import stats

    a, b = protocol.draw(11, 5), protocol.draw(11, 50)
    check(a == b[:5], "case i is the same for N = 5 and N = 50")
    check(protocol.draw(12, 5) != a, "another seed, other cases")
    cases = protocol.draw(3, 2000)
    sizes = [c["size_deg"] for c in cases if c["kind"] != "none"]
    check(min(sizes) >= 0.2 and max(sizes) <= 3.0, "sizes within 0.2-3 deg")
    p = stats.kstest(sizes, stats.loguniform(0.2, 3.0).cdf).pvalue
    check(p > 1e-3, f"sizes log-uniform (KS p = {p:.3g})")
    pos = [c["position_deg"] for c in cases if c["kind"] != "none"]
    p = stats.kstest(pos, stats.uniform(0, 360).cdf).pvalue
    check(p > 1e-3, f"places uniform over the ring (KS p = {p:.3g})")
    for k, lo, hi in (("load_factor", 0.5, 3.0), ("speed_factor", 0.5, 2.0)):
        p = stats.kstest([c[k] for c in cases], stats.loguniform(lo, hi).cdf).pvalue
        check(p > 1e-3, f"{k} log-uniform on {lo:g}-{hi:g} (KS p = {p:.3g})")
    for k in ("bearing", "kind", "load", "rate_hz", "noise"):
        values = list(protocol.SPACE[k])
        counts = [sum(c[k] == v for c in cases) for v in values]
        p = stats.chisquare(counts).pvalue
        check(p > 1e-3, f"{k} uniform over {values} (counts {counts}, chi2 p = {p:.3g})")

    z = stats.norm.ppf(0.975)
    for k, n in ((0, 10), (7, 10), (30, 30), (95, 200)):
        ph = k / n
        c = (ph + z * z / (2 * n)) / (1 + z * z / n)
        h = z / (1 + z * z / n) * math.sqrt(ph * (1 - ph) / n + z * z / (4 * n * n))
        lo, hi = protocol.wilson(k, n)
        check(abs(lo - (c - h)) < 1e-9 and abs(hi - (c + h)) < 1e-9,
              f"Wilson interval of {k}/{n}: [{lo:.4f}, {hi:.4f}] against the closed form")

    deck = open(os.path.join(src, "inputs", "bearing_6208", "in.bearing")).read()
    written = re.findall(r"(?:string|number) (\w+) v_(defect|size|depth|position|dball|dpocket)\b",
                         deck)
    check(len(written) >= 3, f"the deck's run.json defect keys found: {[w[0] for w in written]}")
    for key, _ in written:
        check(key in protocol.TRUTH_KEYS, f"run.json key '{key}' is left out of the user's copy")

    base = {"bearing": "machado2014", "load": "radial", "load_factor": 1.0, "speed_factor": 1.0,
            "rate_hz": 2e4, "noise": "low", "noise_seed": 5, "index": 0}
    inner = dict(base, kind="inner", size_deg=1.0, position_deg=350.0)
    r = protocol.score(inner, {"defect": "inner", "size_deg": 1.1, "size_interval_deg": [0.9, 1.2],
                               "position_deg": 355.0, "position_interval_deg": [345.0, 358.0],
                               "position_reference": "shaft zero"})
    check(r["kind_right"] and r["size_within"] and r["size_covers"], f"inner sized: {r}")
    check(abs(r["position_error_deg"] - 5) < 1e-9 and r["place_within"] and r["place_covers"],
          "inner place 355 for 350: +5 deg, within, covered")
    r = protocol.score(inner, {"defect": "inner", "size_deg": 1.2, "size_interval_deg": [1.1, 1.3],
                               "position_deg": 5.0, "position_interval_deg": [345.0, 15.0],
                               "position_reference": "shaft zero"})
    check(not r["size_within"] and not r["size_covers"], "1.2 for 1.0: outside 15 %, not covered")
    check(abs(r["position_error_deg"] - 15) < 1e-9 and not r["place_within"] and r["place_covers"],
          "inner place 5 for 350 (across 0): +15 deg, outside 10, the interval 345-15 covers")
    spacing = 27.69  # deg, the 6208's ball spacing as an estimate would state it
    outer = dict(base, kind="outer", size_deg=2.0, position_deg=130.0)  # 40 deg from the load
    r = protocol.score(outer, {"defect": "outer", "size_deg": 2.0, "size_interval_deg": None,
                               "position_deg": 12.3, "position_modulo_deg": spacing,
                               "position_interval_deg": [10.0, 14.0],
                               "position_reference": "load direction"})
    check(abs(r["position_error_deg"] - (12.3 - 40 + spacing)) < 1e-9 and r["place_within"] and
          r["place_covers"], f"outer place modulo the spacing: {r['position_error_deg']:.3f} deg")
    check(r["size_within"] and not r["size_covers"], "a size without an interval covers nothing")
    r = protocol.score(outer, {"defect": "inner", "size_deg": 2.0})
    check(not r["kind_right"] and not r["size_within"] and r["place_within"] is False,
          "a race defect named wrong is neither sized nor placed")
    r = protocol.score(dict(outer, load="fixed"), {"defect": "outer", "size_deg": 2.0})
    check(r["place_within"] is None, "no place scored under a balanced load")
    healthy = dict(base, kind="none", size_deg=0.0, position_deg=0.0)
    r = protocol.score(healthy, {"defect": "outer", "detected": True})
    check(r["family_named"] and not r["kind_right"], "a family on a healthy case: a false alarm")
    r = protocol.score(healthy, {"defect": "none", "detected": False})
    check(r["kind_right"] and not r["family_named"], "healthy read healthy")
    if failed:
        sys.exit(f"{len(failed)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()
