"""python3 -m wtc run SCENE [--engine E] [--mode M] [--set key=value ...] [--out DIR]: wtc-sim's run from Python.

The way to run a scene whose controller is written in Python (controller: {type: python, ...}), which wtc-sim
refuses. Exit status as wtc-sim's: 0 success, 1 the run failed its criteria, 2 bad input.
"""
import argparse
import sys

import wtc


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m wtc")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="run a scene, writing what wtc-sim writes")
    run.add_argument("scene")
    run.add_argument("--engine")
    run.add_argument("--mode")
    run.add_argument("--dt", type=float)
    run.add_argument("--duration", type=float)
    run.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    run.add_argument("--out")
    run.add_argument("--quiet", action="store_true")
    run.add_argument("--no-plots", action="store_true")
    run.add_argument("--no-replay", action="store_true")
    args = parser.parse_args(argv)
    sets = {}
    for text in args.set:
        key, eq, value = text.partition("=")
        if not eq or not key:
            print(f"python3 -m wtc: --set {text}: expected key.path=value", file=sys.stderr)
            return 2
        sets[key] = value
    try:
        scene = wtc.load_scene(args.scene, engine=args.engine, mode=args.mode, dt=args.dt, duration=args.duration,
                               set=sets)
        summary = wtc.run(scene, out=args.out, progress=not args.quiet and sys.stderr.isatty(),
                          plots=not args.no_plots, replay=not args.no_replay)
    except wtc.Error as e:
        print(f"python3 -m wtc: {e}", file=sys.stderr)
        return 2
    if not args.quiet:
        print(summary["report"], end="")  # wtc-sim's own lines (apps/runner/run_outputs.hpp, runReport)
    return 0 if summary["success"] else 1


if __name__ == "__main__":
    sys.exit(main())
