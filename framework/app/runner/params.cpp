#include "app/runner/params.h"

#include "app/runner/message_text.h"
#include "physics/core/format.h"

#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

namespace pba::app {
namespace {
std::string number(double v) { return formatExact(v); }
std::string shortNumber(double v) { return formatShort(v); }
}  // namespace

Params& Params::add(Param p) {
  params_.push_back(std::move(p));
  return *this;
}

Params& Params::real(std::string name, Real* value, double min, double max, std::string unit, std::string tooltip) {
  Param p{std::move(name), std::move(unit), std::move(tooltip), ParamKind::Real, min, max};
  p.get = [value] { return *value; };
  p.set = [value](double v) { *value = v; };
  return add(std::move(p));
}

Params& Params::angle(std::string name, Real* radians, double minDegrees, double maxDegrees, std::string tooltip) {
  Param p{std::move(name), "deg", std::move(tooltip), ParamKind::Real, minDegrees, maxDegrees};
  p.degrees = true;
  // Stored in radians, exchanged (UI, files, command line) in degrees.
  p.get = [radians] { return radToDeg(*radians); };
  p.set = [radians](double v) { *radians = degToRad(v); };
  return add(std::move(p));
}

Params& Params::integer(std::string name, int* value, int min, int max, std::string unit, std::string tooltip) {
  Param p{std::move(name), std::move(unit), std::move(tooltip), ParamKind::Integer, double(min), double(max)};
  p.get = [value] { return static_cast<double>(*value); };
  p.set = [value](double v) { *value = static_cast<int>(std::lround(v)); };
  return add(std::move(p));
}

Params& Params::flag(std::string name, bool* value, std::string tooltip) {
  Param p{std::move(name), "", std::move(tooltip), ParamKind::Flag, 0.0, 1.0};
  p.get = [value] { return *value ? 1.0 : 0.0; };
  p.set = [value](double v) { *value = v != 0.0; };
  return add(std::move(p));
}

Param Params::makeChoice(std::string name, std::vector<std::string> choices, std::string tooltip) {
  Param p{std::move(name), "", std::move(tooltip), ParamKind::Choice, 0.0, double(choices.size()) - 1.0};
  p.choices = std::move(choices);
  return p;
}

Params& Params::choice(std::string name, int* index, std::vector<std::string> choices, std::string tooltip) {
  Param p = makeChoice(std::move(name), std::move(choices), std::move(tooltip));
  p.get = [index] { return static_cast<double>(*index); };
  p.set = [index](double v) { *index = static_cast<int>(v); };
  return add(std::move(p));
}

Params& Params::text(std::string name, std::string* value, std::string tooltip) {
  Param p{std::move(name), "", std::move(tooltip), ParamKind::Text, 0.0, 0.0};
  p.getText = [value] { return *value; };
  p.setText = [value](const std::string& v) { *value = v; };
  return add(std::move(p));
}

Params& Params::needsReset() {
  if (!params_.empty()) params_.back().needsReset = true;
  return *this;
}

Params& Params::workload() {
  if (!params_.empty()) params_.back().workload = true;
  return *this;
}

Params& Params::logarithmic() {
  if (!params_.empty()) params_.back().logarithmic = true;
  return *this;
}

Params& Params::shownWhen(std::function<bool()> predicate) {
  if (!params_.empty()) params_.back().shown = std::move(predicate);
  return *this;
}

const Param* Params::find(const std::string& name) const {
  for (const Param& p : params_)
    if (p.name == name) return &p;
  return nullptr;
}

Status Params::setChecked(const Param& p, double value, const std::string& field) {
  if (!std::isfinite(value) || value < p.min || value > p.max) {
    std::string unit = p.unit.empty() ? "" : " " + p.unit;
    return Error{field + ": must be in [" + shortNumber(p.min) + ", " + shortNumber(p.max) + "]" + unit + ", got " +
                 number(value)};
  }
  if (p.kind == ParamKind::Integer && value != std::floor(value))
    return Error{field + ": must be a whole number, got " + number(value)};
  p.set(value);
  return Status::success();
}

Status Params::setFromText(const std::string& name, const std::string& text) {
  const Param* p = find(name);
  if (!p) return Error{shownText(name) + ": no such parameter in this scene"};
  switch (p->kind) {
    case ParamKind::Text:
      p->setText(text);
      return Status::success();
    case ParamKind::Flag:
      if (text == "true" || text == "1" || text == "on") return setChecked(*p, 1.0, name);
      if (text == "false" || text == "0" || text == "off") return setChecked(*p, 0.0, name);
      return Error{name + ": expected true or false, got '" + shownText(text) + "'"};
    case ParamKind::Choice: {
      std::string names;
      for (size_t i = 0; i < p->choices.size(); ++i) {
        if (p->choices[i] == text) return setChecked(*p, double(i), name);
        names += (i ? ", " : "") + p->choices[i];
      }
      return Error{name + ": unknown value '" + shownText(text) + "' (one of: " + names + ")"};
    }
    case ParamKind::Real:
    case ParamKind::Integer: {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end == nullptr || *end != '\0')
        return Error{name + ": expected a number, got '" + shownText(text) + "'"};
      return setChecked(*p, v, name);
    }
  }
  return Error{name + ": unsupported parameter kind"};
}

Status Params::setFromJson(const std::string& name, const nlohmann::json& value, const std::string& prefix) {
  const std::string field = prefix + shownText(name);
  const Param* p = find(name);
  if (!p) return Error{field + ": no such parameter in this scene"};
  switch (p->kind) {
    case ParamKind::Text:
      if (!value.is_string()) return Error{field + ": expected a string, got " + shownJson(value)};
      p->setText(value.get<std::string>());
      return Status::success();
    case ParamKind::Flag:
      if (!value.is_boolean()) return Error{field + ": expected true or false, got " + shownJson(value)};
      return setChecked(*p, value.get<bool>() ? 1.0 : 0.0, field);
    case ParamKind::Choice:
      if (!value.is_string()) return Error{field + ": expected a string, got " + shownJson(value)};
      {
        Status s = setFromText(name, value.get<std::string>());
        return s ? s : Status(Error{prefix + s.error()});
      }
    case ParamKind::Real:
    case ParamKind::Integer:
      if (!value.is_number()) return Error{field + ": expected a number, got " + shownJson(value)};
      return setChecked(*p, value.get<double>(), field);
  }
  return Error{field + ": unsupported parameter kind"};
}

nlohmann::json Params::toJson() const {
  nlohmann::json out = nlohmann::json::object();
  for (const Param& p : params_) {
    if (p.kind == ParamKind::Text) {
      out[p.name] = p.getText();
      continue;
    }
    const double v = p.get();
    switch (p.kind) {
      case ParamKind::Flag:
        out[p.name] = v != 0.0;
        break;
      case ParamKind::Choice:
        out[p.name] = p.choices.at(static_cast<size_t>(v));
        break;
      case ParamKind::Integer:
        out[p.name] = static_cast<long long>(std::llround(v));
        break;
      case ParamKind::Real:
        out[p.name] = v;
        break;
      case ParamKind::Text:
        break;  // handled above
    }
  }
  return out;
}

}  // namespace pba::app
