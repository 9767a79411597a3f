// SPDX-License-Identifier: Apache-2.0
#include "pednav_strict_json/strict_json.hpp"

#include <cmath>
#include <set>
#include <vector>

namespace pednav::strict_json {

std::string pointer_append(const std::string& pointer, std::string_view token) {
    std::string out = pointer + "/";
    for (const char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

namespace {

// One open array or object while parsing: its pointer, the keys seen, and the
// pointer of the member whose value comes next.
struct Level {
    bool is_object = false;
    std::string pointer;
    std::set<std::string> keys;
    std::string member;  // object: pointer of the current key's value
    size_t index = 0;    // array: index of the next element
};

std::string next_pointer(const std::vector<Level>& stack) {
    if (stack.empty()) return "";
    const Level& top = stack.back();
    return top.is_object ? top.member : pointer_append(top.pointer, std::to_string(top.index));
}

void element_done(std::vector<Level>& stack) {
    if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
}

// Line and column (1-based) of byte `offset`, for messages.
std::string position_of(std::string_view text, size_t offset) {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's parse error without its "[json.exception...] parse error at
// ...: " prefix, with bytes that are not printable ASCII (the ill-formed
// UTF-8 it quotes) shown as '?': the message stays valid text.
std::string parse_reason(const std::string& what) {
    std::string reason = what;
    if (const size_t at = reason.find("parse error"); at != std::string::npos) {
        if (const size_t colon = reason.find(": ", at); colon != std::string::npos)
            reason = reason.substr(colon + 2);
    }
    for (char& c : reason) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7f) c = '?';
    }
    return reason;
}

}  // namespace

nlohmann::json parse(std::string_view text, size_t max_depth) {
    if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
        throw Error("", "a NUL byte at " + position_of(text, nul) + " (byte " +
                                      std::to_string(nul) +
                                      "): the text after it would be ignored by C callers");
    }
    std::vector<Level> stack;
    using Event = nlohmann::json::parse_event_t;
    auto callback = [&](int, Event event, nlohmann::json& parsed) -> bool {
        switch (event) {
            case Event::object_start:
            case Event::array_start: {
                Level level;
                level.is_object = event == Event::object_start;
                level.pointer = next_pointer(stack);
                if (stack.size() >= max_depth) {
                    throw Error(
                        level.pointer, "arrays and objects nested deeper than " + std::to_string(max_depth) +
                                           " levels at " +
                                           (level.pointer.empty() ? "the top" : level.pointer));
                }
                stack.push_back(std::move(level));
                break;
            }
            case Event::key: {
                Level& top = stack.back();
                const std::string key = parsed.get<std::string>();
                top.member = pointer_append(top.pointer, key);
                if (!top.keys.insert(key).second)
                    throw Error(top.member,
                                          "duplicate key \"" + key + "\" in " +
                                              (top.pointer.empty() ? "the document" : top.pointer));
                break;
            }
            case Event::object_end:
            case Event::array_end:
                stack.pop_back();
                element_done(stack);
                break;
            case Event::value:
                if (parsed.is_number_float() && !std::isfinite(parsed.get<double>()))
                    throw Error(next_pointer(stack), "the number at " + next_pointer(stack) +
                                                                   " is out of range (not a finite double)");
                element_done(stack);
                break;
        }
        return true;
    };
    try {
        return nlohmann::json::parse(text.begin(), text.end(), callback);
    } catch (const nlohmann::json::parse_error& e) {
        std::string where = position_of(text, e.byte > 0 ? e.byte - 1 : 0);
        throw Error("", "not valid JSON at " + where + ": " + parse_reason(e.what()));
    } catch (const nlohmann::json::out_of_range&) {  // 406: a number overflowing a double
        throw Error(next_pointer(stack), "the number at " + next_pointer(stack) +
                                                       " is out of range (not a finite double)");
    }
}

}  // namespace pednav::strict_json
