# SPDX-License-Identifier: Apache-2.0
"""pednav.run: a whole recording through an engine, as `pednav run` does it."""
import json
import math

from .engine import Engine, config_text, merged_pointers
from .io import Recording, read
from . import records as rec

MOUNTS = ("foot", "chest", "handheld", "waist")


class RunResult:
    """positions, strides, steps (structured arrays), warnings (the records
    the engine refused and plugin failures, as `pednav run` prints them),
    plugin_failures, describe (the engine at the end), origin, latency_s, and
    the recording when one was read."""

    def __init__(self, outputs, warnings, describe, origin, latency_s, recording):
        self.positions = outputs["positions"]
        self.strides = outputs["strides"]
        self.steps = outputs["steps"]
        self.attitudes = outputs["attitudes"]
        self.warnings = warnings
        self.describe = describe
        self.plugin_failures = int(describe.get("counters", {}).get("plugin_failures", 0))
        self.origin = origin
        self.latency_s = latency_s
        self.recording = recording

    def distance_m(self):
        """Horizontal path length of the track."""
        import numpy as np
        p = self.positions["pos_enu_m"]
        return float(np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1])).sum()) if len(p) > 1 else 0.0


def run_config(mount=None, config=None, map=None):
    """The config text `pednav run` would use for these options."""
    if mount is not None and mount not in MOUNTS:
        raise ValueError("mount must be one of " + ", ".join(MOUNTS) + ", not " + repr(mount))
    if mount is None and config is None:
        raise ValueError("run needs mount= or config=")
    doc = json.loads(config_text(config if config is not None else mount))
    if map is not None:
        doc["map"] = {"path": str(map)}
    if mount is not None:
        doc["mount"] = mount
    return doc


def run(source, mount=None, config=None, map=None, format="auto", start_enu_m=(0.0, 0.0, 0.0),
        heading_deg=math.nan, plugin_dirs=None, attitudes=False):
    """Runs a recording (a path read with the engine's readers, a Recording,
    or a dict/list of input arrays: records.IMU/MAG/BARO/GNSS, or an (N, 7)
    IMU array) through the pipeline of `mount` (its preset) or `config`, with
    an optional map (a pednav.map/1 file). The records go to the engine in
    the order and with the start `pednav run` gives them, so the outputs are
    the CLI's. Returns a RunResult; raises PednavError when the config or the
    file is bad."""
    doc = run_config(mount, config, map)
    recording = None
    if isinstance(source, Recording):
        recording = source
    elif isinstance(source, (str, bytes)) or hasattr(source, "__fspath__"):
        reader = doc.get("input", {})
        recording = read(source, format=format if format != "auto" else reader.get("format", "auto") or "auto",
                         column_map=reader.get("column_map"))
    outputs = ["positions", "strides", "steps"] + (["attitudes"] if attitudes else [])
    engine = Engine(doc, plugin_dirs=plugin_dirs, outputs=outputs)
    warnings = []
    try:
        engine.set_start(start_enu_m, heading_deg)
    except Exception as e:  # noqa: BLE001 - reported as the CLI does, the run goes on
        warnings.append("start not applied: " + str(e))

    def note(index, error):
        warnings.append("record %d: %s" % (index, error))

    if recording is not None:
        engine.push_pointers(recording.merged_pointers(), keep=recording, on_error=note)
    else:
        arrays = _input_arrays(source)
        engine.push_pointers(merged_pointers(arrays), keep=arrays, on_error=note)
    try:
        engine.flush()
    except Exception as e:  # noqa: BLE001
        warnings.append("flush: " + str(e))
    result = RunResult(engine.poll(), warnings, engine.describe(), engine.origin(), engine.latency_s(), recording)
    engine.close()
    return result


def _input_arrays(source):
    import numpy as np
    if isinstance(source, dict):
        parts = [v for v in source.values()]
    elif isinstance(source, (list, tuple)):
        parts = list(source)
    else:
        parts = [source]
    arrays = []
    for part in parts:
        a = np.asarray(part)
        if a.dtype.names is None:
            a = rec.imu_from_array(a)
        a = np.ascontiguousarray(a)
        rec.input_type_of(a)
        if len(a):
            arrays.append(a)
    return arrays
