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

/// The tags of `labExercises` (catalog order) that are among `stubs` (notImplementedTags(), which names
/// every stubbed exercise of the course after the start-up probes): the open lab's unfinished ones.
std::vector<std::string> stubbedExercises(const std::vector<ExerciseInfo>& labExercises,
                                          const std::vector<std::string>& stubs);

/// The not-implemented banner: one short line naming the first `shown` of `tags` and counting the rest,
/// pointing at the Exercises panel that lists them all; empty when `tags` is.
std::string stubBannerText(const std::vector<std::string>& tags, size_t shown = 3);

}  // namespace pba::app
