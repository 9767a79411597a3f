// SPDX-License-Identifier: Apache-2.0
#include "params_table.hpp"

#include <algorithm>

#include <pednav_sdk/params_schema.hpp>

namespace pednav::cli {

const std::vector<std::string> kParamsColumns = {"key", "type", "unit", "range", "default", "meaning"};

namespace {

int role_order(const std::string& kind) {
    const char* const order[] = {"step_detector", "attitude_estimator", "position_filter", "map_matcher"};
    for (int i = 0; i < 4; ++i)
        if (kind == order[i]) return i;
    return 4;
}

std::string text_of(const nlohmann::json& j, const char* key) {
    auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// Rows of a schema, or the reason it has none.
void fill(ParamsTable& t, const nlohmann::json& schema) {
    if (schema.is_null()) {
        t.problem = "no params schema: the plugin checks its params itself";
        return;
    }
    if (schema.is_string()) {
        t.problem = "params schema is not valid JSON";
        return;
    }
    try {
        const auto parsed = sdk::ParamsSchema::from_json(schema);
        for (const auto& p : parsed.params()) {
            const std::string range = sdk::range_text(p);
            t.rows.push_back({p.key, sdk::param_type_name(p.type), p.unit.empty() ? "-" : p.unit,
                              range.empty() ? "-" : range, sdk::format_value(p.default_value),
                              p.description});
        }
        if (t.rows.empty()) t.problem = "no parameters";
    } catch (const sdk::SchemaError& e) {
        t.problem = e.what();
    }
}

std::string markdown_cell(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '|') out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out;
}

}  // namespace

std::vector<ParamsTable> params_tables(const nlohmann::json& plugins, const ParamsTableOptions& options) {
    std::vector<const nlohmann::json*> sorted;
    for (const auto& p : plugins)
        if (text_of(p, "id").rfind(options.id_prefix, 0) == 0) sorted.push_back(&p);
    std::stable_sort(sorted.begin(), sorted.end(), [](const nlohmann::json* a, const nlohmann::json* b) {
        const int ra = role_order(text_of(*a, "kind")), rb = role_order(text_of(*b, "kind"));
        return ra != rb ? ra < rb : text_of(*a, "id") < text_of(*b, "id");
    });
    std::vector<ParamsTable> tables;
    std::vector<nlohmann::json> schemas;  // of each table, to group plugins sharing one
    for (const nlohmann::json* p : sorted) {
        const nlohmann::json schema = p->value("params_schema", nlohmann::json());
        const std::string kind = text_of(*p, "kind");
        bool joined = false;
        for (size_t i = 0; i < tables.size() && !joined; ++i)
            if (tables[i].kind == kind && !schema.is_null() && schemas[i] == schema) {
                tables[i].ids.push_back(text_of(*p, "id"));
                joined = true;
            }
        if (joined) continue;
        ParamsTable t;
        t.ids.push_back(text_of(*p, "id"));
        t.kind = kind;
        fill(t, schema);
        tables.push_back(std::move(t));
        schemas.push_back(schema);
    }
    return tables;
}

std::string params_table_title(const ParamsTable& table) {
    std::string title;
    for (const auto& id : table.ids) title += (title.empty() ? "" : ", ") + id;
    return title + " (" + table.kind + ")";
}

std::string params_text(const nlohmann::json& plugins, const ParamsTableOptions& options) {
    std::string out;
    for (const auto& t : params_tables(plugins, options)) {
        if (!out.empty()) out += "\n";
        out += params_table_title(t) + "\n";
        if (!t.problem.empty()) {
            out += "  " + t.problem + "\n";
            continue;
        }
        // Columns as wide as their widest cell; the meaning last, unpadded.
        std::vector<size_t> width(kParamsColumns.size());
        for (size_t c = 0; c < width.size(); ++c) width[c] = kParamsColumns[c].size();
        for (const auto& r : t.rows)
            for (size_t c = 0; c < width.size(); ++c) width[c] = std::max(width[c], r[c].size());
        auto line = [&](const std::vector<std::string>& cells) {
            std::string l = " ";
            for (size_t c = 0; c < cells.size(); ++c)
                l += " " + (c + 1 < cells.size() ? cells[c] + std::string(width[c] - cells[c].size() + 1, ' ')
                                                 : cells[c]);
            return l + "\n";
        };
        out += line(kParamsColumns);
        for (const auto& r : t.rows) out += line(r);
    }
    return out;
}

std::string params_markdown(const nlohmann::json& plugins, const ParamsTableOptions& options) {
    std::string out;
    const std::string hashes(static_cast<size_t>(std::clamp(options.heading_level, 1, 6)), '#');
    for (const auto& t : params_tables(plugins, options)) {
        if (!out.empty()) out += "\n";
        std::string ids;
        for (const auto& id : t.ids) ids += (ids.empty() ? "`" : ", `") + id + "`";
        out += hashes + " " + ids + " (" + t.kind + ")\n\n";
        if (!t.problem.empty()) {
            out += markdown_cell(t.problem) + "\n";
            continue;
        }
        std::string header = "|", rule = "|";
        for (const auto& c : kParamsColumns) {
            header += " " + c + " |";
            rule += " --- |";
        }
        out += header + "\n" + rule + "\n";
        for (const auto& r : t.rows) {
            std::string row = "|";
            for (size_t c = 0; c < r.size(); ++c)
                row += " " + (c == 0 ? "`" + r[c] + "`" : markdown_cell(r[c])) + " |";
            out += row + "\n";
        }
    }
    return out;
}

}  // namespace pednav::cli
