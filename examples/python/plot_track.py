#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Runs a recording through pednav from Python and plots the track over its
ground truth and map with matplotlib; prints the metrics of `pednav eval`.

    PEDNAV_PREFIX=build /usr/bin/python3 examples/python/plot_track.py WALK_DIR [--out track.png]

WALK_DIR is a folder written by `pednav sim` (input.csv, truth.csv,
building.geojson), e.g. `build/bin/pednav sim --route corridor_loop --out walk/`.
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import pednav  # noqa: E402


def map_walls_enu(map_path):
    """The walls of a pednav.map/1 file in ENU metres around its pednav:origin."""
    with open(map_path, encoding="utf-8") as f:
        doc = json.load(f)
    lon0, lat0, h0 = doc["pednav:origin"]
    engine = pednav.Engine("foot")
    engine.set_origin(lat0, lon0, h0)
    walls = []
    for feature in doc["features"]:
        if feature["properties"].get("pednav:kind") == "wall" and feature["geometry"]["type"] == "LineString":
            walls.append([engine.enu_from_geo(lat, lon, h0)[:2] for lon, lat in feature["geometry"]["coordinates"]])
    return walls


def read_truth_xy(truth_path):
    with open(truth_path, encoding="utf-8") as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        points = [(float(r["x"]), float(r["y"])) for r in rows]
    return [p[0] for p in points], [p[1] for p in points]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("walk", help="a pednav sim folder")
    parser.add_argument("--mount", default="foot")
    parser.add_argument("--out", default="track.png")
    args = parser.parse_args()
    recording = pednav.read(os.path.join(args.walk, "input.csv"))
    print("read %s: %s, %d IMU samples; %s" % (recording.path, recording.format, len(recording.imu),
                                              recording.notes[0] if recording.notes else ""))
    result = pednav.run(recording, mount=args.mount)
    truth_path = os.path.join(args.walk, "truth.csv")
    metrics = pednav.evaluate(result, truth_path)
    print("%d steps, %.1f m walked; horizontal error median %.2f m, final %.2f m" % (
        len(result.strides), result.distance_m(), metrics["horizontal_error_m"]["median"], metrics["final_error_m"]))

    fig, ax = plt.subplots(figsize=(8, 6))
    map_path = os.path.join(args.walk, "building.geojson")
    if os.path.exists(map_path):
        for i, wall in enumerate(map_walls_enu(map_path)):
            ax.plot([p[0] for p in wall], [p[1] for p in wall], color="0.6", lw=1, label="walls" if i == 0 else None)
    tx, ty = read_truth_xy(truth_path)
    ax.plot(tx, ty, color="tab:green", lw=1.5, label="truth")
    p = result.positions["pos_enu_m"]
    ax.plot(p[:, 0], p[:, 1], color="tab:blue", lw=1, label="pednav (%s)" % args.mount)
    ends = result.strides["t_ns"]
    steps = result.positions[result.positions["t_ns"].searchsorted(ends).clip(0, len(p) - 1)]["pos_enu_m"]
    ax.plot(steps[:, 0], steps[:, 1], ".", color="tab:blue", ms=3)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_title("%s: median error %.2f m" % (os.path.basename(os.path.normpath(args.walk)),
                                               metrics["horizontal_error_m"]["median"]))
    ax.legend()
    fig.savefig(args.out, dpi=120, bbox_inches="tight")
    print("wrote " + args.out)


if __name__ == "__main__":
    main()
