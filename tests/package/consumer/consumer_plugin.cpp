// SPDX-License-Identifier: Apache-2.0
// A third-party step detector: a STEP every `every_n` IMU samples.
#include <pednav_sdk/library.hpp>

namespace {

class EveryNSteps : public pednav::sdk::StepDetector {
public:
    static constexpr const char* kId = "com.example.consumer.every_n";
    static constexpr const char* kName = "every N";
    static constexpr const char* kVersion = "0.1.0";
    static constexpr const char* kDescription = "package test: a step every N samples";
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_STEP);

    EveryNSteps(pednav::sdk::Params& p, const pednav::sdk::CreateContext&)
        : every_n_(p.integer("every_n", 5, 1, 1000)) {}
    void on_imu(const pn_imu_t& imu) override {
        if (++n_ % every_n_ == 0) emit(pednav::sdk::make_record<pn_step_t>(imu.header.t_ns));
    }

private:
    long every_n_;
    long n_ = 0;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("com.example.consumer", "0.1.0", EveryNSteps)
