// SPDX-License-Identifier: Apache-2.0
// Pipeline throughput per mount through the real loader and the app C API,
// printed as JSON: IMU samples per second (best of N passes, input generation
// excluded) and heap allocations per sample in the steady-state second half.
// A push or flush failing is counted (push_failures) and makes the exit status 1:
// the figures would not be those of the whole pipeline.
//
//   pipeline_throughput [--mount foot] [--passes 5] [--rate 200] [--single-pass]
//
// --single-pass runs one pass of the IMU-only input and brackets the push loop
// with callgrind client requests, for
//   valgrind --tool=callgrind --instr-atstart=no pipeline_throughput --mount foot --single-pass
// (see README "Speed"): instructions per sample = Ir / imu_samples.
#include <valgrind/callgrind.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>
#include <pednav_sim/simulate.hpp>

#include "allocation_counter.hpp"

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct PassResult {
    double seconds = 0;
    uint64_t allocations_second_half = 0;
    size_t outputs = 0;
    size_t push_failures = 0;  // pushes refused or failed: the figures would not be of the full pipeline
    bool ok = true;
};

PassResult run_pass(const std::string& config, const std::vector<const pn_record_header_t*>& records, bool callgrind) {
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
    PassResult r;
    if (pn_engine_create(&info, &engine, &err) != PN_OK) {
        std::fprintf(stderr, "create failed: %s: %s\n", err.where, err.message);
        r.ok = false;
        return r;
    }
    pn_output_t out;
    const size_t half = records.size() / 2;
    uint64_t alloc_mid = 0;
    if (callgrind) CALLGRIND_START_INSTRUMENTATION;
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < records.size(); ++i) {
        if (i == half) alloc_mid = pednav::bench::allocation_count();
        if (pn_engine_push(engine, records[i], &err) != PN_OK && r.push_failures++ == 0)
            std::fprintf(stderr, "push %zu failed: %s: %s\n", i, err.where, err.message);
        while (pn_engine_poll(engine, &out) == PN_OK) ++r.outputs;
    }
    const uint64_t alloc_end = pednav::bench::allocation_count();
    const auto t1 = std::chrono::steady_clock::now();
    if (callgrind) CALLGRIND_STOP_INSTRUMENTATION;
    if (pn_engine_flush(engine, &err) != PN_OK && r.push_failures++ == 0)
        std::fprintf(stderr, "flush failed: %s: %s\n", err.where, err.message);
    pn_engine_destroy(engine);
    r.seconds = std::chrono::duration<double>(t1 - t0).count();
    r.allocations_second_half = alloc_end - alloc_mid;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> mounts;
    int passes = 5;
    double rate_hz = 200;
    bool single = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--mount" && i + 1 < argc) mounts.push_back(argv[++i]);
        else if (a == "--passes" && i + 1 < argc) passes = std::atoi(argv[++i]);
        else if (a == "--rate" && i + 1 < argc) rate_hz = std::atof(argv[++i]);
        else if (a == "--single-pass") single = true;
        else {
            std::fprintf(stderr, "usage: %s [--mount M]... [--passes N] [--rate HZ] [--single-pass]\n", argv[0]);
            return 2;
        }
    }
    if (mounts.empty()) mounts = {"foot", "chest", "handheld", "waist"};
    std::printf("{\n  \"benchmark\": \"pipeline_throughput\",\n  \"rate_hz\": %.0f,\n  \"mounts\": [", rate_hz);
    bool first = true;
    size_t total_failures = 0;
    for (const auto& mount : mounts) {
        const std::string config = read_file(std::string(PEDNAV_CONFIG_DIR) + "/" + mount + ".json");
        if (config.empty()) continue;  // no preset for this mount yet
        pednav::sim::SimOptions so;
        so.mount = mount;
        so.rate_hz = rate_hz;
        so.seed = 7;
        const auto sim = pednav::sim::simulate(pednav::sim::builtin_route("corridor_loop"), so);
        // Two inputs: every simulated sensor (IMU, magnetometer, barometer at the
        // IMU rate), and the IMU alone.
        const auto all_records = sim.records();
        std::vector<const pn_record_header_t*> imu_records;
        for (const auto* r : all_records)
            if (r->type == PN_REC_IMU) imu_records.push_back(r);
        for (int variant = 0; variant < 2; ++variant) {
            if (single && variant == 0) continue;  // callgrind: the IMU-only figure
            const auto& records = variant == 0 ? all_records : imu_records;
            double best = 1e300;
            PassResult last;
            size_t failures = 0;
            for (int p = 0; p < (single ? 1 : passes); ++p) {
                last = run_pass(config, records, single);
                if (!last.ok) return 1;
                best = std::min(best, last.seconds);
                failures += last.push_failures;
            }
            total_failures += failures;
            const double samples = static_cast<double>(sim.imu.size());
            std::printf("%s\n    {\"mount\": \"%s\", \"input\": \"%s\", \"imu_samples\": %zu, \"records\": %zu, "
                        "\"outputs\": %zu, \"best_seconds\": %.6f, \"samples_per_second\": %.0f, "
                        "\"ns_per_sample\": %.1f, \"allocations_per_sample_steady_state\": %.4f, "
                        "\"push_failures\": %zu}",
                        first ? "" : ",", mount.c_str(), variant == 0 ? "imu+mag+baro" : "imu", sim.imu.size(),
                        records.size(), last.outputs, best, samples / best, best / samples * 1e9,
                        static_cast<double>(last.allocations_second_half) / (samples / 2), failures);
            first = false;
        }
    }
    std::printf("\n  ]\n}\n");
    if (total_failures) std::fprintf(stderr, "%zu pushes or flushes failed: the figures are not valid\n", total_failures);
    return total_failures ? 1 : 0;
}
