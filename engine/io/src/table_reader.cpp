// SPDX-License-Identifier: Apache-2.0
#include "table_reader.hpp"

#include "column_checks.hpp"

#include <cmath>
#include <cstdio>

namespace pednav::io::detail {

void set_identity(double R[9]) {
    for (int i = 0; i < 9; ++i) R[i] = (i % 4 == 0) ? 1.0 : 0.0;
}

void set_signed_permutation(double R[9], const int src[3], const double sign[3]) {
    for (int i = 0; i < 9; ++i) R[i] = 0.0;
    for (int i = 0; i < 3; ++i) R[i * 3 + src[i]] = sign[i];
}

namespace {

enum class CellResult { ok, absent, bad };

struct RowContext {
    const TableSpec& spec;
    const std::vector<std::string_view>& fields;
    std::string error;
};

// Empty cells make the sample absent in sparse multi-rate tables, and always
// for the streams a row may lack (magnetometer, pressure: `optional`).
CellResult parse_vec(RowContext& ctx, const Vec3Spec& v, double out[3], bool optional = false,
                     double* scaled = nullptr) {
    double in[3];
    int empty = 0;
    NumberStatus status[3];
    for (int i = 0; i < 3; ++i) {
        status[i] = parse_number(ctx.fields[static_cast<size_t>(v.col[i])], &in[i]);
        if (status[i] == NumberStatus::empty) ++empty;
    }
    if ((optional || ctx.spec.empty_cells_mean_absent) && empty == 3) return CellResult::absent;
    for (int i = 0; i < 3; ++i) {
        if (status[i] != NumberStatus::ok) {
            const auto c = static_cast<size_t>(v.col[i]);
            ctx.error = describe_bad_number(status[i], ctx.fields[c], ctx.spec.names[c]);
            return CellResult::bad;
        }
    }
    if (scaled != nullptr) {
        for (int i = 0; i < 3; ++i) scaled[i] = v.scale * in[i];
    }
    for (int r = 0; r < 3; ++r) {
        out[r] = v.scale * (v.R[r * 3 + 0] * in[0] + v.R[r * 3 + 1] * in[1] + v.R[r * 3 + 2] * in[2]);
    }
    return CellResult::ok;
}

CellResult parse_scalar(RowContext& ctx, int col, double* out, bool optional = false) {
    const auto c = static_cast<size_t>(col);
    const NumberStatus status = parse_number(ctx.fields[c], out);
    if (status == NumberStatus::empty && (optional || ctx.spec.empty_cells_mean_absent)) return CellResult::absent;
    if (status != NumberStatus::ok) {
        ctx.error = describe_bad_number(status, ctx.fields[c], ctx.spec.names[c]);
        return CellResult::bad;
    }
    return CellResult::ok;
}

bool is_comment(const TableSpec& spec, std::string_view line) {
    for (const auto& prefix : spec.comment_prefixes) {
        if (starts_with(line, prefix)) return true;
    }
    return false;
}

}  // namespace

namespace {

// Every column the spec reads lies within the header: a reader forced onto a
// file it does not fit must fail here rather than index fields[-1].
void check_columns(const std::string& path, const TableSpec& spec) {
    const size_t header_line = spec.first_data_index;  // 1-based number of the header line
    if (spec.time_col < 0) throw ReadError(path, header_line, "no time column in the header");
    std::vector<int> cols = {spec.time_col, spec.pressure_col, spec.temperature_col};
    for (const Vec3Spec* v : {&spec.accel, &spec.gyro, &spec.mag})
        cols.insert(cols.end(), v->col, v->col + 3);
    cols.insert(cols.end(), spec.valid_cols.begin(), spec.valid_cols.end());
    for (int c : cols) {
        if (c >= static_cast<int>(spec.column_count) || c >= static_cast<int>(spec.names.size()))
            throw ReadError(path, header_line, "the header has " + std::to_string(spec.column_count) +
                                                   " columns, the format needs column " + std::to_string(c + 1));
    }
}

// A time column in seconds holding a Unix time in ms, us or ns (phone apps):
// the scale that makes it seconds, judged from its first value; 1 otherwise.
// Unix seconds are ~1.7e9, so a value above 1e11 s (3 000 years) is no time in s.
double epoch_scale(double first_time, const char** unit) {
    const double v = std::fabs(first_time);
    if (v >= 1e17) return *unit = "nanoseconds", 1e-9;
    if (v >= 1e14) return *unit = "microseconds", 1e-6;
    if (v >= 1e11) return *unit = "milliseconds", 1e-3;
    return 1.0;
}

}  // namespace

TableReader::TableReader(InputFile& input, const TableSpec& spec, LogBuilder& builder)
    : input_(input), lines_(input, spec.first_data_index), spec_(spec), builder_(builder),
      time_scale_settled_(!spec.time_unit_from_magnitude) {
    check_columns(input.path(), spec_);
    if (spec_.accel.present()) present_ |= kImuBits;
    if (spec_.mag.present()) present_ |= stream_bit(stream_mag);
    if (spec_.pressure_col >= 0) present_ |= stream_bit(stream_pressure);
    if (spec_.accel.present() && spec_.gyro.present()) {
        for (int i = 0; i < 3; ++i)
            checks_.emplace_back(spec_.names[static_cast<size_t>(spec_.accel.col[i])], "m/s^2", 1000.0,
                                 2.0 * kStandardGravity);
        for (int i = 0; i < 3; ++i)
            checks_.emplace_back(spec_.names[static_cast<size_t>(spec_.gyro.col[i])], "rad/s", 50.0, 2.0);
    }
    last_line_ = spec_.first_data_index;
}

uint64_t TableReader::record_types() const {
    uint64_t types = 0;
    if (present_ & kImuBits) types |= PN_REC_MASK(PN_REC_IMU);
    if (present_ & stream_bit(stream_mag)) types |= PN_REC_MASK(PN_REC_MAG);
    if (present_ & stream_bit(stream_pressure)) types |= PN_REC_MASK(PN_REC_BARO);
    return types;
}

bool TableReader::read_lines(size_t lines) {
    if (ended_) return false;
    std::string_view line;
    size_t line_no = 0;
    for (size_t n = 0; n < lines; ++n) {
        if (!lines_.next(&line, &line_no)) {
            end();
            return false;
        }
        last_line_ = line_no;
        read_row(line, line_no, lines_.line_cut());
    }
    return true;
}

void TableReader::end() {
    ended_ = true;
    for (const auto& c : checks_) c.report(builder_);
    if (truncated_line_ > 0 && truncated_line_ == last_line_)
        builder_.note("the last line is incomplete (file cut off while writing?)");
}

void TableReader::read_row(std::string_view raw, size_t line_no, bool cut) {
    const TableSpec& spec = spec_;
    const std::string_view line = trim(raw);
    if (line.empty() || is_comment(spec, line)) return;
    if (cut) {
        builder_.bad_row(line_no,
                         "line longer than " + std::to_string(LineReader::kMaxLineBytes >> 20) + " MiB",
                         present_);
        return;
    }
    // Split the untrimmed line: the trailing empty cell of a tab-separated
    // row is a field (split_into trims each field). One delimiter more
    // than the header has, ending the row, closes it instead: headers
    // are read trimmed, so a trailing tab never makes a column there.
    std::vector<std::string_view>& fields = fields_;
    split_into(raw, spec.delim, fields);
    if (fields.size() == spec.column_count + 1 && fields.back().empty()) fields.pop_back();
    if (fields.size() != spec.column_count) {
        char text[160];
        std::snprintf(text, sizeof text, "%s: %zu fields, the header has %zu",
                      fields.size() < spec.column_count ? "truncated row" : "too many fields", fields.size(),
                      spec.column_count);
        builder_.bad_row(line_no, text, present_);
        truncated_line_ = line_no;
        return;
    }
    RowContext ctx{spec, fields, {}};

    double raw_time = 0.0;
    if (parse_scalar(ctx, spec.time_col, &raw_time) != CellResult::ok) {
        builder_.bad_row(line_no, ctx.error.empty() ? "no time" : ctx.error, present_);
        return;
    }
    if (!time_scale_settled_) {
        time_scale_settled_ = true;
        const char* unit = "";
        spec_.time_scale = epoch_scale(raw_time, &unit);
        if (spec.time_scale != 1.0) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "time column %s: the first value %.6g (line %zu) is a Unix time in %s, not "
                          "seconds: read as %s",
                          spec.names[static_cast<size_t>(spec.time_col)].c_str(), raw_time, line_no, unit, unit);
            builder_.issue(line_no, text);
        }
    }
    for (int c : spec.valid_cols) {
        double flag = 0.0;
        if (parse_number(fields[static_cast<size_t>(c)], &flag) != NumberStatus::ok || flag != 1.0) {
            builder_.bad_row(line_no,
                             "sample flagged invalid by the sensor (" + spec.names[static_cast<size_t>(c)] + ")",
                             present_);
            return;
        }
    }

    double a[3] = {0, 0, 0}, g[3] = {0, 0, 0}, m[3] = {0, 0, 0}, p = 0.0, temp = NAN;
    double cells[6] = {0, 0, 0, 0, 0, 0};
    bool has_imu = false, has_mag = false, has_p = false;
    if (spec.accel.present()) {
        const CellResult ra = parse_vec(ctx, spec.accel, a, false, cells);
        const CellResult rg =
            ra == CellResult::bad ? CellResult::bad : parse_vec(ctx, spec.gyro, g, false, cells + 3);
        if (ra == CellResult::bad || rg == CellResult::bad) {
            builder_.bad_row(line_no, ctx.error, present_);
            return;
        }
        if (ra != rg) {
            builder_.bad_row(line_no, "accelerometer and gyroscope cells must be both present or both empty",
                             present_);
            return;
        }
        has_imu = ra == CellResult::ok;
    }
    if (spec.mag.present()) {
        const CellResult rm = parse_vec(ctx, spec.mag, m, true);
        if (rm == CellResult::bad) builder_.bad_row(line_no, "magnetometer sample: " + ctx.error, stream_bit(stream_mag));
        has_mag = rm == CellResult::ok;
    }
    if (spec.pressure_col >= 0) {
        const CellResult rp = parse_scalar(ctx, spec.pressure_col, &p, true);
        if (rp == CellResult::bad)
            builder_.bad_row(line_no, "pressure sample: " + ctx.error, stream_bit(stream_pressure));
        has_p = rp == CellResult::ok;
        p *= spec.pressure_scale;
        if (has_p && spec.temperature_col >= 0) {
            double tc = 0.0;
            if (parse_number(fields[static_cast<size_t>(spec.temperature_col)], &tc) == NumberStatus::ok) temp = tc;
        }
    }
    if (!has_imu && !has_mag && !has_p) return;

    // Raw counters and tick clocks wrap; unwrap when the value drops by more than half the wrap.
    if (spec.counter_wrap > 0 && have_raw_time_ && raw_time + wrap_offset_ < last_raw_time_ - spec.counter_wrap / 2) {
        wrap_offset_ += spec.counter_wrap;
    }
    const double unwrapped = raw_time + wrap_offset_;
    const double t_s = spec.time_kind == TableSpec::TimeKind::counter ? unwrapped / spec.counter_rate_hz
                                                                      : unwrapped * spec.time_scale;
    if (spec.empty_cells_mean_absent) {
        // Sparse multi-rate rows: each stream keeps its own time order.
        if (has_imu) has_imu = builder_.accept_time(imu_clock_, line_no, t_s, kImuBits);
        if (has_mag) has_mag = builder_.accept_time(mag_clock_, line_no, t_s, stream_bit(stream_mag));
        if (has_p) has_p = builder_.accept_time(pressure_clock_, line_no, t_s, stream_bit(stream_pressure));
        if (!has_imu && !has_mag && !has_p) return;
    } else {
        const unsigned row_streams = (has_imu ? kImuBits : 0u) | (has_mag ? stream_bit(stream_mag) : 0u) |
                                     (has_p ? stream_bit(stream_pressure) : 0u);
        if (!builder_.accept_time(clock_, line_no, t_s, row_streams)) return;
    }
    have_raw_time_ = true;
    last_raw_time_ = unwrapped;
    if (has_imu) {
        builder_.add_imu(line_no, t_s, a, g);
        for (size_t i = 0; i < checks_.size(); ++i) checks_[i].add(cells[i], line_no);
    }
    if (has_mag) builder_.add_mag(line_no, t_s, m);
    if (has_p) builder_.add_baro(line_no, t_s, p, temp);
}

}  // namespace pednav::io::detail
