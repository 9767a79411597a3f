# SPDX-License-Identifier: Apache-2.0
"""numpy structured dtypes laid out exactly as the records of pn_types.h (ABI
1.1), so that arrays of records go to and come from the C API without a copy
per sample. Field names are those of the C structs; the header fields are
flattened (struct_size, type, t_ns, source_id, flags)."""
import numpy as np

REC_IMU, REC_MAG, REC_BARO, REC_GNSS = 1, 2, 3, 4
REC_GAIT_PHASE, REC_STEP, REC_ATTITUDE, REC_ATTITUDE_CORRECTION = 5, 6, 7, 8
REC_POSITION, REC_STRIDE = 9, 10

POSITION_FLAG_HAS_VELOCITY = 1
POSITION_FLAG_HAS_FLOOR = 2
POSITION_FLAG_HAS_PARTICLES = 4
POSITION_FLAG_RECOVERED = 8

_HEADER = [("struct_size", "<u4"), ("type", "<u4"), ("t_ns", "<i8"), ("source_id", "<u4"), ("flags", "<u4")]


def _record(fields):
    return np.dtype(_HEADER + fields, align=True)


IMU = _record([("accel_mps2", "<f8", (3,)), ("gyro_radps", "<f8", (3,))])
MAG = _record([("mag_ut", "<f8", (3,))])
BARO = _record([("pressure_pa", "<f8"), ("temperature_c", "<f8")])
GNSS = _record([("lat_deg", "<f8"), ("lon_deg", "<f8"), ("height_m", "<f8"), ("h_accuracy_m", "<f8"),
                ("v_accuracy_m", "<f8"), ("vel_enu_mps", "<f8", (3,)), ("utc_ns", "<i8"),
                ("satellites", "<i4"), ("fix_type", "<i4")])
GAIT_PHASE = _record([("stance", "<i4"), ("reserved", "<i4"), ("statistic", "<f8")])
STEP = _record([("t_start_ns", "<i8"), ("accel_peak_to_peak_mps2", "<f8"), ("frequency_hz", "<f8"),
                ("accel_max_mps2", "<f8"), ("accel_min_mps2", "<f8"), ("motion_mode", "<i4"),
                ("reserved", "<i4")])
ATTITUDE = _record([("q_enu_from_body", "<f8", (4,)), ("heading_rad", "<f8"), ("gyro_bias_radps", "<f8", (3,)),
                    ("cov_attitude_rad2", "<f8", (9,))])
POSITION = _record([("pos_enu_m", "<f8", (3,)), ("vel_enu_mps", "<f8", (3,)), ("cov_enu_m2", "<f8", (9,)),
                    ("heading_rad", "<f8"), ("floor", "<i4"), ("source", "<i4"), ("live_particles", "<u4"),
                    ("recoveries", "<u4")])
STRIDE = _record([("t_start_ns", "<i8"), ("displacement_enu_m", "<f8", (3,)), ("length_m", "<f8"),
                  ("heading_change_rad", "<f8"), ("cov_displacement_m2", "<f8", (9,)), ("stride_class", "<i4"),
                  ("index", "<i4")])
TRUTH = np.dtype([("t_s", "<f8"), ("pos_enu_m", "<f8", (3,)), ("floor", "<i4"), ("has_z", "<i4")], align=True)

# Record type -> dtype, for inputs and outputs.
BY_TYPE = {REC_IMU: IMU, REC_MAG: MAG, REC_BARO: BARO, REC_GNSS: GNSS, REC_GAIT_PHASE: GAIT_PHASE,
           REC_STEP: STEP, REC_ATTITUDE: ATTITUDE, REC_POSITION: POSITION, REC_STRIDE: STRIDE}
# The sizes of pn_types.h (layout_sentinels.c holds them on the C side).
SIZES = {IMU: 72, MAG: 48, BARO: 40, GNSS: 104, GAIT_PHASE: 40, STEP: 72, ATTITUDE: 160, POSITION: 168,
         STRIDE: 152}
for _dtype, _size in SIZES.items():
    assert _dtype.itemsize == _size, (_dtype, _size)

OUTPUT_NAMES = {REC_POSITION: "positions", REC_STRIDE: "strides", REC_STEP: "steps", REC_ATTITUDE: "attitudes",
                REC_GAIT_PHASE: "gait_phases"}


def empty(dtype, count, record_type):
    """`count` zeroed records of `dtype` with their header's size and type set."""
    a = np.zeros(count, dtype=dtype)
    a["struct_size"] = dtype.itemsize
    a["type"] = record_type
    return a


def imu_from_array(samples):
    """pn_imu_t records from a structured IMU array (returned as is, made
    contiguous) or an (N, 7) float array of t_s, ax, ay, az (m/s^2), gx, gy, gz
    (rad/s)."""
    samples = np.asarray(samples)
    if samples.dtype == IMU:
        return np.ascontiguousarray(samples)
    if samples.dtype.names:
        raise TypeError("push_imu: a structured array must have the dtype pednav.records.IMU")
    if samples.ndim != 2 or samples.shape[1] != 7:
        raise ValueError("push_imu: expected an (N, 7) array of t_s, accel_mps2 x/y/z, gyro_radps x/y/z, got shape "
                         + str(samples.shape))
    samples = samples.astype(np.float64, copy=False)
    out = empty(IMU, len(samples), REC_IMU)
    out["t_ns"] = np.round(samples[:, 0] * 1e9).astype(np.int64)
    out["accel_mps2"] = samples[:, 1:4]
    out["gyro_radps"] = samples[:, 4:7]
    return out


def input_type_of(records):
    """The record type of a structured input array (mag, baro or gnss, or imu)."""
    for record_type in (REC_IMU, REC_MAG, REC_BARO, REC_GNSS):
        if records.dtype == BY_TYPE[record_type]:
            return record_type
    raise TypeError("push: expected an array of pednav.records.IMU, MAG, BARO or GNSS, got dtype "
                    + str(records.dtype))
