#pragma once
// Text from an input (a key, a value, a scene name, a path) quoted in an error message, which is one
// line on stderr (docs/architecture.md §4): control characters escaped, long text shortened.
#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace pba::app {

inline constexpr std::size_t kShownTextBytes = 64;  ///< input text shown in a message, at most

/// `text` unchanged when it is short and printable; else control bytes as \n, \t, \xNN and at most
/// kShownTextBytes bytes (cut at a UTF-8 character boundary) followed by "... (N bytes)".
std::string shownText(const std::string& text);
/// A JSON value for a message: scalars as JSON text (through shownText), arrays and objects by their
/// kind and size, so a deeply nested value is never walked.
std::string shownJson(const nlohmann::json& value);
/// The last guard before stderr: every control character of `message` escaped, so it is one line.
std::string oneLine(const std::string& message);

}  // namespace pba::app
