#!/usr/bin/env python3
"""docs/mobility.md's table of one vehicle, from the report.json of a wtc-mobility run in the six
engine-mode pairs: one row per measured quantity, the six values in one cell ("in all six" when they
agree), the bound, what governs it, and the range of measured / bound.

usage: tools/mobility_table.py mobility/<vehicle>/report.json
"""
import json
import sys

PAIRS = [("bullet", "force"), ("bullet", "constraint"), ("ode", "force"), ("ode", "constraint"),
         ("ode_quick", "force"), ("ode_quick", "constraint")]


def number(x):
    return f"{x:.4g}"


def row(quantity, by_pair):
    first = next(iter(by_pair.values()))
    unit = " " + first["unit"] if first.get("unit") else ""
    values = [by_pair.get(p, {}).get("measured") for p in PAIRS]
    if not first.get("bound") or all(v is None for v in values):
        return f"| {quantity} | — | {first.get('note', '')} | — | — |"
    bound = number(first["bound"]) + unit
    if first.get("bound_lower") is not None:
        bound = number(first["bound_lower"]) + "–" + number(first["bound"]) + unit
    shown = [number(v) if v is not None else "—" for v in values]
    cell = shown[0] + unit + " in all six" if len(set(shown)) == 1 else "; ".join(shown) + unit
    ratios = [f"{100.0 * (v / first['bound'] - 1.0):+.1f}" for v in values if v is not None]
    lo, hi = min(ratios, key=float), max(ratios, key=float)
    ratio = f"{lo} %" if lo == hi else f"{lo} to {hi} %"
    return f"| {quantity} | {bound} | {first['governs']} | {cell} | {ratio} |"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        report = json.load(f)
    rows = {}
    for r in report["results"]:
        rows.setdefault(r["quantity"], {})[(r["engine"], r["mode"])] = r
    print("| event | bound | governing limit | measured: Bullet force, constraint; ODE force, constraint; "
          "ODE quickstep force, constraint | measured / bound |")
    print("|---|---|---|---|---|")
    for quantity, by_pair in rows.items():
        print(row(quantity, by_pair))


if __name__ == "__main__":
    main()
