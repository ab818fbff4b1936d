#pragma once
// JSON text to and from nlohmann::json values, compiled once here: the
// serializer and the parser are nlohmann's largest templates, and each file
// that called dump() or parse() compiled them again (about a second of CPU
// each at -O3; docs/benchmarks.md, "Build and test time"). Each function is
// the nlohmann call it names, with its defaults.
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace epviz::io {

// value.dump(indent): compact on one line with -1, else `indent` spaces per
// level. Throws nlohmann::json::type_error on a string that is not UTF-8.
std::string json_text(const nlohmann::json& value, int indent = -1);
std::string json_text(const nlohmann::ordered_json& value, int indent = -1);

// nlohmann::json::parse(text): throws nlohmann::json::parse_error when
// `text` is not one JSON value.
nlohmann::json parse_json(std::string_view text);
// The same without exceptions: a discarded value (is_discarded()) when `text`
// is not one JSON value.
nlohmann::json parse_json_or_discarded(std::string_view text);

}  // namespace epviz::io
