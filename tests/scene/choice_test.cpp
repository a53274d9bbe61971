// scene::checked_choice: the value when allowed, else an error naming the key and the values.
#include "scene/choice.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace porosph::scene {
namespace {

TEST(CheckedChoice, ReturnsAnAllowedValueAndNamesKeyAndValuesOtherwise) {
  const std::string slip = "free_slip";
  EXPECT_EQ(checked_choice("water.wall_condition", slip, {"no_slip", "free_slip"}), "free_slip");
  try {
    checked_choice("water.wall_condition", "sticky", {"no_slip", "free_slip", "partial"});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "water.wall_condition: expected no_slip, free_slip or partial, got 'sticky'");
  }
}

}  // namespace
}  // namespace porosph::scene
