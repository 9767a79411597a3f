# SPDX-License-Identifier: Apache-2.0
"""pednav.Engine: one pn_engine_t, fed numpy arrays, polled into numpy arrays."""
import json
import math
import os

import numpy as np

from . import records as rec
from ._lib import ffi, lib, new_error, check, raise_error, path_of, sized_text, ABI_VERSION, OUTPUT_SLOT_BYTES

DEFAULT_MASK = (1 << rec.REC_POSITION) | (1 << rec.REC_STRIDE) | (1 << rec.REC_STEP)
# Records pushed per call and output slots polled per call: the queue (below)
# holds every output of one chunk, so none is dropped however long the input.
PUSH_CHUNK = 8192
QUEUE_CAPACITY = 65536


def preset_path(name):
    """The file of a preset ("foot") among the installed configs."""
    return os.path.join(path_of("configs"), name + ".json")


def config_text(config):
    """The JSON text of a config given as a dict, JSON text, a file path or a preset name."""
    if isinstance(config, dict):
        return json.dumps(config)
    if not isinstance(config, str):
        raise TypeError("config must be a dict, JSON text, a .json file or a preset name, not "
                        + type(config).__name__)
    if config.lstrip().startswith("{"):
        return config
    path = config if config.endswith(".json") else preset_path(config)
    if not os.path.exists(path):
        raise FileNotFoundError("no config file or preset " + repr(config) + " (looked for " + path + ")")
    with open(path, encoding="utf-8") as f:
        return f.read()


def _split_outputs(slots, count):
    """Structured arrays per output type from `count` pn_output_t slots."""
    raw = np.frombuffer(ffi.buffer(slots, count * OUTPUT_SLOT_BYTES), dtype=np.uint8).reshape(count, OUTPUT_SLOT_BYTES)
    types = raw[:, 4:8].copy().view("<u4").ravel()
    out = {}
    for record_type, name in rec.OUTPUT_NAMES.items():
        dtype = rec.BY_TYPE[record_type]
        rows = raw[types == record_type, :dtype.itemsize]
        out[name] = np.ascontiguousarray(rows).view(dtype).ravel()
    return out


