// SPDX-License-Identifier: Apache-2.0
// Position filters of an upper-body sensor, one position per step:
//  - step vector: the displacement of a step as K times the double integral
//    of the world-frame horizontal acceleration over it
//    (chest-imu-particle-filter-map-matching eq. 1, K negative, ERRATA.md);
//  - step model: a step length from the acceleration range of the step,
//    L = k (a_max - a_min)^(1/b) + beta (Weinberg for b = 4, beta = 0),
//    along the walking heading.
// Both take the height and the floor from the barometer (step_filter_base.hpp).
#include <cmath>

#include <pednav_pdr/step_length_model.hpp>
#include <pednav_pdr/step_vector.hpp>

#include "step_filter_base.hpp"

namespace {
using namespace pednav::sdk;
using pednav::plugins::StepFilterBase;

class StepVector : public StepFilterBase {
public:
    static constexpr const char* kId = "org.pednav.pdr.step_vector";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:chest", "mount:handheld", "needs:step",
                                                      "needs:attitude", "uses:baro", nullptr};
    static constexpr const char* kName = "step vector (double-integrated acceleration)";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "per step D = K x the double integral of the world-frame horizontal acceleration (chest-imu-particle-"
        "filter-map-matching eq. 1, K negative per ERRATA.md): direction from the acceleration, so the walker "
        "may face away from the sensor; barometric height and floor";
    static constexpr char kSchemaHead[] = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "step_vector_k": {"type": "number", "minimum": -20, "maximum": 20, "default": -4.0,
      "description": "K of eq. (1): the displacement per metre of double-integrated acceleration; negative (the integral points backwards), per user (pednav calibrate)"},
    "remove_mean_accel": {"type": "boolean", "default": false,
      "description": "subtract the step's mean horizontal acceleration before integrating (takes out gravity leaked by a tilt error, but also the mean deceleration of the step that eq. (1) measures); false = eq. (1) as printed"},
    )json";
    static constexpr char kSchemaTail[] = R"json(
  }
})json";
    static constexpr auto kSchema = pednav::plugins::join_schema(kSchemaHead, kSchemaTail);
    static constexpr const char* kParamsSchema = kSchema.text;

    StepVector(Params& p, const CreateContext&)
        : StepFilterBase(p, true), k_(p.number("step_vector_k")), remove_mean_(p.boolean("remove_mean_accel")) {}

private:
    bool remove_mean_accel() const override { return remove_mean_; }
    bool step_displacement(const pn_step_t&, double, const pednav::pdr::PlaneVector& d, double psi, double& east_m,
                           double& north_m) override {
        // K times the integral, turned from the attitude's frame to the start-aligned one (clockwise).
        const double c = std::cos(psi), s = std::sin(psi);
        const double e = k_ * d.east_m, n = k_ * d.north_m;
        east_m = e * c + n * s;
        north_m = -e * s + n * c;
        return true;
    }

    double k_;
    bool remove_mean_;
};

class StepModel : public StepFilterBase {
public:
    static constexpr const char* kId = "org.pednav.pdr.step_model";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:chest", "mount:handheld", "needs:step",
                                                      "needs:attitude", "uses:baro", nullptr};
    static constexpr const char* kName = "step model (length from the acceleration range, walking heading)";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "per step L = k (a_max - a_min)^(1/b) + beta (Weinberg for b = 4, beta = 0; waist-imu-gps-ins-integration "
        "eq. 3.1 as corrected), a height-based k for a user never calibrated, along the walking heading (a body "
        "axis of the attitude plus an offset); barometric height and floor";
    static constexpr char kSchemaHead[] = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "step_model_k": {"type": "number", "x-unit": "m/(m/s^2)^(1/b)", "minimum": 0, "maximum": 10, "default": 0,
      "description": "k of the model, per user (pednav calibrate); 0 = from user_height_m"},
    "step_model_b": {"type": "number", "minimum": 0.5, "maximum": 10, "default": 4,
      "description": "the root b (Weinberg: 4)"},
    "step_model_beta_m": {"type": "number", "x-unit": "m", "minimum": -1, "maximum": 2, "default": 0,
      "description": "the offset beta"},
    "user_height_m": {"type": "number", "x-unit": "m", "minimum": 0.5, "maximum": 2.5, "default": 1.75,
      "description": "with step_model_k = 0: k such that a step of step_model_typical_range_mps2 is 0.415 x this"},
    "step_model_typical_range_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0.1, "maximum": 50, "default": 4,
      "description": "with step_model_k = 0: the acceleration range of a step at normal walking speed"},
    "stairs_step_length_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 1, "default": 0.3,
      "description": "horizontal length of a step the detector marks up or down stairs (the stairs' run); 0 = the model's"},
    )json";
    static constexpr char kSchemaTail[] = R"json(
  }
})json";
    static constexpr auto kSchema = pednav::plugins::join_schema(kSchemaHead, kSchemaTail);
    static constexpr const char* kParamsSchema = kSchema.text;

    StepModel(Params& p, const CreateContext&)
        : StepFilterBase(p, false), model_(model(p)), stairs_length_m_(p.number("stairs_step_length_m")) {}

private:
    static pednav::pdr::StepLengthModel model(Params& p) {
        const double k = p.number("step_model_k"), b = p.number("step_model_b"), beta = p.number("step_model_beta_m");
        const double height = p.number("user_height_m"), range = p.number("step_model_typical_range_mps2");
        if (k > 0) return {k, b, beta};
        pednav::pdr::StepLengthModel m = pednav::pdr::step_length_model_for_height(height, 0.415, range, b);
        m.beta_m = beta;
        return m;
    }
    bool step_displacement(const pn_step_t& step, double heading, const pednav::pdr::PlaneVector&, double,
                           double& east_m, double& north_m) override {
        const bool stairs = step.motion_mode == PN_STEP_MODE_UPSTAIRS || step.motion_mode == PN_STEP_MODE_DOWNSTAIRS;
        const double length = stairs && stairs_length_m_ > 0
                                  ? stairs_length_m_
                                  : pednav::pdr::step_length_m(model_, step.accel_max_mps2 - step.accel_min_mps2);
        east_m = length * std::sin(heading);
        north_m = length * std::cos(heading);
        return length > 0;
    }

    pednav::pdr::StepLengthModel model_;
    double stairs_length_m_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.pdr.position", "1.0.0", StepVector, StepModel)
