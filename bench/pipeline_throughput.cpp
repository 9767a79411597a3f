// SPDX-License-Identifier: Apache-2.0
// Pipeline throughput per mount through the real loader and the app C API
// (libpednav.so), printed as JSON (or, with --markdown, as the rows of the
// README's speed table). Per preset and input:
//
//   samples_per_second        IMU samples per second, best of --passes (input generation excluded)
//   push_ns_p50, push_ns_p99  the time of one pn_engine_push, over every push of one more pass
//   allocations_per_sample    operator new calls in the steady-state second half of the walk
//   rss_kib, engine_heap_kib  the process' resident memory at the end of the walk, the engine
//                             still alive, and the heap the engine and its plugins hold then
//   outputs_digest            FNV-1a of every output polled (the preset's output mask), and
//   all_types_digest          of every output with every type in the mask, then get_latest of
//                             each type: the same figures before and after an engine change
//                             mean the same outputs, bit for bit
//   instructions_per_sample   with --instructions: the walk run again under callgrind (valgrind
//                             on this program with --single-pass), Ir / IMU samples, split into
//                             the engine (libpednav.so) and the plugins (callgrind_split.hpp)
//
// A push or flush failing is counted (push_failures) and makes the exit status 1:
// the figures would not be those of the whole pipeline.
//
//   pipeline_throughput [--mount foot]... [--passes 5] [--rate 200] [--route corridor_loop]
//                       [--gnss-rate 1] [--baro-rate 0] [--input imu|all|both] [--instructions]
//                       [--markdown]
//   pipeline_throughput --single-pass [--single-input imu|all] ...
//
// --route: the simulated walk (a built-in route; outdoor_indoor has GNSS on
// its outdoor segments), --gnss-rate its fix rate, --baro-rate the
// barometer's (0: with every IMU sample, as the magnetometer). --input: the
// IMU alone, every simulated sensor, or both (the default).
//
// --single-pass runs one pass of one input and brackets the push loop with
// callgrind client requests, for
//   valgrind --tool=callgrind --instr-atstart=no pipeline_throughput --mount foot --single-pass
// (what --instructions runs): instructions per sample = Ir / imu_samples.
#include <malloc.h>
#include <valgrind/callgrind.h>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>
#include <pednav_sim/simulate.hpp>

#include "allocation_counter.hpp"
#include "callgrind_split.hpp"

namespace {

using Records = std::vector<const pn_record_header_t*>;

struct Options {
    std::vector<std::string> mounts;
    int passes = 5;
    double rate_hz = 200;
    std::string route = "corridor_loop";
    double gnss_rate_hz = 1.0, baro_rate_hz = 0.0;
    std::string input = "both";  // imu, all, both
    bool single = false;
    bool instructions = false;
    bool markdown = false;
};

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

long status_kib(const char* key) {  // a line of /proc/self/status, in KiB
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + std::strlen(key));
    return -1;
}

size_t heap_in_use() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

