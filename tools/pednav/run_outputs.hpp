// SPDX-License-Identifier: Apache-2.0
// `pednav run`'s outputs as the engine gives them: the track, steps and
// geo-track CSVs written a row at a time and flushed after every poll (a run
// that stops or crashes keeps what it computed), the totals of the summary,
// and what the outputs written at the end need: the positions for GeoJSON,
// GPX and a late geo CSV in a PositionLog (on disk past a few thousand), and
// in memory for the plot.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pednav_engine/replay.hpp>
#include <pednav_io/origin.hpp>
#include <pednav_io/writers.hpp>

namespace pednav::cli {

struct RunOutputPlan {
    std::string track_csv, steps_csv, geo_csv;  // "" = not asked for
    io::Origin geo_origin;                      // --geo-csv is written as the run goes when this is known
    bool log_positions = false;                 // for GeoJSON, GPX, a geo CSV written at the end
    bool keep_positions = false;                // in memory, for the plot
    bool keep_strides = false;
};

class RunOutputs : public OutputHandler {
public:
    explicit RunOutputs(RunOutputPlan plan) : plan_(std::move(plan)) {}
    void on_output(const pn_output_t& output) override;
    void on_polled() override;
    // Closes the CSVs written as the run went; with create_unwritten, a CSV
    // that got no row is written with its header (a run with no output).
    void close(bool create_unwritten);

    const io::RunTotals& totals() const { return totals_; }
    size_t steps() const { return steps_; }
    const io::PositionLog& position_log() const { return position_log_; }
    std::vector<pn_position_t>& positions() { return positions_; }
    std::vector<pn_stride_t>& strides() { return strides_; }

private:
    RunOutputPlan plan_;
    std::unique_ptr<io::TrackCsvWriter> track_;
    std::unique_ptr<io::StepsCsvWriter> steps_csv_;
    std::unique_ptr<io::GeoTrackCsvWriter> geo_;
    io::RunTotals totals_;
    size_t steps_ = 0;
    io::PositionLog position_log_;
    std::vector<pn_position_t> positions_;
    std::vector<pn_stride_t> strides_;
};

}  // namespace pednav::cli
