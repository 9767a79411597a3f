# SPDX-License-Identifier: Apache-2.0
# pednav.Engine over pn_engine.h: numpy batches in, structured arrays out, errors as exceptions.
import math

import numpy as np
import pytest

import pednav
from pednav import records
from conftest import shared_data

KOROGLU_33 = ("koroglu-foot-gcp", "SensorConnectData_33.csv")


def imu_as_columns(imu):
    """The (N, 7) layout of push_imu: t_s, accel m/s^2, gyro rad/s."""
    return np.column_stack([imu["t_ns"] * 1e-9, imu["accel_mps2"], imu["gyro_radps"]])


def test_push_gives_the_outputs_of_run():
    # IMU and magnetometer records pushed as arrays, merged in time order by push.
    rec = pednav.read(shared_data(*KOROGLU_33))
    assert len(rec.mag) == len(rec.imu)
    engine = pednav.Engine("foot")
    engine.set_start()
    engine.push([rec.imu, rec.mag])
    engine.flush()
    out = engine.poll()
    whole = pednav.run(rec, mount="foot")
    # One position per sample after the 1 s of alignment (201 samples at 200 Hz).
    assert len(out["positions"]) == len(whole.positions) == 11000 - 201
    assert out["positions"].tobytes() == whole.positions.tobytes()
    assert out["strides"].tobytes() == whole.strides.tobytes()
    assert list(out["strides"]["index"]) == list(range(len(out["strides"])))
    assert len(out["strides"]) == 47
    # Without the magnetometer the heading is the strapdown's own from the start.
    imu_only = pednav.Engine("foot")
    imu_only.push_imu(rec.imu)
    imu_only.flush()
    positions = imu_only.poll()["positions"]
    assert len(positions) == 10799 and positions["heading_rad"][0] == 0.0
    assert whole.positions["heading_rad"][0] == pytest.approx(-0.9833, abs=1e-4)
    # Polled again: nothing new.
    assert all(len(a) == 0 for a in engine.poll().values())


def test_column_array_equals_structured_array():
    rec = pednav.read(shared_data(*KOROGLU_33))
    a = pednav.Engine("foot")
    a.push_imu(rec.imu[:4000])
    a.flush()
    b = pednav.Engine("foot")
    columns = imu_as_columns(rec.imu[:4000])
    # Times through float seconds: exact here, the file's times are whole nanoseconds.
    assert np.array_equal(records.imu_from_array(columns)["t_ns"], rec.imu["t_ns"][:4000])
    b.push_imu(columns)
    b.flush()
    pa, pb = a.poll()["positions"], b.poll()["positions"]
    assert len(pa) == 4000 - 201 and pa.tobytes() == pb.tobytes()


def test_describe_and_outputs():
    engine = pednav.Engine("foot", outputs=("positions", "attitudes"))
    d = engine.describe()
    assert d["pipeline"]["mount"] == "foot"
    assert engine.latency_s() >= 0.0
    rec = pednav.read(shared_data(*KOROGLU_33))
    engine.push_imu(rec.imu[:2000])
    engine.flush()
    out = engine.poll()
    assert len(out["attitudes"]) == 2000 - 201 and len(out["strides"]) == 0
    q = out["attitudes"]["q_enu_from_body"]
    assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-9)
    assert engine.describe()["counters"]["records_in"] == 2000
    with pytest.raises(ValueError):
        engine.set_outputs(["speed"])


def test_errors_carry_status_where_and_detail():
    with pytest.raises(pednav.PednavError) as e:
        pednav.Engine({"format": "pednav-config/1", "mount": "foot", "pipelines": {"foot": {"nope": 1}}})
    assert e.value.status == "PN_E_INVALID_CONFIG" and e.value.where.startswith("/pipelines/foot")
    with pytest.raises(FileNotFoundError):
        pednav.Engine("no_such_preset")
    engine = pednav.Engine("foot")
    samples = np.zeros((5, 7))
    samples[:, 0] = [0.0, 0.01, 0.02, 0.02, 0.04]  # the fourth repeats a time
    samples[:, 3] = 9.81
    with pytest.raises(pednav.PednavError) as e:
        engine.push_imu(samples)
    assert e.value.status == "PN_E_OUT_OF_ORDER" and e.value.detail == 3
    nan = np.zeros((1, 7))
    nan[0, 0], nan[0, 1] = 1.0, math.nan
    with pytest.raises(pednav.PednavError) as e:
        engine.push_imu(nan)
    assert e.value.status == "PN_E_NUMERIC" and e.value.detail == 0
    with pytest.raises(ValueError):
        engine.push_imu(np.zeros((3, 6)))
    mag = records.empty(records.MAG, 1, records.REC_MAG)
    mag["t_ns"] = 5
    with pytest.raises(pednav.PednavError) as e:
        engine.push(mag)  # before the last IMU sample's time
    assert e.value.status == "PN_E_OUT_OF_ORDER"


def test_origin_and_map():
    engine = pednav.Engine("foot")
    assert engine.origin() is None
    engine.set_origin(47.5, 8.25, 410.0)
    assert engine.origin() == (47.5, 8.25, 410.0)
    with pytest.raises(pednav.PednavError) as e:
        engine.set_origin(100.0, 0.0)
    assert e.value.status in ("PN_E_INVALID_ARGUMENT", "PN_E_BAD_STATE")
    # The foot pipeline has no map matcher: the map is refused, naming why.
    with pytest.raises(pednav.PednavError) as e:
        engine.load_map({"type": "FeatureCollection", "features": []})
    assert e.value.status == "PN_E_UNSUPPORTED"
