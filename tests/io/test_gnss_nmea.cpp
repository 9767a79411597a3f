// SPDX-License-Identifier: Apache-2.0
// The NMEA 0183 reader on hand-written logs (tests/io/data/*.nmea) shaped
// like real receivers' output: a u-blox M8 style multi-GNSS log (GN talker,
// one GSA per constellation, GST, a fix-less start, a damaged GGA, a bad
// field, a line cut short) and an old GPS-only receiver across midnight UTC
// (dates in RMC and ZDA, a GLONASS GSA beside a GPS-only GGA, a logger's
// prefix, a bad checksum, a no-fix epoch).
#include <doctest/doctest.h>

#include <cmath>

#include "pednav_io/gnss_log.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

std::string data(const std::string& name) { return std::string(PEDNAV_IO_TEST_DATA_DIR) + "/" + name; }

constexpr double kKnot = 1852.0 / 3600.0;
constexpr double kDeg = M_PI / 180.0;
constexpr int64_t kSecond = 1000000000;
// 2024-05-01T10:00:00Z and 2024-01-01T00:00:00Z in Unix seconds.
constexpr int64_t kMay1At10 = 1714557600;
constexpr int64_t kJan1 = 1704067200;

bool has_note(const SensorLog& log, const std::string& text) {
    for (const auto& n : log.notes)
        if (n.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("nmea: a multi-GNSS receiver's epochs become fixes on the IMU clock") {
    GnssReadOptions o;
    o.time.first_epoch_t_s = 5.0;  // the first epoch, 09:59:59 (no fix yet), at t = 5 s
    const SensorLog log = read_gnss_file(data("gnss_ublox_m8.nmea"), o);
    CHECK(log.format == "nmea");
    REQUIRE(log.gnss.size() == 4);

    // 10:00:00: GGA position and height (MSL + geoid), GST sigmas, RMC speed and course.
    const pn_gnss_t& a = log.gnss[0];
    CHECK(a.header.t_ns == 6 * kSecond);
    CHECK(a.lat_deg == doctest::Approx(48.0 + 51.396 / 60.0).epsilon(1e-13));
    CHECK(a.lon_deg == doctest::Approx(2.0 + 21.132 / 60.0).epsilon(1e-13));
    CHECK(a.height_m == doctest::Approx(80.0));
    CHECK(a.h_accuracy_m == doctest::Approx(2.5));  // hypot(2.0, 1.5)
    CHECK(a.v_accuracy_m == doctest::Approx(3.0));
    CHECK(a.satellites == 8);
    CHECK(a.fix_type == PN_GNSS_FIX_AUTONOMOUS);
    CHECK(a.utc_ns == kMay1At10 * kSecond);
    REQUIRE((a.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) != 0);
    CHECK(a.vel_enu_mps[0] == doctest::Approx(0.5 * kKnot * std::sin(77.52 * kDeg)));
    CHECK(a.vel_enu_mps[1] == doctest::Approx(0.5 * kKnot * std::cos(77.52 * kDeg)));

    // 10:00:01: the GGA has a bad checksum, the RMC alone makes the fix: no
    // height, HDOP and satellites from the two GSAs.
    const pn_gnss_t& b = log.gnss[1];
    CHECK(b.header.t_ns == 7 * kSecond);
    CHECK(b.lat_deg == doctest::Approx(48.0 + 51.3965 / 60.0).epsilon(1e-13));
    CHECK(b.height_m == 0.0);
    CHECK(b.v_accuracy_m == kGnssNoHeightAccuracy_m);
    CHECK(b.h_accuracy_m == doctest::Approx(1.2 * o.uere_m));
    CHECK(b.satellites == 8);  // 5 GPS + 3 GLONASS ids
    CHECK(b.fix_type == PN_GNSS_FIX_AUTONOMOUS);
    CHECK(b.vel_enu_mps[0] == doctest::Approx(0.52 * kKnot * std::sin(80.0 * kDeg)));

    // 10:00:02: standing (speed 0, course empty: zero velocity); its GSA is
    // damaged, so HDOP x UERE and 1.5 x that vertically.
    const pn_gnss_t& c = log.gnss[2];
    CHECK(c.h_accuracy_m == doctest::Approx(1.3 * o.uere_m));
    CHECK(c.v_accuracy_m == doctest::Approx(1.5 * 1.3 * o.uere_m));
    REQUIRE((c.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) != 0);
    CHECK(c.vel_enu_mps[0] == 0.0);
    CHECK(c.vel_enu_mps[1] == 0.0);

    // 10:00:03: a differential 2D fix, satellites only in the GSA, velocity from the VTG (km/h).
    const pn_gnss_t& d = log.gnss[3];
    CHECK(d.header.t_ns == 9 * kSecond);
    CHECK(d.fix_type == PN_GNSS_FIX_DIFFERENTIAL);
    CHECK(d.satellites == 5);
    CHECK(d.h_accuracy_m == doctest::Approx(0.9 * o.uere_m));
    CHECK(d.height_m == doctest::Approx(80.3));  // the receiver's held height, kept ...
    CHECK(d.v_accuracy_m == kGnssNoHeightAccuracy_m);  // ... with no weight
    CHECK(d.vel_enu_mps[0] == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(d.vel_enu_mps[1] == doctest::Approx(-1.0));
    CHECK(d.utc_ns == (kMay1At10 + 3) * kSecond);

    CHECK(log.utc_ns_at_zero == (kMay1At10 - 1 - 5) * kSecond);  // 09:59:59 at t = 5 s
}

TEST_CASE("nmea: bad sentences are named by line and skipped, the rest of the epoch kept") {
    const SensorLog log = read_gnss_file(data("gnss_ublox_m8.nmea"));
    CHECK(has_issue(log, 16, "sentence skipped: checksum mismatch in GNGGA: computed 7E, the sentence says 4F"));
    CHECK(has_issue(log, 22, "sentence skipped: bad fix mode 'X' in GSA"));
    CHECK(has_issue(log, 26, "sentence skipped: no checksum (*hh): truncated sentence?"));
    CHECK(log.issues.size() == 3);
    REQUIRE(log.stream("gnss") != nullptr);
    CHECK(log.stream("gnss")->bad_rows == 3);
    CHECK(has_note(log, "1 epochs without a fix (GGA fix quality 0)"));
    CHECK(has_note(log, "sentences not used: GSV 2 TXT 1"));
    CHECK(has_note(log, "horizontal accuracy: 1 fixes from the file's sigmas, 3 from HDOP x UERE (5 m), 0 without"));
}

TEST_CASE("nmea: an explicit UTC of t = 0 places the epochs exactly") {
    GnssReadOptions o;
    REQUIRE(parse_utc("2024-05-01T09:59:00Z", &o.time.utc_ns_at_zero));
    const SensorLog log = read_gnss_file(data("gnss_ublox_m8.nmea"), o);
    REQUIRE(log.gnss.size() == 4);
    CHECK(log.gnss[0].header.t_ns == 60 * kSecond);
    CHECK(log.gnss[3].header.t_ns == 63 * kSecond);
    CHECK(log.utc_ns_at_zero == o.time.utc_ns_at_zero);

    // Without a date in the file, the day of the given UTC is taken.
    const std::string dir = temp_dir();
    const std::string gga_only =
        write_file(dir, "gga.nmea", "$GPGGA,120000.0,4851.3960,N,00221.1320,E,1,09,0.9,35.0,M,45.0,M,,*6D\n");
    REQUIRE(parse_utc("2024-05-01T11:59:50Z", &o.time.utc_ns_at_zero));
    const SensorLog g = read_gnss_file(gga_only, o);
    REQUIRE(g.gnss.size() == 1);
    CHECK(g.gnss[0].header.t_ns == 10 * kSecond);
    CHECK(g.gnss[0].utc_ns == (kMay1At10 + 7200) * kSecond);
    CHECK(has_note(g, "no date in the file"));
}

TEST_CASE("nmea: an old GPS receiver across midnight, a GSA of another talker, a logger's prefix") {
    const SensorLog log = read_gnss_file(data("gnss_gps_midnight.nmea"));
    CHECK(detect_gnss_format(data("gnss_gps_midnight.nmea")) == "nmea");
    REQUIRE(log.gnss.size() == 3);  // 23:59:59, 00:00:00, 00:00:01; 00:00:02 has no fix
    CHECK(log.gnss[0].header.t_ns == 0);
    CHECK(log.gnss[1].header.t_ns == 1 * kSecond);  // past midnight
    CHECK(log.gnss[2].header.t_ns == 2 * kSecond);
    CHECK(log.gnss[0].lat_deg == doctest::Approx(-(33.0 + 56.102 / 60.0)).epsilon(1e-13));
    CHECK(log.gnss[0].lon_deg == doctest::Approx(151.0 + 11.456 / 60.0).epsilon(1e-13));
    CHECK(log.gnss[0].height_m == doctest::Approx(42.5));
    CHECK(log.gnss[0].utc_ns == (kJan1 - 1) * kSecond);
    CHECK(log.gnss[1].utc_ns == kJan1 * kSecond);
    // The GPS GSA gives VDOP 2.0; the GLONASS one (VDOP 9.9) describes another solution.
    CHECK(log.gnss[0].h_accuracy_m == doctest::Approx(1.5 * 5.0));
    CHECK(log.gnss[0].v_accuracy_m == doctest::Approx(2.0 * 5.0));
    CHECK(log.gnss[2].v_accuracy_m == doctest::Approx(1.5 * 1.6 * 5.0));  // only a GLONASS GSA
    CHECK(log.gnss[2].satellites == 6);
    CHECK((log.gnss[2].header.flags & PN_GNSS_FLAG_HAS_VELOCITY) == 0);
    CHECK(log.gnss[1].vel_enu_mps[0] == doctest::Approx(kKnot));  // 1 knot due east
    CHECK(has_issue(log, 8, "sentence skipped: checksum mismatch in GPGSV: computed 7E, the sentence says 00"));
    CHECK(log.issues.size() == 1);
    CHECK(has_note(log, "1 lines with text before the '$'"));
    CHECK(has_note(log, "1 epochs without a fix (GGA fix quality 0)"));
}

TEST_CASE("nmea: a file with no fix at all, and a UERE scales the DOPs") {
    const std::string dir = temp_dir();
    const std::string none = write_file(dir, "cold.nmea",
                                        "$GPGGA,120000.0,,,,,0,00,,,M,,M,,*7B\n"
                                        "$GPGGA,120001.0,,,,,0,00,,,M,,M,,*7A\n");
    CHECK_THROWS_WITH_AS(read_gnss_file(none), doctest::Contains("cold.nmea: no GNSS fix could be read"),
                         ReadError);
    GnssReadOptions o;
    o.uere_m = 2.0;
    const SensorLog log = read_gnss_file(data("gnss_gps_midnight.nmea"), o);
    CHECK(log.gnss[0].h_accuracy_m == doctest::Approx(3.0));
    CHECK(log.gnss[0].v_accuracy_m == doctest::Approx(4.0));
}

TEST_CASE("parse_utc: Unix seconds and ISO 8601") {
    int64_t ns = 0;
    CHECK(parse_utc("1714557600.25", &ns));
    CHECK(ns == kMay1At10 * kSecond + 250000000);
    CHECK(parse_utc("2024-05-01T10:00:00.5Z", &ns));
    CHECK(ns == kMay1At10 * kSecond + 500000000);
    CHECK(iso_utc(ns) == "2024-05-01T10:00:00.500Z");
    CHECK_FALSE(parse_utc("2024-05-01 10:00:00", &ns));
    CHECK_FALSE(parse_utc("2024-13-01T10:00:00Z", &ns));
    CHECK_FALSE(parse_utc("yesterday", &ns));
}
