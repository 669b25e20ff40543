#pragma once
// Live plots over time of any numeric scene metric (docs/architecture.md §3): a ring buffer per metric, filled
// once per displayed frame from Scene::metrics(), and the scale and caption of its plot. Samples are
// doubles: in floats a conserved energy of 0.5 J drew a staircase of rounding steps. No GL, no
// ImGui: tested headless.
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
  std::vector<double> series(const std::string& name) const;
  std::size_t capacity() const { return capacity_; }

 private:
  struct Ring {
    std::vector<double> values;
    std::size_t next = 0;  ///< index of the oldest sample once full
  };
  std::size_t capacity_;
  std::map<std::string, Ring> rings_;
};

/// How the plot panel draws a series: the samples minus `offset`, between lo and hi.
struct PlotScale {
  double offset = 0.0;        ///< subtracted from every sample (the mean when `deviation`)
  double lo = 0.0, hi = 1.0;  ///< range of the plotted values (after the offset); hi > lo
  bool deviation = false;     ///< the series varies by less than kDeviationShare of its magnitude
};
/// Below this spread relative to its magnitude a series is plotted as its deviation from the mean (a
/// conserved quantity, rounding noise): its range label would otherwise read "[0.5, 0.5]".
inline constexpr double kDeviationShare = 1e-3;
PlotScale plotScale(const std::vector<double>& series);
/// The plot's caption: "name = last  [lo, hi]" with as many significant digits (3 to 15) as it takes
/// for lo and hi to read differently; for a deviation scale "name = last  mean m, deviation [lo, hi]".
std::string plotCaption(const std::string& name, const std::vector<double>& series, const PlotScale& scale);

}  // namespace pba::app
