# SPDX-License-Identifier: Apache-2.0
# pednav.fleet on a LocalCluster of 2 workers on loopback: reprocessing with
# per-walk failures and retries, the tables, and a parameter sweep.
import csv
import json
import os
import shutil
import subprocess
import sys

import pytest

import pednav
from pednav import fleet
from conftest import cli, shared_data


@pytest.fixture(scope="module")
def client():
    c = fleet.connect(workers=2)
    assert len(c.scheduler_info()["workers"]) == 2
    assert all(a.startswith("tcp://127.0.0.1:") for a in c.scheduler_info()["workers"])
    yield c
    fleet.close_client(c)


@pytest.fixture(scope="module")
def walks_folder(tmp_path_factory):
    """Two simulated walks (with truth), a real recording, and a file no reader takes."""
    folder = tmp_path_factory.mktemp("walks")
    for seed in (1, 2):
        cli("sim", "--route", "corridor_loop", "--mount", "foot", "--seed", seed, "--out", folder / ("sim%d" % seed))
    shutil.copy(shared_data("koroglu-foot-gcp", "SensorConnectData_35.csv"), folder / "koroglu35.csv")
    (folder / "broken.csv").write_text("this is not a recording\n")
    return folder


def test_reprocess_a_folder(client, walks_folder, tmp_path):
    result = fleet.reprocess(walks_folder, "foot", out_dir=tmp_path, client=client, progress=False)
    assert [r["name"] for r in result.rows] == ["broken", "koroglu35", "sim1", "sim2"]
    broken = result.row("broken")
    assert broken["status"] == "failed"
    assert broken["error"].startswith("PN_E_BAD_INPUT at %s:1: unknown format" % (walks_folder / "broken.csv"))
    # Each walk's numbers are those of pednav run and pednav eval on it.
    sim1 = result.row("sim1")
    single = pednav.run(walks_folder / "sim1" / "input.csv", mount="foot")
    assert sim1["status"] == "ok" and sim1["steps"] == len(single.strides) == 86
    metrics = pednav.evaluate(single, walks_folder / "sim1" / "truth.csv")
    assert sim1["horizontal_median_m"] == metrics["horizontal_error_m"]["median"]
    assert sim1["final_error_m"] == metrics["final_error_m"] < 2.0
    cli("run", "--mount", "foot", "--input", walks_folder / "sim1" / "input.csv", "--output", tmp_path / "cli.csv")
    assert (tmp_path / "tracks" / "sim1.track.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    assert result.row("koroglu35")["horizontal_median_m"] is None  # no truth in a plain folder
    # The tables.
    with open(tmp_path / "metrics.csv", newline="") as f:
        table = list(csv.DictReader(f))
    assert [r["name"] for r in table] == ["broken", "koroglu35", "sim1", "sim2"]
    assert float(table[2]["horizontal_median_m"]) == sim1["horizontal_median_m"]
    doc = json.loads((tmp_path / "metrics.json").read_text())
    assert doc["summary"]["walks"] == 4 and doc["summary"]["ok"] == 3 and doc["summary"]["failed"] == 1
    medians = sorted([result.row("sim1")["horizontal_median_m"], result.row("sim2")["horizontal_median_m"]])
    assert doc["summary"]["horizontal_median_m"]["worst"] == medians[1]
    assert doc["walks"][2]["metrics"]["step_count"] == 86


def test_a_manifest_with_truth_and_a_task_that_raises_is_retried(client, walks_folder, tmp_path):
    manifest = tmp_path / "walks.json"
    manifest.write_text(json.dumps({"walks": [
        {"name": "k35", "input": str(walks_folder / "koroglu35.csv"),
         "truth": shared_data("koroglu-foot-gcp", "SensorConnectData_35_gcp.csv")},
        {"name": "missing", "input": "nowhere.csv"}]}))
    walks = fleet.load_walks(str(manifest))
    assert walks[1].input == str(tmp_path / "nowhere.csv")
    result = fleet.reprocess(walks, "foot", out_dir=tmp_path / "out", client=client, progress=False)
    k35 = result.row("k35")
    assert k35["status"] == "ok" and k35["horizontal_median_m"] < 3.0
    assert result.row("missing")["error"].endswith("nowhere.csv: file not found")
    # A task that raises is retried (the client's retries, as reprocess sets them) ...
    marker = tmp_path / "attempts"
    futures = client.map(flaky_task, [str(marker)], retries=2, pure=False)
    assert futures[0].result() == 3  # failed twice, succeeded on the last retry
    # ... and one that still fails becomes a failed row while the rest go on.
    rows = fleet.run.gather(client, client.map(flaky_task, [str(tmp_path / "once")], retries=0, pure=False),
                            [fleet.Walk("flaky", "x.csv")], fleet.Progress(1, enabled=False))
    assert rows[0]["status"] == "failed" and rows[0]["error"] == "task failed: OSError: attempt 1 failed"


def flaky_task(marker):
    """Raises on the first two attempts (an OSError, as a lost disk would)."""
    attempts = int(open(marker).read()) + 1 if os.path.exists(marker) else 1
    with open(marker, "w") as f:
        f.write(str(attempts))
    if attempts < 3:
        raise OSError("attempt %d failed" % attempts)
    return attempts


def test_sweep_scores_candidates_over_walks(client, walks_folder, tmp_path):
    walks = [w for w in fleet.load_walks(str(walks_folder)) if w.truth]
    assert len(walks) == 2
    space = {"step_detector.threshold": [0.2, 0.5, 2.0]}
    result = fleet.sweep(walks, "foot", space, out_dir=tmp_path, client=client, progress=False)
    assert len(result.candidates) == 3
    for c in result.candidates:
        assert c["walks"] == 2 and c["failed"] == 0
        assert c["worst"] == max(c["per_walk"].values())
    medians = [c["median"] for c in result.candidates]
    assert medians == sorted(medians)
    # The default (0.5) scored over the same walks as a fleet run scores them.
    default = next(c for c in result.candidates if c["params"]["step_detector.threshold"] == 0.5)
    plain = fleet.reprocess(walks, "foot", client=client, progress=False)
    assert sorted(default["per_walk"].values()) == sorted(r["horizontal_median_m"] for r in plain.rows)
    best = json.loads((tmp_path / "best_config.json").read_text())
    assert best["pipelines"]["foot"]["step_detector"]["params"]["threshold"] == \
        result.best["params"]["step_detector.threshold"]
    assert best == result.best_config
    # Random search draws the same candidates for the same seed.
    a = fleet.candidates({"step_detector.threshold": {"min": 0.1, "max": 2.0, "log": True}}, "random", 4, seed=3)
    b = fleet.candidates({"step_detector.threshold": {"min": 0.1, "max": 2.0, "log": True}}, "random", 4, seed=3)
    assert a == b and len(a) == 4 and all(0.1 <= c["step_detector.threshold"] <= 2.0 for c in a)
    with pytest.raises(ValueError, match="no nope"):
        fleet.sweep(walks, "foot", {"nope.x": [1]}, client=client, progress=False)


def test_the_command_line(walks_folder, tmp_path):
    env = dict(os.environ)
    done = subprocess.run([sys.executable, "-m", "pednav.fleet", "run", "--walks", str(walks_folder), "--out",
                           str(tmp_path), "--workers", "2"], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 1, done.stderr  # one walk failed
    assert "4 walks, 3 ok, 1 failed" in done.stdout
    assert "4/4 walks, 1 failed" in done.stderr  # the progress display
    assert (tmp_path / "metrics.csv").exists() and (tmp_path / "tracks" / "sim2.track.csv").exists()
    bad = subprocess.run([sys.executable, "-m", "pednav.fleet", "run", "--walks", str(tmp_path / "none"), "--out",
                          str(tmp_path)], capture_output=True, text=True, env=env, timeout=60)
    assert bad.returncode == 2 and "no folder or manifest" in bad.stderr
