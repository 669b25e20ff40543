#include "app/runner/exercise_catalog.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace pba::app {

std::vector<ExerciseInfo> loadExercises(const std::string& path, const std::string& lab) {
  std::vector<ExerciseInfo> out;
  std::ifstream in(path);
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (header) {
      header = false;
      continue;
    }
    std::istringstream row(line);
    ExerciseInfo e;
    std::string minutes;
    if (std::getline(row, e.tag, '\t') && std::getline(row, e.lab, '\t') && std::getline(row, e.title, '\t') &&
        std::getline(row, minutes, '\t')) {
      e.minutes = std::atoi(minutes.c_str());
      std::getline(row, e.hint);
      if (e.lab == lab) out.push_back(std::move(e));
    }
  }
  return out;
}

std::vector<std::string> stubbedExercises(const std::vector<ExerciseInfo>& labExercises,
                                          const std::vector<std::string>& stubs) {
  std::vector<std::string> out;
  for (const ExerciseInfo& e : labExercises)
    if (std::find(stubs.begin(), stubs.end(), e.tag) != stubs.end()) out.push_back(e.tag);
  return out;
}

std::string stubBannerText(const std::vector<std::string>& tags, size_t shown) {
  if (tags.empty()) return {};
  std::string text;
  for (size_t i = 0; i < std::min(shown, tags.size()); ++i) text += (i ? ", " : "") + tags[i];
  if (tags.size() > shown) text += " and " + std::to_string(tags.size() - shown) + " more";
  return text + " not implemented (stubs run): see Exercises in the panel, then ./pba grade";
}

}  // namespace pba::app
