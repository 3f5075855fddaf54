"""The ledge climb's table from a directory of wtc-sim runs (bench/ledge_climb_matrix.sh)."""
import json
import pathlib
import sys

rows = []
for summary in sorted(pathlib.Path(sys.argv[1]).glob("*/summary.json")):
    s = json.loads(summary.read_text())
    f = s.get("fields", s)
    p = s["parameters"]
    drives = s.get("drives", {})
    fold = max(drives.get(d, {}).get("peak_effort", 0.0) for d in ("front_carrier", "rear_carrier"))
    wheel = max(v.get("peak_effort", 0.0) for k, v in drives.items() if k.endswith("_wheel"))
    why = next((w.split(": ", 1)[1] for w in s.get("warnings", []) if w.startswith("controller:")), "")
    rows.append("| {:.2f} | {:.1f} | {:+.0f} | {} | {} | {} | {} | {} | {:.0f} / {:.0f} | {:.0f} | {:.0f} | {:.0f} | {:.1f} | {:.0f} | {} |".format(
        p["ledge_height"], p["approach_speed"], p["yaw_deg"], s["engine"], s["mode"],
        "yes" if s["success"] else "no", "yes" if f.get("climbed") else "no",
        "{:.1f}".format(f["time_to_climb_s"]) if "time_to_climb_s" in f else "-",
        f.get("max_front_pitch_deg", 0), f.get("max_rear_pitch_deg", 0), f.get("max_tilt_deg", 0), fold, wheel,
        s.get("real_time_factor", 0), 100.0 * s.get("wtc_share", 0), why[:90]))
print("| height m | speed m/s | yaw deg | engine | mode | success | climbed | time to climb s | peak pitch front / rear deg | max tilt deg | peak fold N m | peak wheel N m | real-time factor | WTC % | controller |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
print("\n".join(rows))
