#!/usr/bin/env python3
"""docs/mobility.md's table of one vehicle, from the report.json of a wtc-mobility run in the
engine-mode pairs it ran (docs/mobility.md's tables: Bullet, ODE and ODE's quickstep in force and
constraint mode): one row per measured quantity, the pairs' values in one cell ("in all six" when
they agree), the bound, what governs it, and the range of measured / bound.

usage: tools/mobility_table.py mobility/<vehicle>/report.json
"""
import json
import sys

ENGINE_NAMES = {"bullet": "Bullet", "ode": "ODE", "ode_quick": "ODE quickstep", "mujoco": "MuJoCo"}
COUNTS = {2: "both", 3: "all three", 4: "all four", 5: "all five", 6: "all six", 7: "all seven", 8: "all eight"}
PAIRS = []  # the report's engine-mode pairs, in its order (main)


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
    agree = len(set(shown)) == 1 and len(shown) > 1
    cell = f"{shown[0]}{unit} in {COUNTS.get(len(shown), f'all {len(shown)}')}" if agree else "; ".join(shown) + unit
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
        if (r["engine"], r["mode"]) not in PAIRS:
            PAIRS.append((r["engine"], r["mode"]))
    modes_of = {}
    for engine, mode in PAIRS:
        modes_of.setdefault(engine, []).append(mode)
    measured = "; ".join(f"{ENGINE_NAMES.get(e, e)} {', '.join(m)}" for e, m in modes_of.items())
    print(f"| event | bound | governing limit | measured: {measured} | measured / bound |")
    print("|---|---|---|---|---|")
    for quantity, by_pair in rows.items():
        print(row(quantity, by_pair))


if __name__ == "__main__":
    main()
