// SPDX-License-Identifier: Apache-2.0
// The Madgwick attitude estimator alone through the plugin ABI (dlopen,
// pnp_entry_v1, process per record), MARG form: per sample one IMU and one
// magnetometer record (a simulated handheld walk, the field gated as in the
// preset). Prints figures; not a test.
//
//   madgwick_bench [--route building_tour] [--rate 200] [--mag-rate HZ] [--form marg|imu] [--passes 10] [--callgrind]
// --mag-rate: the magnetometer on every round(rate / HZ)-th IMU sample (default: every sample).
//   valgrind --tool=callgrind --instr-atstart=no madgwick_bench --callgrind
// (instructions per sample = Ir / samples).
#include <valgrind/callgrind.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_sim/simulate.hpp>

#include "plugin_abi_driver.hpp"

int main(int argc, char** argv) {
    std::string route = "building_tour", form = "marg";
    double rate = 200, mag_rate = 0;
    bool callgrind = false;
    int passes = 10;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--route" && i + 1 < argc) route = argv[++i];
        else if (a == "--rate" && i + 1 < argc) rate = std::stod(argv[++i]);
        else if (a == "--form" && i + 1 < argc) form = argv[++i];
        else if (a == "--mag-rate" && i + 1 < argc) mag_rate = std::stod(argv[++i]);
        else if (a == "--callgrind") callgrind = true;
        else if (a == "--passes" && i + 1 < argc) passes = std::max(1, std::stoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: %s [--route NAME] [--rate HZ] [--mag-rate HZ] [--form marg|imu] [--passes N] [--callgrind]\n",
                         argv[0]);
            return 2;
        }
    }
    try {
        std::ifstream f(std::string(PEDNAV_CONFIG_DIR) + "/handheld.json");
        std::stringstream ss;
        ss << f.rdbuf();
        nlohmann::json params = nlohmann::json::parse(ss.str())["pipelines"]["handheld"]["attitude_estimator"]["params"];
        params["form"] = form;
        pednav::sim::SimOptions so;
        so.mount = "handheld";
        so.rate_hz = rate;
        so.with_baro = so.with_gnss = false;
        so.mag_rate_hz = mag_rate;
        const auto walk = pednav::sim::simulate(pednav::sim::builtin_route(route), so);
        const auto records = walk.records();  // IMU and MAG, time order
        pednav::bench::PluginNode node =
            pednav::bench::create_plugin("libpnp_madgwick.so", "org.pednav.pdr.madgwick", params, "handheld", rate);
        pednav::bench::RecordSink sink;
        size_t attitudes = 0, mag_used = 0;
        std::vector<double> seconds;
        for (int pass = 0; pass < (callgrind ? 1 : passes); ++pass) {
            pn_error_t err{};
            err.struct_size = sizeof err;
            if (pass > 0 && node.ops->reset(node.self, &err) != PN_OK) throw std::runtime_error(err.message);
            attitudes = mag_used = 0;
            const auto t0 = std::chrono::steady_clock::now();
            if (callgrind) CALLGRIND_START_INSTRUMENTATION;
            for (const pn_record_header_t* r : records) {
                sink.count = 0;
                node.ops->process(node.self, &r, 1, &sink.sink, nullptr);
                if (sink.count) {
                    ++attitudes;
                    mag_used += (sink.at(0)->flags & PN_ATTITUDE_FLAG_MAG_USED) != 0;
                }
            }
            if (callgrind) CALLGRIND_STOP_INSTRUMENTATION;
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        const double best = pednav::eval::percentile(seconds, 0);
        const size_t n = walk.imu.size();
        std::printf("{\"plugin\": \"org.pednav.pdr.madgwick\", \"form\": \"%s\", \"route\": \"%s\", \"rate_hz\": %.0f, "
                    "\"samples\": %zu, \"records\": %zu, \"attitudes\": %zu, \"mag_used\": %zu, \"passes\": %zu, "
                    "\"samples_per_second\": %.0f, \"ns_per_sample\": %.1f}\n",
                    form.c_str(), route.c_str(), rate, n, records.size(), attitudes, mag_used, seconds.size(), n / best,
                    best * 1e9 / n);
        node.ops->destroy(node.self);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "madgwick_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
