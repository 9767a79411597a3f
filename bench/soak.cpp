// SPDX-License-Identifier: Apache-2.0
// Soak: hours of simulated 100 Hz input with every sensor (IMU, magnetometer
// and barometer at 100 Hz, GNSS at 1 Hz outdoors) through each preset, from
// the real loader through the app C API, printed as JSON lines. The input is
// the closed loop "outdoor_indoor" (pednav sim: 200 m, out of a building and
// back, 180 s with its 20 s of standing at the start) walked again and again
// on one continuous clock. Printed per preset, every --every-h hours: resident
// memory (VmRSS), outputs so far; at the end: NaN or infinite values found in
// the outputs (must be 0), outputs by type against what the laps expect
// (strides: the simulated steps of a lap x laps), push failures.
//
//   soak [--hours 24] [--every-h 1] [--mount foot]...     24 h: 8.64 M IMU samples per preset
//   soak --short                                           1 h, printed every 10 min
//
// Exit status 1 when any output was not finite, a push failed, or the
// resident memory grew by more than 16 MiB after the first report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>
#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Resident set size of this process, MiB (/proc/self/status VmRSS).
double rss_mib() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("VmRSS:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
    }
    return -1.0;
}

bool all_finite(const double* v, size_t n) {
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

// Whether every value an output carries is finite.
bool output_finite(const pn_output_t& o) {
    switch (o.header.type) {
        case PN_REC_POSITION:
            return all_finite(o.position.pos_enu_m, 3) && all_finite(o.position.cov_enu_m2, 9) &&
                   std::isfinite(o.position.heading_rad) &&
                   ((o.position.header.flags & PN_POSITION_FLAG_HAS_VELOCITY) == 0 ||
                    all_finite(o.position.vel_enu_mps, 3));
        case PN_REC_STRIDE:
            return all_finite(o.stride.displacement_enu_m, 3) && std::isfinite(o.stride.length_m) &&
                   std::isfinite(o.stride.heading_change_rad);
        case PN_REC_STEP:
            return std::isfinite(o.step.accel_peak_to_peak_mps2) && std::isfinite(o.step.frequency_hz);
        default: return true;
    }
}

struct Lap {
    std::vector<pn_imu_t> imu;
    std::vector<pn_mag_t> mag;
    std::vector<pn_baro_t> baro;
    std::vector<pn_gnss_t> gnss;
    std::vector<const pn_record_header_t*> records;  // merged, pointing into the vectors above
    int64_t duration_ns = 0;                          // lap period: last IMU time + one sample
    size_t steps = 0;                                 // simulated steps (foot: strides of the instrumented foot)
};

Lap make_lap(const std::string& mount) {
    pednav::sim::SimOptions so;
    so.mount = mount;
    so.rate_hz = 100.0;
    so.seed = 11;
    so.gnss_rate_hz = 1.0;
    so.baro_rate_hz = 0.0;  // with every IMU sample, as the magnetometer
    const auto sim = pednav::sim::simulate(pednav::sim::builtin_route("outdoor_indoor"), so);
    Lap lap;
    lap.imu = sim.imu;
    lap.mag = sim.mag;
    lap.baro = sim.baro;
    lap.gnss = sim.gnss;
    lap.duration_ns = sim.imu.back().header.t_ns + 10000000;
    lap.steps = sim.step_times_s.size();
    return lap;
}

// Moves every record of the lap by dt_ns (the next lap on the same clock).
void shift(Lap& lap, int64_t dt_ns) {
    for (auto& r : lap.imu) r.header.t_ns += dt_ns;
    for (auto& r : lap.mag) r.header.t_ns += dt_ns;
    for (auto& r : lap.baro) r.header.t_ns += dt_ns;
    for (auto& r : lap.gnss) {
        r.header.t_ns += dt_ns;
        if (r.utc_ns != 0) r.utc_ns += dt_ns;
    }
}

struct Counts {
    size_t by_type[PN_REC_TYPE_COUNT] = {};
    size_t not_finite = 0;
    size_t push_failures = 0;
};

void drain(pn_engine_t* engine, Counts& c) {
    pn_output_t out[256];
    size_t n = 0;
    do {
        if (pn_engine_poll_many(engine, out, 256, &n) != PN_OK) return;
        for (size_t i = 0; i < n; ++i) {
            if (out[i].header.type < PN_REC_TYPE_COUNT) ++c.by_type[out[i].header.type];
            if (!output_finite(out[i])) ++c.not_finite;
        }
    } while (n == 256);
}

bool soak(const std::string& mount, double hours, double every_h) {
    const std::string config = read_file(std::string(PEDNAV_CONFIG_DIR) + "/" + mount + ".json");
    const char* dirs[] = {PEDNAV_PLUGIN_OUTPUT_DIR};
    pn_engine_create_info_t info{};
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config.c_str();
    info.plugin_dirs = dirs;
    info.plugin_dir_count = 1;
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_engine_t* engine = nullptr;
    if (pn_engine_create(&info, &engine, &err) != PN_OK) {
        std::fprintf(stderr, "%s: create failed: %s: %s\n", mount.c_str(), err.where, err.message);
        return false;
    }
    Lap lap = make_lap(mount);
    // Pointers into the lap's vectors, which shift() moves in time in place.
    lap.records = pednav::io::merged_records(lap.imu, lap.mag, lap.baro, lap.gnss);
    const int64_t total_ns = static_cast<int64_t>(hours * 3600e9);
    const int64_t every_ns = static_cast<int64_t>(every_h * 3600e9);
    Counts c;
    size_t imu_pushed = 0;
    int64_t next_report_ns = every_ns;
    double rss_first = -1.0, rss_max_after_first = 0.0;
    int64_t lap_start_ns = 0;
    while (lap_start_ns < total_ns) {
        for (const pn_record_header_t* r : lap.records) {
            if (r->t_ns >= total_ns) break;
            if (pn_engine_push(engine, r, &err) != PN_OK && c.push_failures++ == 0)
                std::fprintf(stderr, "%s: push at t = %.3f s failed: %s: %s\n", mount.c_str(), r->t_ns * 1e-9,
                             err.where, err.message);
            if (r->type == PN_REC_IMU && ++imu_pushed % 1024 == 0) drain(engine, c);
            if (r->t_ns >= next_report_ns) {
                drain(engine, c);
                const double rss = rss_mib();
                if (rss_first < 0) rss_first = rss;
                else if (rss > rss_max_after_first) rss_max_after_first = rss;
                std::printf("{\"mount\": \"%s\", \"hours\": %.2f, \"imu_samples\": %zu, \"rss_mib\": %.1f, "
                            "\"positions\": %zu, \"strides\": %zu, \"steps\": %zu, \"not_finite\": %zu}\n",
                            mount.c_str(), r->t_ns / 3600e9, imu_pushed, rss, c.by_type[PN_REC_POSITION],
                            c.by_type[PN_REC_STRIDE], c.by_type[PN_REC_STEP], c.not_finite);
                std::fflush(stdout);
                next_report_ns += every_ns;
            }
        }
        lap_start_ns += lap.duration_ns;
        shift(lap, lap.duration_ns);
    }
    if (pn_engine_flush(engine, &err) != PN_OK && c.push_failures++ == 0)
        std::fprintf(stderr, "%s: flush failed: %s: %s\n", mount.c_str(), err.where, err.message);
    drain(engine, c);
    pn_engine_destroy(engine);
    // The last lap may be cut by the end of the run: expected strides pro rata.
    const double lap_fraction = static_cast<double>(total_ns) / static_cast<double>(lap.duration_ns);
    const double expected_strides = lap_fraction * static_cast<double>(lap.steps);
    const double growth = rss_first < 0 ? 0.0 : std::max(0.0, rss_max_after_first - rss_first);
    std::printf("{\"mount\": \"%s\", \"summary\": true, \"hours\": %.2f, \"laps\": %.2f, \"imu_samples\": %zu, "
                "\"positions\": %zu, \"strides\": %zu, \"strides_expected\": %.0f, \"steps\": %zu, "
                "\"not_finite\": %zu, \"push_failures\": %zu, \"rss_first_mib\": %.1f, \"rss_growth_mib\": %.1f}\n",
                mount.c_str(), hours, lap_fraction, imu_pushed, c.by_type[PN_REC_POSITION], c.by_type[PN_REC_STRIDE],
                expected_strides, c.by_type[PN_REC_STEP], c.not_finite, c.push_failures, rss_first, growth);
    std::fflush(stdout);
    return c.not_finite == 0 && c.push_failures == 0 && growth <= 16.0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> mounts;
    double hours = 24.0, every_h = 1.0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--hours" && i + 1 < argc) hours = std::atof(argv[++i]);
        else if (a == "--every-h" && i + 1 < argc) every_h = std::atof(argv[++i]);
        else if (a == "--mount" && i + 1 < argc) mounts.push_back(argv[++i]);
        else if (a == "--short") hours = 1.0, every_h = 1.0 / 6.0;
        else {
            std::fprintf(stderr, "usage: %s [--hours H] [--every-h H] [--mount M]... | --short\n", argv[0]);
            return 2;
        }
    }
    if (!(hours > 0) || !(every_h > 0)) {
        std::fprintf(stderr, "--hours and --every-h must be positive\n");
        return 2;
    }
    if (mounts.empty()) mounts = {"foot", "chest", "handheld", "waist"};
    bool ok = true;
    for (const auto& m : mounts) ok = soak(m, hours, every_h) && ok;
    return ok ? 0 : 1;
}
