# SPDX-License-Identifier: Apache-2.0
"""fleet.sweep: grid or random search over plugin params, each candidate
scored over many walks (median and worst of a metric, never one walk)."""
import copy
import csv
import itertools
import json
import math
import os
import random
import statistics
import uuid

from .cluster import Progress, close_client, connect
from .run import gather, resolve_config
from .tasks import process_walk
from .walks import Walk, load_walks


class SweepResult:
    """candidates (each: params, median, worst, mean, walks, failed; best
    first), best (the first), best_config (the config dict with the best
    params) and the files written."""

    def __init__(self, candidates, best_config, files):
        self.candidates = candidates
        self.best = candidates[0] if candidates else None
        self.best_config = best_config
        self.files = files


def _values(name, spec, method, rng):
    if isinstance(spec, list):
        if not spec:
            raise ValueError("sweep space: %s has no values" % name)
        return spec if method == "grid" else [rng.choice(spec)]
    if isinstance(spec, dict) and method == "random" and {"min", "max"} <= set(spec):
        lo, hi = float(spec["min"]), float(spec["max"])
        if spec.get("log"):
            return [math.exp(rng.uniform(math.log(lo), math.log(hi)))]
        return [rng.uniform(lo, hi)]
    raise ValueError("sweep space: %s must be a list of values%s" %
                     (name, " or {\"min\", \"max\", \"log\"}" if method == "random" else ""))


def candidates(space, method="grid", samples=16, seed=0):
    """Param assignments {"role.param": value}: every combination of the
    lists (grid), or `samples` random draws (random: a list is drawn from, a
    {"min", "max", "log"} range sampled uniformly or log-uniformly)."""
    names = sorted(space)
    for n in names:
        if n.count(".") != 1:
            raise ValueError("sweep space: %r must be ROLE.PARAM, e.g. step_detector.threshold" % n)
    if method == "grid":
        return [dict(zip(names, combo)) for combo in itertools.product(*(_values(n, space[n], "grid", None)
                                                                          for n in names))]
    if method != "random":
        raise ValueError("sweep method must be grid or random, not " + repr(method))
    rng = random.Random(seed)
    return [{n: _values(n, space[n], "random", rng)[0] for n in names} for _ in range(samples)]


def apply_params(config, params):
    """A copy of config with each ROLE.PARAM set in its mount's pipeline."""
    doc = copy.deepcopy(config)
    pipeline = doc.get("pipelines", {}).get(doc.get("mount"))
    if pipeline is None:
        raise ValueError("config has no pipeline for its mount %r" % doc.get("mount"))
    for name, value in params.items():
        role, param = name.split(".")
        if role not in pipeline:
            raise ValueError("sweep space: the %s pipeline has no %s (it has %s)"
                             % (doc["mount"], role, ", ".join(sorted(pipeline))))
        pipeline[role].setdefault("params", {})[param] = value
    return doc


def score(rows, objective):
    """median, worst, mean of `objective` over the walks; a candidate with a
    failed walk or a walk without the metric scores infinite (ranked last)."""
    values = [r.get(objective) for r in rows]
    failed = sum(r["status"] != "ok" for r in rows)
    good = [v for v in values if isinstance(v, (int, float)) and math.isfinite(v)]
    if failed or len(good) != len(rows) or not good:
        return {"median": math.inf, "worst": math.inf, "mean": math.inf, "failed": failed,
                "errors": sorted({r["error"] for r in rows if r["error"]})[:3]}
    return {"median": statistics.median(good), "worst": max(good), "mean": statistics.fmean(good), "failed": 0}


def sweep(walks, config, space, objective="horizontal_median_m", method="grid", samples=16, seed=0, out_dir=None,
          mount=None, client=None, scheduler=None, workers=2, retries=1, progress=True, pattern="*.csv"):
    """Scores every candidate of `space` over all `walks` (all candidate x
    walk tasks at once on the cluster), ranks them by the median of
    `objective` (a column of tasks.COLUMNS) then its worst, and writes
    sweep.csv, sweep.json and best_config.json to out_dir."""
    if not isinstance(walks, (list, tuple)):
        walks = load_walks(walks, pattern)
    walks = [w if isinstance(w, Walk) else Walk(**w) for w in walks]
    if not walks:
        raise ValueError("sweep needs at least one walk")
    base = resolve_config(config, mount)
    cands = candidates(space, method, samples, seed)
    configs = [apply_params(base, c) for c in cands]
    own_client = client is None
    if own_client:
        client = connect(scheduler, workers)
    try:
        token = uuid.uuid4().hex[:12]
        tasks = [(ci, w) for ci in range(len(cands)) for w in walks]
        futures = [client.submit(process_walk, w.as_dict(), configs[ci], None, retries=retries, pure=False,
                                 key="pednav-sweep-%s-%d" % (token, k)) for k, (ci, w) in enumerate(tasks)]
        rows = gather(client, futures, [w for _, w in tasks],
                      Progress(len(futures), what="runs", enabled=progress))
    finally:
        if own_client:
            close_client(client)
    ranked = []
    for ci, params in enumerate(cands):
        mine = [rows[k] for k, (cj, _) in enumerate(tasks) if cj == ci]
        entry = {"params": params, "walks": len(mine)}
        entry.update(score(mine, objective))
        entry["per_walk"] = {r["name"]: r.get(objective) for r in mine}
        ranked.append(entry)
    ranked.sort(key=lambda e: (e["median"], e["worst"]))
    best_config = apply_params(base, ranked[0]["params"]) if math.isfinite(ranked[0]["median"]) else None
    files = write_sweep(ranked, best_config, objective, out_dir) if out_dir else ()
    return SweepResult(ranked, best_config, files)


def write_sweep(ranked, best_config, objective, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    names = sorted(ranked[0]["params"]) if ranked else []
    csv_path = os.path.join(out_dir, "sweep.csv")
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["rank"] + names + [objective + "_median", objective + "_worst", objective + "_mean",
                                       "walks", "failed"])
        for i, e in enumerate(ranked):
            w.writerow([i + 1] + [e["params"][n] for n in names] + [e["median"], e["worst"], e["mean"], e["walks"],
                                                                   e["failed"]])
    json_path = os.path.join(out_dir, "sweep.json")
    with open(json_path, "w", encoding="utf-8") as f:
        finite = [{k: (None if isinstance(v, float) and not math.isfinite(v) else v) for k, v in e.items()}
                  for e in ranked]  # a candidate with a failed walk: null scores (JSON has no infinity)
        json.dump({"objective": objective, "candidates": finite}, f, indent=2)
        f.write("\n")
    files = [csv_path, json_path]
    if best_config is not None:
        best_path = os.path.join(out_dir, "best_config.json")
        with open(best_path, "w", encoding="utf-8") as f:
            json.dump(best_config, f, indent=2)
            f.write("\n")
        files.append(best_path)
    return files
