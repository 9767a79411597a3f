// SPDX-License-Identifier: Apache-2.0
#include "pednav_eval/calibration.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <pednav_eval/truth_readers.hpp>
#include <pednav_pdr/step_length_model.hpp>

namespace pednav::eval {

namespace {

double seconds(int64_t ns) { return static_cast<double>(ns) * 1e-9; }

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

bool in_leg(const CalibrationLeg& leg, int64_t t_ns) {
    const double t = seconds(t_ns);
    return t > leg.t_start_s && t <= leg.t_end_s;
}

std::string leg_name(const CalibrationRun& run, size_t i) {
    return run.name + (run.legs.size() > 1 ? " leg " + std::to_string(i + 1) : "");
}

// Estimated length of each leg: the strides that end within it.
std::vector<double> estimated_lengths(const std::vector<CalibrationRun>& runs) {
    std::vector<double> out;
    for (const CalibrationRun& run : runs)
        for (size_t i = 0; i < run.legs.size(); ++i) {
            double d = 0;
            size_t n = 0;
            for (const pn_stride_t& s : run.strides)
                if (in_leg(run.legs[i], s.header.t_ns)) d += s.length_m, ++n;
            if (n == 0) throw std::runtime_error(leg_name(run, i) + ": the pipeline found no step in it");
            out.push_back(d);
        }
    return out;
}

std::vector<double> true_lengths(const std::vector<CalibrationRun>& runs) {
    std::vector<double> out;
    for (const CalibrationRun& run : runs)
        for (const CalibrationLeg& leg : run.legs) out.push_back(leg.distance_m);
    return out;
}

double number_param(const nlohmann::json& p, const char* key) {
    const auto it = p.find(key);
    if (it == p.end() || !it->is_number())
        throw std::runtime_error(std::string("the position filter's params have no number ") + key +
                                 " (list every parameter, as the presets do)");
    return it->get<double>();
}

CalibrationResult fit_step_vector(const nlohmann::json& p, const std::vector<CalibrationRun>& runs) {
    const double k = number_param(p, "step_vector_k");
    CalibrationResult r;
    const std::vector<double> est = estimated_lengths(runs), truth = true_lengths(runs);
    double se = 0, st = 0;
    for (size_t i = 0; i < est.size(); ++i) se += est[i], st += truth[i];
    if (!(se > 0)) throw std::runtime_error("the runs moved 0 m: K cannot be scaled");
    const double k_new = k * st / se;
    if (!(std::fabs(k_new) <= 20))
        throw std::runtime_error("the fitted step_vector_k " + fmt(k_new) + " is outside [-20, 20]: the walks' distances and the runs disagree by " + fmt(st / se) + " times");
    for (size_t i = 0; i < est.size(); ++i) {
        r.relative_errors_before.push_back((est[i] - truth[i]) / truth[i]);
        r.relative_errors_after.push_back((est[i] * st / se - truth[i]) / truth[i]);
    }
    r.params["step_vector_k"] = k_new;
    r.summary = "step_vector_k " + fmt(k) + " -> " + fmt(k_new) + " (true " + fmt(st) + " m / estimated " + fmt(se) +
                " m over " + std::to_string(est.size()) + " leg" + (est.size() == 1 ? "" : "s") + ")";
    return r;
}

CalibrationResult fit_step_model(const nlohmann::json& p, const std::vector<CalibrationRun>& runs,
                                 const CalibrationOptions& o) {
    const double b = number_param(p, "step_model_b"), beta = number_param(p, "step_model_beta_m");
    const double k_old = number_param(p, "step_model_k");
    std::vector<pdr::CalibrationWalk> walks;
    for (const CalibrationRun& run : runs)
        for (size_t i = 0; i < run.legs.size(); ++i) {
            pdr::CalibrationWalk w;
            w.distance_m = run.legs[i].distance_m;
            for (const pn_step_t& s : run.steps)
                if (s.motion_mode != PN_STEP_MODE_STATIC && in_leg(run.legs[i], s.header.t_ns))
                    w.accel_ranges_mps2.push_back(s.accel_max_mps2 - s.accel_min_mps2);
            if (w.accel_ranges_mps2.empty())
                throw std::runtime_error(leg_name(run, i) + ": the step detector found no step in it");
            walks.push_back(std::move(w));
        }
    const pdr::StepLengthFit fit = o.fit_root ? pdr::fit_step_length_and_root(walks, o.root_min, o.root_max, o.fit_beta, beta)
                                              : pdr::fit_step_length(walks, b, o.fit_beta, beta);
    if (!(fit.model.k > 0 && fit.model.k <= 10))
        throw std::runtime_error("the fitted step_model_k " + fmt(fit.model.k) + " is outside (0, 10]");
    if (!(fit.model.beta_m >= -1 && fit.model.beta_m <= 2))
        throw std::runtime_error("the fitted step_model_beta_m " + fmt(fit.model.beta_m) + " m is outside [-1, 2]");
    CalibrationResult r;
    const std::vector<double> est = estimated_lengths(runs), truth = true_lengths(runs);
    for (size_t i = 0; i < walks.size(); ++i) {
        double d = 0;
        for (double range : walks[i].accel_ranges_mps2) d += pdr::step_length_m(fit.model, range);
        r.relative_errors_before.push_back((est[i] - truth[i]) / truth[i]);
        r.relative_errors_after.push_back((d - truth[i]) / truth[i]);
    }
    r.params["step_model_k"] = fit.model.k;
    r.params["step_model_b"] = fit.model.b;
    r.params["step_model_beta_m"] = fit.model.beta_m;
    r.summary = "step_model_k " + fmt(k_old) + " -> " + fmt(fit.model.k) + ", step_model_b " + fmt(b) + " -> " +
                fmt(fit.model.b) + ", step_model_beta_m " + fmt(beta) + " -> " + fmt(fit.model.beta_m) + " m (" +
                std::to_string(fit.walks) + " leg" + (fit.walks == 1 ? "" : "s") + ", rms relative error " +
                fmt(fit.rms_relative_error) + ")";
    return r;
}

}  // namespace

CalibrationLeg whole_walk_leg(double distance_m) {
    if (!(distance_m > 0)) throw std::runtime_error("a walk's distance must be positive, not " + fmt(distance_m));
    return {-INFINITY, INFINITY, distance_m};
}

std::vector<CalibrationLeg> landmark_legs(const std::string& path) {
    if (std::filesystem::is_directory(path)) {
        const Truth truth = read_humolire(path);
        std::vector<CalibrationLeg> legs;
        for (size_t i = 1; i < truth.points.size(); ++i) {
            const TruthPoint &a = truth.points[i - 1], &b = truth.points[i];
            const double d = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
            if (d > 0 && b.t_s > a.t_s) legs.push_back({a.t_s, b.t_s, d});
        }
        if (legs.empty()) throw std::runtime_error(path + ": no two landmarks apart");
        return legs;
    }
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open the landmarks file " + path);
    struct Mark {
        double t, x, y;
    };
    std::vector<Mark> marks;
    std::string line;
    bool header_seen = false;
    for (size_t n = 1; std::getline(in, line); ++n) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::string text = line;
        for (char& c : text)
            if (c == ',' || c == ';' || c == '\t') c = ' ';
        std::istringstream fields(text);
        Mark m{};
        std::string extra;
        if (!(fields >> m.t >> m.x >> m.y) || (fields >> extra)) {
            if (marks.empty() && !header_seen && std::isalpha(static_cast<unsigned char>(line[first]))) {
                header_seen = true;  // a header line ("t,x,y")
                continue;
            }
            throw std::runtime_error(path + ":" + std::to_string(n) + ": expected t,x,y (s, m, m), got '" + line + "'");
        }
        if (!std::isfinite(m.t) || !std::isfinite(m.x) || !std::isfinite(m.y))
            throw std::runtime_error(path + ":" + std::to_string(n) + ": not a finite number");
        if (!marks.empty() && m.t <= marks.back().t)
            throw std::runtime_error(path + ":" + std::to_string(n) + ": time " + fmt(m.t) +
                                     " s is not after the previous landmark's");
        marks.push_back(m);
    }
    if (marks.size() < 2) throw std::runtime_error(path + ": needs at least two landmarks, has " + std::to_string(marks.size()));
    std::vector<CalibrationLeg> legs;
    for (size_t i = 1; i < marks.size(); ++i) {
        const double d = std::hypot(marks[i].x - marks[i - 1].x, marks[i].y - marks[i - 1].y);
        if (d > 0) legs.push_back({marks[i - 1].t, marks[i].t, d});
    }
    if (legs.empty()) throw std::runtime_error(path + ": every landmark is at the same place");
    return legs;
}

CalibrationResult calibrate_position_filter(const nlohmann::json& p, const std::vector<CalibrationRun>& runs,
                                            const CalibrationOptions& o) {
    if (runs.empty()) throw std::runtime_error("no walk to calibrate on");
    for (const CalibrationRun& run : runs)
        if (run.legs.empty()) throw std::runtime_error(run.name + ": no leg of known length");
    if (!p.is_object()) throw std::runtime_error("the position filter has no params object");
    if (p.contains("step_vector_k")) {
        if (o.fit_beta || o.fit_root)
            throw std::runtime_error("the step vector has only K to fit: --fit-beta and --fit-root are for a step model");
        return fit_step_vector(p, runs);
    }
    if (p.contains("step_model_k")) return fit_step_model(p, runs, o);
    throw std::runtime_error(
        "the position filter has neither step_vector_k nor step_model_k among its params: nothing this command can calibrate");
}

}  // namespace pednav::eval
