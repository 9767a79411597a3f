// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a recording read by read_sensor_file (the readers of
// pednav inspect/run and pn_recording_open), with the format detected
// (PEDNAV_FUZZ_FORMAT "auto") or forced to one name, which is where a reader
// meets files it was not written for. A ReadError is the expected answer to a
// bad file; any other exception, a crash or a sanitizer report is a finding.
//   "column-map": the input is a column map (JSON), kPartSeparator, the data.
//   "humolire-senslogs": accelerometer file, kPartSeparator, gyroscope file.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_files.hpp"
#include "pednav_io/sensor_log.hpp"

#ifndef PEDNAV_FUZZ_FORMAT
#error "PEDNAV_FUZZ_FORMAT names the format to force (or \"auto\")"
#endif

namespace {

void read(const std::string& path, const pednav::io::ReadOptions& options) {
    try {
        const pednav::io::SensorLog log = pednav::io::read_sensor_file(path, options);
        // What pednav run does next: the merged stream must point at the records.
        const auto merged = pednav::io::merged_records(log);
        if (merged.size() != log.imu.size() + log.mag.size() + log.baro.size() + log.gnss.size()) __builtin_trap();
    } catch (const pednav::io::ReadError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using pednav::fuzz::split_parts;
    using pednav::fuzz::write_work_file;
    const std::string format = PEDNAV_FUZZ_FORMAT;
    pednav::io::ReadOptions options;
    options.format = format;
    if (format == "column-map") {
        const auto parts = split_parts(data, size, 2);
        const nlohmann::json map = nlohmann::json::parse(parts[0].begin(), parts[0].end(), nullptr, false);
        if (map.is_discarded()) return 0;
        options.column_map = &map;
        read(write_work_file("data.csv", parts[1]), options);
    } else if (format == "humolire-senslogs") {
        const auto parts = split_parts(data, size, 2);
        write_work_file("gyroscope-calibrated.txt", parts[1]);
        read(write_work_file("accelerometer-calibrated.txt", parts[0]), options);
    } else {
        read(write_work_file("recording.txt", std::string_view(reinterpret_cast<const char*>(data), size)), options);
    }
    return 0;
}
