#include "app/window/lab_settings.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/runner/host_system.h"

namespace pba::app {

std::string settingsDirectory(const std::string& lab) {
  const std::filesystem::path base = userConfigDir();
  if (base.empty()) return {};
  return (base / "pba-labs" / lab).string();
}

LabSettings loadLabSettings(const std::string& directory) {
  LabSettings s;
  if (directory.empty()) return s;
  std::ifstream in(std::filesystem::path(directory) / "settings.json");
  if (!in) return s;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    s.lastScene = j.value("last_scene", s.lastScene);
    s.windowWidth = std::clamp(j.value("window_width", s.windowWidth), 320, 8192);
    s.windowHeight = std::clamp(j.value("window_height", s.windowHeight), 240, 8192);
    s.lecture = j.value("lecture", s.lecture);
    s.plotted = j.value("plotted", s.plotted);
  } catch (const std::exception&) {
    return LabSettings{};  // a damaged settings file must never stop a lab from starting
  }
  return s;
}

bool saveLabSettings(const std::string& directory, const LabSettings& s) {
  if (directory.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  std::ofstream out(std::filesystem::path(directory) / "settings.json", std::ios::trunc);
  if (!out) return false;
  const nlohmann::json j = {{"last_scene", s.lastScene},
                            {"window_width", s.windowWidth},
                            {"window_height", s.windowHeight},
                            {"lecture", s.lecture},
                            {"plotted", s.plotted}};
  out << j.dump(2) << '\n';
  return static_cast<bool>(out);
}

}  // namespace pba::app
