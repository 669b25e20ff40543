#pragma once
// Scene parameters declared once and used four ways: the ImGui panel (slider with unit and (?)
// tooltip), scene files (JSON, round-trip exact), command line overrides (--set name=value and the
// lab's own flags) and validation (range checks whose messages name the field).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "physics/core/enum_names.h"
#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba::app {

enum class ParamKind { Real, Integer, Flag, Choice, Text };

/// One editable parameter. get/set read and write the scene's own field.
struct Param {
  std::string name;     ///< key in scene files and on the command line, e.g. "restitution"
  std::string unit;     ///< shown after the slider, e.g. "m/s²"; empty for dimensionless
  std::string tooltip;  ///< the (?) help text: what it does and a typical value
  ParamKind kind = ParamKind::Real;
  double min = 0.0, max = 1.0;  ///< inclusive range (Real and Integer)
  bool logarithmic = false;     ///< slider in log scale (wide positive ranges)
  bool needsReset = false;      ///< changing it rebuilds the scene (e.g. particle count)
  /// Its maximum is an amount of work (a batch's solves, a benchmark's size), not a physical extreme:
  /// the extremes check (app/checks/param_extremes.h) does not run the scene there, only checks the refusals.
  bool workload = false;
  std::vector<std::string> choices;  ///< names of a Choice, in index order
  std::function<double()> get;       ///< Real, Integer, Flag, Choice
  std::function<void(double)> set;
  std::function<std::string()> getText;  ///< Text (file paths, lists of names)
  std::function<void(const std::string&)> setText;
  /// For Real parameters whose UI shows degrees: stored in radians, shown in degrees.
  bool degrees = false;
  /// When set and false, the panel hides the widget (a setting of another mode, e.g. the line search
  /// of a solver that is not selected). Scene files and the command line still read and write it.
  std::function<bool()> shown;
};

class Params {
 public:
  Params& real(std::string name, Real* value, double min, double max, std::string unit, std::string tooltip);
  /// An angle stored in radians and shown in degrees at the UI (docs/architecture.md §2); min/max in degrees.
  Params& angle(std::string name, Real* radians, double minDegrees, double maxDegrees, std::string tooltip);
  Params& integer(std::string name, int* value, int min, int max, std::string unit, std::string tooltip);
  Params& flag(std::string name, bool* value, std::string tooltip);
  Params& choice(std::string name, int* index, std::vector<std::string> choices, std::string tooltip);
  /// Free text, e.g. a model file path or a comma-separated list of joint names. The scene checks
  /// its meaning in reset() (a file that does not load is the scene's error to report).
  Params& text(std::string name, std::string* value, std::string tooltip);
  /// An enum chosen by name from its table (physics/core/enum_names.h), e.g. a lab's
  /// `constexpr auto kLayoutNames = enumNames<Layout>({{Layout::Grid, "grid"}, {Layout::Mesh, "mesh"}});`.
  template <typename Enum, std::size_t N>
  Params& choiceEnum(std::string name, Enum* value, const EnumNames<Enum, N>& names, std::string tooltip) {
    return choiceEnum(std::move(name), value, names.names(), std::move(tooltip));
  }
  template <typename Enum>
  Params& choiceEnum(std::string name, Enum* value, std::vector<std::string> choices, std::string tooltip) {
    Param p = makeChoice(std::move(name), std::move(choices), std::move(tooltip));
    p.get = [value] { return static_cast<double>(static_cast<int>(*value)); };
    p.set = [value](double v) { *value = static_cast<Enum>(static_cast<int>(v)); };
    return add(std::move(p));
  }
  /// Marks the most recently added parameter as one that needs a reset to take effect.
  Params& needsReset();
  /// Marks the most recently added parameter's maximum as a workload (Param::workload).
  Params& workload();
  /// Marks the most recently added Real parameter for a logarithmic slider.
  Params& logarithmic();
  /// Shows the most recently added parameter in the panel only while `predicate` holds.
  Params& shownWhen(std::function<bool()> predicate);

  const std::vector<Param>& all() const { return params_; }
  std::vector<Param>& all() { return params_; }
  const Param* find(const std::string& name) const;

  /// Sets `name` from text (a number, true/false, or a choice name); validates the range.
  /// Errors name the field: "restitution: must be in [0, 1], got 1.5".
  Status setFromText(const std::string& name, const std::string& text);
  /// Sets `name` from a JSON value; same validation. fieldPrefix is prepended to messages.
  Status setFromJson(const std::string& name, const nlohmann::json& value, const std::string& fieldPrefix);
  /// All parameters as a JSON object (numbers, booleans, choice names).
  nlohmann::json toJson() const;

 private:
  Param makeChoice(std::string name, std::vector<std::string> choices, std::string tooltip);
  Params& add(Param p);
  Status setChecked(const Param& p, double value, const std::string& field);
  std::vector<Param> params_;
};

}  // namespace pba::app
