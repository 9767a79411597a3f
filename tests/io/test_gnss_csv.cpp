// SPDX-License-Identifier: Apache-2.0
// The GNSS CSV reader on hand-written files (tests/io/data/): every field of
// the records, the rows it must skip and why, and the merge with an IMU log.
#include <doctest/doctest.h>

#include <cmath>

#include "pednav_io/gnss_log.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

std::string data(const std::string& name) { return std::string(PEDNAV_IO_TEST_DATA_DIR) + "/" + name; }

}  // namespace

TEST_CASE("gnss csv: fields converted once, optional cells filled by the documented rules") {
    const SensorLog log = read_gnss_file(data("gnss_fixes.csv"));
    CHECK(log.format == "csv");
    CHECK(log.imu.empty());
    REQUIRE(log.gnss.size() == 4);  // t = 10, 11, 12, 16 (17 has 3.5 satellites)
    const pn_gnss_t& a = log.gnss[0];
    CHECK(a.header.type == PN_REC_GNSS);
    CHECK(a.header.struct_size == sizeof(pn_gnss_t));
    CHECK(a.header.t_ns == 10000000000);
    CHECK(a.lat_deg == doctest::Approx(48.8566).epsilon(1e-12));
    CHECK(a.lon_deg == doctest::Approx(2.3522).epsilon(1e-12));
    CHECK(a.height_m == doctest::Approx(95.2));
    CHECK(a.h_accuracy_m == doctest::Approx(3.5));
    CHECK(a.v_accuracy_m == doctest::Approx(5.0));
    CHECK(a.satellites == 9);
    CHECK(a.fix_type == PN_GNSS_FIX_UNKNOWN);  // no fix column
    CHECK(a.utc_ns == 0);
    REQUIRE((a.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) != 0);
    CHECK(a.vel_enu_mps[0] == doctest::Approx(1.3));  // course 90 deg: due east
    CHECK(std::fabs(a.vel_enu_mps[1]) < 1e-12);
    CHECK(a.vel_enu_mps[2] == 0.0);

    // No vertical accuracy: 1.5 x the horizontal one.
    CHECK(log.gnss[1].v_accuracy_m == doctest::Approx(1.5 * 3.4));
    // Position only: no height (0, vertical accuracy kGnssNoHeightAccuracy_m),
    // horizontal accuracy = UERE (HDOP 1 assumed), no velocity, satellites unknown.
    const pn_gnss_t& c = log.gnss[2];
    CHECK(c.height_m == 0.0);
    CHECK(c.v_accuracy_m == kGnssNoHeightAccuracy_m);
    CHECK(c.h_accuracy_m == doctest::Approx(GnssReadOptions{}.uere_m));
    CHECK((c.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) == 0);
    CHECK(c.satellites == 0);
    // Standing still: speed 0 and no course is a zero velocity.
    const pn_gnss_t& d = log.gnss[3];
    CHECK(d.header.t_ns == 16000000000);
    REQUIRE((d.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) != 0);
    CHECK(d.vel_enu_mps[0] == 0.0);
    CHECK(d.vel_enu_mps[1] == 0.0);
    CHECK(d.satellites == 11);

    const StreamInfo* s = log.stream("gnss");
    REQUIRE(s != nullptr);
    CHECK(s->count == 4);
    CHECK(s->bad_rows == 6);
    CHECK(s->t_first_s == doctest::Approx(10.0));
    CHECK(s->t_last_s == doctest::Approx(16.0));
    CHECK(s->gaps == 1);  // 12 -> 16 s, longer than the 3 s default
}

TEST_CASE("gnss csv: bad rows are named by line and skipped") {
    const SensorLog log = read_gnss_file(data("gnss_fixes.csv"));
    CHECK(has_issue(log, 6, "row skipped: not a number: '2.35225x' in column lon"));
    CHECK(has_issue(log, 7, "row skipped: truncated line: 6 fields, the header has 10"));
    CHECK(has_issue(log, 8, "row skipped: latitude 91 beyond 90 degrees"));
    CHECK(has_issue(log, 9, "row skipped: horizontal accuracy 0 m is not positive"));
    CHECK(has_issue(log, 11, "row skipped: time goes backwards"));
    CHECK(has_issue(log, 12, "1 samples with a repeated timestamp dropped in gnss (first at line 12)"));
    CHECK(has_issue(log, 13, "row skipped: sats must be a count, not '3.5'"));
}

