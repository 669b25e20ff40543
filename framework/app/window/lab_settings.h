#pragma once
// Per-lab persisted settings (docs/architecture.md §3): last scene, window size, lecture mode, plotted metrics.
// Stored as JSON next to the ImGui ini in <user config folder>/pba-labs/<lab>/: %APPDATA% on Windows,
// ~/Library/Application Support on macOS, $XDG_CONFIG_HOME (default ~/.config) elsewhere.
#include <string>
#include <vector>

namespace pba::app {

struct LabSettings {
  std::string lastScene;
  int windowWidth = 1280;
  int windowHeight = 720;
  bool lecture = false;
  std::vector<std::string> plotted;  ///< metric names shown in the plot panel
};

/// Folder of lab `lab`'s settings (created on save). Empty when no home folder is known.
std::string settingsDirectory(const std::string& lab);
/// Reads the settings; missing or unreadable files give the defaults (never an error for the user).
LabSettings loadLabSettings(const std::string& directory);
/// Writes the settings; returns false when the folder cannot be written.
bool saveLabSettings(const std::string& directory, const LabSettings& settings);

}  // namespace pba::app
