# SPDX-License-Identifier: Apache-2.0
# Fixtures of the pednav Python tests: the shared recordings, the CLI, simulated walks.
import json
import os
import subprocess

import pytest

import pednav


def shared_data(*parts):
    """A path under ../shared/data; a missing file fails the test naming it."""
    root = os.environ.get("PEDNAV_SHARED_DATA_DIR")
    assert root, "PEDNAV_SHARED_DATA_DIR is not set (ctest sets it)"
    path = os.path.join(root, *parts)
    assert os.path.exists(path), "missing recording: " + path
    return path


def cli(*args, check=True):
    """Runs the pednav CLI of the build; returns the completed process."""
    done = subprocess.run([pednav.path_of("cli"), *map(str, args)], capture_output=True, text=True, check=False)
    if check:
        assert done.returncode == 0, "pednav %s failed: %s" % (" ".join(map(str, args)), done.stderr)
    return done


def cli_json(*args):
    return json.loads(cli(*args).stdout)


@pytest.fixture(scope="session")
def work_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("pednav")


@pytest.fixture(scope="session")
def sim_walk(work_dir):
    """A simulated foot walk (pednav sim): its folder, with input.csv and truth.csv."""
    out = work_dir / "sim_corridor_loop"
    cli("sim", "--route", "corridor_loop", "--mount", "foot", "--seed", "7", "--out", out)
    return out
