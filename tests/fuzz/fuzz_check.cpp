#include "fuzz_check.h"

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace pba::fuzz {

std::string writeInput(const unsigned char* data, std::size_t size, const std::string& ext) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("pba-fuzz-" + std::to_string(::getpid()) + ext)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace pba::fuzz
