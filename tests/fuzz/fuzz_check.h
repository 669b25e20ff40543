#pragma once
// What every fuzz target asserts besides "no sanitizer report": an error is one line that starts with
// the input's name (docs/architecture.md §4). A violation aborts, which libFuzzer reports as a crash.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace pba::fuzz {

inline void require(bool condition, const char* what, const std::string& detail) {
  if (condition) return;
  std::fprintf(stderr, "fuzz property violated: %s: %s\n", what, detail.c_str());
  std::abort();
}

inline void requireOneLineNaming(const std::string& error, const std::string& name) {
  require(error.find('\n') == std::string::npos, "an error is one line", error);
  require(error.rfind(name, 0) == 0, "an error starts with the input's name", error);
}

/// The input written to a file of its own (per process) with extension `ext`; the path.
std::string writeInput(const unsigned char* data, std::size_t size, const std::string& ext);

}  // namespace pba::fuzz
