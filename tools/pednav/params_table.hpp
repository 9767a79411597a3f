// SPDX-License-Identifier: Apache-2.0
// Every plugin's parameters as a table: `pednav plugins --params` (text) and
// `--params --markdown` (the README's tables), from the "plugins" array of a
// plugin listing: entries with "id", "kind" and "params_schema" (the schema
// object; a string when it is not valid JSON; null when there is none).
//
// Plugins are ordered by pipeline role, then id; plugins of one kind with the
// same schema share one table. Rows are sorted by key: key, type, unit, range,
// default, meaning.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::cli {

struct ParamsTableOptions {
    std::string id_prefix;  // only plugins whose id starts with this
    int heading_level = 4;  // Markdown heading of each plugin: "####"
};

// One table: the plugins it describes and its rows, or why there is none.
struct ParamsTable {
    std::vector<std::string> ids;
    std::string kind;
    std::string problem;  // "no params schema ...", "params schema is not valid JSON", ...
    std::vector<std::vector<std::string>> rows;  // cells: key, type, unit, range, default, meaning
};

extern const std::vector<std::string> kParamsColumns;  // "key", "type", ...

std::vector<ParamsTable> params_tables(const nlohmann::json& plugins, const ParamsTableOptions& options = {});
// "org.pednav.foot.ekf15, org.pednav.foot.ekf15.dense (position_filter)"
std::string params_table_title(const ParamsTable& table);

std::string params_text(const nlohmann::json& plugins, const ParamsTableOptions& options = {});
std::string params_markdown(const nlohmann::json& plugins, const ParamsTableOptions& options = {});

}  // namespace pednav::cli
