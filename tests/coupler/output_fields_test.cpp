// The fields a solver declares with its first state (porosph.proto, OutputField) are what run.xdmf
// lists for its phase; a declaration run.xdmf could not carry (a name that breaks the index, a
// width that is no scalar, vector or tensor, an unknown type) is refused with the reason.
#include <gtest/gtest.h>

#include "coupler/run_record.h"

namespace porosph::coupler {
namespace {

TEST(OutputFields, DeclaredFieldsAreWhatTheIndexLists) {
  RunRecord record;
  record.dimension = 2;
  PhaseRecord& soil = record.phases["soil"];
  soil.phase = "soil";
  soil.output_fields = {{"velocity", 2, "Float", "m/s"}, {"overlap_steps", 1, "Int", ""}};
  const auto fields = xdmf_fields_of(record, soil);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[1].name, "overlap_steps");
  EXPECT_EQ(fields[1].cols, 1u);
  EXPECT_EQ(fields[1].number_type, "Int");
  // A solver that declares nothing gets its phase's built-in fields.
  soil.output_fields.clear();
  EXPECT_EQ(xdmf_fields_of(record, soil).size(), snapshot_fields_of_phase("soil", 2).size());
}

TEST(OutputFields, DeclarationsTheIndexCannotCarryAreRefused) {
  const auto problem = [](coupling::OutputField f) { return output_field_problem(f, 2); };
  EXPECT_EQ(problem({"absorbed_impulse", 2, "Float", "N s"}), "");
  EXPECT_EQ(problem({"stress", 9, "Float", "Pa"}), "");
  EXPECT_EQ(problem({"fixed", 1, "UChar", ""}), "");
  EXPECT_NE(problem({"", 1, "Float", ""}), "");
  EXPECT_NE(problem({"a\"/><Grid", 1, "Float", ""}), "");  // would break run.xdmf
  EXPECT_NE(problem({"x/y", 1, "Float", ""}), "");
  EXPECT_NE(problem({"position", 2, "Float", "m"}), "");  // the geometry, never a field
  EXPECT_NE(problem({std::string(65, 'a'), 1, "Float", ""}), "");
  EXPECT_NE(problem({"v", 3, "Float", ""}), "");  // neither 1, D = 2 nor 9
  EXPECT_NE(problem({"v", 0, "Float", ""}), "");
  EXPECT_NE(problem({"v", 1, "Double", ""}), "");
  EXPECT_NE(problem({"v", 1, "Float", "<b>"}), "");
}

}  // namespace
}  // namespace porosph::coupler
