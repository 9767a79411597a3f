// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a GNSS file (NMEA 0183 or the CSV of fixes) read by
// read_gnss_file, detected (PEDNAV_FUZZ_FORMAT "auto") or forced ("nmea",
// "csv"), then summarised as pednav inspect does and put on an IMU log's
// clock. A ReadError is the expected answer to a bad file; anything else
// escaping, a crash or a sanitizer report is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_files.hpp"
#include "pednav_io/gnss_log.hpp"

#ifndef PEDNAV_FUZZ_FORMAT
#error "PEDNAV_FUZZ_FORMAT names the format to force (or \"auto\")"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = pednav::fuzz::write_work_file(
        "gnss.txt", std::string_view(reinterpret_cast<const char*>(data), size));
    pednav::io::GnssReadOptions options;
    options.format = PEDNAV_FUZZ_FORMAT;
    // The time base of pednav run --gnss: the first byte picks an exact UTC of t = 0 or none.
    if (size > 0 && (data[0] & 1) != 0) options.time.utc_ns_at_zero = 1714557600000000000LL;
    try {
        const pednav::io::SensorLog gnss = pednav::io::read_gnss_file(path, options);
        for (const pn_gnss_t& fix : gnss.gnss) {
            if (!std::isfinite(fix.lat_deg) || !std::isfinite(fix.lon_deg) || std::fabs(fix.lat_deg) > 90.0 ||
                std::fabs(fix.lon_deg) > 180.0)
                __builtin_trap();  // a fix kept must be a place on the earth
        }
        (void)pednav::io::gnss_fixes_json(gnss.gnss).dump();
        pednav::io::SensorLog imu;
        pednav::io::use_gnss(imu, gnss);
    } catch (const pednav::io::ReadError&) {
    }
    return 0;
}