struct Fnv1a {
    uint64_t h = 1469598103934665603ull;
    void add(const void* p, size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
};

pn_engine_t* create_engine(const std::string& config) {
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
    if (pn_engine_create(&info, &engine, &err) != PN_OK)
        std::fprintf(stderr, "create failed: %s: %s\n", err.where, err.message);
    return engine;
}

struct Pass {
    bool ok = false;
    double seconds = 0;
    uint64_t allocations_second_half = 0;
    size_t outputs = 0;
    size_t push_failures = 0;
    uint64_t digest = 0;
    std::vector<int64_t> push_ns;  // per push, when timed
    long rss_kib = -1;
    long engine_heap_kib = -1;
};

enum class PassKind { throughput, callgrind, latency, every_type };

void count_failure(Pass& r, pn_status_t st, const char* what, size_t i, const pn_error_t& err) {
    if (st != PN_OK && r.push_failures++ == 0)
        std::fprintf(stderr, "%s %zu failed: %s: %s\n", what, i, err.where, err.message);
}

Pass run_pass(const std::string& config, const Records& records, PassKind kind) {
    Pass r;
    const size_t heap_before = heap_in_use();
    pn_engine_t* engine = create_engine(config);
    if (!engine) return r;
    if (kind == PassKind::every_type)
        pn_engine_set_output_mask(engine, PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) |
                                              PN_REC_MASK(PN_REC_STEP) | PN_REC_MASK(PN_REC_ATTITUDE) |
                                              PN_REC_MASK(PN_REC_GAIT_PHASE) |
                                              PN_REC_MASK(PN_REC_ATTITUDE_CORRECTION));
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_output_t out;
    Fnv1a digest;
    const size_t half = records.size() / 2;
    uint64_t alloc_mid = 0;
    if (kind == PassKind::latency || kind == PassKind::every_type) {
        if (kind == PassKind::latency) r.push_ns.resize(records.size());
        for (size_t i = 0; i < records.size(); ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            const pn_status_t st = pn_engine_push(engine, records[i], &err);
            const auto t1 = std::chrono::steady_clock::now();
            if (kind == PassKind::latency)
                r.push_ns[i] = std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count();
            count_failure(r, st, "push", i, err);
            while (pn_engine_poll(engine, &out) == PN_OK) {
                digest.add(&out, out.header.struct_size);
                ++r.outputs;
            }
        }
        r.rss_kib = status_kib("VmRSS:");
        r.engine_heap_kib = static_cast<long>((heap_in_use() - heap_before) / 1024);
        if (kind == PassKind::every_type)
            for (pn_record_type_t t = 0; t < PN_REC_TYPE_COUNT; ++t)
                if (pn_engine_get_latest(engine, t, &out) == PN_OK) digest.add(&out, out.header.struct_size);
    } else {
        if (kind == PassKind::callgrind) CALLGRIND_START_INSTRUMENTATION;
        const auto t0 = std::chrono::steady_clock::now();
        for (size_t i = 0; i < records.size(); ++i) {
            if (i == half) alloc_mid = pednav::bench::allocation_count();
            count_failure(r, pn_engine_push(engine, records[i], &err), "push", i, err);
            while (pn_engine_poll(engine, &out) == PN_OK) ++r.outputs;
        }
        const uint64_t alloc_end = pednav::bench::allocation_count();
        const auto t1 = std::chrono::steady_clock::now();
        if (kind == PassKind::callgrind) CALLGRIND_STOP_INSTRUMENTATION;
        r.seconds = std::chrono::duration<double>(t1 - t0).count();
        r.allocations_second_half = alloc_end - alloc_mid;
    }
    count_failure(r, pn_engine_flush(engine, &err), "flush", records.size(), err);
    while (pn_engine_poll(engine, &out) == PN_OK) {
        digest.add(&out, out.header.struct_size);
        ++r.outputs;
    }
    pn_engine_destroy(engine);
    r.digest = digest.h;
    r.ok = true;
    return r;
}

int64_t percentile(std::vector<int64_t> v, double p) {
    if (v.empty()) return 0;
    const size_t k = std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

// One row of output: a preset on one input.
struct Row {
    std::string mount, input;
    size_t imu_samples = 0, records = 0, outputs = 0, push_failures = 0;
    double best_seconds = 0;
    double allocations_per_sample = 0;
    int64_t push_p50 = 0, push_p99 = 0;
    long rss_kib = -1, engine_heap_kib = -1;
    uint64_t outputs_digest = 0, all_types_digest = 0;
    pednav::bench::InstructionSplit split;
};

// The same walk under callgrind: this program again, one pass of one input.
pednav::bench::InstructionSplit measure_instructions(const Options& o, const std::string& mount,
                                                     bool all_sensors) {
    pednav::bench::InstructionSplit s;
    char dir[] = "/tmp/pipeline_throughput.XXXXXX";
    if (!mkdtemp(dir)) {
        s.error = "no temporary directory";
        return s;
    }
    const std::string out = std::string(dir) + "/callgrind.out";
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) {
        s.error = "cannot find this program";
        return s;
    }
    self[n] = '\0';
    char cmd[8192];
    std::snprintf(
        cmd, sizeof cmd,
        "valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=%s '%s' --mount '%s' "
        "--single-pass --single-input %s --route '%s' --rate %.17g --gnss-rate %.17g --baro-rate %.17g "
        ">/dev/null 2>&1",
        out.c_str(), self, mount.c_str(), all_sensors ? "all" : "imu", o.route.c_str(), o.rate_hz,
        o.gnss_rate_hz, o.baro_rate_hz);
    if (std::system(cmd) != 0) {
        s.error = "valgrind failed (is it installed?)";
    } else {
        s = pednav::bench::split_callgrind_profile(out);
    }
    std::remove(out.c_str());
    rmdir(dir);
    return s;
}

