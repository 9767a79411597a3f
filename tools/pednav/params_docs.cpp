// SPDX-License-Identifier: Apache-2.0
#include "params_docs.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

#include "cli_common.hpp"
#include "params_table.hpp"

namespace pednav::cli {

namespace {

constexpr const char* kBegin = "<!-- params:begin";
constexpr const char* kEnd = "<!-- params:end -->";

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) nl = text.size();
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    return lines;
}

// One generated block: the line indices of its two markers and its options.
struct Block {
    size_t begin, end;
    ParamsTableOptions options;
};

ParamsTableOptions parse_options(const std::string& name, size_t line_no, const std::string& marker) {
    const size_t close = marker.rfind("-->");
    if (close == std::string::npos || close < std::strlen(kBegin))
        throw std::runtime_error(name + ":" + std::to_string(line_no) +
                                 ": the params:begin marker is not closed with -->");
    ParamsTableOptions o;
    const std::string attrs = marker.substr(std::strlen(kBegin), close - std::strlen(kBegin));
    size_t pos = 0;
    while (pos < attrs.size()) {
        const size_t a = attrs.find_first_not_of(' ', pos);
        if (a == std::string::npos) break;
        const size_t b = std::min(attrs.find(' ', a), attrs.size());
        const std::string token = attrs.substr(a, b - a);
        pos = b;
        if (token.rfind("id=", 0) == 0) {
            o.id_prefix = token.substr(3);
        } else if (token.rfind("level=", 0) == 0 && token.size() == 7 && token[6] >= '1' && token[6] <= '6') {
            o.heading_level = token[6] - '0';
        } else {
            throw std::runtime_error(name + ":" + std::to_string(line_no) +
                                     ": unknown params:begin attribute \"" + token +
                                     "\" (id=PREFIX, level=1..6)");
        }
    }
    return o;
}

std::vector<Block> find_blocks(const std::string& name, const std::vector<std::string>& lines) {
    std::vector<Block> blocks;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string l = trim(lines[i]);
        if (l == kEnd)
            throw std::runtime_error(name + ":" + std::to_string(i + 1) + ": " + kEnd +
                                     " without a params:begin");
        if (l.rfind(kBegin, 0) != 0) continue;
        Block b{i, i, parse_options(name, i + 1, l)};
        for (b.end = i + 1; b.end < lines.size() && trim(lines[b.end]) != kEnd; ++b.end) {
        }
        if (b.end == lines.size())
            throw std::runtime_error(name + ":" + std::to_string(i + 1) + ": params:begin without " + kEnd);
        blocks.push_back(b);
        i = b.end;
    }
    if (blocks.empty()) throw std::runtime_error(name + " has no " + std::string(kBegin) + " --> block");
    return blocks;
}

// Cells of a Markdown table row; "\|" stays inside a cell.
std::vector<std::string> split_row(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    const std::string l = trim(line);
    for (size_t i = 1; i < l.size(); ++i) {
        if (l[i] == '\\' && i + 1 < l.size() && l[i + 1] == '|') {
            cell += "\\|";
            ++i;
        } else if (l[i] == '|') {
            cells.push_back(trim(cell));
            cell.clear();
        } else {
            cell += l[i];
        }
    }
    return cells;
}

std::string strip_backticks(const std::string& s) {
    std::string out;
    for (char c : s)
        if (c != '`') out += c;
    return out;
}

// The tables of a block as written: per plugin title, its rows by key.
struct Row {
    size_t line;
    std::vector<std::string> cells;
};
struct Table {
    std::string title;
    size_t line = 0;
    std::vector<std::string> header;
    std::map<std::string, Row> rows;
};

std::vector<Table> parse_tables(const std::vector<std::string>& lines, size_t first_line_no) {
    std::vector<Table> tables;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string l = trim(lines[i]);
        if (l.rfind('#', 0) == 0) {
            Table t;
            t.title = trim(strip_backticks(l.substr(l.find_first_not_of('#'))));
            t.line = first_line_no + i;
            tables.push_back(t);
        } else if (l.rfind('|', 0) == 0 && !tables.empty()) {
            Table& t = tables.back();
            const auto cells = split_row(l);
            if (t.header.empty()) {
                t.header = cells;
            } else if (!cells.empty() && cells[0].rfind("---", 0) != 0) {
                t.rows[strip_backticks(cells[0])] = {first_line_no + i, cells};
            }
        }
    }
    return tables;
}

std::string at(const std::string& name, size_t line_no) {
    return name + ":" + std::to_string(line_no) + ": ";
}

