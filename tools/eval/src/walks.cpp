// SPDX-License-Identifier: Apache-2.0
#include <pednav_eval/walks.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <pednav_eval/truth_readers.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::eval {

// ------------------------------------------------ shared recordings

const std::vector<int>& koroglu_walk_numbers() {
    static const std::vector<int> numbers = {33, 35, 39, 42, 44};
    return numbers;
}

RecordedWalk koroglu_walk(const std::string& data_dir, int number) {
    const std::string base = data_dir + "/koroglu-foot-gcp/SensorConnectData_" + std::to_string(number);
    RecordedWalk w;
    w.name = "koroglu-" + std::to_string(number);
    w.mount = "foot";
    w.input = base + ".csv";
    w.truth_kind = TruthKind::footprints;
    w.truth_path = base + "_gcp.csv";
    w.alignment = Alignment::fitted;
    w.gyro_range_radps = kKorogluGyroRangeRadps;
    return w;
}

const std::vector<std::string>& xio_walk_names() {
    static const std::vector<std::string> names = {"short_walk", "long_walk"};
    return names;
}

RecordedWalk xio_walk(const std::string& data_dir, const std::string& name) {
    RecordedWalk w;
    w.name = "xio-" + name;
    w.mount = "foot";
    w.input = data_dir + "/xio-gait-ngimu/" + name + ".csv";
    w.truth_kind = TruthKind::loop;
    return w;
}

const std::vector<std::string>& ipol_trials() {
    static const std::vector<std::string> trials = {"1-1", "1-2", "5-1", "5-2", "10-1", "10-2", "15-1", "19-1"};
    return trials;
}

const std::vector<std::string>& ipol_parts() {
    static const std::vector<std::string> parts = {"lf", "rf", "lb"};
    return parts;
}

RecordedWalk ipol_walk(const std::string& data_dir, const std::string& trial, const std::string& part) {
    if (part != "lf" && part != "rf" && part != "lb")
        throw std::runtime_error("ipol walk " + trial + ": unknown part '" + part + "' (lf, rf or lb)");
    const std::string base = data_dir + "/ipol-gait-waist-feet/" + trial;
    RecordedWalk w;
    w.name = "ipol-" + trial + "-" + part;
    w.mount = part == "lb" ? "waist" : "foot";
    w.input = base + "_" + part + ".txt";
    w.truth_kind = TruthKind::step_events;
    w.truth_path = base + ".json";
    w.feet = part == "lb" ? "both" : (part == "lf" ? "left" : "right");
    return w;
}

const std::vector<std::string>& humolire_walk_names() {
    static const std::vector<std::string> names = {"user1_straight", "user1_8_shape", "user1_square_2x",
                                                   "user3_forward"};
    return names;
}

double humolire_user_height_m(const std::string& data_dir, const std::string& name) {
    int user = 0;
    if (std::sscanf(name.c_str(), "user%d_", &user) != 1) return 0.0;
    std::ifstream in(data_dir + "/humolire-phone/participant.txt");
    std::string line;
    while (std::getline(in, line)) {
        int number = 0;
        double height_cm = 0.0;
        if (std::sscanf(line.c_str(), "%d %lf", &number, &height_cm) == 2 && number == user && height_cm > 0)
            return height_cm / 100.0;
    }
    return 0.0;
}

RecordedWalk humolire_walk(const std::string& data_dir, const std::string& name) {
    RecordedWalk w;
    w.name = "humolire-" + name;
    w.mount = "handheld";
    w.input = data_dir + "/humolire-phone/" + name;
    w.truth_kind = TruthKind::landmarks;
    w.truth_path = w.input;
    w.give_start = true;
    w.user_height_m = humolire_user_height_m(data_dir, name);
    return w;
}

std::vector<RecordedWalk> recorded_walks(const std::string& data_dir) {
    std::vector<RecordedWalk> walks;
    for (int n : koroglu_walk_numbers()) walks.push_back(koroglu_walk(data_dir, n));
    for (const std::string& name : xio_walk_names()) walks.push_back(xio_walk(data_dir, name));
    for (const std::string& trial : ipol_trials())
        for (const std::string& part : ipol_parts()) walks.push_back(ipol_walk(data_dir, trial, part));
    for (const std::string& name : humolire_walk_names()) walks.push_back(humolire_walk(data_dir, name));
    return walks;
}

Truth read_walk_truth(const RecordedWalk& walk) {
    switch (walk.truth_kind) {
        case TruthKind::footprints: return read_koroglu_gcp(walk.truth_path);
        case TruthKind::loop: return make_loop_truth();
        case TruthKind::step_events: return read_ipol_steps(walk.truth_path, kIpolRateHz, kIpolLegM, walk.feet);
        case TruthKind::landmarks: return read_humolire(walk.truth_path);
        case TruthKind::simulated:
        case TruthKind::ipin_posi: break;
    }
    throw std::runtime_error(walk.name + ": no reader for a " + truth_kind_name(walk.truth_kind) + " truth");
}

// ------------------------------------------------- simulated walks

