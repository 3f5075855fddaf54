#!/usr/bin/env python3
"""Figures of a wtc-mobility report (report.json in the directory given):

- dp_slip.png: DP/W against the driving slip i, each engine and mode, beside the bound mu(s);
- searches.png: each search's trials (value against run, passed or not) with the bound.

Exits 1 without drawing when matplotlib is missing (wtc-mobility then warns).
"""
import json
import os
import sys


def main():
    if len(sys.argv) < 2:
        print("usage: plot_mobility.py <wtc-mobility output directory>", file=sys.stderr)
        return 2
    out = sys.argv[1]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return 1
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    results = report["results"]
    name = report["vehicle"]["name"]

    drawbar = [r for r in results if r["event"] == "drawbar"]
    if drawbar:
        fig, ax = plt.subplots(figsize=(6, 4))
        bound = sorted((r["slip"], r["bound"]) for r in drawbar)
        soil = report.get("ground", {}).get("soil")
        label = f"bound: the soil's steady state ({soil})" if soil else "bound: mu(s) at the driven wheels"
        ax.plot([b[0] * 100 for b in bound], [b[1] for b in bound], "k--", label=label)
        for key in sorted({(r["engine"], r["mode"]) for r in drawbar}):
            pts = sorted((r["slip"], r["measured"]) for r in drawbar
                         if (r["engine"], r["mode"]) == key and r["measured"] is not None)
            ax.plot([p[0] * 100 for p in pts], [p[1] for p in pts], "o-", label=f"{key[0]} {key[1]}")
        ax.set_xlabel("driving slip i (%)")
        ax.set_ylabel("DP / W")
        ax.set_title(f"{name}: drawbar pull against slip")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "dp_slip.png"), dpi=120)

    searches = [r for r in results if r["trials"]]
    if searches:
        events = sorted({r["event"] for r in searches})
        cols = min(3, len(events))
        nrows = (len(events) + cols - 1) // cols
        fig, axes = plt.subplots(nrows, cols, figsize=(4.6 * cols, 3.8 * nrows), squeeze=False,
                                 constrained_layout=True)
        for ax in axes.flat[len(events):]:
            ax.axis("off")
        for ax, event in zip(axes.flat, events):
            rows = [r for r in searches if r["event"] == event]
            for k, r in enumerate(rows):
                xs = list(range(1, len(r["trials"]) + 1))
                ys = [t["value"] for t in r["trials"]]
                ax.plot(xs, ys, "-", alpha=0.5, label=f"{r['engine']} {r['mode']}")
                ax.scatter([x for x, t in zip(xs, r["trials"]) if t["passed"]],
                           [t["value"] for t in r["trials"] if t["passed"]], marker="o", color=f"C{k}")
                ax.scatter([x for x, t in zip(xs, r["trials"]) if not t["passed"]],
                           [t["value"] for t in r["trials"] if not t["passed"]], marker="x", color=f"C{k}")
            ax.axhline(rows[0]["bound"], color="k", ls="--", label="bound")
            if "bound_lower" in rows[0]:
                ax.axhline(rows[0]["bound_lower"], color="k", ls=":")
            ax.set_title(f"{rows[0]['quantity']} ({rows[0]['unit']})", fontsize=9)
            ax.set_yscale("log" if event in ("step", "gap") and rows[0]["bound"] < 0.05 else "linear")
            ax.set_xlabel("run (o passed, x failed)")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=6)
        fig.suptitle(f"{name}: searches")
        fig.savefig(os.path.join(out, "searches.png"), dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
