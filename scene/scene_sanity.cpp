// Whether a valid scene means something (issue 29): rules over the typed scene, after the schema
// and the relations between keys. Each finds the key to blame and fails with file:line:key.
//  - the derived quantities a solver computes stay finite and positive: |g|, the domain's extent,
//    the water's pressure scale rho0 c^2, kinematic viscosity mu / rho0 and particle mass
//    rho0 dp^D, each soil material's P-wave speed, the seepage law's inputs (a water viscosity > 0,
//    gravity > 0, a grain diameter whose square does not underflow);
//  - a speed the scene prescribes to water (inflow zones, the Taylor-Green field) stays below
//    Mach kMachLimit;
//  - the output interval is not far below the expected time step (kMinOutputIntervalOverDt);
//  - a flow_rate inflow zone is a whole number of lattice rows across the flow (or it would carry
//    another discharge than flow_rate).
#include "scene/scene_sanity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "porous/seepage_laws.h"
#include "scene/scene_internal.h"
#include "scene/thin_walls.h"

namespace porosph::scene {
namespace {

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

/// Three significant digits, for estimates ("1.86e-05").
std::string rounded(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return format_number(std::strtod(text, nullptr));
}

double norm_of(const std::vector<double>& v) {
  double sum = 0.0;
  for (double c : v) sum += c * c;
  return std::sqrt(sum);
}

/// The fastest sound speed of the phases present [m/s].
double fastest_sound_speed(const Scene& scene) {
  double c = 0.0;
  if (scene.water) c = std::max(c, scene.water->sound_speed);
  if (scene.soil) c = std::max(c, scene.soil->effective_sound_speed());
  return c;
}

class SanityChecker {
 public:
  SanityChecker(const toml::table& root, const Scene& scene, const ErrorContext& errors)
      : root_(root), scene_(scene), errors_(errors) {}

  void check() {
    run();
    if (scene_.water) water(*scene_.water);
    if (scene_.soil)
      for (std::size_t i = 0; i < scene_.soil->materials.size(); ++i)
        material(scene_.soil->materials[i], "soil.materials[" + std::to_string(i) + "]");
    output_interval();
  }

 private:
  /// Fails at `key` (its line, if the scene has it).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    errors_.fail(root_.at_path(key).node(), key, message);
  }

  void run() const {
    const double g = norm_of(scene_.run.gravity);
    if (!std::isfinite(g))
      fail("run.gravity", "its magnitude |g| overflows to " + format_number(g));
    for (std::size_t k = 0; k < scene_.domain.min.size(); ++k) {
      const double extent = scene_.domain.max[k] - scene_.domain.min[k];
      if (!std::isfinite(extent))
        fail("domain.max", std::string("the domain's extent along ") + axis_name(k) +
                               " overflows to " + format_number(extent));
      const double support = 2.0 * scene_.h();  // both kernels vanish beyond 2 h
      if (extent < support)
        fail("run.dp",
             "gives a kernel support 2 h = 2 run.h_factor dp = " + format_number(support) +
                 " m wider than the domain along " + axis_name(k) + " (" + format_number(extent) +
                 " m): the particles would all be neighbours of one cell; lower run.dp");
    }
  }

