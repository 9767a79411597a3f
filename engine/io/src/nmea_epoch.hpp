// SPDX-License-Identifier: Apache-2.0
// Internal: what the sentences of one receiver epoch (one UTC time) say,
// gathered sentence by sentence, and the fix they make together
// (docs/formats.md, "NMEA 0183").
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gnss_fix.hpp"
#include "nmea_sentence.hpp"

namespace pednav::io::detail {

struct NmeaEpoch {
    size_t line = 0;  // 1-based line of the epoch's first sentence
    bool has_time = false;
    int64_t time_of_day_ns = 0;
    bool has_date = false;
    int64_t date_days = 0;  // days since 1970-01-01 (RMC or ZDA)

    struct Gga {
        bool present = false;
        std::string talker;
        int quality = 0;
        double lat_deg = NAN, lon_deg = NAN;
        double altitude_msl_m = NAN, geoid_separation_m = NAN;
        int satellites = -1;  // -1: empty field
        double hdop = NAN;
    } gga;
    struct Rmc {
        bool present = false;
        bool valid = false;  // status A and mode indicator not N
        char mode = 0;       // NMEA 2.3 mode indicator, 0 when absent
        double lat_deg = NAN, lon_deg = NAN;
        double speed_mps = NAN, course_deg = NAN;
    } rmc;
    struct Vtg {
        bool present = false;
        bool valid = false;  // mode indicator not N
        double speed_mps = NAN, course_deg = NAN;
    } vtg;
    struct Gst {
        bool present = false;
        double sigma_lat_m = NAN, sigma_lon_m = NAN, sigma_alt_m = NAN;
    } gst;
    struct Gsa {
        std::string talker;
        int fix_mode = 0;  // 1 no fix, 2 = 2D, 3 = 3D
        double hdop = NAN, vdop = NAN;
        int satellite_ids = 0;
    };
    std::vector<Gsa> gsa;
};

// Why an epoch made no record.
enum class NoFix { none, gga_quality_zero, rmc_void, no_position, not_measured };

// Applies one sentence to the epoch. Returns false with `problem` set when a
// field it needs is missing or malformed ("truncated GGA: 9 fields, 14
// expected", "bad latitude '48x7.03'"); the epoch is then unchanged.
// Sentence types other than GGA, RMC, GSA, GST, VTG and ZDA are not applied.
bool apply_nmea_sentence(const NmeaSentence& s, NmeaEpoch* epoch, std::string* problem);

// The time a sentence carries (GGA, RMC, GST, ZDA), when it has one and it
// parses: the epoch it belongs to. False for sentences without a time.
bool nmea_sentence_time(const NmeaSentence& s, int64_t* time_of_day_ns);

// The fix of a complete epoch, or `why` it has none.
FixFields nmea_epoch_fix(const NmeaEpoch& epoch, NoFix* why);

}  // namespace pednav::io::detail
