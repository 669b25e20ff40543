// The enum-name tables (physics/core/enum_names.h): both directions, the order a choice list needs, and
// that every named enum of the library round-trips through its own table (a name used twice in one
// table would parse to the first value only). A table out of the enum's order is a compile error, which
// a test cannot show; `enumNames` is also run outside a constant expression below.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "physics/cloth/solver.h"
#include "physics/collision/broad_phase.h"
#include "physics/core/enum_names.h"
#include "physics/ode/integrators.h"
#include "physics/rigid/settings.h"

namespace pba {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr auto kFruitNames =
    enumNames<Fruit>({{Fruit::Apple, "apple", "Malus"}, {Fruit::Pear, "pear"}, {Fruit::Plum, "plum", "Prunus"}});

TEST(EnumNames, NamesParsesAndListsInTheEnumsOrder) {
  static_assert(kFruitNames.size() == 3);
  static_assert(kFruitNames.name(Fruit::Pear) == "pear");
  static_assert(kFruitNames.parse("plum") == Fruit::Plum);
  EXPECT_EQ(kFruitNames.name(static_cast<Fruit>(7)), "?");
  EXPECT_FALSE(kFruitNames.parse("Pear").has_value());  // names are exact
  EXPECT_FALSE(kFruitNames.parse("").has_value());
  EXPECT_EQ(kFruitNames.names(), (std::vector<std::string>{"apple", "pear", "plum"}));
  EXPECT_EQ(kFruitNames.joined(), "apple, pear, plum");
  EXPECT_EQ(kFruitNames.description(Fruit::Apple), "Malus");
  EXPECT_TRUE(kFruitNames.description(Fruit::Pear).empty());
  const auto values = kFruitNames.values();
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(static_cast<std::size_t>(values[i]), i);
}

TEST(EnumNames, ATableBuiltAtRunTimeIsTheSame) {
  const EnumName<Fruit> entries[] = {{Fruit::Apple, "apple"}, {Fruit::Pear, "pear"}, {Fruit::Plum, "plum"}};
  const auto table = enumNames<Fruit>(entries);
  EXPECT_EQ(table.names(), kFruitNames.names());
}

template <typename Table>
void expectRoundTrip(const Table& table, const char* what) {
  std::set<std::string> seen;
  for (const auto& e : table.entries) {
    EXPECT_FALSE(e.name.empty()) << what;
    EXPECT_TRUE(seen.insert(std::string(e.name)).second) << what << ": '" << e.name << "' twice";
    EXPECT_EQ(table.parse(e.name), e.value) << what << ": " << e.name;
  }
}

TEST(EnumNames, EveryLibraryTableRoundTrips) {
  expectRoundTrip(cloth::kClothSolverNames, "cloth solvers");
  expectRoundTrip(cloth::kBendingModelNames, "bending models");
  expectRoundTrip(ode::kIntegratorNames, "integrators");
  expectRoundTrip(rigid::kPositionCorrectionNames, "position corrections");
  expectRoundTrip(rigid::kFrictionModelNames, "friction models");
  expectRoundTrip(rigid::kGyroscopicModeNames, "gyroscopic modes");
  expectRoundTrip(collision::kBroadPhaseNames, "broad phases");
}

}  // namespace
}  // namespace pba
