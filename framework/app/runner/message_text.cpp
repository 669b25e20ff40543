#include "app/runner/message_text.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace pba::app {
namespace {

void appendEscaped(std::string& out, unsigned char c) {
  switch (c) {
    case '\n':
      out += "\\n";
      return;
    case '\r':
      out += "\\r";
      return;
    case '\t':
      out += "\\t";
      return;
    default:
      break;
  }
  if (c < 0x20 || c == 0x7f) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", c);
    out += hex;
  } else {
    out += static_cast<char>(c);
  }
}

bool printable(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return false;
  return true;
}

}  // namespace

std::string shownText(const std::string& text) {
  if (text.size() <= kShownTextBytes && printable(text)) return text;
  std::size_t end = std::min(text.size(), kShownTextBytes);
  // Never cut inside a UTF-8 sequence: back up over continuation bytes (10xxxxxx).
  while (end < text.size() && end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  std::string out;
  for (std::size_t i = 0; i < end; ++i) appendEscaped(out, static_cast<unsigned char>(text[i]));
  if (end < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string shownJson(const nlohmann::json& value) {
  if (value.is_array()) return "an array of " + std::to_string(value.size()) + " elements";
  if (value.is_object()) return "an object of " + std::to_string(value.size()) + " keys";
  if (value.is_string()) return "\"" + shownText(value.get<std::string>()) + "\"";
  return shownText(value.dump());
}

std::string oneLine(const std::string& message) {
  if (printable(message)) return message;
  std::string out;
  for (unsigned char c : message) appendEscaped(out, c);
  return out;
}

}  // namespace pba::app
