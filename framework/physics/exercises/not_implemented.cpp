#include "physics/exercises/not_implemented.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>

namespace pba::exercises {
namespace {
struct Record {
  std::mutex mutex;
  std::set<std::string, std::less<>> tags;
  std::set<std::string, std::less<>> used;  // outside the probes
  std::vector<void (*)()> probes;
};
Record& record() {
  static Record instance;
  return instance;
}

// Whether a stub ran outside the probes since the last clearNotImplemented() (anyNotImplementedUsed).
std::atomic<bool> usedAny{false};

// True while runProbes() runs: probes call every exercise on purpose, which is not a use to trace.
std::atomic<bool> probing{false};

// Whether `tag` appears in the comma-separated list of PBA_STUB_EXERCISES (or the list is "all").
bool stubRequested(std::string_view tag) {
  const char* list = std::getenv("PBA_STUB_EXERCISES");
  if (list == nullptr) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    if (item == "all" || item == tag) return true;
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return false;
}
}  // namespace

ExerciseSwitch::ExerciseSwitch(std::string_view tag) : tag_(tag), stub_(stubRequested(tag)) {}

void ExerciseSwitch::noteFirstRun() const {
  if (probing.load()) return;
  if (traced_.exchange(true)) return;
  const char* path = std::getenv("PBA_EXERCISE_TRACE");
  if (path == nullptr || *path == '\0') return;
  // One short line per process and tag, written with a single append: safe with concurrent writers.
  if (std::FILE* f = std::fopen(path, "a")) {
    const std::string line = tag_ + "\n";
    std::fwrite(line.data(), 1, line.size(), f);
    std::fclose(f);
  }
}

void markNotImplemented(std::string_view tag) {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  if (r.tags.find(tag) == r.tags.end()) r.tags.emplace(tag);
  if (!probing.load() && r.used.find(tag) == r.used.end()) {
    r.used.emplace(tag);
    usedAny.store(true);
  }
}

std::vector<std::string> notImplementedTags() {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  return {r.tags.begin(), r.tags.end()};
}

std::vector<std::string> notImplementedTagsUsed() {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  return {r.used.begin(), r.used.end()};
}

bool anyNotImplementedUsed() { return usedAny.load(); }

bool registerProbe(void (*probe)()) {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  r.probes.push_back(probe);
  return true;
}

void runProbes() {
  std::vector<void (*)()> probes;
  {
    Record& r = record();
    std::lock_guard lock(r.mutex);
    probes = r.probes;
  }
  probing.store(true);
  for (auto* probe : probes) probe();
  probing.store(false);
}

void clearNotImplemented() {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  r.tags.clear();
  r.used.clear();
  usedAny.store(false);
}

}  // namespace pba::exercises
