// SPDX-License-Identifier: Apache-2.0
#include "run_outputs.hpp"

namespace pednav::cli {

void RunOutputs::on_output(const pn_output_t& o) {
    switch (o.header.type) {
        case PN_REC_POSITION:
            totals_.add(o.position);
            if (!plan_.track_csv.empty()) {
                if (!track_) track_ = std::make_unique<io::TrackCsvWriter>(plan_.track_csv);
                track_->add(o.position);
            }
            if (!plan_.geo_csv.empty() && plan_.geo_origin.known) {
                if (!geo_) geo_ = std::make_unique<io::GeoTrackCsvWriter>(plan_.geo_csv, plan_.geo_origin);
                geo_->add(o.position);
            }
            if (plan_.log_positions) position_log_.add(o.position);
            if (plan_.keep_positions) positions_.push_back(o.position);
            break;
        case PN_REC_STRIDE:
            totals_.add(o.stride);
            if (!plan_.steps_csv.empty()) {
                if (!steps_csv_) steps_csv_ = std::make_unique<io::StepsCsvWriter>(plan_.steps_csv);
                steps_csv_->add(o.stride);
            }
            if (plan_.keep_strides) strides_.push_back(o.stride);
            break;
        case PN_REC_STEP: ++steps_; break;
        default: break;
    }
}

void RunOutputs::on_polled() {
    if (track_) track_->flush();
    if (steps_csv_) steps_csv_->flush();
    if (geo_) geo_->flush();
}

void RunOutputs::close(bool create_unwritten) {
    if (create_unwritten) {
        if (!track_ && !plan_.track_csv.empty())
            track_ = std::make_unique<io::TrackCsvWriter>(plan_.track_csv);
        if (!steps_csv_ && !plan_.steps_csv.empty())
            steps_csv_ = std::make_unique<io::StepsCsvWriter>(plan_.steps_csv);
        if (!geo_ && !plan_.geo_csv.empty() && plan_.geo_origin.known)
            geo_ = std::make_unique<io::GeoTrackCsvWriter>(plan_.geo_csv, plan_.geo_origin);
    }
    if (track_) track_->close();
    if (steps_csv_) steps_csv_->close();
    if (geo_) geo_->close();
    track_.reset();
    steps_csv_.reset();
    geo_.reset();
}

}  // namespace pednav::cli
