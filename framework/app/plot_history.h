#pragma once
// Live plots over time of any numeric scene metric (docs/architecture.md §3): a ring buffer per metric,
// filled once per displayed frame from Scene::metrics(). No GL, no ImGui: tested headless.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pba::app {

class PlotHistory {
 public:
  explicit PlotHistory(std::size_t capacity = 600) : capacity_(capacity) {}

  /// Appends every numeric (or boolean) entry of `metrics` at simulated time t [s].
  void record(double t, const nlohmann::json& metrics);
  void clear();

  /// Names of the metrics seen so far, sorted.
  std::vector<std::string> names() const;
  /// Samples of `name`, oldest first (at most capacity()).
  std::vector<float> series(const std::string& name) const;
  std::size_t capacity() const { return capacity_; }

 private:
  struct Ring {
    std::vector<float> values;
    std::size_t next = 0;  ///< index of the oldest sample once full
  };
  std::size_t capacity_;
  std::map<std::string, Ring> rings_;
};

}  // namespace pba::app
