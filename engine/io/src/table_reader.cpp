// SPDX-License-Identifier: Apache-2.0
#include "table_reader.hpp"

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
CellResult parse_vec(RowContext& ctx, const Vec3Spec& v, double out[3], bool optional = false) {
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

void read_table(const TextFile& file, const TableSpec& spec, LogBuilder& builder) {
    unsigned present = 0;
    if (spec.accel.present()) present |= kImuBits;
    if (spec.mag.present()) present |= stream_bit(stream_mag);
    if (spec.pressure_col >= 0) present |= stream_bit(stream_pressure);

    Clock clock(""), imu_clock("accel/gyro"), mag_clock("mag"), pressure_clock("pressure");
    std::vector<std::string_view> fields;
    double last_raw_time = 0.0, wrap_offset = 0.0;
    bool have_raw_time = false;
    size_t truncated_last_line = 0;

    for (size_t index = spec.first_data_index; index < file.lines.size(); ++index) {
        const size_t line_no = index + 1;
        const std::string_view line = trim(file.lines[index]);
        if (line.empty() || is_comment(spec, line)) continue;
        // Split the untrimmed line: the trailing empty cell of a tab-separated
        // row is a field (split_into trims each field). One delimiter more
        // than the header has, ending the row, closes it instead: headers
        // are read trimmed, so a trailing tab never makes a column there.
        split_into(file.lines[index], spec.delim, fields);
        if (fields.size() == spec.column_count + 1 && fields.back().empty()) fields.pop_back();
        if (fields.size() != spec.column_count) {
            char text[160];
            std::snprintf(text, sizeof text, "%s: %zu fields, the header has %zu",
                          fields.size() < spec.column_count ? "truncated row" : "too many fields",
                          fields.size(), spec.column_count);
            builder.bad_row(line_no, text, present);
            if (index + 1 == file.lines.size()) truncated_last_line = line_no;
            continue;
        }
        RowContext ctx{spec, fields, {}};

        double raw_time = 0.0;
        if (parse_scalar(ctx, spec.time_col, &raw_time) != CellResult::ok) {
            builder.bad_row(line_no, ctx.error.empty() ? "no time" : ctx.error, present);
            continue;
        }
        bool invalid = false;
        for (int c : spec.valid_cols) {
            double flag = 0.0;
            if (parse_number(fields[static_cast<size_t>(c)], &flag) != NumberStatus::ok || flag != 1.0) {
                builder.bad_row(
                    line_no,
                    "sample flagged invalid by the sensor (" + spec.names[static_cast<size_t>(c)] + ")",
                    present);
                invalid = true;
                break;
            }
        }
        if (invalid) continue;

        double a[3] = {0, 0, 0}, g[3] = {0, 0, 0}, m[3] = {0, 0, 0}, p = 0.0, temp = NAN;
        bool has_imu = false, has_mag = false, has_p = false;
        if (spec.accel.present()) {
            const CellResult ra = parse_vec(ctx, spec.accel, a);
            const CellResult rg = ra == CellResult::bad ? CellResult::bad : parse_vec(ctx, spec.gyro, g);
            if (ra == CellResult::bad || rg == CellResult::bad) {
                builder.bad_row(line_no, ctx.error, present);
                continue;
            }
            if (ra != rg) {
                builder.bad_row(
                    line_no, "accelerometer and gyroscope cells must be both present or both empty", present);
                continue;
            }
            has_imu = ra == CellResult::ok;
        }
        if (spec.mag.present()) {
            const CellResult rm = parse_vec(ctx, spec.mag, m, true);
            if (rm == CellResult::bad) {
                builder.bad_row(line_no, "magnetometer sample: " + ctx.error, stream_bit(stream_mag));
            }
            has_mag = rm == CellResult::ok;
        }
        if (spec.pressure_col >= 0) {
            const CellResult rp = parse_scalar(ctx, spec.pressure_col, &p, true);
            if (rp == CellResult::bad)
                builder.bad_row(line_no, "pressure sample: " + ctx.error, stream_bit(stream_pressure));
            has_p = rp == CellResult::ok;
            p *= spec.pressure_scale;
            if (has_p && spec.temperature_col >= 0) {
                double tc = 0.0;
                if (parse_number(fields[static_cast<size_t>(spec.temperature_col)], &tc) == NumberStatus::ok)
                    temp = tc;
            }
        }
        if (!has_imu && !has_mag && !has_p) continue;

        // Raw counters and tick clocks wrap; unwrap when the value drops by more than half the wrap.
        if (spec.counter_wrap > 0 && have_raw_time &&
            raw_time + wrap_offset < last_raw_time - spec.counter_wrap / 2) {
            wrap_offset += spec.counter_wrap;
        }
        const double unwrapped = raw_time + wrap_offset;
        const double t_s = spec.time_kind == TableSpec::TimeKind::counter ? unwrapped / spec.counter_rate_hz
                                                                          : unwrapped * spec.time_scale;
        if (spec.empty_cells_mean_absent) {
            // Sparse multi-rate rows: each stream keeps its own time order.
            if (has_imu) has_imu = builder.accept_time(imu_clock, line_no, t_s, kImuBits);
            if (has_mag) has_mag = builder.accept_time(mag_clock, line_no, t_s, stream_bit(stream_mag));
            if (has_p) has_p = builder.accept_time(pressure_clock, line_no, t_s, stream_bit(stream_pressure));
            if (!has_imu && !has_mag && !has_p) continue;
        } else {
            const unsigned row_streams = (has_imu ? kImuBits : 0u) | (has_mag ? stream_bit(stream_mag) : 0u) |
                                         (has_p ? stream_bit(stream_pressure) : 0u);
            if (!builder.accept_time(clock, line_no, t_s, row_streams)) continue;
        }
        have_raw_time = true;
        last_raw_time = unwrapped;
        if (has_imu) builder.add_imu(line_no, t_s, a, g);
        if (has_mag) builder.add_mag(line_no, t_s, m);
        if (has_p) builder.add_baro(line_no, t_s, p, temp);
    }
    if (truncated_last_line > 0) builder.note("the last line is incomplete (file cut off while writing?)");
}

}  // namespace pednav::io::detail