void compare_block(const std::string& name, const std::vector<std::string>& written_lines,
                   size_t first_line_no, const std::string& generated, std::vector<std::string>& out) {
    const auto expected_lines = split_lines(generated);
    const auto expected = parse_tables(expected_lines, 1);
    const auto written = parse_tables(written_lines, first_line_no);
    const size_t before = out.size();
    auto find = [](const std::vector<Table>& v, const std::string& title) -> const Table* {
        for (const auto& t : v)
            if (t.title == title) return &t;
        return nullptr;
    };
    const size_t block_line = first_line_no - 1;
    for (const auto& e : expected) {
        const Table* w = find(written, e.title);
        if (!w) {
            out.push_back(at(name, block_line) + e.title + ": no table in the file");
            continue;
        }
        for (const auto& [key, row] : e.rows) {
            auto it = w->rows.find(key);
            if (it == w->rows.end()) {
                out.push_back(at(name, w->line) + e.title + ", " + key + ": in the schema, not in the file");
                continue;
            }
            for (size_t c = 0; c < row.cells.size(); ++c) {
                const std::string have = c < it->second.cells.size() ? it->second.cells[c] : "";
                if (have != row.cells[c])
                    out.push_back(at(name, it->second.line) + e.title + ", " + key + ": " +
                                  kParamsColumns[c] + " is \"" + have + "\" in the file, \"" + row.cells[c] +
                                  "\" in the schema");
            }
        }
        for (const auto& [key, row] : w->rows)
            if (!e.rows.count(key))
                out.push_back(at(name, row.line) + e.title + ", " + key + ": in the file, not in the schema");
    }
    for (const auto& w : written)
        if (!find(expected, w.title))
            out.push_back(at(name, w.line) + w.title + ": in the file, not among the plugins found");
    if (out.size() != before) return;
    // Same tables, other text (a heading level, spacing, a paragraph).
    for (size_t i = 0; i < std::max(expected_lines.size(), written_lines.size()); ++i) {
        const std::string e = i < expected_lines.size() ? expected_lines[i] : "(end of block)";
        const std::string w = i < written_lines.size() ? written_lines[i] : "(end of block)";
        if (e != w) {
            out.push_back(at(name, first_line_no + i) + "\"" + w + "\" where the generated text has \"" + e +
                          "\"");
            return;
        }
    }
}

void write_text_file(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path);
}

}  // namespace

std::vector<std::string> params_docs_differences(const std::string& name, const std::string& text,
                                                 const nlohmann::json& plugins) {
    const auto lines = split_lines(text);
    std::vector<std::string> out;
    for (const Block& b : find_blocks(name, lines)) {
        const std::vector<std::string> inside(lines.begin() + static_cast<long>(b.begin) + 1,
                                              lines.begin() + static_cast<long>(b.end));
        compare_block(name, inside, b.begin + 2, params_markdown(plugins, b.options), out);
    }
    return out;
}

std::string params_docs_updated(const std::string& name, const std::string& text,
                                const nlohmann::json& plugins) {
    const auto lines = split_lines(text);
    std::string out;
    size_t next = 0;
    for (const Block& b : find_blocks(name, lines)) {
        for (; next <= b.begin; ++next) out += lines[next] + "\n";
        out += params_markdown(plugins, b.options);
        next = b.end;
    }
    for (; next < lines.size(); ++next) out += lines[next] + "\n";
    return out;
}

int params_command(const nlohmann::json& plugins, const ParamsRequest& request) {
    if (request.check && request.update) throw UsageError("--check and --update exclude each other");
    if ((request.check || request.update) && request.files.empty())
        throw UsageError(std::string(request.check ? "--check" : "--update") + " needs the Markdown files");
    if (!request.check && !request.update) {
        if (!request.files.empty())
            throw UsageError("unexpected argument " + request.files[0] + " (--check or --update FILE...)");
        std::fputs((request.markdown ? params_markdown(plugins) : params_text(plugins)).c_str(), stdout);
        return 0;
    }
    if (request.update) {
        for (const auto& path : request.files) {
            const std::string text = read_text_file(path);
            const std::string updated = params_docs_updated(path, text, plugins);
            if (updated != text) write_text_file(path, updated);
            std::printf("%s: %s\n", path.c_str(),
                        updated != text ? "parameter tables regenerated" : "up to date");
        }
        return 0;
    }
    size_t differences = 0;
    for (const auto& path : request.files) {
        const auto found = params_docs_differences(path, read_text_file(path), plugins);
        for (const auto& d : found) std::fprintf(stderr, "%s\n", d.c_str());
        if (found.empty())
            std::printf("%s: the parameter tables agree with the plugins' schemas\n", path.c_str());
        differences += found.size();
    }
    if (differences == 0) return 0;
    std::string command = executable_dir() + "/pednav plugins --params --markdown";
    for (const auto& d : request.plugin_dirs) command += " --plugin-dir " + d;
    command += " --update";
    for (const auto& path : request.files) command += " " + path;
    std::fprintf(
        stderr,
        "%zu difference%s between the parameter tables and the schemas; regenerate the tables with:\n  %s\n",
        differences, differences == 1 ? "" : "s", command.c_str());
    return 1;
}

}  // namespace pednav::cli
