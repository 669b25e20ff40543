#include "app/plot_history.h"

namespace pba::app {

void PlotHistory::record(double, const nlohmann::json& metrics) {
  if (!metrics.is_object()) return;
  for (const auto& [key, value] : metrics.items()) {
    float v = 0.0f;
    if (value.is_number()) v = value.get<float>();
    else if (value.is_boolean()) v = value.get<bool>() ? 1.0f : 0.0f;
    else continue;
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

std::vector<float> PlotHistory::series(const std::string& name) const {
  const auto it = rings_.find(name);
  if (it == rings_.end()) return {};
  const Ring& ring = it->second;
  std::vector<float> out;
  out.reserve(ring.values.size());
  for (std::size_t i = 0; i < ring.values.size(); ++i) out.push_back(ring.values[(ring.next + i) % ring.values.size()]);
  return out;
}

}  // namespace pba::app
