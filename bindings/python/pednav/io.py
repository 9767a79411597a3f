# SPDX-License-Identifier: Apache-2.0
"""pednav.read: a recording read by the engine's own readers (pn_io.h)."""
import json

import numpy as np

from . import records as rec
from ._lib import ffi, lib, new_error, check, sized_text

# The unit of each field handed to the engine (docs/formats.md).
UNITS = {
    "imu": {"t_ns": "ns", "accel_mps2": "m/s^2", "gyro_radps": "rad/s"},
    "mag": {"t_ns": "ns", "mag_ut": "uT"},
    "baro": {"t_ns": "ns", "pressure_pa": "Pa", "temperature_c": "degC"},
    "gnss": {"t_ns": "ns", "lat_deg": "deg", "lon_deg": "deg", "height_m": "m", "h_accuracy_m": "m",
             "v_accuracy_m": "m", "vel_enu_mps": "m/s", "utc_ns": "ns"},
    "truth": {"t_s": "s", "pos_enu_m": "m"},
}


class Recording:
    """What a reader made of a file: `imu`, `mag`, `baro`, `gnss` (structured
    arrays of records.IMU, MAG, BARO, GNSS in SI units), `truth`
    (records.TRUTH, local ENU metres) with `truth_labels`, `units` (field ->
    unit per stream), `info` (the reader's description: format, axes, streams
    with units found and converted, rates, gaps), `notes` and `issues`
    ((line, message) pairs the reader read past)."""

    def __init__(self, path, format="auto", column_map=None, gap_s=None):
        options = {}
        if column_map is not None:
            options["column_map"] = column_map
        if gap_s is not None:
            options["gap_s"] = gap_s
        handle = ffi.new("pn_recording_t **")
        err = new_error()
        check(lib().pn_recording_open(str(path).encode(), format.encode(),
                                      json.dumps(options).encode() if options else ffi.NULL, handle, err), err)
        self._rec = ffi.gc(handle[0], lib().pn_recording_destroy)
        self.path = str(path)
        self.info = json.loads(sized_text(lambda b, c, s: lib().pn_recording_describe(self._rec, b, c, s)))
        self.format = self.info["format"]
        self.notes = list(self.info["notes"])
        self.issues = [(i["line"], i["message"]) for i in self.info["issues"]]
        self.units = UNITS
        for name, record_type in (("imu", rec.REC_IMU), ("mag", rec.REC_MAG), ("baro", rec.REC_BARO),
                                  ("gnss", rec.REC_GNSS)):
            setattr(self, name, self._stream(record_type))
        points = ffi.new("const pn_truth_point_t **")
        count = ffi.new("size_t *")
        lib().pn_recording_truth(self._rec, points, count)
        self.truth = self._copy(points[0], count[0], rec.TRUTH)
        self.truth_labels = list(self.info.get("truth_labels", []))

    @staticmethod
    def _copy(pointer, count, dtype):
        if count == 0:
            return np.zeros(0, dtype=dtype)
        return np.frombuffer(ffi.buffer(pointer, count * dtype.itemsize), dtype=dtype).copy()

    def _stream(self, record_type):
        dtype = rec.BY_TYPE[record_type]
        records = ffi.new("const void **")
        count = ffi.new("size_t *")
        stride = ffi.new("size_t *")
        lib().pn_recording_stream(self._rec, record_type, records, count, stride)
        if count[0] and stride[0] != dtype.itemsize:
            raise RuntimeError("pednav: the library's records are %d bytes, this package's %d"
                               % (stride[0], dtype.itemsize))
        return self._copy(records[0], count[0], dtype)

    def merged_pointers(self):
        """Addresses of every input record in the order `pednav run` pushes
        them (valid while this Recording lives)."""
        pointers = ffi.new("const pn_record_header_t *const **")
        count = ffi.new("size_t *")
        lib().pn_recording_merged(self._rec, pointers, count)
        if count[0] == 0:
            return np.zeros(0, dtype=np.uint64)
        return np.frombuffer(ffi.buffer(pointers[0], count[0] * 8), dtype=np.uint64).copy()

    def stream_info(self, name):
        """The reader's summary of a stream ("accel", "gyro", "mag", "pressure", "gnss")."""
        for s in self.info["streams"]:
            if s["name"] == name:
                return s
        raise KeyError("no stream " + name + " in " + self.path)


def read(path, format="auto", column_map=None, gap_s=None):
    """Reads a recording with the engine's readers; raises PednavError naming
    path:line when the file cannot be read."""
    return Recording(path, format=format, column_map=column_map, gap_s=gap_s)


def formats():
    """The format names read() takes besides "auto"."""
    return json.loads(sized_text(lib().pn_recording_formats))


def write_track_csv(path, positions):
    """The track CSV `pednav run --output` writes (and `pednav eval` reads)."""
    positions = np.ascontiguousarray(positions, dtype=rec.POSITION)
    err = new_error()
    check(lib().pn_write_track_csv(str(path).encode(), ffi.cast("const pn_position_t *", positions.ctypes.data),
                                   len(positions), err), err)


def write_steps_csv(path, strides):
    """The steps CSV of `pednav run --steps`."""
    strides = np.ascontiguousarray(strides, dtype=rec.STRIDE)
    err = new_error()
    check(lib().pn_write_steps_csv(str(path).encode(), ffi.cast("const pn_stride_t *", strides.ctypes.data),
                                   len(strides), err), err)
