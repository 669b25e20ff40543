#include "app/window/plot_history.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pba::app {

void PlotHistory::record(double, const nlohmann::json& metrics) {
  if (!metrics.is_object()) return;
  for (const auto& [key, value] : metrics.items()) {
    double v = 0.0;
    if (value.is_number())
      v = value.get<double>();
    else if (value.is_boolean())
      v = value.get<bool>() ? 1.0 : 0.0;
    else
      continue;
    Ring& ring = rings_[key];
    if (ring.values.size() < capacity_) {
      ring.values.push_back(v);
    } else {
      ring.values[ring.next] = v;
      ring.next = (ring.next + 1) % capacity_;
    }
  }
}

void PlotHistory::clear() { rings_.clear(); }

std::vector<std::string> PlotHistory::names() const {
  std::vector<std::string> out;
  for (const auto& [key, ring] : rings_) out.push_back(key);
  return out;
}

std::vector<double> PlotHistory::series(const std::string& name) const {
  const auto it = rings_.find(name);
  if (it == rings_.end()) return {};
  const Ring& ring = it->second;
  std::vector<double> out;
  out.reserve(ring.values.size());
  for (std::size_t i = 0; i < ring.values.size(); ++i) out.push_back(ring.values[(ring.next + i) % ring.values.size()]);
  return out;
}

PlotScale plotScale(const std::vector<double>& series) {
  PlotScale scale;
  if (series.empty()) return scale;
  const auto [lo, hi] = std::minmax_element(series.begin(), series.end());
  double mean = 0.0;
  for (double v : series) mean += v / static_cast<double>(series.size());
  const double spread = *hi - *lo;
  scale.deviation = spread > 0.0 && spread < kDeviationShare * std::max(std::abs(*lo), std::abs(*hi));
  scale.offset = scale.deviation ? mean : 0.0;
  scale.lo = *lo - scale.offset;
  scale.hi = *hi - scale.offset;
  if (!(scale.hi > scale.lo)) {  // a constant series: a band around it
    const double pad = std::max(1e-12, 0.05 * std::abs(scale.lo));
    scale.lo -= pad;
    scale.hi += pad;
  }
  return scale;
}

namespace {
std::string formatG(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}
}  // namespace

std::string plotCaption(const std::string& name, const std::vector<double>& series, const PlotScale& scale) {
  if (series.empty()) return name;
  const auto [lo, hi] = std::minmax_element(series.begin(), series.end());
  const double a = *lo - scale.offset, b = *hi - scale.offset;
  int digits = 3;
  while (digits < 15 && a != b && formatG(a, digits) == formatG(b, digits)) ++digits;
  const int valueDigits = scale.deviation ? 9 : std::max(4, digits);
  std::string text = name + " = " + formatG(series.back(), valueDigits) + "  ";
  if (scale.deviation) text += "mean " + formatG(scale.offset, 9) + ", deviation ";
  return text + "[" + formatG(a, digits) + ", " + formatG(b, digits) + "]";
}

}  // namespace pba::app
