#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Walks per second of pednav.fleet on a LocalCluster of 1 and of 2 workers,
and the scaling ratio. The walks are simulated (pednav sim, foot mount).

    PEDNAV_PREFIX=build PYTHONPATH=bindings/python /usr/bin/python3 bench/python/fleet_walks_per_second.py [--walks 12]
"""
import argparse
import subprocess
import tempfile
import time

import pednav
from pednav import fleet


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--walks", type=int, default=12)
    parser.add_argument("--route", default="corridor_loop")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="pednav-fleet-bench-") as folder:
        for seed in range(args.walks):
            subprocess.run([pednav.path_of("cli"), "sim", "--route", args.route, "--mount", "foot", "--seed",
                            str(seed + 1), "--out", "%s/walk%02d" % (folder, seed)], check=True,
                           capture_output=True)
        walks = fleet.load_walks(folder)
        rates = {}
        for workers in (1, 2):
            client = fleet.connect(workers=workers)
            try:
                fleet.reprocess(walks[:workers], "foot", client=client, progress=False)  # workers warm
                start = time.perf_counter()
                result = fleet.reprocess(walks, "foot", client=client, progress=False)
                elapsed = time.perf_counter() - start
            finally:
                fleet.close_client(client)
            assert result.summary["ok"] == len(walks), result.failed()
            rates[workers] = len(walks) / elapsed
            print("%d worker%s: %d walks (%s, with pednav eval) in %.2f s: %.2f walks/s"
                  % (workers, "" if workers == 1 else "s", len(walks), args.route, elapsed, rates[workers]))
        print("scaling 2 workers / 1 worker: %.2f" % (rates[2] / rates[1]))


if __name__ == "__main__":
    main()
