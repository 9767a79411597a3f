# SPDX-License-Identifier: Apache-2.0
# pednav.read over pn_io.h: the engine's readers, their units, notes and errors.
import numpy as np
import pytest

import pednav
from pednav import records
from conftest import cli_json, shared_data


def test_read_matches_pednav_inspect():
    path = shared_data("koroglu-foot-gcp", "SensorConnectData_33.csv")
    rec = pednav.read(path)
    inspect = cli_json("inspect", path, "--json")
    assert rec.format == "microstrain-sensorconnect-a" == inspect["format"]
    assert len(rec.imu) == inspect["records"]["imu"] == 11000
    assert rec.notes == inspect["notes"]
    accel = rec.stream_info("accel")
    assert accel["units_found"] == "g" and accel["units_converted"] == "m/s^2"
    assert accel["rate_hz"] == pytest.approx(200.008, abs=1e-3)
    assert rec.units["imu"]["gyro_radps"] == "rad/s"
    # SI units: a foot at rest at the start measures about 1 g.
    g = np.linalg.norm(rec.imu["accel_mps2"][:100], axis=1).mean()
    assert g == pytest.approx(9.81, abs=0.15)
    assert np.all(np.diff(rec.imu["t_ns"]) > 0)
    assert rec.imu["struct_size"][0] == records.IMU.itemsize and rec.imu["type"][0] == records.REC_IMU


def test_read_magnetometer_and_truth_streams():
    foot = pednav.read(shared_data("koroglu-foot-gcp", "SensorConnectData_33.csv"))
    assert len(foot.mag) == 11000 and foot.mag.dtype == records.MAG
    mag = foot.stream_info("mag")
    assert mag["units_found"] == "gauss" and mag["units_converted"] == "uT"
    field = np.linalg.norm(foot.mag["mag_ut"], axis=1)
    assert 15.0 < np.median(field) < 80.0  # the Earth's field, in microtesla


def test_read_an_ipin_logfile_with_truth_and_issues(tmp_path):
    lines = ["% LogFile created by the 'GetSensorData' App", "POSI;0.010;1;40.31360000;-3.48370000;0;0"]
    for i in range(200):  # 50 Hz for 4 s, the sensor clock 100 s ahead of the app's
        ts = 100.0 + i * 0.02
        lines.append("ACCE;%.3f;%.3f;0.5;1.0;9.7;3" % (ts - 100.0 + 0.001, ts))
        lines.append("GYRO;%.3f;%.3f;0.01;0.02;0.03;3" % (ts - 100.0 + 0.002, ts + 0.01))
        if i % 10 == 0:
            lines.append("PRES;%.3f;%.3f;1013.25;0" % (ts - 100.0 + 0.004, ts))
    lines.append("GYRO;3.0;102.0;abc;0;0;3")  # a bad row, read past
    lines.append("POSI;3.990;2;40.31369000;-3.48370000;1;0")  # 10 m north, floor 1
    path = tmp_path / "logfile.txt"
    path.write_text("\n".join(lines) + "\n")
    log = pednav.read(path)
    assert log.format == "ipin-logfile" and len(log.imu) == 199
    assert log.baro["pressure_pa"][0] == pytest.approx(101325.0)  # hPa in the file
    assert log.stream_info("pressure")["units_found"] == "hPa"
    assert len(log.truth) == 2 and log.truth_labels == ["POSI 1", "POSI 2"]
    assert log.truth["t_s"][1] == pytest.approx(3.99) and log.truth["floor"][1] == 1
    assert log.truth["pos_enu_m"][1][1] == pytest.approx(0.00009 * 111034.0, rel=0.002)
    assert any("not a number: 'abc'" in message for _, message in log.issues)
    inspect = cli_json("inspect", path, "--json")
    assert len(log.truth) == inspect["records"]["truth"] and len(log.issues) == len(inspect["issues"])

def test_read_errors_name_the_file_and_line(tmp_path):
    with pytest.raises(pednav.PednavError) as e:
        pednav.read(tmp_path / "missing.csv")
    assert e.value.status == "PN_E_BAD_INPUT" and e.value.where == str(tmp_path / "missing.csv")
    assert "not found" in e.value.message
    bad = tmp_path / "bad.csv"
    bad.write_text("t,ax,ay,az,gx,gy,gz\n0.00,0,0,9.8,0,0,0\n")
    with pytest.raises(pednav.PednavError) as e:
        pednav.read(bad, format="no-such-format")
    assert e.value.status == "PN_E_BAD_INPUT" and str(bad) in e.value.where
    with pytest.raises(pednav.PednavError) as e:
        pednav.Recording(bad, gap_s=-1)
    assert e.value.status == "PN_E_INVALID_ARGUMENT" and e.value.where == "/gap_s"


def test_formats_and_track_writer_round_trip(tmp_path):
    assert "pednav-csv" in pednav.formats() and "column-map" in pednav.formats()
    positions = records.empty(records.POSITION, 3, records.REC_POSITION)
    positions["t_ns"] = [0, 5_000_000, 10_000_000]
    positions["pos_enu_m"] = [[0, 0, 0], [1.25, -2.5, 0.125], [2, 3, 4]]
    positions["heading_rad"] = [0.0, -np.pi / 2, np.pi]
    positions["flags"] = [0, records.POSITION_FLAG_HAS_FLOOR, records.POSITION_FLAG_HAS_FLOOR]
    positions["floor"] = [0, 1, -1]
    pednav.write_track_csv(tmp_path / "t.csv", positions)
    lines = (tmp_path / "t.csv").read_text().splitlines()
    assert lines[0] == "t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz"
    assert lines[2] == "0.005000000,1.250000,-2.500000,0.125000,270.0000,1,0,0,0,0"
    assert lines[3].startswith("0.010000000,2.000000,3.000000,4.000000,180.0000,-1,")
    with pytest.raises(pednav.PednavError) as e:
        pednav.write_track_csv(tmp_path / "no-folder" / "t.csv", positions)
    assert e.value.status == "PN_E_IO"
