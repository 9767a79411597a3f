# SPDX-License-Identifier: Apache-2.0
"""Writes one small bad input of the catalogue (tests/bad_input/CMakeLists.txt).

usage: make_input.py KIND DIR [PRESET]  ->  DIR/<file> (the name each kind writes is fixed below);
       the config kinds start from PRESET (configs/foot.json)

Inputs are generated, never committed: a still foot IMU at 100 Hz (gravity on z)
with the fault of KIND placed at known lines, so a test can name the line.
"""
import json
import math
import os
import sys

HEADER = "t,ax,ay,az,gx,gy,gz\n"


def row(i, t=None, ax=0.05, ay=-0.03, az=9.81, gx=None, gy=-0.002, gz=0.0005):
    t = i * 0.01 if t is None else t
    # A small deterministic ripple so that no column is constant.
    r = 0.01 * math.sin(0.7 * i)
    gx = 0.001 + r / 10 if gx is None else gx
    return "%.6f,%.5f,%.5f,%.5f,%.6f,%.6f,%.6f\n" % (t, ax + r, ay - r, az + r, gx, gy, gz)


def rows(a, b, **kw):
    return "".join(row(i, **kw) for i in range(a, b))


def canonical(body):
    return HEADER + body


def walk_gyro(i):
    """A gyro swinging +-6 rad/s at 1 Hz, as a foot's does."""
    return 6.0 * math.sin(2 * math.pi * i * 0.01)


def make(kind):
    """(file name, bytes) of KIND."""
    # Line numbers: the header is line 1, row i is line i + 2.
    if kind == "clean":
        return "clean.csv", canonical(rows(0, 1000))
    if kind == "nan_inf":  # lines 302 (NaN) and 303 (inf)
        body = rows(0, 300) + row(300, az=float("nan")) + row(301, gx=float("inf")) + rows(302, 1000)
        return "nan_inf.csv", canonical(body)
    if kind == "time_backwards":  # line 402 goes back to 1.0 s
        return "backwards.csv", canonical(rows(0, 400) + row(400, t=1.0) + rows(401, 1000))
    if kind == "duplicate_time":  # line 502 repeats line 501's time
        return "duplicate.csv", canonical(rows(0, 500) + row(500, t=4.99) + rows(500, 1000))
    if kind == "gap_10s":  # rows 500.. shifted by 10 s: the gap ends at line 502
        return "gap.csv", canonical(rows(0, 500) + "".join(row(i, t=i * 0.01 + 10.0) for i in range(500, 1000)))
    if kind == "burst_1khz":  # 100 rows 1 ms apart at lines 502..601, then 100 Hz again
        burst = "".join(row(500 + k, t=5.0 + k * 0.001) for k in range(100))
        rest = "".join(row(i, t=5.1 + (i - 500) * 0.01) for i in range(500, 1000))
        return "burst.csv", canonical(rows(0, 500) + burst + rest)
    if kind == "saturated_gyro":  # gx clipped at 4.363 rad/s (250 deg/s): a quarter of the rows sit at +-4.363
        body = "".join(row(i, gx=max(-4.363, min(4.363, walk_gyro(i)))) for i in range(1000))
        return "saturated.csv", canonical(body)
    if kind == "accel_in_g":
        return "in_g.csv", canonical(rows(0, 1000, ax=0.005, ay=-0.003, az=1.0))
    if kind == "gyro_in_degps":
        body = "".join(row(i, gx=math.degrees(walk_gyro(i))) for i in range(1000))
        return "in_degps.csv", canonical(body)
    if kind == "empty":
        return "empty.csv", ""
    if kind == "header_only":
        return "header_only.csv", HEADER
    if kind == "nul_midway":  # a NUL byte at the start of line 6002, 372 kB in (a log padded with zeros)
        return "nul.csv", canonical(rows(0, 6000)) + "\0" + rows(6000, 7000)
    if kind == "truncated_last_line":  # line 1001 cut off while writing
        return "truncated.csv", canonical(rows(0, 999) + "9.99,0.05,-0.0")
    if kind == "binary":
        data = bytes((i * 37 + 11) % 256 for i in range(4096))
        return "garbage.csv", data
    if kind == "million_columns":  # line 502 holds a million fields
        return "wide.csv", canonical(rows(0, 500) + ",".join(["1"] * 1000000) + "\n" + rows(500, 1000))
    if kind == "bom":
        return "bom.csv", "\ufeff" + canonical(rows(0, 1000))
    if kind == "crlf":
        return "crlf.csv", canonical(rows(0, 1000)).replace("\n", "\r\n")
    if kind == "cr_only":
        return "cr_only.csv", canonical(rows(0, 1000)).replace("\n", "\r")
    if kind == "unix_ms":  # t in Unix milliseconds
        return "unix_ms.csv", canonical("".join(row(i, t=1.7e12 + i * 10.0) for i in range(1000)))
    if kind == "absurd_values":  # ax = 1e6 on lines 302..304
        return "absurd.csv", canonical(rows(0, 300) + rows(300, 303, ax=1e6) + rows(303, 1000))
    if kind == "nonpositive_pressure":
        body = "".join(row(i).rstrip("\n") + ",0\n" for i in range(1000))
        return "pressure.csv", "t,ax,ay,az,gx,gy,gz,p\n" + body
    if kind == "utf8_cell":  # ill-formed UTF-8 in a cell (line 302) and in the file name
        body = (HEADER + rows(0, 300)).encode() + b"3.00,\xff\xfe,0,9.8,0,0,0\n" + rows(301, 1000).encode()
        return "bad\udcffname.csv", body
    if kind == "comment_only":
        return "comment.csv", "# a file of one comment line\n"
    if kind == "no_time_column":
        return "no_t.csv", "x,ax,ay,az,gx,gy,gz\n" + rows(0, 10)
    if kind == "xsens_counter":  # PacketCounter without SampleTimeFine nor a rate line; 256 Hz
        lines = ["PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z"]
        for i in range(1024):
            lines.append("%d\t0.05\t-0.03\t9.81\t0.001\t-0.002\t%.6f" % (i, 0.0005 + 0.001 * math.sin(i)))
        return "xsens.txt", "\n".join(lines) + "\n"
    if kind == "unreadable":  # a directory without a recording
        return "folder", None
    if kind == "map_truncated":
        return "map.geojson", '{"format": "pednav.map/1", "type": "FeatureCollection", "features": ['
    if kind == "map_deep":  # 100 000 nested arrays where the features belong
        return "map.geojson", ('{"format": "pednav.map/1", "type": "FeatureCollection", "features": '
                               + "[" * 100000 + "]" * 100000 + "}")
    if kind.startswith("gnss_"):
        return "gnss.csv", make_gnss(kind[len("gnss_"):])
    if kind.startswith("config_"):
        return "config.json", make_config(kind[len("config_"):])
    raise SystemExit("unknown kind " + kind)


