// Plain struct <-> Protobuf message conversions: every field survives a trip through the wire
// format, and converting a message of the same shape again reuses the storage.
#include "proto/wire_convert.h"

#include <gtest/gtest.h>

#include <string>

namespace porosph::wire {
namespace {

coupling::StepState sample_state() {
  coupling::StepState s;
  s.step = 17;
  s.time = 0.125;
  s.dt_limit = 1e-4;
  s.dt_cfl = 2e-4;
  s.dt_viscous = 3e-4;
  s.dt_force = 1e-4;
  s.overlap_id = {4, 9, -1};
  s.overlap_position = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  s.overlap_velocity = {-1, 1, -2, 2, -3, 3};
  s.overlap_density = {1000, 1001, 1002};
  s.overlap_mass = {0.1, 0.1, 0.2};
  s.overlap_porosity = {0.3, 0.35, 0.4};
  s.overlap_material = {0, 1, 2};
  s.region_min = {-1, -2};
  s.region_max = {3, 4};
  s.diagnostics.particle_count = 100;
  s.diagnostics.free_count = 60;
  s.diagnostics.removed_count = 2;
  s.diagnostics.mass = 6.5;
  s.diagnostics.kinetic_energy = 0.75;
  s.diagnostics.max_speed = 1.5;
  s.diagnostics.momentum = {0.25, -0.5};
  s.diagnostics.observables = {{"front", 0.3}, {"head", 1.25}};
  s.diagnostics.physics_seconds = 0.01;
  s.diagnostics.wall_seconds = 0.0125;
  s.diagnostics.communication_seconds = 0.002;
  s.diagnostics.impulse_sources = {"gravity", "walls"};
  s.diagnostics.external_impulse = {0.0, -1e-3, 2.5e-4, 1e-300};
  s.diagnostics.balance_momentum = {0.125, -0.375};
  s.checkpoint_written = 3;
  return s;
}

coupling::StepState through_the_wire(const coupling::StepState& in) {
  StepState message;
  to_wire(in, message);
  StepState parsed;
  EXPECT_TRUE(parsed.ParseFromString(message.SerializeAsString()));
  coupling::StepState out;
  from_wire(parsed, out);
  return out;
}

TEST(WireConvert, StepStateSurvivesSerialisation) {
  const coupling::StepState in = sample_state();
  const coupling::StepState out = through_the_wire(in);
  // Doubles travel as their 8-byte IEEE representation: equality is exact.
  EXPECT_EQ(out.step, in.step);
  EXPECT_EQ(out.time, in.time);
  EXPECT_EQ(out.dt_limit, in.dt_limit);
  EXPECT_EQ(out.dt_cfl, in.dt_cfl);
  EXPECT_EQ(out.dt_viscous, in.dt_viscous);
  EXPECT_EQ(out.dt_force, in.dt_force);
  EXPECT_EQ(out.overlap_id, in.overlap_id);
  EXPECT_EQ(out.overlap_position, in.overlap_position);
  EXPECT_EQ(out.overlap_velocity, in.overlap_velocity);
  EXPECT_EQ(out.overlap_density, in.overlap_density);
  EXPECT_EQ(out.overlap_mass, in.overlap_mass);
  EXPECT_EQ(out.overlap_porosity, in.overlap_porosity);
  EXPECT_EQ(out.overlap_material, in.overlap_material);
  EXPECT_EQ(out.region_min, in.region_min);
  EXPECT_EQ(out.region_max, in.region_max);
  EXPECT_EQ(out.diagnostics.particle_count, 100u);
  EXPECT_EQ(out.diagnostics.free_count, 60u);
  EXPECT_EQ(out.diagnostics.removed_count, 2u);
  EXPECT_EQ(out.diagnostics.mass, 6.5);
  EXPECT_EQ(out.diagnostics.kinetic_energy, 0.75);
  EXPECT_EQ(out.diagnostics.max_speed, 1.5);
  EXPECT_EQ(out.diagnostics.momentum, in.diagnostics.momentum);
  EXPECT_EQ(out.diagnostics.observables, in.diagnostics.observables);
  EXPECT_EQ(out.diagnostics.physics_seconds, 0.01);
  EXPECT_EQ(out.diagnostics.wall_seconds, 0.0125);
  EXPECT_EQ(out.diagnostics.communication_seconds, 0.002);
  EXPECT_EQ(out.diagnostics.impulse_sources, in.diagnostics.impulse_sources);
  EXPECT_EQ(out.diagnostics.external_impulse, in.diagnostics.external_impulse);
  EXPECT_EQ(out.diagnostics.balance_momentum, in.diagnostics.balance_momentum);
  EXPECT_EQ(out.checkpoint_written, in.checkpoint_written);
}

// A solver that books no external impulses (a foreign one, or an older built-in) leaves the
// fields empty, and they arrive empty.
TEST(WireConvert, ExternalImpulseBooksAreOptional) {
  coupling::StepState in = sample_state();
  in.diagnostics.impulse_sources.clear();
  in.diagnostics.external_impulse.clear();
  in.diagnostics.balance_momentum.clear();
  const coupling::StepState out = through_the_wire(in);
  EXPECT_TRUE(out.diagnostics.impulse_sources.empty());
  EXPECT_TRUE(out.diagnostics.external_impulse.empty());
  EXPECT_TRUE(out.diagnostics.balance_momentum.empty());
}

TEST(WireConvert, StepCommandSetupAndTimingSurviveSerialisation) {
  coupling::StepCommand command;
  command.step = 3;
  command.time = 0.5;
  command.dt = 2.5e-5;
  command.write_output = true;
  command.output_index = 7;
  command.stop = true;
  command.interaction_acceleration = {1, -2, 3, -4};
  command.saturation = {0.5, 1.0};
  command.porosity = {0.4, 0.7};
  command.other_region_min = {0, 0};
  command.other_region_max = {1, 2};
  command.write_checkpoint = true;
  command.checkpoint_index = 4;
  StepCommand message, parsed;
  to_wire(command, message);
  ASSERT_TRUE(parsed.ParseFromString(message.SerializeAsString()));
  coupling::StepCommand back;
  from_wire(parsed, back);
  EXPECT_EQ(back.step, 3u);
  EXPECT_EQ(back.time, 0.5);
  EXPECT_EQ(back.dt, 2.5e-5);
  EXPECT_TRUE(back.write_output);
  EXPECT_EQ(back.output_index, 7u);
  EXPECT_TRUE(back.stop);
  EXPECT_EQ(back.interaction_acceleration, command.interaction_acceleration);
  EXPECT_EQ(back.saturation, command.saturation);
  EXPECT_EQ(back.porosity, command.porosity);
  EXPECT_EQ(back.other_region_min, command.other_region_min);
  EXPECT_EQ(back.other_region_max, command.other_region_max);
  EXPECT_TRUE(back.write_checkpoint);
  EXPECT_EQ(back.checkpoint_index, 4u);

  coupling::SetupData setup;
  setup.phase = "soil";
  setup.scene_toml = "[run]\nend_time = 1.0\n";
  setup.scene_name = "column";
  setup.output_dir = "/tmp/out";
  setup.dimension = 3;
  setup.dp = 0.01;
  setup.h = 0.012;
  setup.dt0 = 1e-4;
  setup.end_time = 2;
  setup.gravity = {0, 0, -9.81};
  setup.timeout_seconds = 12;
  setup.restore_checkpoint = "/tmp/out/checkpoint/soil_0002.h5";
  setup.resume_output_index = 5;
  wire::Setup setup_message;
  to_wire(setup, setup_message);
  coupling::SetupData setup_back;
  from_wire(setup_message, setup_back);
  EXPECT_EQ(setup_back.phase, "soil");
  EXPECT_EQ(setup_back.scene_toml, setup.scene_toml);
  EXPECT_EQ(setup_back.scene_name, "column");
  EXPECT_EQ(setup_back.output_dir, "/tmp/out");
  EXPECT_EQ(setup_back.dimension, 3);
  EXPECT_EQ(setup_back.dp, 0.01);
  EXPECT_EQ(setup_back.h, 0.012);
  EXPECT_EQ(setup_back.dt0, 1e-4);
  EXPECT_EQ(setup_back.end_time, 2);
  EXPECT_EQ(setup_back.gravity, setup.gravity);
  EXPECT_EQ(setup_back.timeout_seconds, 12);
  EXPECT_EQ(setup_back.restore_checkpoint, setup.restore_checkpoint);
  EXPECT_EQ(setup_back.resume_output_index, 5u);

  coupling::Timing timing{1.5, 1.0, 0.25};
  Goodbye goodbye;
  to_wire(timing, goodbye);
  coupling::Timing timing_back;
  from_wire(goodbye, timing_back);
  EXPECT_EQ(timing_back.wall_seconds, 1.5);
  EXPECT_EQ(timing_back.physics_seconds, 1.0);
  EXPECT_EQ(timing_back.communication_seconds, 0.25);
}

TEST(WireConvert, ReconvertingOverwritesEverythingAndDropsStaleObservables) {
  coupling::StepState first = sample_state();
  coupling::StepState second = sample_state();
  second.overlap_id = {1};
  second.overlap_porosity.clear();
  second.diagnostics.observables = {{"head", 2.0}};
  StepState message;
  to_wire(first, message);
  to_wire(second, message);
  coupling::StepState out = sample_state();
  from_wire(message, out);
  EXPECT_EQ(out.overlap_id, std::vector<std::int64_t>{1});
  EXPECT_TRUE(out.overlap_porosity.empty());
  EXPECT_EQ(message.diagnostics().observables().size(), 1u);
  EXPECT_EQ(out.diagnostics.observables, (std::map<std::string, double>{{"head", 2.0}}));
}

TEST(WireConvert, SameShapeReusesVectorStorage) {
  const coupling::StepState in = sample_state();
  StepState message;
  to_wire(in, message);
  coupling::StepState out;
  from_wire(message, out);
  const double* position_data = out.overlap_position.data();
  const std::int64_t* id_data = out.overlap_id.data();
  const double* wire_position_data = message.overlap_position().data();
  coupling::StepState moved = in;
  for (double& x : moved.overlap_position) x += 1.0;
  to_wire(moved, message);
  from_wire(message, out);
  EXPECT_EQ(out.overlap_position, moved.overlap_position);
  EXPECT_EQ(out.overlap_position.data(), position_data);  // no reallocation
  EXPECT_EQ(out.overlap_id.data(), id_data);
  EXPECT_EQ(message.overlap_position().data(), wire_position_data);
}

}  // namespace
}  // namespace porosph::wire