  void water(const WaterPhase& w) const {
    const double pressure_scale = w.rho0 * w.sound_speed * w.sound_speed;
    if (!finite_positive(pressure_scale))
      fail("water.sound_speed",
           "the pressure scale rho0 c^2 = " + format_number(pressure_scale) +
               " Pa is not a finite positive number (water.rho0 = " + format_number(w.rho0) + ")");
    const double nu = w.viscosity / w.rho0;
    if (!std::isfinite(nu) || (w.viscosity > 0.0 && !(nu > 0.0)))
      fail("water.viscosity", "the kinematic viscosity mu / rho0 = " + format_number(nu) +
                                  " m^2/s is out of the range of a double (water.rho0 = " +
                                  format_number(w.rho0) + ")");
    for (std::size_t i = 0; i < w.inflows.size(); ++i) {
      const std::string key = "water.inflow[" + std::to_string(i) + "]";
      const bool given = root_.at_path(key + ".velocity").node() != nullptr;
      prescribed_speed(w.inflows[i].speed, key + (given ? ".velocity" : ".flow_rate"), w);
      if (!given) whole_rows_across(w.inflows[i], key);
    }
    for (std::size_t i = 0; i < w.reservoirs.size(); ++i) {
      const ReservoirZone& r = w.reservoirs[i];
      if (r.boundary != "open" || r.direction.size() != r.min.size()) continue;
      std::size_t axis = 0;
      for (std::size_t k = 0; k < r.direction.size(); ++k)
        if (r.direction[k] != 0.0) axis = k;
      const double dp = scene_.run.dp, support = 2.0 * scene_.h();
      // the buffer's rows along the normal, as the solver counts them
      const double rows = static_cast<double>(lattice_count(r.min[axis], r.max[axis], dp));
      if (rows * dp < support - 1e-12 * dp)
        fail("water.reservoir[" + std::to_string(i) + "].max",
             "the open reservoir's buffer holds " + format_number(rows) + " rows of run.dp = " +
                 format_number(dp) + " m along its direction (" + format_number(rows * dp) +
                 " m), less than the kernel support 2 h = " + format_number(support) +
                 " m: the water next to the open side would lack neighbours; widen the box");
    }
    if (w.initial_velocity == "taylor_green")
      prescribed_speed(w.taylor_green_speed, "water.taylor_green_speed", w);
    const double mass = w.rho0 * std::pow(scene_.run.dp, scene_.run.dimension);
    if (!finite_positive(mass))
      fail("run.dp",
           "the water particle mass rho0 dp^" + std::to_string(scene_.run.dimension) + " = " +
               format_number(mass) +
               " kg is not a finite positive number (water.rho0 = " + format_number(w.rho0) + ")");
  }

  /// A flow_rate zone carries flow_rate only when the lattice of run.dp fills its box across the
  /// flow: its particles move at flow_rate / cross_section, so the discharge is that speed times
  /// the rows' width (rows x dp per axis across the direction, lattice_count), not the box's.
  /// A box 0.04 m across at dp 0.0283 holds one row and would carry 71 % of flow_rate.
  void whole_rows_across(const InflowZone& z, const std::string& key) const {
    const double dp = scene_.run.dp;
    double filled = 1.0;
    std::string across;
    for (std::size_t k = 0; k < z.direction.size() && k < z.min.size(); ++k) {
      if (z.direction[k] != 0.0) continue;
      const double extent = z.max[k] - z.min[k];
      const double rows = static_cast<double>(lattice_count(z.min[k], z.max[k], dp));
      filled *= rows * dp / extent;
      across += (across.empty() ? "" : ", ") + rounded(extent) + " m along " +
                std::string(1, "xyz"[k % 3]) + " holds " + format_number(rows) + " row" +
                (rows == 1.0 ? "" : "s") + ", " + rounded(rows * dp) + " m";
    }
    if (std::fabs(filled - 1.0) <= 1e-6) return;
    fail(key + ".max", "the zone's box is not a whole number of rows of run.dp = " +
                           format_number(dp) + " m across the flow (" + across +
                           "): its particles move at flow_rate / cross_section, so it would "
                           "carry " +
                           rounded(100.0 * filled) +
                           " % of flow_rate; make the box a whole number of dp across (and "
                           "cross_section with it) or choose run.dp to fit");
  }

  /// A speed the scene prescribes to water stays below kMachLimit c0.
  void prescribed_speed(double speed, const std::string& key, const WaterPhase& w) const {
    if (std::fabs(speed) <= kMachLimit * w.sound_speed) return;
    fail(key, "prescribes water at " + rounded(std::fabs(speed)) + " m/s, Mach " +
                  rounded(std::fabs(speed) / w.sound_speed) +
                  " for water.sound_speed = " + format_number(w.sound_speed) +
                  " m/s; the weakly compressible model holds "
                  "below Mach " +
                  format_number(kMachLimit) + " (c0 >= 10 |v|max by design)");
  }

