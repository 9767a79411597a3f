// SPDX-License-Identifier: Apache-2.0
// RecordStream, and read_sensor_file and scan_sensor_file on top of it.
#include "pednav_io/record_stream.hpp"

#include <exception>

#include "formats.hpp"
#include "record_merger.hpp"

namespace pednav::io {

namespace {

// Lines read between two looks at the records ready.
constexpr size_t kLinesPerStep = 256;
constexpr size_t kBlockRecords = 4096;

}  // namespace

struct RecordStream::Impl {
    Impl(const std::string& path, const ReadOptions& read_options, size_t window)
        : options(read_options), merger(window), builder(log, options, &merger) {
        input = std::make_unique<detail::InputFile>(detail::resolve_recording_path(path));
        const detail::FormatReader& reader = detail::choose_reader(path, input->head(), options);
        log.format = reader.name;
        log.path = path;
        builder.note(std::string("format: ") + reader.name + " (" + reader.description + ")" +
                     (options.format == "auto" || options.format.empty() ? ", detected" : ", as requested"));
        rows = reader.open(*input, options, builder, log);
        if (rows->whole_file()) merger.set_window(0);
        const uint64_t types = rows->record_types();
        for (pn_record_type_t t : {PN_REC_IMU, PN_REC_MAG, PN_REC_BARO, PN_REC_GNSS})
            merger.set_open(t, (types & PN_REC_MASK(t)) != 0);
    }

    // Reads lines until records are ready or the input ends; false at the end of everything.
    bool step() {
        if (!input_ended) {
            if (!rows->read_lines(kLinesPerStep)) input_ended = true;
            return true;
        }
        if (finished) return false;
        finished = true;
        builder.finish();
        if (!log.axes.empty()) log.notes.push_back("body axes: " + log.axes);
        merger.close_all();
        return true;
    }

    ReadOptions options;
    SensorLog log;
    detail::RecordMerger merger;
    detail::LogBuilder builder;
    std::unique_ptr<detail::InputFile> input;
    std::unique_ptr<detail::RowReader> rows;
    bool input_ended = false;
    bool finished = false;
    std::exception_ptr error;  // the input went bad: given once the records before it are out
    bool failed = false;       // the error has been given
};

RecordStream::RecordStream(const std::string& path, const ReadOptions& options, size_t merge_window_records)
    : impl_(std::make_unique<Impl>(path, options, merge_window_records)) {}

RecordStream::~RecordStream() = default;

size_t RecordStream::read(std::vector<InputRecord>& out, size_t max_records) {
    Impl& s = *impl_;
    size_t given = 0;
    if (!s.error) {
        try {
            while (given < max_records) {
                given += s.merger.release(out, max_records - given);
                if (given == max_records || !s.step()) break;
            }
        } catch (const ReadError&) {
            // The records read before the bad part are handed out first, then the error.
            s.error = std::current_exception();
            s.merger.close_all();
        }
    }
    if (s.error) {
        given += s.merger.release(out, max_records - given);
        if (given == 0 && !s.failed) {
            s.failed = true;
            std::rethrow_exception(s.error);
        }
    }
    return given;
}

bool RecordStream::done() const {
    return impl_->failed || (impl_->finished && impl_->merger.queued() == 0);
}

const SensorLog& RecordStream::log() const { return impl_->log; }

bool RecordStream::first_imu_t_ns(int64_t* t_ns) {
    Impl& s = *impl_;
    try {
        while (!s.builder.has_imu() && !s.input_ended && !s.error) {
            if (!s.rows->read_lines(kLinesPerStep)) s.input_ended = true;
        }
    } catch (const ReadError&) {
        s.error = std::current_exception();  // given by read(), after the records before it
        s.merger.close_all();
    }
    if (!s.builder.has_imu()) return false;
    *t_ns = s.log.records.imu_first_t_ns;
    return true;
}

uint64_t RecordStream::bytes_read() const { return impl_->rows->bytes_read(); }
uint64_t RecordStream::bytes_total() const { return impl_->rows->bytes_total(); }

SensorLog read_sensor_file(const std::string& path, const ReadOptions& options) {
    RecordStream stream(path, options, 0);
    std::vector<pn_imu_t> imu;
    std::vector<pn_mag_t> mag;
    std::vector<pn_baro_t> baro;
    std::vector<pn_gnss_t> gnss;
    std::vector<InputRecord> block;
    while (stream.read(block, kBlockRecords) > 0) {
        for (const InputRecord& r : block) {
            switch (r.header.type) {
                case PN_REC_IMU: imu.push_back(r.imu); break;
                case PN_REC_MAG: mag.push_back(r.mag); break;
                case PN_REC_BARO: baro.push_back(r.baro); break;
                default: gnss.push_back(r.gnss); break;
            }
        }
        block.clear();
    }
    SensorLog log = stream.log();
    log.imu = std::move(imu);
    log.mag = std::move(mag);
    log.baro = std::move(baro);
    log.gnss = std::move(gnss);
    return log;
}

SensorLog scan_sensor_file(const std::string& path, const ReadOptions& options) {
    RecordStream stream(path, options);
    std::vector<pn_gnss_t> gnss;
    std::vector<InputRecord> block;
    while (stream.read(block, kBlockRecords) > 0) {
        for (const InputRecord& r : block)
            if (r.header.type == PN_REC_GNSS) gnss.push_back(r.gnss);
        block.clear();
    }
    SensorLog log = stream.log();
    log.gnss = std::move(gnss);
    return log;
}

}  // namespace pednav::io
