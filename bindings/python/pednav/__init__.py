# SPDX-License-Identifier: Apache-2.0
"""pednav from Python: the engine (pn_engine.h) and its readers (pn_io.h)
over libpednav, with numpy arrays in and out.

    import pednav
    rec = pednav.read("walk.csv")                 # the engine's readers
    result = pednav.run("walk.csv", mount="foot") # the whole pipeline
    result.positions["pos_enu_m"]                 # (N, 3) metres
    pednav.evaluate(result, "truth.csv")          # the metrics of pednav eval

    engine = pednav.Engine("foot")
    engine.push_imu(samples)                      # (N, 7): t_s, accel m/s^2, gyro rad/s
    engine.flush()
    out = engine.poll()                           # positions, strides, steps
"""
from . import records
from ._lib import PednavError, path_of
from .engine import Engine
from .evaluate import EvaluationError, evaluate
from .io import Recording, formats, read, write_steps_csv, write_track_csv
from .run import RunResult, run, run_config


def version():
    """The version of the loaded libpednav."""
    from ._lib import ffi, lib
    return ffi.string(lib().pn_version_string()).decode()


__all__ = ["Engine", "PednavError", "EvaluationError", "Recording", "RunResult", "evaluate", "formats", "path_of",
           "read", "records", "run", "run_config", "version", "write_steps_csv", "write_track_csv"]
