# SPDX-License-Identifier: Apache-2.0
# pednav.run and pednav.evaluate give the numbers of `pednav run` and `pednav eval`.
import re

import numpy as np
import pytest

import pednav
from pednav import records
from conftest import cli, cli_json, shared_data

SUMMARY = re.compile(r"samples (\d+), positions (\d+), steps (\d+), distance ([0-9.]+) m")


def cli_run(tmp_path, name, *args):
    track, steps = tmp_path / (name + "_cli_track.csv"), tmp_path / (name + "_cli_steps.csv")
    done = cli("run", *args, "--output", track, "--steps", steps)
    return track.read_bytes(), steps.read_bytes(), SUMMARY.search(done.stdout).groups()


def python_run(tmp_path, name, result):
    track, steps = tmp_path / (name + "_py_track.csv"), tmp_path / (name + "_py_steps.csv")
    pednav.write_track_csv(track, result.positions)
    pednav.write_steps_csv(steps, result.strides)
    return track.read_bytes(), steps.read_bytes()


@pytest.mark.parametrize("walk", [("koroglu-foot-gcp", "SensorConnectData_35.csv"),
                                  ("xio-gait-ngimu", "short_walk.csv"),  # IMU only (the others with magnetometer)
                                  ("ipol-gait-waist-feet", "5-1_lf.txt")])
def test_run_equals_the_cli_on_recordings(tmp_path, walk):
    path = shared_data(*walk)
    name = walk[1].split(".")[0]
    track, steps, summary = cli_run(tmp_path, name, "--mount", "foot", "--input", path)
    result = pednav.run(path, mount="foot")
    assert python_run(tmp_path, name, result) == (track, steps)
    samples, positions, step_count, distance = summary
    assert len(result.recording.imu) == int(samples) and len(result.positions) == int(positions)
    assert len(result.strides) == int(step_count) > 10
    assert "%.2f" % result.distance_m() == distance
    assert result.warnings == [] and result.plugin_failures == 0


def test_run_equals_the_cli_on_a_simulated_walk(tmp_path, sim_walk):
    imu = sim_walk / "input.csv"
    track, steps, summary = cli_run(tmp_path, "sim", "--mount", "foot", "--input", imu)
    result = pednav.run(imu, mount="foot")
    assert python_run(tmp_path, "sim", result) == (track, steps)
    # The same records given as arrays (from the reader) run the same.
    rec = pednav.read(imu)
    from_arrays = pednav.run({"imu": rec.imu, "mag": rec.mag, "baro": rec.baro}, mount="foot")
    assert from_arrays.positions.tobytes() == result.positions.tobytes()
    # And so does an (N, 7) array of t_s, accel, gyro when the file has only IMU samples.
    if len(rec.mag) == 0 and len(rec.baro) == 0:
        columns = np.column_stack([rec.imu["t_ns"] * 1e-9, rec.imu["accel_mps2"], rec.imu["gyro_radps"]])
        assert pednav.run(columns, mount="foot").positions.tobytes() == result.positions.tobytes()

    # evaluate: the metrics of pednav eval on the CLI's own track.
    expected = cli_json("eval", "--track", tmp_path / "sim_cli_track.csv", "--truth", sim_walk / "truth.csv",
                        "--steps", tmp_path / "sim_cli_steps.csv", "--json")
    metrics = pednav.evaluate(result, sim_walk / "truth.csv")
    assert metrics == expected
    assert metrics["horizontal_error_m"]["median"] < 2.0  # a simulated corridor loop, metres
    assert metrics["step_count"] == len(result.strides)


def test_evaluate_a_recording_against_its_footprints(tmp_path):
    path = shared_data("koroglu-foot-gcp", "SensorConnectData_33.csv")
    truth = shared_data("koroglu-foot-gcp", "SensorConnectData_33_gcp.csv")
    track, _, _ = cli_run(tmp_path, "k33", "--mount", "foot", "--input", path)
    expected = cli_json("eval", "--track", tmp_path / "k33_cli_track.csv", "--truth", truth, "--json")
    result = pednav.run(path, mount="foot")
    assert pednav.evaluate(result.positions, truth) == expected
    assert expected["alignment"]["mode"] == "fitted"
    with pytest.raises(pednav.EvaluationError) as e:
        pednav.evaluate(result.positions, tmp_path / "missing_truth.csv")
    assert "missing_truth.csv" in str(e.value)


def test_run_with_a_config_and_bad_inputs(tmp_path):
    config = pednav.run_config(mount="foot")
    config["pipelines"]["foot"]["step_detector"]["params"] = {}
    path = shared_data("koroglu-foot-gcp", "SensorConnectData_33.csv")
    assert pednav.run(path, config=config).positions.tobytes() == pednav.run(path, mount="foot").positions.tobytes()
    with pytest.raises(ValueError):
        pednav.run(path, mount="skates")
    with pytest.raises(pednav.PednavError) as e:
        pednav.run(tmp_path / "none.csv", mount="foot")
    assert e.value.status == "PN_E_BAD_INPUT"
    # A record refused mid-stream is reported and the run goes on, as the CLI does.
    rec = pednav.read(path)
    imu = rec.imu.copy()
    imu["accel_mps2"][500, 0] = np.nan
    result = pednav.run({"imu": imu}, mount="foot")
    assert len(result.warnings) == 1 and result.warnings[0].startswith("record 500: PN_E_NUMERIC")
    assert len(result.positions) == len(pednav.run(rec, mount="foot").positions) - 1
    assert records.POSITION.itemsize == result.positions["struct_size"][0]


def test_the_plot_example(tmp_path, sim_walk):
    import os
    import subprocess
    import sys
    script = os.path.join(os.path.dirname(__file__), "..", "..", "..", "examples", "python", "plot_track.py")
    done = subprocess.run([sys.executable, script, str(sim_walk), "--out", str(tmp_path / "t.png")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    median = pednav.evaluate(pednav.run(sim_walk / "input.csv", mount="foot"),
                             sim_walk / "truth.csv")["horizontal_error_m"]["median"]
    assert "horizontal error median %.2f m" % median in done.stdout
    assert (tmp_path / "t.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
