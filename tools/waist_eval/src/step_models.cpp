// SPDX-License-Identifier: Apache-2.0
#include <pednav_waist_eval/step_models.hpp>

#include <cmath>
#include <functional>
#include <stdexcept>

#include <pednav_pdr/inverted_pendulum.hpp>
#include <pednav_pdr/step_length_model.hpp>

namespace pednav::waist_eval {

namespace {

constexpr double kLegToHeight = 0.53;  // leg length (greater trochanter to the floor) over body height

// A model: the basis values of one step (the user's height given), and
// whether an exponent q in the basis is fitted with its constants (within
// [q_min, q_max]).
struct Model {
    const char* name;
    std::function<std::vector<double>(const IpolStep&, double height_m, double q)> basis;
    bool fit_q;
    double q_min = 0, q_max = 0;
};

// One leg: its steps, and the distance they cover.
struct LegData {
    size_t trial;
    const std::vector<IpolStep>* steps;
    double distance_m;
};

pdr::LinearCalibrationWalk walk_of(const Model& m, const LegData& leg, double height_m, double q) {
    pdr::LinearCalibrationWalk w{{}, leg.distance_m};
    for (const IpolStep& s : *leg.steps) {
        const std::vector<double> g = m.basis(s, height_m, q);
        if (w.basis_sums.empty()) w.basis_sums.assign(g.size(), 0.0);
        for (size_t j = 0; j < g.size(); ++j) w.basis_sums[j] += g[j];
    }
    return w;
}

double predicted_m(const pdr::LinearCalibrationWalk& w, const std::vector<double>& c) {
    double d = 0;
    for (size_t j = 0; j < c.size(); ++j) d += c[j] * w.basis_sums[j];
    return d;
}

struct Fit {
    std::vector<double> c;
    double q = 0;
};

// Constants on `legs`; with fit_q, q by golden section on the rms relative
// error.
Fit fit(const Model& m, const std::vector<LegData>& legs, const std::vector<double>& heights) {
    const auto fit_at = [&](double q, double* rms) {
        std::vector<pdr::LinearCalibrationWalk> walks;
        for (const LegData& l : legs) walks.push_back(walk_of(m, l, heights[l.trial], q));
        Fit f{pdr::fit_linear_step_model(walks), q};
        double s = 0;
        for (const auto& w : walks) s += std::pow(predicted_m(w, f.c) / w.distance_m - 1.0, 2);
        *rms = std::sqrt(s / static_cast<double>(walks.size()));
        return f;
    };
    double rms1 = 0, rms2 = 0;
    if (!m.fit_q) return fit_at(0.0, &rms1);
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = m.q_min, hi = m.q_max, x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
    Fit f1 = fit_at(x1, &rms1), f2 = fit_at(x2, &rms2);
    while (hi - lo > 1e-4) {
        if (rms1 <= rms2) {
            hi = x2, x2 = x1, f2 = f1, rms2 = rms1;
            x1 = hi - phi * (hi - lo);
            f1 = fit_at(x1, &rms1);
        } else {
            lo = x1, x1 = x2, f1 = f2, rms1 = rms2;
            x2 = lo + phi * (hi - lo);
            f2 = fit_at(x2, &rms2);
        }
    }
    return rms1 <= rms2 ? f1 : f2;
}

double error_pct(const Model& m, const Fit& f, const LegData& leg, double height_m) {
    const pdr::LinearCalibrationWalk w = walk_of(m, leg, height_m, f.q);
    return 100.0 * (predicted_m(w, f.c) / leg.distance_m - 1.0);
}

}  // namespace

std::vector<StepModelScores> score_step_models(const std::vector<IpolTrial>& trials,
                                               double default_height_m) {
    const auto root4 = [](double r) { return std::pow(std::max(0.0, r), 0.25); };
    const auto pendulum = [](const IpolStep& s, double h) {
        return pdr::inverted_pendulum_step_m(kLegToHeight * h, s.pelvis_rise_m);
    };
    const std::vector<Model> models = {
        {"Weinberg k (a_max - a_min)^(1/4)",
         [&](const IpolStep& s, double, double) { return std::vector<double>{root4(s.accel_range_mps2)}; },
         false},
        {"the same times the user's height",
         [&](const IpolStep& s, double h, double) {
             return std::vector<double>{h * root4(s.accel_range_mps2)};
         },
         false},
        {"k (a_max - a_min)^(1/4) f^q, q fitted with k",
         [&](const IpolStep& s, double, double q) {
             return std::vector<double>{root4(s.accel_range_mps2) * std::pow(s.frequency_hz, q)};
         },
         true, -1.0, 2.0},
        {"a + b f",
         [](const IpolStep& s, double, double) {
             return std::vector<double>{1.0, s.frequency_hz};
         },
         false},
        {"inverted pendulum K 2 sqrt(2 l h - h^2), l = 0.53 x height",
         [&](const IpolStep& s, double h, double) { return std::vector<double>{pendulum(s, h)}; }, false},
        {"the same plus an offset",
         [&](const IpolStep& s, double h, double) {
             return std::vector<double>{pendulum(s, h), 1.0};
         },
         false},
        {"k (a_max - a_min)^(1/4) + beta",
         [&](const IpolStep& s, double, double) {
             return std::vector<double>{root4(s.accel_range_mps2), 1.0};
         },
         false},
        {"k (a_max - a_min)^(1/b), b fitted with k (1/b = q)",
         [](const IpolStep& s, double, double q) {
             return std::vector<double>{std::pow(std::max(0.0, s.accel_range_mps2), q)};
         },
         true, 0.1, 1.0},
    };
    std::vector<double> heights;
    std::vector<LegData> legs;
    for (size_t i = 0; i < trials.size(); ++i) {
        const IpolTrial& t = trials[i];
        heights.push_back(std::isfinite(t.run.height_m) ? t.run.height_m : default_height_m);
        // The steps cover the waist's path over the leg, a little longer than
        // its chord (the pelvis' yaw swing): the foot's chord times the ratio.
        legs.push_back({i, &t.run.out_steps, t.foot.out_m * t.run.out_path_ratio});
        legs.push_back({i, &t.run.back_steps, t.foot.back_m * t.run.back_path_ratio});
    }
    const auto legs_where = [&](const std::function<bool(const IpolTrial&)>& keep) {
        std::vector<LegData> out;
        for (const LegData& l : legs)
            if (keep(trials[l.trial])) out.push_back(l);
        return out;
    };
    std::vector<StepModelScores> scores;
    for (const Model& m : models) {
        StepModelScores s;
        s.name = m.name;
        std::map<std::string, Fit> without, own;
        for (const IpolTrial& t : trials) {
            if (without.count(t.subject)) continue;
            without[t.subject] =
                fit(m, legs_where([&](const IpolTrial& o) { return o.subject != t.subject; }), heights);
            own[t.subject] =
                fit(m, legs_where([&](const IpolTrial& o) { return o.subject == t.subject; }), heights);
            s.constant_by_subject[t.subject] = own[t.subject].c.front();
        }
        for (const LegData& l : legs) {
            const IpolTrial& t = trials[l.trial];
            s.loso_error_pct.push_back(error_pct(m, without.at(t.subject), l, heights[l.trial]));
            s.own_error_pct.push_back(error_pct(m, own.at(t.subject), l, heights[l.trial]));
            const std::vector<LegData> other =
                legs_where([&](const IpolTrial& o) { return o.subject == t.subject && o.trial != t.trial; });
            if (!other.empty())
                s.other_trial_error_pct.push_back(error_pct(m, fit(m, other, heights), l, heights[l.trial]));
        }
        scores.push_back(s);
    }
    return scores;
}

}  // namespace pednav::waist_eval
