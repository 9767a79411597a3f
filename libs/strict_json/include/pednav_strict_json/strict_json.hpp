// SPDX-License-Identifier: Apache-2.0
// JSON documents read strictly: the engine's config and whatever the tools
// patch into it, column maps, and GeoJSON maps. nlohmann's parser accepts any depth (and dump(), the destructor's
// helpers and our own walks then recurse as deep), keeps the last of two equal
// keys, reads 1e400 as infinity and stops at nothing a C string would hide;
// here each of those is an error naming where it is.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace pednav::strict_json {

// Deeper than any config or column map needs (the presets nest 5 levels), and
// shallow enough that recursing through it costs a few KiB of a 512 KiB
// thread stack.
constexpr size_t kMaxDepth = 64;

struct Error : std::runtime_error {
    Error(std::string json_pointer, const std::string& message)
        : std::runtime_error(message), pointer(std::move(json_pointer)) {}
    std::string pointer;  // JSON pointer of the value at fault ("" = the document)
};

// Parses `text` as one JSON document. Throws Error when it is not
// valid JSON (the message carries nlohmann's byte position), holds a NUL byte,
// nests arrays and objects deeper than max_depth, repeats a key in an object,
// or holds a number that is not finite (1e400).
nlohmann::json parse(std::string_view text, size_t max_depth = kMaxDepth);

// Appends one reference token to a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointer_append(const std::string& pointer, std::string_view token);

}  // namespace pednav::strict_json
