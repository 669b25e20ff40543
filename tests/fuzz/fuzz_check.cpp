#include "fuzz_check.h"

#include <filesystem>
#include <fstream>
#include <random>

namespace pba::fuzz {

std::string writeInput(const unsigned char* data, std::size_t size, const std::string& ext) {
  // One file per process and extension, rewritten for every input: a random token, drawn once, keeps
  // parallel fuzzers apart.
  static const std::string token = std::to_string(std::random_device{}());
  const std::string path = (std::filesystem::temp_directory_path() / ("pba-fuzz-" + token + ext)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace pba::fuzz
