// The water's porosity and pore velocity fields (fluid_solver/pore_fields.h): written only in
// scenes with soil; porosity 1 but at the overlap particles the coupler sent it for; pore
// velocity = velocity / porosity.
#include "fluid_solver/pore_fields.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace porosph::water {
namespace {

using Vec = sph::Vec<2>;

TEST(PoreFields, WithoutSoilWritesNothing) {
  PoreFields<2> none(false);
  std::vector<io::FieldView> fields;
  const std::vector<Vec> velocity(3, Vec(1.0, 0.0));
  none.update({0.5}, {1}, velocity);
  none.append_fields(fields, velocity);
  EXPECT_TRUE(fields.empty());
}

TEST(PoreFields, PoreVelocityIsTheDarcyVelocityOverThePorosity) {
  PoreFields<2> pore(true);
  const std::vector<Vec> velocity = {Vec(0.0, -0.01), Vec(0.2, 0.0), Vec(0.0, -0.004),
                                     Vec(1.0, 1.0)};
  pore.update({0.4, 0.5, 0.0}, {2, 1, 3}, velocity);  // overlap particle k is water particle index
  std::vector<io::FieldView> fields;
  pore.append_fields(fields, velocity);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0].name, "porosity");
  EXPECT_EQ(fields[1].name, "pore_velocity");
  ASSERT_EQ(fields[1].rows, 4u);
  ASSERT_EQ(fields[1].cols, 2u);
  const double* n = fields[0].f64;
  const double* u = fields[1].f64;
  EXPECT_EQ(n[0], 1.0);  // no soil near: the Darcy and the pore velocity are the same
  EXPECT_EQ(u[1], -0.01);
  EXPECT_EQ(n[1], 0.5);
  EXPECT_DOUBLE_EQ(u[2], 0.4);
  EXPECT_EQ(n[2], 0.4);
  EXPECT_DOUBLE_EQ(u[5], -0.01);
  EXPECT_EQ(n[3], 0.0);  // no pore space: 0, not a division by zero
  EXPECT_EQ(u[6], 0.0);

  pore.update({}, {}, velocity);  // a snapshot with no soil near: porosity 1 everywhere
  EXPECT_EQ(pore.porosity(), std::vector<double>(4, 1.0));
  EXPECT_THROW(pore.update({0.4}, {0, 1}, velocity), std::invalid_argument);
}

TEST(PoreFields, BeforeAnyPorosityTheFieldsMatchTheParticles) {
  PoreFields<2> pore(true);
  const std::vector<Vec> velocity(5, Vec(0.0, 1.0));
  std::vector<io::FieldView> fields;
  pore.append_fields(fields, velocity);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0].rows, 5u);
  EXPECT_EQ(fields[1].f64[1], 1.0);
}

}  // namespace
}  // namespace porosph::water
