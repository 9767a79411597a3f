# SPDX-License-Identifier: Apache-2.0
"""What one Dask task does: one walk through one engine, its track written,
its metrics computed by `pednav eval`. Problems of the walk itself (the
reader's or the engine's error, a truth that cannot be read) come back as a
failed row with their message; anything else raises, so that Dask retries
the task (a lost worker, a full disk)."""
import os
import time

# The columns of the metrics table, in order.
COLUMNS = ["name", "status", "error", "samples", "positions", "steps", "distance_m", "plugin_failures",
           "horizontal_median_m", "horizontal_p75_m", "horizontal_max_m", "final_error_m", "ipin_score_m",
           "loop_closure_m", "truth_step_count", "track", "seconds"]


def metric(metrics, path):
    """A number of the `pednav eval --json` document by dotted path
    ("horizontal_error_m.median"); None when absent."""
    value = metrics
    for key in path.split("."):
        if not isinstance(value, dict) or key not in value:
            return None
        value = value[key]
    return value


def failed_row(walk, message, seconds=0.0):
    row = {c: None for c in COLUMNS}
    row.update(name=walk["name"], status="failed", error=message, seconds=round(seconds, 3))
    return row


def process_walk(walk, config, out_dir=None):
    """Runs `walk` (Walk.as_dict()) with `config` (a config dict; the walk's
    mount, when it has one, overrides the config's). Returns a row of COLUMNS
    plus "metrics" (the whole eval document, or None without truth)."""
    import pednav

    started = time.perf_counter()
    try:
        config = dict(config)
        if walk.get("mount"):
            config["mount"] = walk["mount"]
        result = pednav.run(walk["input"], config=config, format=walk.get("format") or "auto")
        track = None
        if out_dir is not None:
            os.makedirs(out_dir, exist_ok=True)
            track = os.path.join(out_dir, walk["name"] + ".track.csv")
            pednav.write_track_csv(track, result.positions)
            pednav.write_steps_csv(os.path.join(out_dir, walk["name"] + ".steps.csv"), result.strides)
        metrics = None
        if walk.get("truth") or (walk.get("kind") or "").startswith("loop"):
            metrics = pednav.evaluate(result, walk.get("truth"), kind=walk.get("kind") or "auto")
    except (pednav.PednavError, pednav.EvaluationError, ValueError, FileNotFoundError) as e:
        return failed_row(walk, str(e), time.perf_counter() - started)
    row = {c: None for c in COLUMNS}
    row.update(name=walk["name"], status="ok", error="", samples=len(result.recording.imu),
               positions=len(result.positions), steps=len(result.strides), distance_m=round(result.distance_m(), 3),
               plugin_failures=result.plugin_failures, track=track,
               seconds=round(time.perf_counter() - started, 3))
    if result.plugin_failures:
        row["status"] = "plugin_failures"
        row["error"] = "; ".join(result.warnings[:3])
    if metrics is not None:
        row.update(horizontal_median_m=metric(metrics, "horizontal_error_m.median"),
                   horizontal_p75_m=metric(metrics, "horizontal_error_m.p75"),
                   horizontal_max_m=metric(metrics, "horizontal_error_m.max"),
                   final_error_m=metric(metrics, "final_error_m"), ipin_score_m=metric(metrics, "ipin_score_m"),
                   loop_closure_m=metric(metrics, "loop_closure.horizontal_m"),
                   truth_step_count=metric(metrics, "truth_step_count"))
    row["metrics"] = metrics
    return row
