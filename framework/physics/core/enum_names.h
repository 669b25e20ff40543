#pragma once
// One way to name an enum's values for the UI, scene files, the command line and messages: a table of
// (value, name) pairs written once beside the enum, for example
//
//   enum class Layout { Grid, Mesh };
//   inline constexpr auto kLayoutNames = enumNames<Layout>({{Layout::Grid, "grid"}, {Layout::Mesh, "mesh"}});
//
// The pairs must follow the enum's order from 0 (a UI choice's index is the value): a table out of that
// order does not compile, since enumNames() then calls a function that is not constexpr. The table
// answers both ways (name(), parse()) and lists the names in order (names(), for a choice list).
#include <array>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pba {

template <typename Enum>
struct EnumName {
  Enum value;
  std::string_view name;           ///< short, for files, the command line and choice lists ("dls")
  std::string_view description{};  ///< optional, for people ("Damped least squares")
};

template <typename Enum, std::size_t N>
struct EnumNames {
  std::array<EnumName<Enum>, N> entries;

  constexpr std::size_t size() const { return N; }
  /// The value's name; "?" for a value outside the table.
  constexpr std::string_view name(Enum value) const {
    const auto i = static_cast<std::size_t>(value);
    return i < N ? entries[i].name : std::string_view("?");
  }
  /// The value's description (empty when the table gives none).
  constexpr std::string_view description(Enum value) const {
    const auto i = static_cast<std::size_t>(value);
    return i < N ? entries[i].description : std::string_view();
  }
  /// The value called `text`, if any.
  constexpr std::optional<Enum> parse(std::string_view text) const {
    for (const EnumName<Enum>& e : entries)
      if (e.name == text) return e.value;
    return std::nullopt;
  }
  /// Every value, in the enum's order.
  constexpr std::array<Enum, N> values() const {
    std::array<Enum, N> v{};
    for (std::size_t i = 0; i < N; ++i) v[i] = entries[i].value;
    return v;
  }
  /// Every name, in the enum's order (a choice list).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    out.reserve(N);
    for (const EnumName<Enum>& e : entries) out.emplace_back(e.name);
    return out;
  }
  /// The names joined by `separator`, for messages ("one of: a, b, c").
  std::string joined(std::string_view separator = ", ") const {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) (out += i ? separator : "") += entries[i].name;
    return out;
  }
};

namespace detail {
// Not constexpr on purpose: reaching it while a table is built at compile time is a compile error.
[[noreturn]] inline void enumNamesOutOfOrder() { std::abort(); }
}  // namespace detail

template <typename Enum, std::size_t N>
constexpr EnumNames<Enum, N> enumNames(const EnumName<Enum> (&entries)[N]) {
  EnumNames<Enum, N> table{};
  for (std::size_t i = 0; i < N; ++i) {
    if (static_cast<std::size_t>(entries[i].value) != i) detail::enumNamesOutOfOrder();
    table.entries[i] = entries[i];
  }
  return table;
}

}  // namespace pba
