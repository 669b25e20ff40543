// A name part that no other process running the same tests picks (the release and sanitizer suites run
// in parallel and share the temporary folder): a random number, portable where a process id is not.
#pragma once

#include <random>
#include <string>

namespace pba::testing {

inline std::string processUniqueToken() {
  static const std::string token = [] {
    std::random_device device;
    return std::to_string(device()) + std::to_string(device());
  }();
  return token;
}

}  // namespace pba::testing