TEST_CASE("gnss csv: columns by name in any order and case, fix codes, no-fix rows") {
    const SensorLog log = read_gnss_file(data("gnss_reordered.csv"));
    REQUIRE(log.gnss.size() == 2);
    CHECK(log.gnss[0].header.t_ns == 100250000000);
    CHECK(log.gnss[0].lat_deg == doctest::Approx(-33.4569).epsilon(1e-12));
    CHECK(log.gnss[0].lon_deg == doctest::Approx(-70.6483).epsilon(1e-12));
    CHECK(log.gnss[0].fix_type == PN_GNSS_FIX_DIFFERENTIAL);
    CHECK(log.gnss[0].satellites == 7);
    CHECK(log.gnss[0].vel_enu_mps[1] == doctest::Approx(2.0));  // course 0: due north
    CHECK(log.gnss[1].fix_type == PN_GNSS_FIX_AUTONOMOUS);
    CHECK(log.gnss[1].vel_enu_mps[1] == doctest::Approx(-1.0));  // course 180: south
    CHECK(log.gnss[1].height_m == 0.0);                          // no alt column
    CHECK(log.issues.empty());
    bool noted = false;
    for (const auto& n : log.notes) noted = noted || n == "1 rows without a fix (fix = 0) skipped";
    CHECK(noted);
}

TEST_CASE("gnss files: detection, forced formats and fatal errors name the file") {
    CHECK(detect_gnss_format(data("gnss_fixes.csv")) == "csv");
    const std::string dir = temp_dir();
    const std::string imu = write_file(dir, "imu.csv", "t,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n");
    CHECK_THROWS_WITH_AS(read_gnss_file(imu), doctest::Contains("imu.csv:1: unknown GNSS format"), ReadError);
    const std::string no_fix = write_file(dir, "nofix.csv", "t,lat,lon,fix\n1,,,0\n2,,,0\n");
    CHECK_THROWS_WITH_AS(read_gnss_file(no_fix),
                         doctest::Contains("nofix.csv: no GNSS fix could be read (the receiver had no fix"),
                         ReadError);
    const std::string no_lon = write_file(dir, "nolon.csv", "t,lat,lng\n1,2,3\n");
    CHECK_THROWS_AS(read_gnss_file(no_lon), ReadError);
    GnssReadOptions forced;
    forced.format = "gpx";
    CHECK_THROWS_WITH_AS(read_gnss_file(data("gnss_fixes.csv"), forced),
                         doctest::Contains("unknown GNSS format name 'gpx'"), ReadError);
    CHECK_THROWS_WITH_AS(read_gnss_file(dir + "/missing.csv"), doctest::Contains("missing.csv: file not found"),
                         ReadError);
}

TEST_CASE("gnss csv: use_gnss puts the fixes in the IMU log in time order") {
    const std::string dir = temp_dir();
    std::string rows = "t,ax,ay,az,gx,gy,gz\n";
    for (int i = 0; i <= 2000; ++i) rows += std::to_string(i * 0.01) + ",0,0,9.81,0,0,0\n";
    SensorLog log = read_sensor_file(write_file(dir, "imu.csv", rows));
    const SensorLog gnss = read_gnss_file(data("gnss_fixes.csv"));
    use_gnss(log, gnss);
    CHECK(log.gnss.size() == 4);
    REQUIRE(log.stream("gnss") != nullptr);
    CHECK(log.stream("gnss")->count == 4);
    const auto records = merged_records(log);
    CHECK(records.size() == 2001 + 4);
    size_t gnss_seen = 0;
    for (size_t i = 1; i < records.size(); ++i) {
        CHECK(records[i - 1]->t_ns <= records[i]->t_ns);
        if (records[i]->type == PN_REC_GNSS) {
            ++gnss_seen;
            // At equal times the IMU sample comes first.
            CHECK(records[i - 1]->type == PN_REC_IMU);
        }
    }
    CHECK(gnss_seen == 4);
    CHECK(log.notes.back().find("GNSS: 4 fixes from") == 0);
}
