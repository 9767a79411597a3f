# SPDX-License-Identifier: Apache-2.0
"""pednav-batch (python3 -m pednav.fleet): fleet reprocessing and sweeps.

  pednav-batch run   --walks DIR|MANIFEST --out DIR [--config FOOT|FILE.json] [--mount M]
                     [--scheduler tcp://HOST:8786 | --workers N] [--retries N] [--pattern GLOB]
  pednav-batch sweep --walks DIR|MANIFEST --out DIR --space SPACE.json [--method grid|random]
                     [--samples N] [--seed N] [--objective COLUMN] (same cluster options)
Exit status: 0 every walk processed, 1 some walks failed (the table says which), 2 a usage mistake.
"""
import argparse
import json
import math
import sys

from . import reprocess, sweep
from .tasks import COLUMNS


def _parser():
    p = argparse.ArgumentParser(prog="pednav-batch", description="Reprocess recorded walks on Dask.")
    sub = p.add_subparsers(dest="command", required=True)
    for name in ("run", "sweep"):
        s = sub.add_parser(name)
        s.add_argument("--walks", required=True, help="a folder of recordings or a manifest (.json or .csv)")
        s.add_argument("--out", required=True, help="the results folder")
        s.add_argument("--config", default=None, help="a preset name (foot) or a config file (default: the mount's)")
        s.add_argument("--mount", default=None, help="foot, chest, handheld or waist")
        s.add_argument("--scheduler", default=None, help="a Dask scheduler address (default: a LocalCluster)")
        s.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
        s.add_argument("--retries", type=int, default=1, help="retries of a task that raised (default 1)")
        s.add_argument("--pattern", default="*.csv", help="recordings of a folder (default *.csv)")
        s.add_argument("--quiet", action="store_true", help="no progress display")
        if name == "sweep":
            s.add_argument("--space", required=True, help="JSON: {\"ROLE.PARAM\": [values] or {min, max, log}}")
            s.add_argument("--method", choices=("grid", "random"), default="grid")
            s.add_argument("--samples", type=int, default=16, help="random: candidates drawn")
            s.add_argument("--seed", type=int, default=0)
            s.add_argument("--objective", default="horizontal_median_m", choices=[c for c in COLUMNS if
                                                                                   c.endswith("_m")])
    return p


def _fmt(v):
    return "-" if v is None or (isinstance(v, float) and not math.isfinite(v)) else (
        "%.3f" % v if isinstance(v, float) else str(v))


def main(argv=None):
    args = _parser().parse_args(argv)
    config = args.config if args.config is not None else (args.mount or "foot")
    common = dict(out_dir=args.out, mount=args.mount, scheduler=args.scheduler, workers=args.workers,
                  retries=args.retries, progress=not args.quiet, pattern=args.pattern)
    try:
        if args.command == "run":
            result = reprocess(args.walks, config, **common)
            for r in result.rows:
                line = "%-28s %-8s steps %-5s median %-8s final %-8s" % (
                    r["name"], r["status"], _fmt(r["steps"]), _fmt(r["horizontal_median_m"]), _fmt(r["final_error_m"]))
                print(line + ("  " + r["error"] if r["error"] else ""))
            s = result.summary
            print("%d walks, %d ok, %d failed; table %s" % (s["walks"], s["ok"], s["failed"], " ".join(result.files)))
            return 1 if s["failed"] or s["plugin_failures"] else 0
        with open(args.space, encoding="utf-8") as f:
            space = json.load(f)
        result = sweep(args.walks, config, space, objective=args.objective, method=args.method,
                       samples=args.samples, seed=args.seed, **common)
        for i, c in enumerate(result.candidates[:10]):
            print("%2d  median %-8s worst %-8s %s" % (i + 1, _fmt(c["median"]), _fmt(c["worst"]),
                                                       json.dumps(c["params"])))
        print("best config: %s" % (result.files[-1] if result.best_config else "none (every candidate failed)"))
        return 0 if result.best_config else 1
    except (ValueError, FileNotFoundError, json.JSONDecodeError) as e:
        print("pednav-batch: %s" % e, file=sys.stderr)
        return 2