void print_json_row(const Row& r, bool first) {
    std::printf(
        "%s\n    {\"mount\": \"%s\", \"input\": \"%s\", \"imu_samples\": %zu, \"records\": %zu, \"outputs\": "
        "%zu, "
        "\"best_seconds\": %.6f, \"samples_per_second\": %.0f, \"ns_per_sample\": %.1f, "
        "\"allocations_per_sample_steady_state\": %.4f, \"push_ns_p50\": %lld, \"push_ns_p99\": %lld, "
        "\"rss_kib\": %ld, \"engine_heap_kib\": %ld, \"outputs_digest\": \"%016llx\", "
        "\"all_types_digest\": \"%016llx\", ",
        first ? "" : ",", r.mount.c_str(), r.input.c_str(), r.imu_samples, r.records, r.outputs,
        r.best_seconds, static_cast<double>(r.imu_samples) / r.best_seconds,
        r.best_seconds / static_cast<double>(r.imu_samples) * 1e9, r.allocations_per_sample,
        static_cast<long long>(r.push_p50), static_cast<long long>(r.push_p99), r.rss_kib, r.engine_heap_kib,
        static_cast<unsigned long long>(r.outputs_digest),
        static_cast<unsigned long long>(r.all_types_digest));
    if (r.split.ok) {
        const double n = static_cast<double>(r.imu_samples);
        std::printf("\"instructions_per_sample\": {\"total\": %.0f, \"engine\": %.0f, \"plugins\": %.0f}, ",
                    static_cast<double>(r.split.total) / n, static_cast<double>(r.split.engine) / n,
                    static_cast<double>(r.split.plugins) / n);
    } else if (!r.split.error.empty()) {
        std::printf("\"instructions_per_sample\": null, \"instructions_error\": \"%s\", ",
                    r.split.error.c_str());
    }
    std::printf("\"push_failures\": %zu}", r.push_failures);
}

// The command that measures the row again (the figures of one row come from one preset on one input).
std::string command_for(const Options& o, const Row& r) {
    char walk[160] = "";
    const Options defaults;
    if (o.route != defaults.route || o.rate_hz != defaults.rate_hz ||
        o.gnss_rate_hz != defaults.gnss_rate_hz || o.baro_rate_hz != defaults.baro_rate_hz)
        std::snprintf(walk, sizeof walk, " --route %s --rate %g --gnss-rate %g --baro-rate %g",
                      o.route.c_str(), o.rate_hz, o.gnss_rate_hz, o.baro_rate_hz);
    char cmd[320];
    std::snprintf(cmd, sizeof cmd, "`build/bin/pipeline_throughput --mount %s%s --input %s --passes %d%s`",
                  r.mount.c_str(), walk, r.input == "imu" ? "imu" : "all", o.passes,
                  r.split.ok ? " --instructions" : "");
    return cmd;
}

void print_markdown_row(const Options& o, const Row& r) {
    const double n = static_cast<double>(r.imu_samples);
    char instructions[96] = "";
    if (r.split.ok)
        std::snprintf(instructions, sizeof instructions, "%.0f + %.0f = %.0f",
                      static_cast<double>(r.split.engine) / n, static_cast<double>(r.split.plugins) / n,
                      static_cast<double>(r.split.total) / n);
    std::printf("| %s | %s | %.2f M | %s | %g | %lld / %lld ns | %.1f MiB (engine %.1f MiB) | %s |\n",
                r.mount.c_str(), r.input.c_str(), n / r.best_seconds * 1e-6, instructions,
                r.allocations_per_sample, static_cast<long long>(r.push_p50),
                static_cast<long long>(r.push_p99), static_cast<double>(r.rss_kib) / 1024.0,
                static_cast<double>(r.engine_heap_kib) / 1024.0, command_for(o, r).c_str());
}

