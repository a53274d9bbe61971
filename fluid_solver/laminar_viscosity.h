// The laminar viscosity laws of the water: the second term of the seed paper's eq. 3, one struct
// per law, and the one dispatch from water.laminar_viscosity to the pair loops compiled for each
// (water_rates.cpp). Adding a law (docs/contributing.md): a struct here, listed in
// LaminarViscosityLaws, and its registration in scene/terms_water.cpp (laminar_viscosity_law),
// which makes its name a value of water.laminar_viscosity and lists its term in run.json.
//
// Every law sums over the pairs a b of water, and of water and no-slip wall particles (mirrored
// velocity), with the regularised factor F_ab = x_ab . grad_a W_ab / (r_ab^2 + eta^2),
// eta^2 = 0.01 h^2 (viscosity_morris.h). Since F_ab <= 0 each opposes v_ab: it is dissipative.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "fluid_solver/viscosity_morris.h"
#include "sph/vector.h"

namespace porosph::water {

/// What a law may use of the scene: the dynamic viscosity and the rest density.
struct LaminarViscosityConstants {
  double mu = 0.0;    ///< water.viscosity [Pa s]
  double rho0 = 0.0;  ///< water.rho0 [kg/m^3]
};

/// What a law may use of the pair a b.
template <int D>
struct LaminarPair {
  double m_b;                   ///< mass of b [kg] (per metre in 2D)
  double rho_a, rho_b;          ///< densities [kg/m^3]
  double inv_rho_a, inv_rho_b;  ///< their inverses
  double factor;                ///< F_ab [1/m^(D+2)]
  sph::Vec<D> v_ab;             ///< v_a - v_b (the mirrored wall velocity for a wall b)
};

/// No laminar term (water.viscosity = 0).
struct NoLaminarViscosity {
  static constexpr const char* kName = "";
};

/// Morris, Fox & Zhu (1997), J. Comput. Phys. 136, 214-226, eq. 8:
///   (dv_a/dt) = sum_b m_b (mu_a + mu_b) / (rho_a rho_b) F_ab v_ab,  mu_a = mu_b = mu.
struct MorrisViscosity {
  static constexpr const char* kName = "morris";
  template <int D>
  static sph::Vec<D> acceleration(const LaminarViscosityConstants& c, const LaminarPair<D>& p) {
    return morris_viscous_acceleration<D>(p.m_b, c.mu, c.mu, p.inv_rho_a, p.inv_rho_b, p.factor,
                                          p.v_ab);
  }
};

/// Lo & Shao (2002), Appl. Ocean Res. 24, 275-286 (the laminar term of DualSPHysics):
///   (dv_a/dt) = sum_b m_b 4 nu0 / (rho_a + rho_b) F_ab v_ab,  nu0 = mu / rho0.
/// Equal to Morris's where rho_a = rho_b = rho0; the pair's density enters as its mean.
struct LoShaoViscosity {
  static constexpr const char* kName = "lo_shao";
  template <int D>
  static sph::Vec<D> acceleration(const LaminarViscosityConstants& c, const LaminarPair<D>& p) {
    return (p.m_b * 4.0 * (c.mu / c.rho0) / (p.rho_a + p.rho_b) * p.factor) * p.v_ab;
  }
};

/// The registered laws, in the order of scene/terms_water.cpp.
using LaminarViscosityLaws = std::tuple<MorrisViscosity, LoShaoViscosity>;

/// The names of LaminarViscosityLaws (for the registry's consistency test).
inline std::vector<std::string> laminar_viscosity_law_names() {
  return std::apply([](auto... law) { return std::vector<std::string>{decltype(law)::kName...}; },
                    LaminarViscosityLaws{});
}

/// f(law) with the law named `name` as its concrete type ("" : NoLaminarViscosity); returns what
/// f returns. Throws std::invalid_argument for a name no law here has.
template <class Result, class F>
Result visit_laminar_viscosity(const std::string& name, F&& f) {
  if (name.empty()) return f(NoLaminarViscosity{});
  std::optional<Result> result;
  std::apply(
      [&](auto... law) {
        ((!result && name == decltype(law)::kName ? (void)(result = f(law)) : void()), ...);
      },
      LaminarViscosityLaws{});
  if (!result)
    throw std::invalid_argument("water.laminar_viscosity: no law '" + name +
                                "' in fluid_solver/laminar_viscosity.h");
  return *std::move(result);
}

}  // namespace porosph::water