def make_gnss(what):
    """A GNSS CSV of 1 Hz fixes walking north at 1.4 m/s, spoiled by WHAT; fix i is at line i + 2."""
    out = "t,lat,lon,hacc,sats\n"
    for i in range(60):
        t = i * 1.0 + (0.002 * ((i * 7) % 5) if what == "routine_1hz" else 0.0)  # receiver jitter
        lat = 48.1 + i * 1.4 / 111320.0
        if what == "jumps" and i == 30:
            lat += 0.01  # 1.1 km away for one fix
        sats = 0 if what == "zero_satellites" and 20 <= i < 25 else 9
        if what == "before_imu":
            t -= 5.0  # the receiver logged 5 s before the IMU started
        out += "%.3f,%.8f,11.5,3.0,%d\n" % (t, lat, sats)
    return out


def stage(doc, role):
    return doc["pipelines"]["foot"][role]


def make_config(what):
    """The foot preset spoiled by WHAT, as text."""
    with open(sys.argv[3], encoding="utf-8") as f:
        text = f.read()
    doc = json.loads(text)
    if what == "unknown_key":
        stage(doc, "step_detector")["params"]["treshold"] = 0.5
    elif what == "wrong_type":
        stage(doc, "step_detector")["params"]["threshold"] = "high"
    elif what == "out_of_range":
        stage(doc, "step_detector")["params"]["threshold"] = -1.0
    elif what == "mag_range_inverted":
        p = stage(doc, "attitude_estimator")["params"]
        p["mag_min_ut"], p["mag_max_ut"] = 100.0, 15.0
    elif what == "missing_plugin":
        stage(doc, "position_filter")["plugin"] = "org.example.no.such.filter"
    elif what == "deep_params":  # 60 000 nested arrays in a plugin's params
        return text.replace('"threshold": 0.5', '"threshold": 0.5, "deep": ' + "[" * 60000 + "]" * 60000, 1)
    elif what == "deep_description":
        return text.replace('"description": "', '"description": ' + "[" * 60000 + "]" * 60000 + ', "x": "', 1)
    elif what == "duplicate_key":
        return text.replace('"threshold": 0.5', '"threshold": 0.5, "threshold": 5.0', 1)
    elif what == "nul":
        return text.rstrip() + "\0{\"mount\": \"chest\"}\n"
    elif what == "number_overflow":
        return text.replace('"threshold": 0.5', '"threshold": 1e400', 1)
    elif what == "array":
        return "[" + text + "]"
    elif what == "invalid_utf8":
        return text.encode("utf-8").replace(b"Foot-mounted", b"Foot\xff\xfemounted", 1)
    elif what == "huge":  # 64 MiB of description
        doc["description"] = "x" * (64 << 20)
    else:
        raise SystemExit("unknown config kind " + what)
    return json.dumps(doc, indent=1)


def main():
    kind, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    name, content = make(kind)
    path = os.path.join(out_dir, name).encode("utf-8", "surrogateescape")
    if content is None:
        os.makedirs(path, exist_ok=True)
        return
    with open(path, "wb") as f:
        f.write(content if isinstance(content, bytes) else content.encode("utf-8"))
    if kind.startswith("gnss_"):  # the recording the fixes go with, 10 s from t = 0
        with open(os.path.join(out_dir, "clean.csv"), "w", encoding="utf-8") as f:  # noqa
            f.write(canonical(rows(0, 1000)))


main()
