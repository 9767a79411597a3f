# SPDX-License-Identifier: Apache-2.0
"""pednav.evaluate: the metrics of `pednav eval` (docs/metrics.md), computed
by that command itself so that Python and the CLI give the same numbers."""
import json
import os
import subprocess
import tempfile

from ._lib import path_of
from .io import write_track_csv, write_steps_csv


class EvaluationError(RuntimeError):
    """`pednav eval` could not evaluate: its message (a truth file at fault, ...)."""


def _as_file(value, folder, name, writer):
    if isinstance(value, (str, bytes)) or hasattr(value, "__fspath__"):
        return os.fspath(value)
    path = os.path.join(folder, name)
    writer(path, value)
    return path


def evaluate(track, truth, kind="auto", align=None, fit_points=None, steps=None, map=None, origin=None,
             plot=None):
    """Metrics of a track against a ground truth, as a dict (the JSON of
    `pednav eval --json`: horizontal_m, final_error_m, ipin_score_m,
    loop_closure_m, ...). track: a track CSV, a positions array or a RunResult
    (whose strides then give the step count); truth: a truth file or folder
    (kind "auto", "sim", "koroglu", "humolire", "ipin", "ipol", or "loop" /
    "loop:LENGTH_M" with truth=None); align: "none", "start", "first-segment",
    "fitted" (default: the command's per kind); map: a pednav.map/1 file to
    count wall crossings; plot: an SVG to draw."""
    with tempfile.TemporaryDirectory(prefix="pednav-eval-") as folder:
        if hasattr(track, "positions"):
            if steps is None and len(track.strides):
                steps = track.strides
            track = track.positions
        args = [path_of("cli"), "eval", "--track", _as_file(track, folder, "track.csv", write_track_csv), "--json"]
        if truth is not None:
            args += ["--truth", os.fspath(truth)]
        if kind != "auto":
            args += ["--kind", kind]
        if align is not None:
            args += ["--align", align]
        if fit_points is not None:
            args += ["--fit-points", str(int(fit_points))]
        if steps is not None:
            args += ["--steps", _as_file(steps, folder, "steps.csv", write_steps_csv)]
        if map is not None:
            args += ["--map", os.fspath(map)]
        if origin is not None:
            args += ["--origin", ",".join(repr(float(v)) for v in origin)]
        if plot is not None:
            args += ["--plot", os.fspath(plot)]
        done = subprocess.run(args, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise EvaluationError(done.stderr.strip() or "pednav eval exited with status %d" % done.returncode)
    return json.loads(done.stdout)
