# SPDX-License-Identifier: Apache-2.0
# Run by run_installed_test.cmake on an installed prefix: the package finds
# its library, plugins, presets and CLI there, and runs a recording as the
# installed CLI does.
import os
import subprocess
import sys

prefix, data_dir, work_dir = sys.argv[1:4]
import pednav  # noqa: E402

assert pednav.__file__.startswith(prefix), pednav.__file__
assert os.path.realpath(pednav.path_of("library")).startswith(os.path.realpath(prefix))
walk = os.path.join(data_dir, "koroglu-foot-gcp", "SensorConnectData_39.csv")
result = pednav.run(walk, mount="foot")
assert len(result.strides) > 10, len(result.strides)
track = os.path.join(work_dir, "cli_track.csv")
subprocess.run([os.path.join(prefix, "bin", "pednav"), "run", "--mount", "foot", "--input", walk,
                "--output", track], check=True, capture_output=True)
mine = os.path.join(work_dir, "py_track.csv")
pednav.write_track_csv(mine, result.positions)
with open(track, "rb") as a, open(mine, "rb") as b:
    assert a.read() == b.read(), "the installed package's track differs from the installed CLI's"
metrics = pednav.evaluate(result, os.path.join(data_dir, "koroglu-foot-gcp", "SensorConnectData_39_gcp.csv"))
assert metrics["horizontal_error_m"]["n"] > 0
print("installed pednav %s: %d positions, %d steps, median error %.2f m" % (
    pednav.version(), len(result.positions), len(result.strides), metrics["horizontal_error_m"]["median"]))
