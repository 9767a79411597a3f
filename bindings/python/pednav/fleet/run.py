# SPDX-License-Identifier: Apache-2.0
"""fleet.reprocess: a config mapped over walks on a Dask cluster."""
import csv
import json
import math
import os
import statistics
import uuid

from ..run import run_config
from ..engine import config_text
from .cluster import Progress, close_client, connect
from .tasks import COLUMNS, failed_row, process_walk
from .walks import Walk, load_walks


class FleetResult:
    """rows (one per walk, in walk order, of tasks.COLUMNS), summary (walks,
    ok, failed, and median / mean / worst of each error column over the walks
    that have it) and the files written."""

    def __init__(self, rows, summary, files):
        self.rows = rows
        self.summary = summary
        self.files = files

    def failed(self):
        return [r for r in self.rows if r["status"] == "failed"]

    def row(self, name):
        return next(r for r in self.rows if r["name"] == name)


def resolve_config(config, mount=None):
    """A config dict from a preset name, JSON text, a .json file or a dict."""
    if isinstance(config, dict):
        doc = json.loads(json.dumps(config))
    else:
        doc = json.loads(config_text(config))
    if mount is not None:
        doc = run_config(mount=mount, config=doc)
    return doc


def summarize(rows, columns=("horizontal_median_m", "horizontal_p75_m", "final_error_m", "ipin_score_m",
                             "loop_closure_m")):
    summary = {"walks": len(rows), "ok": sum(r["status"] == "ok" for r in rows),
               "failed": sum(r["status"] == "failed" for r in rows),
               "plugin_failures": sum(r["status"] == "plugin_failures" for r in rows)}
    for c in columns:
        values = [r[c] for r in rows if isinstance(r.get(c), (int, float)) and math.isfinite(r[c])]
        if values:
            summary[c] = {"n": len(values), "median": statistics.median(values),
                          "mean": statistics.fmean(values), "worst": max(values)}
    return summary


def write_table(rows, summary, out_dir, stem="metrics"):
    """metrics.csv (the table) and metrics.json (summary and rows, with each
    walk's whole eval document) in out_dir; returns their paths."""
    os.makedirs(out_dir, exist_ok=True)
    csv_path, json_path = os.path.join(out_dir, stem + ".csv"), os.path.join(out_dir, stem + ".json")
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: ("" if v is None else v) for k, v in r.items()})
    with open(json_path, "w", encoding="utf-8") as f:
        json.dump({"summary": summary, "walks": rows}, f, indent=2)
        f.write("\n")
    return csv_path, json_path


def gather(client, futures, walks, progress):
    """Rows of the futures in walk order; a task that failed after its
    retries becomes a failed row with its exception."""
    from dask.distributed import as_completed

    index = {f.key: i for i, f in enumerate(futures)}
    rows = [None] * len(futures)
    for future in as_completed(futures):
        i = index[future.key]
        try:
            rows[i] = future.result()
        except Exception as e:  # noqa: BLE001 - the walk is reported, the rest go on
            rows[i] = failed_row(walks[i].as_dict(), "task failed: %s: %s" % (type(e).__name__, e))
        progress.update(failed=rows[i]["status"] == "failed")
    return rows


def reprocess(walks, config="foot", out_dir=None, mount=None, client=None, scheduler=None, workers=2, retries=1,
              progress=True, pattern="*.csv"):
    """Runs `config` over `walks` (a folder, a manifest or a list of Walk),
    one engine per task, on `client`, or a client of `scheduler`, or a new
    LocalCluster of `workers` processes. With out_dir: tracks and steps in
    out_dir/tracks, metrics.csv and metrics.json in out_dir. Each task is
    retried `retries` times when it raises (not when the walk itself is bad:
    that is a failed row with the reader's or engine's message)."""
    if not isinstance(walks, (list, tuple)):
        walks = load_walks(walks, pattern)
    walks = [w if isinstance(w, Walk) else Walk(**w) for w in walks]
    doc = resolve_config(config, mount)
    own_client = client is None
    if own_client:
        client = connect(scheduler, workers)
    try:
        tracks = os.path.join(out_dir, "tracks") if out_dir else None
        token = uuid.uuid4().hex[:12]
        futures = client.map(process_walk, [w.as_dict() for w in walks], config=doc, out_dir=tracks,
                             retries=retries, pure=False,
                             key=["pednav-walk-%s-%d" % (token, i) for i in range(len(walks))])
        rows = gather(client, futures, walks, Progress(len(walks), enabled=progress))
    finally:
        if own_client:
            close_client(client)
    summary = summarize(rows)
    files = write_table(rows, summary, out_dir) if out_dir else ()
    return FleetResult(rows, summary, files)
