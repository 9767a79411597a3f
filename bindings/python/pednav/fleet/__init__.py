# SPDX-License-Identifier: Apache-2.0
"""pednav.fleet: reprocess many recorded walks on Dask, one engine per task.

    from pednav import fleet
    table = fleet.reprocess("walks/", config="foot", out_dir="results/")   # LocalCluster, 2 workers
    table = fleet.reprocess("walks.json", config=cfg, scheduler="tcp://10.0.0.5:8786")
    best = fleet.sweep("walks/", "foot", {"step_detector.threshold": [0.3, 0.5, 0.7]}, out_dir="sweep/")

The command line is `pednav-batch` (or `python3 -m pednav.fleet`).
"""
from .cluster import Progress, close_client, connect
from .run import FleetResult, reprocess, summarize, write_table
from .sweep import SweepResult, candidates, sweep
from .tasks import COLUMNS, metric, process_walk
from .walks import Walk, find_walks, load_walks, read_manifest

__all__ = ["COLUMNS", "FleetResult", "Progress", "SweepResult", "Walk", "candidates", "close_client", "connect",
           "find_walks", "load_walks", "metric", "process_walk", "read_manifest", "reprocess", "summarize",
           "sweep", "write_table"]