int usage(const char* argv0) {
    std::fprintf(
        stderr,
        "usage: %s [--mount M]... [--passes N] [--rate HZ] [--route NAME] [--gnss-rate HZ] [--baro-rate HZ]\n"
        "          [--input imu|all|both] [--instructions] [--markdown]\n"
        "       %s --single-pass [--single-input imu|all] ...\n",
        argv0, argv0);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    std::string single_input = "imu";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--mount" && has_value)
            o.mounts.push_back(argv[++i]);
        else if (a == "--passes" && has_value)
            o.passes = std::max(1, std::atoi(argv[++i]));
        else if (a == "--rate" && has_value)
            o.rate_hz = std::atof(argv[++i]);
        else if (a == "--route" && has_value)
            o.route = argv[++i];
        else if (a == "--gnss-rate" && has_value)
            o.gnss_rate_hz = std::atof(argv[++i]);
        else if (a == "--baro-rate" && has_value)
            o.baro_rate_hz = std::atof(argv[++i]);
        else if (a == "--input" && has_value)
            o.input = argv[++i];
        else if (a == "--single-input" && has_value)
            single_input = argv[++i];
        else if (a == "--single-pass")
            o.single = true;
        else if (a == "--instructions")
            o.instructions = true;
        else if (a == "--markdown")
            o.markdown = true;
        else
            return usage(argv[0]);
    }
    if (o.input != "imu" && o.input != "all" && o.input != "both") return usage(argv[0]);
    if (o.single) o.input = single_input == "all" ? "all" : "imu";
    if (o.mounts.empty()) o.mounts = {"foot", "chest", "handheld", "waist"};
    if (o.markdown) {
        std::printf(
            "| preset | input | samples/s | instructions / sample: engine + plugins = total | allocations / "
            "sample | push p50 / p99 | resident memory | command |\n| --- | --- | --- | --- | --- | --- | "
            "--- | --- |\n");
    } else {
        std::printf(
            "{\n  \"benchmark\": \"pipeline_throughput\",\n  \"rate_hz\": %g,\n  \"route\": \"%s\",\n"
            "  \"gnss_rate_hz\": %g,\n  \"baro_rate_hz\": %g,\n  \"mounts\": [",
            o.rate_hz, o.route.c_str(), o.gnss_rate_hz, o.baro_rate_hz);
    }
    bool first = true;
    size_t total_failures = 0;
    for (const auto& mount : o.mounts) {
        const std::string config = read_file(std::string(PEDNAV_CONFIG_DIR) + "/" + mount + ".json");
        if (config.empty()) continue;  // no preset for this mount yet
        pednav::sim::SimOptions so;
        so.mount = mount;
        so.rate_hz = o.rate_hz;
        so.seed = 7;
        so.gnss_rate_hz = o.gnss_rate_hz;
        so.baro_rate_hz = o.baro_rate_hz;
        const auto sim = pednav::sim::simulate(pednav::sim::builtin_route(o.route), so);
        // Two inputs: every simulated sensor (IMU, magnetometer, barometer,
        // GNSS on the route's outdoor segments), and the IMU alone.
        const Records all_records = sim.records();
        Records imu_records;
        for (const auto* r : all_records)
            if (r->type == PN_REC_IMU) imu_records.push_back(r);
        for (const bool all_sensors : {true, false}) {
            if (o.input != "both" && (o.input == "all") != all_sensors) continue;
            const Records& records = all_sensors ? all_records : imu_records;
            Row row;
            row.mount = mount;
            row.input = all_sensors ? (sim.gnss.empty() ? "imu+mag+baro" : "imu+mag+baro+gnss") : "imu";
            row.imu_samples = sim.imu.size();
            row.records = records.size();
            row.best_seconds = 1e300;
            for (int p = 0; p < (o.single ? 1 : o.passes); ++p) {
                const Pass pass =
                    run_pass(config, records, o.single ? PassKind::callgrind : PassKind::throughput);
                if (!pass.ok) return 1;
                row.best_seconds = std::min(row.best_seconds, pass.seconds);
                row.push_failures += pass.push_failures;
                row.outputs = pass.outputs;
                row.allocations_per_sample = static_cast<double>(pass.allocations_second_half) /
                                             (static_cast<double>(row.imu_samples) / 2);
            }
            if (!o.single) {
                const Pass latency = run_pass(config, records, PassKind::latency);
                const Pass every = run_pass(config, records, PassKind::every_type);
                if (!latency.ok || !every.ok) return 1;
                row.push_failures += latency.push_failures + every.push_failures;
                row.push_p50 = percentile(latency.push_ns, 0.50);
                row.push_p99 = percentile(latency.push_ns, 0.99);
                row.rss_kib = latency.rss_kib;
                row.engine_heap_kib = latency.engine_heap_kib;
                row.outputs_digest = latency.digest;
                row.all_types_digest = every.digest;
                if (o.instructions) row.split = measure_instructions(o, mount, all_sensors);
            }
            total_failures += row.push_failures;
            if (o.markdown)
                print_markdown_row(o, row);
            else
                print_json_row(row, first);
            first = false;
        }
    }
    if (!o.markdown) std::printf("\n  ]\n}\n");
    if (total_failures) std::fprintf(stderr, "%zu pushes or flushes failed: the figures are not valid\n", total_failures);
    return total_failures ? 1 : 0;
}
