#include "physics/exercises/not_implemented.h"

#include <algorithm>
#include <mutex>
#include <set>

namespace pba::exercises {
namespace {
struct Record {
  std::mutex mutex;
  std::set<std::string, std::less<>> tags;
  std::vector<void (*)()> probes;
};
Record& record() {
  static Record instance;
  return instance;
}
}  // namespace

void markNotImplemented(std::string_view tag) {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  if (r.tags.find(tag) == r.tags.end()) r.tags.emplace(tag);
}

std::vector<std::string> notImplementedTags() {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  return {r.tags.begin(), r.tags.end()};
}

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
  for (auto* probe : probes) probe();
}

void clearNotImplemented() {
  Record& r = record();
  std::lock_guard lock(r.mutex);
  r.tags.clear();
}

}  // namespace pba::exercises
