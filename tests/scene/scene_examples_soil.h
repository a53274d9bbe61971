// Scenes with soil shared by the scene tests: a soil-only granular column and a coupled
// water-soil tank.
#pragma once

#include <string>

namespace porosph::scene::test {

/// A 2D granular column collapsing in a container open at the top (aluminium bars of Bui et al.
/// 2008: E = 0.84 MPa, nu = 0.3, phi = 19.8 deg); every soil key but the required ones left at
/// its default.
inline const std::string kGranularColumn2D = R"(# Granular column collapse, soil only.
[scene]
name = "granular_column"

[run]
end_time = 1.0
output_interval = 0.05
dp = 0.002
dt0 = 1e-5

[domain]
min = [-0.01, -0.01]
max = [0.51, 0.2]

[soil]
initial_stress = "geostatic"

[[soil.materials]]
name = "aluminium_bars"
density = 2650
young_modulus = 0.84e6
poisson_ratio = 0.3
friction_angle = 19.8

[[soil.blocks]]
shape = "box"
min = [0, 0]
max = [0.2, 0.1]
material = "aluminium_bars"

[[walls]]
shape = "container"
min = [0.0, 0.0]
max = [0.5, 0.2]
open_faces = ["y+"]

[[observables]]
name = "runout"
kind = "front_position"
direction = [1, 0]

[[observables]]
name = "settlement"
kind = "max_displacement"

[[observables]]
name = "base_stress"
kind = "mean_field"
field = "stress_yy"
region_min = [0.0, 0.0]
region_max = [0.05, 0.01]
)";

/// A 2D tank: a sand mound (E, nu; Kozeny-Carman seepage) on a rigid gravel bed (K, G;
/// Forchheimer-Den Adel seepage) under water, a baffle wall for the water only.
inline const std::string kSubmergedBed2D = R"([scene]
name = "submerged_bed"
description = "Sand on a rigid gravel bed under water"

[run]
end_time = 0.2
output_interval = 0.01
dp = 0.005
dt0 = 1e-5
c_a = 0.005
max_steps = 5000

[domain]
min = [-0.02, -0.02]
max = [0.42, 0.5]

[water]
sound_speed = 15.0

[[water.blocks]]
shape = "box"
min = [0, 0]
max = [0.4, 0.3]
label = "pool"

[soil]
solver = "my_soil_solver"
wall_condition = "free_slip"
alpha = 0.2
beta = 0
artificial_stress_epsilon = 0.3
artificial_stress_exponent = 4
sound_speed = 40.0
k0 = "elastic"
damping_duration = 0.05
damping_coefficient = 0.05

[[soil.materials]]
name = "gravel"
density = 1700
saturated_density = 2050
porosity = 0.35
bulk_modulus = 5e6
shear_modulus = 3e6
friction_angle = 40
fixed = true
seepage = "forchheimer_den_adel"
d15 = 0.01

[[soil.materials]]
name = "sand"
density = 1500
porosity = 0.42
young_modulus = 1e7
poisson_ratio = 0.25
cohesion = 500
friction_angle = 32
dilatancy_angle = 2
artificial_stress = true
seepage = "darcy_kozeny_carman"
effective_diameter = 0.0004
variable_permeability = false
wet_cohesion_loss = true

[[soil.blocks]]
shape = "box"
min = [0, 0]
max = [0.4, 0.05]
material = "gravel"

[[soil.blocks]]
shape = "polygon"
vertices = [[0.1, 0.05], [0.3, 0.05], [0.2, 0.15]]
material = "sand"
label = "mound"

[[walls]]
shape = "container"
min = [0.0, 0.0]
max = [0.4, 0.5]
open_faces = ["y+"]

[[walls]]
shape = "box"
min = [0.38, 0.3]
max = [0.4, 0.5]
phases = ["water"]
condition = "free_slip"
label = "baffle"

[[observables]]
name = "sand_porosity"
kind = "mean_field"
phase = "soil"
field = "porosity"
region_min = [0.1, 0.05]
region_max = [0.3, 0.15]

[[observables]]
name = "p_bed"
kind = "pressure_at"
point = [0.2, 0.06]

[[observables]]
name = "water_count"
kind = "particle_count"
)";

}  // namespace porosph::scene::test