  void material(const SoilMaterial& m, const std::string& key) const {
    const double modulus = m.bulk_modulus + 4.0 * m.shear_modulus / 3.0;
    const double speed = std::sqrt(modulus / m.density);
    if (!finite_positive(speed)) {
      const bool young = root_.at_path(key + ".young_modulus").node() != nullptr;
      fail(key + (young ? ".young_modulus" : ".bulk_modulus"),
           "the P-wave speed sqrt((K + 4G/3) / density) = " + format_number(speed) +
               " m/s is not a finite positive number (K = " + format_number(m.bulk_modulus) +
               " Pa, G = " + format_number(m.shear_modulus) +
               " Pa, density = " + format_number(m.density) + " kg/m^3)");
    }
    if (m.seepage == "none" || !scene_.water) return;  // the law acts between water and soil
    const std::string law = "seepage '" + m.seepage + "' of " + key;
    // No gravity is allowed: the drag's unit weight gamma_w = rho0 |g| then takes the standard
    // gravity 9.80665 m/s^2 (coupler/interaction/soil_water_interaction.cpp), so that a
    // conductivity stays a material property (the momentum-exchange test runs without gravity).
    const std::vector<porous::SeepageLawSpec> laws = porous::seepage_laws();
    const porous::SeepageLawSpec* spec = porous::find_seepage_law(laws, m.seepage);
    if (spec == nullptr) return;  // the schema refuses unknown laws
    if (spec->needs_viscosity && !(scene_.water->viscosity > 0.0))
      fail("water.viscosity", law + " needs a water viscosity > 0 (its kinematic viscosity)");
    for (const KeySpec& parameter : spec->keys) {  // the laws use their keys squared at most
      const double d = m.seepage_parameter(parameter.name());
      const std::string unit = parameter.unit.empty() ? std::string()
                               : parameter.unit.find('/') == std::string::npos
                                   ? " " + parameter.unit + "^2"
                                   : " (" + parameter.unit + ")^2";
      if (!finite_positive(d * d))
        fail(key + "." + parameter.name(), "its square " + format_number(d * d) + unit +
                                               " is not a finite positive number (" + law + ")");
    }
  }

  void output_interval() const {
    const double dt = expected_time_step(scene_);
    if (scene_.run.output_interval >= kMinOutputIntervalOverDt * dt) return;
    fail("run.output_interval",
         "is " + format_number(scene_.run.output_interval) +
             " s, far below the expected time step ~" + rounded(dt) +
             " s (min of dt0, cfl h / c, the viscous and gravity limits): the coupler writes at "
             "most one output per step, so every step would write a snapshot; give at least " +
             rounded(kMinOutputIntervalOverDt * dt) + " s (run.dt0 for an output every step)");
  }

  const toml::table& root_;
  const Scene& scene_;
  const ErrorContext& errors_;
};

}  // namespace

double expected_time_step(const Scene& scene) {
  const RunSettings& r = scene.run;
  const double h = scene.h();
  double dt = r.dt0;
  const double c = fastest_sound_speed(scene);
  if (c > 0.0) dt = std::min(dt, r.cfl * h / c);
  if (scene.water && scene.water->viscosity > 0.0)
    dt = std::min(dt, r.viscous_coefficient * h * h * scene.water->rho0 / scene.water->viscosity);
  const double g = norm_of(r.gravity);
  if (g > 0.0) dt = std::min(dt, r.c_a * std::sqrt(h / g));
  return dt;
}

void check_scene_sanity(const toml::table& root, const Scene& scene, const ErrorContext& errors) {
  SanityChecker(root, scene, errors).check();
}

}  // namespace porosph::scene
