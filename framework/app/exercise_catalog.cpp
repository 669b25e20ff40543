#include "app/exercise_catalog.h"

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

}  // namespace pba::app
