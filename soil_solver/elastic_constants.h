// Isotropic linear elasticity of the soil skeleton (Hooke's law in the rate form of seed paper
// eq. 6). The solver works with the bulk modulus K and the shear modulus G; scenes give Young's
// modulus E and Poisson's ratio nu. Standard relations (e.g. Timoshenko & Goodier, Theory of
// Elasticity, or any continuum-mechanics text):
//   K = E / (3 (1 - 2 nu)),   G = E / (2 (1 + nu)),
//   E = 9 K G / (3 K + G),    nu = (3 K - 2 G) / (2 (3 K + G)).
// Granular-flow example (Bui et al. 2008, docs/cases.md granular_collapse): E = 0.84 MPa, nu = 0.3
// gives K = 0.7 MPa.
#pragma once

#include <cmath>
#include <stdexcept>

namespace porosph::soil {

/// The four isotropic elastic constants, always mutually consistent (build them with the
/// functions below).
struct ElasticConstants {
  double young = 0.0;          ///< E [Pa]
  double poisson = 0.0;        ///< nu [-]
  double bulk_modulus = 0.0;   ///< K [Pa]
  double shear_modulus = 0.0;  ///< G [Pa]
};

/// K, G from E > 0 and -1 < nu < 1/2 (throws std::invalid_argument otherwise: nu = 1/2 would
/// make K infinite, an incompressible skeleton that an explicit solver cannot handle).
inline ElasticConstants elastic_from_young_poisson(double young, double poisson) {
  if (!(young > 0.0)) throw std::invalid_argument("soil elasticity: E must be > 0");
  if (!(poisson > -1.0 && poisson < 0.5)) {
    throw std::invalid_argument("soil elasticity: nu must lie in (-1, 0.5)");
  }
  ElasticConstants e;
  e.young = young;
  e.poisson = poisson;
  e.bulk_modulus = young / (3.0 * (1.0 - 2.0 * poisson));
  e.shear_modulus = young / (2.0 * (1.0 + poisson));
  return e;
}

/// E, nu from K > 0 and G > 0 (throws std::invalid_argument otherwise).
inline ElasticConstants elastic_from_bulk_shear(double bulk_modulus, double shear_modulus) {
  if (!(bulk_modulus > 0.0) || !(shear_modulus > 0.0)) {
    throw std::invalid_argument("soil elasticity: K and G must be > 0");
  }
  ElasticConstants e;
  e.bulk_modulus = bulk_modulus;
  e.shear_modulus = shear_modulus;
  e.young = 9.0 * bulk_modulus * shear_modulus / (3.0 * bulk_modulus + shear_modulus);
  e.poisson =
      (3.0 * bulk_modulus - 2.0 * shear_modulus) / (2.0 * (3.0 * bulk_modulus + shear_modulus));
  return e;
}

}  // namespace porosph::soil
