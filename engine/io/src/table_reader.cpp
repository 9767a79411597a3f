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
void check_columns(const TextFile& file, const TableSpec& spec) {
    const size_t header_line = spec.first_data_index;  // 1-based number of the header line
    if (spec.time_col < 0) throw ReadError(file.path, header_line, "no time column in the header");
    std::vector<int> cols = {spec.time_col, spec.pressure_col, spec.temperature_col};
    for (const Vec3Spec* v : {&spec.accel, &spec.gyro, &spec.mag})
        cols.insert(cols.end(), v->col, v->col + 3);
    cols.insert(cols.end(), spec.valid_cols.begin(), spec.valid_cols.end());
    for (int c : cols) {
        if (c >= static_cast<int>(spec.column_count) || c >= static_cast<int>(spec.names.size()))
            throw ReadError(file.path, header_line, "the header has " + std::to_string(spec.column_count) +
                                                        " columns, the format needs column " +
                                                        std::to_string(c + 1));
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

void read_table(const TextFile& file, const TableSpec& given_spec, LogBuilder& builder) {
    TableSpec spec = given_spec;  // time_scale may be settled by the first time
    bool time_scale_settled = !spec.time_unit_from_magnitude;
    check_columns(file, spec);
    unsigned present = 0;
    if (spec.accel.present()) present |= kImuBits;
    if (spec.mag.present()) present |= stream_bit(stream_mag);
    if (spec.pressure_col >= 0) present |= stream_bit(stream_pressure);

    Clock clock(""), imu_clock("accel/gyro"), mag_clock("mag"), pressure_clock("pressure");
    std::vector<std::string_view> fields;
    // Plausibility per inertial column: accelerometer beyond 1000 m/s^2 (100 g)
    // or flat above 2 g, gyroscope beyond 50 rad/s (2 900 deg/s) or flat above 2 rad/s.
    std::vector<ColumnCheck> checks;
    double cells[6] = {0, 0, 0, 0, 0, 0};
    if (spec.accel.present() && spec.gyro.present()) {
        for (int i = 0; i < 3; ++i)
            checks.emplace_back(spec.names[static_cast<size_t>(spec.accel.col[i])], "m/s^2", 1000.0,
                                2.0 * kStandardGravity);
        for (int i = 0; i < 3; ++i)
            checks.emplace_back(spec.names[static_cast<size_t>(spec.gyro.col[i])], "rad/s", 50.0, 2.0);
    }
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
        if (!time_scale_settled) {
            time_scale_settled = true;
            const char* unit = "";
            spec.time_scale = epoch_scale(raw_time, &unit);
            if (spec.time_scale != 1.0) {
                char text[200];
                std::snprintf(text, sizeof text,
                              "time column %s: the first value %.6g (line %zu) is a Unix time in %s, not "
                              "seconds: read as %s",
                              spec.names[static_cast<size_t>(spec.time_col)].c_str(), raw_time, line_no, unit,
                              unit);
                builder.issue(line_no, text);
            }
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
            const CellResult ra = parse_vec(ctx, spec.accel, a, false, cells);
            const CellResult rg =
                ra == CellResult::bad ? CellResult::bad : parse_vec(ctx, spec.gyro, g, false, cells + 3);
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
        if (has_imu) {
            builder.add_imu(line_no, t_s, a, g);
            for (size_t i = 0; i < checks.size(); ++i) checks[i].add(cells[i], line_no);
        }
        if (has_mag) builder.add_mag(line_no, t_s, m);
        if (has_p) builder.add_baro(line_no, t_s, p, temp);
    }
    for (const auto& c : checks) c.report(builder);
    if (truncated_last_line > 0) builder.note("the last line is incomplete (file cut off while writing?)");
}

}  // namespace pednav::io::detail
