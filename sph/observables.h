// Observables (scene::Observable): quantities measured on the free particles of one phase at every
// output time. prepare_observable decodes a scene observable once (kind, field, vectors, region);
// evaluate_observable then runs one O(N) reduction (sph/observable_reductions.h) without string
// work or allocation.
//
// Rules for missing data: a kind that needs a field the view does not provide (its pointer in
// ParticleView is null, e.g. porosity on water, pressure on soil, displacement on water) evaluates
// to NaN; so does mean_field velocity_z in 2D. Whether the field exists cannot be checked at
// prepare time (there is no view yet); the scene loader already rejects such combinations.
// With a region and no particle inside it: front_position, max_height and mean_field give NaN;
// max_speed, kinetic_energy, particle_count and max_displacement give 0.
#pragma once

#include <limits>
#include <stdexcept>
#include <string>

#include "scene/scene.h"
#include "sph/observable_reductions.h"
#include "sph/vector.h"

namespace porosph::sph {

/// An observable with its kind and field decoded and its vectors converted, ready to evaluate
/// every step without string work or allocation.
template <int D>
struct PreparedObservable {
  enum class Kind {
    FrontPosition,
    MaxHeight,
    MaxSpeed,
    KineticEnergy,
    ParticleCount,
    PressureAt,
    MeanField,
    MaxDisplacement,
    LoadVelocity,
    WallForce
  };
  using Field = ParticleField;
  std::string name;
  Kind kind = Kind::MaxSpeed;
  Vec<D> origin = Vec<D>::Zero(), direction = Vec<D>::Zero(), point = Vec<D>::Zero();
  Field field = Field::Density;  ///< MeanField only
  Region<D> region;              ///< every kind but PressureAt; has_region = false: all particles
  std::string load;              ///< LoadVelocity only: the soil load's label
  std::string wall;              ///< WallForce only: the moving wall's label
};

/// The ParticleField named `name` (observables[].field); throws std::invalid_argument naming
/// `what` for an unknown name.
inline ParticleField parse_particle_field(const std::string& name, const std::string& what) {
  static constexpr struct {
    const char* name;
    ParticleField field;
  } table[] = {{"density", ParticleField::Density},      {"mass", ParticleField::Mass},
               {"pressure", ParticleField::Pressure},    {"porosity", ParticleField::Porosity},
               {"speed", ParticleField::Speed},          {"velocity_x", ParticleField::VelocityX},
               {"velocity_y", ParticleField::VelocityY}, {"velocity_z", ParticleField::VelocityZ},
               {"stress_xx", ParticleField::StressXX},   {"stress_yy", ParticleField::StressYY},
               {"stress_zz", ParticleField::StressZZ},   {"stress_xy", ParticleField::StressXY},
               {"stress_xz", ParticleField::StressXZ},   {"stress_yz", ParticleField::StressYZ}};
  for (const auto& entry : table)
    if (name == entry.name) return entry.field;
  throw std::invalid_argument(what + ": unknown field '" + name + "'");
}

/// Decodes kind front_position | max_height | max_speed | kinetic_energy | particle_count |
/// pressure_at | mean_field | max_displacement, the field of mean_field and the optional region.
/// Throws std::invalid_argument on an unknown kind or field, a missing direction / point / field,
/// a vector of the wrong length, region_min without region_max (or the reverse), a region with
/// region_max <= region_min in some component, a region on pressure_at, or a field on a kind
/// other than mean_field.
template <int D>
PreparedObservable<D> prepare_observable(const scene::Observable& o) {
  using Kind = typename PreparedObservable<D>::Kind;
  PreparedObservable<D> p;
  p.name = o.name;
  const std::string what = "observable '" + o.name + "'";
  if (o.kind == "front_position" || o.kind == "max_height") {
    p.kind = o.kind == "max_height" ? Kind::MaxHeight : Kind::FrontPosition;
    p.origin = to_vec<D>(o.origin, what + " origin");
    p.direction = to_vec<D>(o.direction, what + " direction");
    if (o.direction.empty()) throw std::invalid_argument(what + ": direction is required");
  } else if (o.kind == "max_speed") {
    p.kind = Kind::MaxSpeed;
  } else if (o.kind == "kinetic_energy") {
    p.kind = Kind::KineticEnergy;
  } else if (o.kind == "particle_count") {
    p.kind = Kind::ParticleCount;
  } else if (o.kind == "pressure_at") {
    p.kind = Kind::PressureAt;
    p.point = to_vec<D>(o.point, what + " point");
    if (o.point.empty()) throw std::invalid_argument(what + ": point is required");
  } else if (o.kind == "mean_field") {
    p.kind = Kind::MeanField;
    if (o.field.empty()) throw std::invalid_argument(what + ": field is required for mean_field");
    p.field = parse_particle_field(o.field, what);
  } else if (o.kind == "max_displacement") {
    p.kind = Kind::MaxDisplacement;
  } else if (o.kind == "wall_force") {
    p.kind = Kind::WallForce;  // the water solver's own (moving_walls.h); NaN here
    p.direction = to_vec<D>(o.direction, what + " direction");
    p.wall = o.wall;
  } else if (o.kind == "load_velocity") {
    p.kind = Kind::LoadVelocity;  // the soil solver's own (surface_loads.h); NaN here
    p.load = o.load;
  } else {
    throw std::invalid_argument(what + ": unknown kind '" + o.kind + "'");
  }
  if (!o.field.empty() && p.kind != Kind::MeanField)
    throw std::invalid_argument(what + ": field is only allowed for kind mean_field");

  if (o.region_min.empty() != o.region_max.empty())
    throw std::invalid_argument(what + ": give region_min and region_max together or neither");
  if (!o.region_min.empty()) {
    if (p.kind == Kind::PressureAt)
      throw std::invalid_argument(what + ": pressure_at takes no region");
    p.region.has_region = true;
    p.region.lo = to_vec<D>(o.region_min, what + " region_min");
    p.region.hi = to_vec<D>(o.region_max, what + " region_max");
    if (!(p.region.hi.array() > p.region.lo.array()).all())
      throw std::invalid_argument(what +
                                  ": region_max must be greater than region_min in every "
                                  "component");
  }
  return p;
}

/// Value of `o` on the particles `p` (the kernel is used by pressure_at only). See the file
/// comment for the NaN / 0 rules.
template <int D, class Kernel>
double evaluate_observable(const PreparedObservable<D>& o, const ParticleView<D>& p,
                           const Kernel& kernel) {
  using Kind = typename PreparedObservable<D>::Kind;
  switch (o.kind) {
    case Kind::FrontPosition:
    case Kind::MaxHeight:
      return front_position(p, o.origin, o.direction, o.region);
    case Kind::MaxSpeed:
      return max_speed(p, o.region);
    case Kind::KineticEnergy:
      return kinetic_energy(p, o.region);
    case Kind::ParticleCount:
      return particle_count(p, o.region);
    case Kind::PressureAt:
      return pressure_at(p, o.point, kernel);
    case Kind::MeanField:
      return mean_field(p, o.field, o.region);
    case Kind::MaxDisplacement:
      return max_displacement(p, o.region);
    case Kind::LoadVelocity:  // needs the loads: a solver that has them evaluates it itself
    case Kind::WallForce:     // needs the wall pairs: the water solver evaluates it itself
      break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace porosph::sph
