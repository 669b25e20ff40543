#pragma once
// The exercise catalog resources/exercises.tsv (tag, lab, title, minutes, hint): one source for ./pba
// grade and for the lab's on-screen exercise status. `minutes` is the estimated time a student who has read
// the workbook section needs for the exercise.
#include <string>
#include <vector>

namespace pba::app {

struct ExerciseInfo {
  std::string tag;  ///< e.g. "HELLO-1"
  std::string lab;  ///< e.g. "hello"
  std::string title;
  int minutes = 0;  ///< estimated time [min]
  std::string hint;
};

/// Exercises of `lab` listed in the catalog file at `path` (empty when the file is missing).
std::vector<ExerciseInfo> loadExercises(const std::string& path, const std::string& lab);

}  // namespace pba::app
