// SPDX-License-Identifier: Apache-2.0
#include "cmd_sim.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <pednav_sim/simulate.hpp>

#include "cli_common.hpp"
#include "pednav_strict_json/strict_json.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav sim --route FILE|NAME --out DIR [--mount foot|chest|handheld|waist] [--rate HZ] [--seed N]\n"
    "                  [--no-errors] [--mounting ROLL,PITCH,YAW] [--no-mag] [--no-baro] [--no-gnss]\n"
    "                  [--mag-rate HZ] [--baro-rate HZ] [--heel-strike-g G] [--surge M] [--jitter S]\n"
    "                  [--gnss-jump T,DURATION,EAST,NORTH]...\n"
    "       pednav sim --list\n"
    "  --route     a route JSON file (pednav-route/1) or a built-in route name\n"
    "  --mounting  sensor axes in the foot/body frame, degrees (default 0,0,0)\n"
    "  --no-errors exact sensors: no noise, bias, scale factor, saturation or drift\n"
    "  --mag-rate, --baro-rate  on a subset of the IMU samples (default: every sample)\n"
    "  --heel-strike-g  foot: landing transient of this peak acceleration on level floors (default 0)\n"
    "  --surge     chest/handheld/waist: forward oscillation of the trunk at the step frequency, m\n"
    "              (default: handheld 0.02, chest and waist 0)\n"
    "  --jitter    irregular sample times: each sample moved by up to +-S seconds (below half the interval)\n"
    "  --gnss-jump  multipath: from T s for DURATION s every fix is EAST, NORTH metres off (repeatable)\n";

bool is_builtin(const std::string& name) {
    const std::vector<std::string> names = pednav::sim::builtin_route_names();
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const char* const pednav_cmd_sim_usage = kUsage;

int pednav_cmd_sim(const std::vector<std::string>& args) {
    using namespace pednav::sim;
    std::string route_arg, out_dir;
    SimOptions options;
    pednav::cli::Args in(args, kUsage);
    while (!in.done()) {
        const std::string a = in.next();
        auto value = [&] { return in.value(a); };
        if (a == "--route")
            route_arg = value();
        else if (a == "--out")
            out_dir = value();
        else if (a == "--mount")
            options.mount = value();
        else if (a == "--rate")
            options.rate_hz = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--seed")
            options.seed = pednav::cli::parse_count(value(), a);
        else if (a == "--no-errors")
            options.sensor_errors = false;
        else if (a == "--no-mag")
            options.with_mag = false;
        else if (a == "--no-baro")
            options.with_baro = false;
        else if (a == "--no-gnss")
            options.with_gnss = false;
        else if (a == "--mag-rate")
            options.mag_rate_hz = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--baro-rate")
            options.baro_rate_hz = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--surge")
            options.surge_m = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--jitter")
            options.time_jitter_s = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--heel-strike-g")
            options.heel_strike_g = pednav::cli::parse_numbers(value(), 1, a)[0];
        else if (a == "--gnss-jump") {
            const std::vector<double> v = pednav::cli::parse_numbers(value(), 4, a);
            if (v[0] < 0 || v[1] <= 0) throw pednav::cli::UsageError("--gnss-jump needs T >= 0 and DURATION > 0");
            GnssJump jump;
            jump.t_s = v[0];
            jump.duration_s = v[1];
            jump.offset_enu_m[0] = v[2];
            jump.offset_enu_m[1] = v[3];
            options.gnss_jumps.push_back(jump);
        } else if (a == "--mounting") {
            const std::vector<double> rpy = pednav::cli::parse_numbers(value(), 3, a);
            std::copy(rpy.begin(), rpy.end(), options.mounting_rpy_deg);
        } else if (a == "--list") {
            for (const std::string& name : builtin_route_names())
                std::printf("%-16s %s\n", name.c_str(), builtin_route(name).description.c_str());
            return 0;
        } else {
            throw pednav::cli::UsageError("unknown option " + a);
        }
    }
    if (route_arg.empty() || out_dir.empty())
        throw pednav::cli::UsageError("--route and --out are required");
    try {
        // A route file when one of that name is there, else a built-in route (a
        // folder named like a built-in route is not a route file).
        Route route;
        std::error_code ec;
        if (std::filesystem::is_regular_file(route_arg, ec)) {
            try {
                route = parse_route(pednav::strict_json::parse(pednav::cli::read_text_file(route_arg)));
            } catch (const pednav::strict_json::Error& e) {
                throw std::runtime_error(route_arg + (e.pointer.empty() ? "" : ":" + e.pointer) + ": " + e.what());
            }
            if (route.name.empty()) route.name = route_arg;
        } else if (std::filesystem::exists(route_arg, ec) && !is_builtin(route_arg)) {
            throw std::runtime_error(route_arg + ": not a route file (a pednav-route/1 JSON file or a built-in route name)");
        } else {
            route = builtin_route(route_arg);
        }
        const SimOutput out = simulate(route, options);
        write_outputs(out, route, out_dir);
        std::printf("%s, %s mount, %.0f Hz: %.1f s, %.1f m, %zu steps, %zu GNSS fixes -> %s\n",
                    route.name.c_str(), options.mount.c_str(), options.rate_hz,
                    out.truth.empty() ? 0.0 : out.truth.back().t_s, out.distance_m, out.step_times_s.size(),
                    out.gnss.size(), out_dir.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav sim: %s\n", e.what());
        return 1;
    }
}