sim::SimOptions sim_options(const SimulatedWalk& w) {
    sim::SimOptions so;
    so.mount = w.mount;
    so.rate_hz = w.rate_hz;
    so.seed = w.seed;
    so.sensor_errors = w.sensor_errors;
    so.with_baro = w.with_baro;
    so.with_gnss = w.with_gnss;
    for (int i = 0; i < 3; ++i) so.mounting_rpy_deg[i] = w.mounting_rpy_deg[i];
    sim::ImuErrorModel& m = so.imu;
    for (double* v : {&m.accel_noise_mps2_per_rthz, &m.accel_bias_mps2, &m.accel_bias_rw_mps2_per_rts, &m.accel_scale,
                      &m.gyro_noise_radps_per_rthz, &m.gyro_bias_radps, &m.gyro_bias_rw_radps_per_rts, &m.gyro_scale})
        *v *= w.error_scale;
    m.accel_bias_rw_mps2_per_rts *= w.accel_bias_walk_scale;
    if (!w.gyro_scale_errors) m.gyro_scale = 0.0;
    so.heel_strike_g = w.gait.heel_strike_g;
    so.surge_m = w.surge_m;
    so.time_jitter_s = w.time_jitter_s;
    return so;
}

sim::Route sim_route(const SimulatedWalk& w) {
    sim::Route route = sim::builtin_route(w.route);
    if (w.gait.speed_mps > 0) route.speed_mps = w.gait.speed_mps;
    if (w.gait.step_length_m > 0) route.step_length_m = w.gait.step_length_m;
    if (w.gait.stance_fraction > 0) route.stance_fraction = w.gait.stance_fraction;
    return route;
}

std::vector<SimulatedWalk> builtin_sim_walks(const std::string& mount, uint64_t seed) {
    std::vector<SimulatedWalk> walks;
    for (const char* route : {"corridor_loop", "stairs", "figure_eight", "building_tour", "outdoor_indoor"}) {
        SimulatedWalk w;
        w.route = route;
        w.mount = mount;
        w.seed = seed;
        w.with_baro = w.with_gnss = true;
        if (mount == "chest") w.surge_m = kChestSurgeM;
        walks.push_back(w);
    }
    return walks;
}

namespace {
SimulatedWalk tilted(const std::string& route) {
    SimulatedWalk w;
    w.route = route;
    w.mounting_rpy_deg[0] = 20;
    w.mounting_rpy_deg[1] = -30;
    w.mounting_rpy_deg[2] = 10;
    return w;
}
}  // namespace

std::vector<SimulatedWalk> imu_error_walks(double rate_hz) {
    std::vector<SimulatedWalk> walks;
    for (const char* route : {"corridor_loop", "stairs"}) {
        // 0: exact; > 0: every error times this; < 0: the accelerometer bias walk times -this.
        for (double errors : {0.0, 1.0, 5.0, -100.0, -300.0}) {
            SimulatedWalk w = tilted(route);
            w.rate_hz = rate_hz;
            w.sensor_errors = errors != 0;
            w.error_scale = errors > 0 ? errors : 1.0;
            w.accel_bias_walk_scale = errors < 0 ? -errors : 1.0;
            walks.push_back(w);
        }
    }
    return walks;
}

std::vector<SimulatedWalk> hupt_walks() {
    std::vector<SimulatedWalk> walks;
    for (const char* route : {"stairs", "building_tour"})
        for (double errors : {1.0, 5.0})
            for (uint64_t seed = 1; seed <= 4; ++seed) {
                SimulatedWalk w = tilted(route);
                w.error_scale = errors;
                w.seed = seed;
                walks.push_back(w);
            }
    return walks;
}

const std::vector<Gait>& sweep_gaits() {
    static const std::vector<Gait> gaits = {{"slow", 0.8, 0.55, 0.36, 0.0},
                                            {"normal", 1.3, 0.7, 0.28, 0.0},
                                            {"brisk", 1.9, 0.85, 0.2, 2.0},
                                            {"jog", 3.0, 1.1, 0.12, 3.0}};
    return gaits;
}

const std::vector<double>& sweep_rates_hz() {
    static const std::vector<double> rates = {100.0, 200.0, 256.0, 400.0};
    return rates;
}

const std::vector<std::array<double, 3>>& sweep_mountings_rpy_deg() {
    // Level; tilted; upside down; on its side; pitched -80 deg (x almost vertical); an odd angle.
    static const std::vector<std::array<double, 3>> mountings = {{0, 0, 0},  {20, -30, 10}, {180, 0, 0},
                                                                 {90, 0, 0}, {0, -80, 0},   {-150, 40, 120}};
    return mountings;
}

std::vector<SimulatedWalk> sweep_walks(bool gyro_scale_errors) {
    std::vector<SimulatedWalk> walks;
    for (const Gait& g : sweep_gaits())
        for (double rate : sweep_rates_hz())
            for (const auto& m : sweep_mountings_rpy_deg())
                for (uint64_t seed = 1; seed <= 3; ++seed) {
                    SimulatedWalk w;
                    w.rate_hz = rate;
                    w.seed = seed;
                    for (int i = 0; i < 3; ++i) w.mounting_rpy_deg[i] = m[i];
                    w.gait = g;
                    w.gyro_scale_errors = gyro_scale_errors;
                    walks.push_back(w);
                }
    return walks;
}

}  // namespace pednav::eval
