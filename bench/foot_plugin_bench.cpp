// SPDX-License-Identifier: Apache-2.0
// Throughput of the foot plugins alone, driven through the plugin ABI (dlopen,
// pnp_entry_v1, process per record) in lock-step with the EKF's correction fed
// back, as the engine would: stance detection + attitude + EKF, input
// generation excluded. Prints figures; not a test.
//
//   foot_plugin_bench [--route building_tour] [--rate 200] [--patch '{"joseph_form":false}'] [--passes 10]
//                     [--filter org.pednav.foot.ekf15.dense] [--callgrind]
// --filter picks the position filter plugin (default: the preset's).
// Each pass runs the whole walk from reset plugins; the best pass gives
// samples_per_second, the median pass median_samples_per_second.
//   valgrind --tool=callgrind --instr-atstart=no foot_plugin_bench --callgrind
// (instructions per sample = Ir / samples).
#include <valgrind/callgrind.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_plugin.h>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_foot_eval/patches.hpp>
#include <pednav_sim/simulate.hpp>

#include "plugin_abi_driver.hpp"

namespace {

std::string read_text(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

using Node = pednav::bench::PluginNode;
using Sink = pednav::bench::RecordSink;

Node create(const std::string& library, const std::string& id, const nlohmann::json& params, double rate) {
    return pednav::bench::create_plugin(library, id, params, "foot", rate);
}

}  // namespace

int main(int argc, char** argv) {
    std::string route = "building_tour", patch = "{}", filter;
    double rate = 200;
    bool callgrind = false;
    int passes = 10;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--route" && i + 1 < argc) route = argv[++i];
        else if (a == "--rate" && i + 1 < argc) rate = std::stod(argv[++i]);
        else if (a == "--patch" && i + 1 < argc) patch = argv[++i];
        else if (a == "--filter" && i + 1 < argc) filter = argv[++i];
        else if (a == "--callgrind") callgrind = true;
        else if (a == "--passes" && i + 1 < argc) passes = std::max(1, std::stoi(argv[++i]));
    }
    try {
        const std::string preset = read_text(std::string(PEDNAV_CONFIG_DIR) + "/foot.json");
        nlohmann::json cfg = nlohmann::json::parse(
            pednav::eval::patched_config(preset, pednav::foot_eval::ekf_patch(nlohmann::json::parse(patch))));
        auto& pipe = cfg["pipelines"]["foot"];
        if (!filter.empty()) pipe["position_filter"]["plugin"] = filter;

        pednav::sim::SimOptions so;
        so.rate_hz = rate;
        so.with_mag = so.with_baro = so.with_gnss = false;
        so.mounting_rpy_deg[1] = -30;
        const auto walk = pednav::sim::simulate(pednav::sim::builtin_route(route), so);

        Node det = create("libpnp_foot_stance.so", pipe["step_detector"]["plugin"], pipe["step_detector"]["params"], rate);
        Node att = create("libpnp_foot_strapdown.so", pipe["attitude_estimator"]["plugin"],
                          pipe["attitude_estimator"]["params"], rate);
        Node ekf = create("libpnp_foot_ekf.so", pipe["position_filter"]["plugin"], pipe["position_filter"]["params"], rate);
        Sink s_det, s_att, s_ekf;
        std::array<unsigned char, PN_RECORD_MAX_SIZE> correction{};
        const size_t n = walk.imu.size();
        size_t positions = 0;
        // One pass = the whole walk from reset plugins; timed per pass.
        const auto run_pass = [&]() {
            bool have_correction = false;
            size_t next_imu = 0;
            positions = 0;
            for (size_t i = 0; i < n; ++i) {
                const pn_record_header_t* imu = &walk.imu[i].header;
                s_det.count = 0;
                det.ops->process(det.self, &imu, 1, &s_det.sink, nullptr);
                // The detector looks ahead: each decision releases its IMU sample downstream.
                for (size_t g = 0; g < s_det.count; ++g) {
                    const pn_record_header_t* sample = &walk.imu[next_imu++].header;
                    if (have_correction) {
                        const auto* c = reinterpret_cast<const pn_record_header_t*>(correction.data());
                        att.ops->process(att.self, &c, 1, &s_att.sink, nullptr);
                        have_correction = false;
                    }
                    s_att.count = 0;
                    att.ops->process(att.self, &sample, 1, &s_att.sink, nullptr);
                    const pn_record_header_t* batch[3] = {sample, s_det.at(g), nullptr};
                    uint32_t count = 2;
                    if (s_att.count) batch[count++] = s_att.at(0);
                    s_ekf.count = 0;
                    ekf.ops->process(ekf.self, batch, count, &s_ekf.sink, nullptr);
                    for (size_t k = 0; k < s_ekf.count; ++k) {
                        const pn_record_header_t* r = s_ekf.at(k);
                        if (r->type == PN_REC_POSITION) ++positions;
                        if (r->type == PN_REC_ATTITUDE_CORRECTION) {
                            std::memcpy(correction.data(), r, r->struct_size);
                            have_correction = true;
                        }
                    }
                }
            }
        };
        std::vector<double> seconds;
        for (int pass = 0; pass < (callgrind ? 1 : passes); ++pass) {
            if (pass > 0) {
                pn_error_t err{};
                err.struct_size = sizeof err;
                for (Node* node : {&det, &att, &ekf})
                    if (node->ops->reset(node->self, &err) != PN_OK) throw std::runtime_error(err.message);
            }
            const auto t0 = std::chrono::steady_clock::now();
            if (callgrind) CALLGRIND_START_INSTRUMENTATION;
            run_pass();
            if (callgrind) CALLGRIND_STOP_INSTRUMENTATION;
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        const double best = pednav::eval::percentile(seconds, 0),
                     median = pednav::eval::percentile(seconds, 50, pednav::eval::PercentileMethod::higher);
        std::printf("{\"route\": \"%s\", \"rate_hz\": %.0f, \"samples\": %zu, \"positions\": %zu, \"passes\": %zu, "
                    "\"best_seconds\": %.4f, \"samples_per_second\": %.0f, \"median_samples_per_second\": %.0f, "
                    "\"ns_per_sample\": %.1f}\n",
                    route.c_str(), rate, n, positions, seconds.size(), best, n / best, n / median, best * 1e9 / n);
        for (Node* node : {&det, &att, &ekf}) node->ops->destroy(node->self);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "foot_plugin_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
