// SPDX-License-Identifier: Apache-2.0
// A format whose reading needs the whole file before its first record (IPIN:
// each sensor clock is placed on the app clock by its smallest delay over the
// file) is read whole at the first read_lines, as before streaming.
#include "formats.hpp"

namespace pednav::io::detail {

namespace {

class WholeFileReader : public RowReader {
public:
    WholeFileReader(InputFile& input, const ReadOptions& options, LogBuilder& builder, SensorLog& log,
                    WholeFileRead read)
        : input_(input), options_(options), builder_(builder), log_(log), read_(read) {}

    bool read_lines(size_t) override {
        if (done_) return false;
        done_ = true;
        const TextFile file = input_.read_all();
        read_(file, options_, builder_, log_);
        return false;
    }
    uint64_t record_types() const override {
        return PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG) | PN_REC_MASK(PN_REC_BARO) |
               PN_REC_MASK(PN_REC_GNSS);
    }
    bool whole_file() const override { return true; }
    uint64_t bytes_read() const override { return input_.rest().bytes_read(); }
    uint64_t bytes_total() const override { return input_.rest().size_bytes(); }

private:
    InputFile& input_;
    const ReadOptions& options_;
    LogBuilder& builder_;
    SensorLog& log_;
    WholeFileRead read_;
    bool done_ = false;
};

}  // namespace

std::unique_ptr<RowReader> open_whole_file(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                           SensorLog& log, WholeFileRead read) {
    return std::make_unique<WholeFileReader>(input, options, builder, log, read);
}

}  // namespace pednav::io::detail