class Engine:
    """An engine built from a config (dict, JSON text, .json path or preset
    name such as "foot"). plugin_dirs default to the installed plugins.
    Outputs of the types in `outputs` reach poll(): any of "positions",
    "strides", "steps", "attitudes", "gait_phases"."""

    def __init__(self, config="foot", plugin_dirs=None, mount=None,
                 outputs=("positions", "strides", "steps")):
        text = config_text(config)
        if mount is not None:
            doc = json.loads(text)
            doc["mount"] = mount
            text = json.dumps(doc)
        dirs = list(plugin_dirs) if plugin_dirs is not None else [path_of("plugins")]
        self._keep = [ffi.new("char[]", d.encode()) for d in dirs]
        dir_array = ffi.new("const char *[]", self._keep) if dirs else ffi.NULL
        config_c = ffi.new("char[]", text.encode())
        info = ffi.new("pn_engine_create_info_t *")
        info.abi_version = ABI_VERSION
        info.struct_size = ffi.sizeof("pn_engine_create_info_t")
        info.config_json = config_c
        info.plugin_dirs = dir_array
        info.plugin_dir_count = len(dirs)
        info.output_queue_capacity = QUEUE_CAPACITY
        handle = ffi.new("pn_engine_t **")
        err = new_error()
        check(lib().pn_engine_create(info, handle, err), err)
        self._engine = ffi.gc(handle[0], lib().pn_engine_destroy)
        self._err = err
        self._slots = ffi.new("pn_output_t[]", PUSH_CHUNK)
        self._pending = {name: [] for name in rec.OUTPUT_NAMES.values()}
        self.set_outputs(outputs)

    # ------------------------------------------------------------ settings
    def set_outputs(self, outputs):
        names = {v: k for k, v in rec.OUTPUT_NAMES.items()}
        mask = 0
        for name in outputs:
            if name not in names:
                raise ValueError("unknown output " + repr(name) + " (expected one of " + ", ".join(names) + ")")
            mask |= 1 << names[name]
        status = lib().pn_engine_set_output_mask(self._engine, mask)
        if status < 0:
            raise ValueError("output mask refused: " + ffi.string(lib().pn_status_name(status)).decode())

    def set_start(self, pos_enu_m=(0.0, 0.0, 0.0), heading_deg=math.nan):
        """Start point (ENU m) and heading (deg clockwise from north, NaN =
        from the sensors); False when no stage takes one."""
        err = new_error()
        status = lib().pn_engine_set_start(self._engine, ffi.new("double[3]", list(pos_enu_m)), heading_deg, err)
        return check(status, err, allow=(-3,)) == 0

    def set_origin(self, lat_deg, lon_deg, height_m=0.0):
        """The WGS-84 point at ENU (0, 0, 0)."""
        err = new_error()
        point = ffi.new("pn_geo_point_t *", {"lat_deg": lat_deg, "lon_deg": lon_deg, "height_m": height_m})
        check(lib().pn_engine_set_origin(self._engine, point, err), err)

    def origin(self):
        """(lat_deg, lon_deg, height_m), or None while the engine has none."""
        point = ffi.new("pn_geo_point_t *")
        if lib().pn_engine_get_origin(self._engine, point) != 0:
            return None
        return point.lat_deg, point.lon_deg, point.height_m

    def enu_from_geo(self, lat_deg, lon_deg, height_m=0.0):
        """ENU metres of a WGS-84 point through the engine's origin (exact
        ellipsoidal conversion), for a few points such as a map's vertices."""
        point = ffi.new("pn_geo_point_t *", {"lat_deg": lat_deg, "lon_deg": lon_deg, "height_m": height_m})
        out = ffi.new("double[3]")
        status = lib().pn_engine_enu_from_geo(self._engine, point, out)
        if status != 0:
            raise ValueError("enu_from_geo: the engine has no origin yet")
        return out[0], out[1], out[2]

    def load_map(self, map_data, format="pednav.map/1"):
        """A map for the map matcher: a path, GeoJSON text or bytes, or a dict."""
        if isinstance(map_data, dict):
            data = json.dumps(map_data).encode()
        elif isinstance(map_data, bytes):
            data = map_data
        elif map_data.lstrip().startswith("{"):
            data = map_data.encode()
        else:
            with open(map_data, "rb") as f:
                data = f.read()
        err = new_error()
        check(lib().pn_engine_load_map(self._engine, format.encode(), data, len(data), err), err)

    def reconfigure(self, stage, params):
        """New params (dict) for a stage by role or instance name."""
        text = json.dumps(params).encode()
        err = new_error()
        check(lib().pn_engine_reconfigure(self._engine, stage.encode(), text, len(text), err), err)

    # -------------------------------------------------------------- inputs
    def push_imu(self, samples):
        """IMU samples: a structured array of records.IMU or an (N, 7) array
        of t_s, accel (m/s^2), gyro (rad/s). Raises PednavError on the first
        rejected sample (err.detail = its index in `samples`)."""
        data = rec.imu_from_array(samples)
        for start in range(0, len(data), PUSH_CHUNK):
            chunk = data[start:start + PUSH_CHUNK]
            err = new_error()
            status = lib().pn_engine_push_imu(self._engine, ffi.cast("const pn_imu_t *", chunk.ctypes.data),
                                              len(chunk), data.dtype.itemsize, err)
            self._drain()
            if status < 0:
                err.detail += start
                raise_error(status, err)

    def push(self, records):
        """Records of one input type (records.MAG, BARO, GNSS or IMU arrays),
        each pushed as pn_engine_push would; or a list of such arrays, merged
        in time order (at equal t_ns: IMU, MAG, BARO, GNSS)."""
        if isinstance(records, (list, tuple)):
            arrays = [np.ascontiguousarray(a) for a in records if len(a)]
        else:
            arrays = [np.ascontiguousarray(records)]
        for a in arrays:
            rec.input_type_of(a)
        pointers = merged_pointers(arrays)
        self.push_pointers(pointers, keep=arrays)

    def push_pointers(self, pointers, keep=None, on_error=None):
        """Pushes records by address (a uint64 array, in push order). Without
        on_error, raises PednavError at the first failure; with it, calls
        on_error(index, PednavError) and goes on with the next record, as
        `pednav run` does. `keep` holds the arrays pointed into alive."""
        del keep  # referenced by the caller for the duration of the call
        total = len(pointers)
        start = 0
        while start < total:
            chunk = pointers[start:start + PUSH_CHUNK]
            err = new_error()
            status = lib().pn_engine_push_records(
                self._engine, ffi.cast("const pn_record_header_t *const *", chunk.ctypes.data), len(chunk), err)
            self._drain()
            if status >= 0:
                start += len(chunk)
                continue
            failed = start + int(err.detail)
            try:
                raise_error(status, err)
            except Exception as e:  # PednavError
                e.detail = failed
                if on_error is None:
                    raise
                on_error(failed, e)
            start = failed + 1

    def flush(self):
        """End of stream: drains the look-ahead of every stage."""
        err = new_error()
        status = lib().pn_engine_flush(self._engine, err)
        self._drain()
        check(status, err)

    def reset(self):
        err = new_error()
        check(lib().pn_engine_reset(self._engine, err), err)
        self._pending = {name: [] for name in rec.OUTPUT_NAMES.values()}

    # ------------------------------------------------------------- outputs
    def _drain(self):
        count = ffi.new("size_t *")
        while True:
            lib().pn_engine_poll_many(self._engine, self._slots, PUSH_CHUNK, count)
            if count[0] == 0:
                return
            for name, array in _split_outputs(self._slots, count[0]).items():
                if len(array):
                    self._pending[name].append(array)
            if count[0] < PUSH_CHUNK:
                return

    def poll(self):
        """Every output since the last poll: a dict of structured arrays
        "positions", "strides", "steps", "attitudes", "gait_phases"."""
        self._drain()
        out = {}
        for record_type, name in rec.OUTPUT_NAMES.items():
            parts = self._pending[name]
            out[name] = np.concatenate(parts) if parts else np.zeros(0, dtype=rec.BY_TYPE[record_type])
            self._pending[name] = []
        return out

    def describe(self):
        """The engine's description (pn_engine_describe) as a dict."""
        return json.loads(sized_text(lambda b, c, s: lib().pn_engine_describe(self._engine, b, c, s)))

    def latency_s(self):
        return lib().pn_engine_latency_ns(self._engine) * 1e-9

    def close(self):
        if self._engine is not None:
            ffi.release(self._engine)  # runs pn_engine_destroy now, once
            self._engine = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def merged_pointers(arrays):
    """Addresses of the records of `arrays` (contiguous structured input
    arrays) in time order, at equal t_ns IMU, MAG, BARO, GNSS, then array
    order: the order of io::merged_records."""
    if not arrays:
        return np.zeros(0, dtype=np.uint64)
    t = np.concatenate([a["t_ns"] for a in arrays])
    kind = np.concatenate([np.full(len(a), rec.input_type_of(a), dtype=np.int64) for a in arrays])
    addr = np.concatenate([np.uint64(a.ctypes.data) + np.arange(len(a), dtype=np.uint64) * np.uint64(a.dtype.itemsize)
                           for a in arrays])
    order = np.lexsort((kind, t))  # stable: t first, then type
    return np.ascontiguousarray(addr[order])
