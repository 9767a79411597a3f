// SPDX-License-Identifier: Apache-2.0
// senslogs two-file Android logs (humolire-phone): accelerometer-*.txt and
// gyroscope-*.txt side by side. Six header lines (the file's own name, a blank,
// the unit sentence, a link, a blank, the column names), then space-separated
// "elapsed-time-system elapsed-time-sensor x y z". Time: elapsed-time-sensor
// (s since the recording started). The gyroscope is interpolated at the
// accelerometer times. Axes: see android_axes.hpp.
#include "android_axes.hpp"
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

constexpr const char* kColumns = "elapsed-time-system elapsed-time-sensor x y z";

size_t header_index(const TextFile& file) {
    const size_t limit = std::min<size_t>(file.lines.size(), 10);
    for (size_t i = 0; i < limit; ++i) {
        if (trim(file.lines[i]) == kColumns) return i;
    }
    return std::string::npos;
}

std::string base_name(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string dir_name(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

// Replaces the first `from` in the file name by `to`.
std::string sibling(const std::string& path, const std::string& from, const std::string& to) {
    std::string name = base_name(path);
    const size_t at = name.find(from);
    if (at == std::string::npos) return "";
    name.replace(at, from.size(), to);
    return dir_name(path) + "/" + name;
}

// One of the two files, read a line at a time.
struct Source {
    Source(InputFile& file, bool is_accel)
        : input(file), accel(is_accel), name(base_name(file.path())), clock(name),
          lines(file, header_or_throw(file) + 1) {}
    static size_t header_or_throw(const InputFile& file) {
        const size_t header = header_index(file.head());
        if (header == std::string::npos) throw ReadError(file.path(), 0, "no 'elapsed-time-system ...' header line");
        return header;
    }
    InputFile& input;
    bool accel;
    std::string name;
    Clock clock;
    LineCursor lines;
    bool ended = false;
};

// The two files side by side: the accelerometer's read on while its samples
// can be paired, the gyroscope's when the next one is needed. Each file's
// issues are listed together (issue channel 0 and 1), as when they were read
// one after the other.
class HumolireReader : public RowReader {
public:
    HumolireReader(InputFile& given, std::unique_ptr<InputFile> other, bool given_accel, LogBuilder& builder,
                   SensorLog& log)
        : other_(std::move(other)),
          accel_(given_accel ? given : *other_, true),
          gyro_(given_accel ? *other_ : given, false),
          builder_(builder),
          log_(log) {}

    bool read_lines(size_t lines) override {
        for (size_t n = 0; n < lines; ++n) {
            Source* next = nullptr;
            if (!accel_.ended && (!builder_.pairing_waits() || gyro_.ended))
                next = &accel_;
            else if (!gyro_.ended)
                next = &gyro_;
            else if (!accel_.ended)
                next = &accel_;
            if (next == nullptr) return end();
            read_line(*next);
        }
        return true;
    }
    uint64_t record_types() const override { return PN_REC_MASK(PN_REC_IMU); }
    uint64_t bytes_read() const override {
        return accel_.input.rest().bytes_read() + gyro_.input.rest().bytes_read();
    }
    uint64_t bytes_total() const override {
        return accel_.input.rest().size_bytes() + gyro_.input.rest().size_bytes();
    }

private:
    void read_line(Source& src) {
        builder_.set_context(src.name);
        builder_.set_channel(src.accel ? 0 : 1);
        std::string_view raw;
        size_t line_no = 0;
        if (!src.lines.next(&raw, &line_no)) {
            src.ended = true;
            builder_.end_of(src.accel ? stream_accel : stream_gyro);
        } else {
            read_row(src, raw, line_no);
        }
        builder_.set_context("");
        builder_.set_channel(0);
    }

    void read_row(Source& src, std::string_view raw, size_t line_no) {
        const unsigned bits = stream_bit(src.accel ? stream_accel : stream_gyro);
        const std::string_view line = trim(raw);
        if (line.empty()) return;
        split_into(line, ' ', fields_);
        if (fields_.size() != 5) {
            builder_.bad_row(line_no, fields_.size() < 5 ? "truncated row" : "too many fields", bits);
            return;
        }
        static const char* const columns[5] = {"elapsed-time-system", "elapsed-time-sensor", "x", "y", "z"};
        double v[5];
        for (int k = 0; k < 5; ++k) {
            const NumberStatus status = parse_number(fields_[static_cast<size_t>(k)], &v[k]);
            if (status != NumberStatus::ok) {
                builder_.bad_row(line_no, describe_bad_number(status, fields_[static_cast<size_t>(k)], columns[k]),
                                 bits);
                return;
            }
        }
        if (!builder_.accept_time(src.clock, line_no, v[1], bits)) return;
        double body[3];
        android_to_flu(&v[2], body);
        if (src.accel) {
            builder_.add_accel(line_no, v[1], body);
        } else {
            builder_.add_gyro(line_no, v[1], body);
        }
    }

    bool end() {
        if (!ended_) {
            ended_ = true;
            log_.axes = kAndroidAxesText;
            builder_.note("two files: " + accel_.input.path() + " and " + gyro_.input.path() +
                          "; time from elapsed-time-sensor");
        }
        return false;
    }

    std::unique_ptr<InputFile> other_;
    Source accel_, gyro_;
    LogBuilder& builder_;
    SensorLog& log_;
    std::vector<std::string_view> fields_;
    bool ended_ = false;
};

}  // namespace

bool detect_humolire(const TextFile& file) {
    if (header_index(file) == std::string::npos || file.lines.empty()) return false;
    const std::string first = to_lower(trim(file.lines[0]));
    return starts_with(first, "accelerometer") || starts_with(first, "gyroscope");
}

std::unique_ptr<RowReader> open_humolire(InputFile& input, const ReadOptions&, LogBuilder& builder,
                                         SensorLog& log) {
    const TextFile& file = input.head();
    const std::string first = to_lower(trim(file.lines[0]));
    const bool given_accel = starts_with(first, "accelerometer");
    const std::string other_path = given_accel ? sibling(file.path, "accelerometer", "gyroscope")
                                               : sibling(file.path, "gyroscope", "accelerometer");
    if (other_path.empty()) {
        throw ReadError(file.path, 0,
                        "two-file recording: cannot derive the name of the other file (expected the words "
                        "'accelerometer' and 'gyroscope' in the file names)");
    }
    std::unique_ptr<InputFile> other;
    try {
        other = std::make_unique<InputFile>(other_path);
    } catch (const ReadError& e) {
        throw ReadError(file.path, 0,
                        std::string("two-file recording: the ") +
                            (given_accel ? "gyroscope" : "accelerometer") + " file " + other_path + ": " +
                            e.reason());
    }
    const TextFile& accel_file = given_accel ? file : other->head();
    const TextFile& gyro_file = given_accel ? other->head() : file;
    // The unit sentence of each file (line 3) must say what the engine assumes.
    const std::string accel_units = accel_file.lines.size() > 2 ? std::string(trim(accel_file.lines[2])) : "";
    const std::string gyro_units = gyro_file.lines.size() > 2 ? std::string(trim(gyro_file.lines[2])) : "";
    if (accel_units.find("m/s^2") == std::string::npos) {
        builder.issue(3, base_name(accel_file.path) + ": unit line does not say m/s^2 ('" + accel_units +
                             "'); read as m/s^2");
    }
    if (gyro_units.find("radians/second") == std::string::npos &&
        gyro_units.find("rad/s") == std::string::npos) {
        builder.issue(3, base_name(gyro_file.path) + ": unit line does not say radians/second ('" +
                             gyro_units + "'); read as rad/s");
    }
    builder.set_units(stream_accel, "m/s^2", "m/s^2");
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    return std::make_unique<HumolireReader>(input, std::move(other), given_accel, builder, log);
}

}  // namespace pednav::io::detail
