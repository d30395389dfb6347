#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The template fit's tables against today's sizing: reads OUT/template.csv
(studies/template_bank.py) and the sizing study's doc/report/sizing/sizing.csv ('width or chain
curve': the same records), writes OUT/template_tables.md: the error per case at 10, 20, 50 kHz
(low noise), and the coverage and the cases within 15 % per load and defect, low / high noise.

  studies/template_report.py OUT [SIZING_CSV]
"""
import csv
import os
import sys

TODAY = "width or chain curve"
RATES = [1e4, 2e4, 5e4]


def key(r):
    return (r["load"], r["defect"], float(r["position_deg"]), float(r["size_deg"]),
            float(r["rate_hz"]), r["noise"])


def kind(r):
    if r["defect"] == "outer" and r["load"] == "radial" and float(r["position_deg"]) != 90:
        return f"outer {float(r['position_deg']) - 90:g} deg off the load"
    if r["defect"] == "inner" and float(r["position_deg"]) != 90:
        return f"inner at {float(r['position_deg']):g} deg"
    return r["defect"]


def cell(r):
    if r is None:
        return "-"
    if not r["size_deg_est"]:
        return "not sized"
    e = float(r["error_pct"])
    s = f"{e:+.1f} %" + ("" if r["covers"] == "True" else " (miss)")
    if r.get("position_error_deg") and r["defect"] == "outer" and r["load"] == "radial":
        s += f", pos {float(r['position_error_deg']):+.0f} deg" + (
            "" if r.get("branch") == "True" else " mod")
    elif r.get("position_error_deg") and r["defect"] == "inner" and r["load"] == "radial":
        s += f", pos {float(r['position_error_deg']):+.0f} deg"
    return s


def main(argv):
    out = argv[0]
    today_csv = argv[1] if len(argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "doc", "report", "sizing", "sizing.csv")
    new = {key(r): r for r in csv.DictReader(open(os.path.join(out, "template.csv")))}
    old = {key(r): r for r in csv.DictReader(open(today_csv)) if r["method"] == TODAY}
    cases = sorted({k[:4] for k in new}, key=lambda k: (k[0] != "fixed", k[0] != "force", k[1],
                                                         k[2], k[3]))
    lines = ["Error of the template fit (today's width or chain curve in brackets), low noise; "
             "'(miss)': the interval does not hold the true size; outer radial 'pos': the angle's "
             "error from the load direction ('mod': modulo the ball spacing, the branch not "
             "resolved); inner radial 'pos': the angle on the ring with a shaft angle.", "",
             "| load | defect | size (deg) | 10 kHz | 20 kHz | 50 kHz |", "| --- " * 6 + "|"]
    for c in cases:
        r0 = next(new[k] for k in new if k[:4] == c)
        cells = []
        for rate in RATES:
            k = c + (rate, "low")
            today = cell(old.get(k)).split(',')[0]
            cells.append(f"{cell(new.get(k))} ({today})" if k in new else "-")
        lines.append(f"| {c[0]} | {kind(r0)} | {c[3]:g} | " + " | ".join(cells) + " |")
    lines += ["", "Coverage of the interval (one not sized counts as not covered) and, in brackets, "
              "the cases within 15 %, low / high noise; today's in the second row of each:", "",
              "| load | defect | cases | method | 10 kHz | 20 kHz | 50 kHz |", "| --- " * 7 + "|"]
    groups = {}
    for k, r in new.items():
        groups.setdefault((k[0], "outer off-centre" if kind(r).startswith("outer ") else
                           r["defect"]), []).append(k)
    total = {}
    for g in sorted(groups):
        for name, src in (("template", new), ("today", old)):
            cells = []
            for rate in RATES:
                parts = []
                for noise in ("low", "high"):
                    ks = [k for k in groups[g] if k[4] == rate and k[5] == noise and k in src]
                    cov = sum(src[k]["covers"] == "True" for k in ks)
                    w15 = sum(bool(src[k]["error_pct"]) and abs(float(src[k]["error_pct"])) <= 15
                              for k in ks)
                    t = total.setdefault((name, rate, noise), [0, 0, 0])
                    t[0] += cov
                    t[1] += w15
                    t[2] += len(ks)
                    parts.append(f"{cov}/{len(ks)} ({w15})")
                cells.append(" / ".join(parts))
            n = len([k for k in groups[g] if k[4] == 2e4 and k[5] == "low"])
            lines.append(f"| {g[0]} | {g[1]} | {n} | {name} | " + " | ".join(cells) + " |")
    for name in ("template", "today"):
        cells = []
        for rate in RATES:
            parts = []
            for noise in ("low", "high"):
                c, w, n = total.get((name, rate, noise), [0, 0, 0])
                parts.append(f"{c}/{n} = {100 * c / max(n, 1):.0f} % ({w})")
            cells.append(" / ".join(parts))
        lines.append(f"| all | | | {name} | " + " | ".join(cells) + " |")
    with open(os.path.join(out, "template_tables.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
