// Jaumann (objective) stress rate of the elastic soil skeleton, seed paper eq. 6 and the first
// four terms of eq. 12a (Bui et al. 2008, eq. 26-27 there):
//   dsigma^{ab}/dt = sigma^{ag} omega^{bg} + sigma^{gb} omega^{ag}             (co-rotation)
//                  + 2 G e_dot^{ab} + K eps_dot^{gg} delta^{ab}                (Hooke)
// with e_dot = eps_dot - (eps_dot^{gg} / 3) delta the DEVIATORIC strain rate: eq. 6 calls eps_dot
// in its 2G term "deviatoric"; with the total strain rate there the volumetric stiffness would be
// K + 2G/3 instead of K. This is the standard form of Bui et al. 2008.
//
// Matrix form of the co-rotation: sigma^{ag} omega^{bg} = (sigma omega^T)^{ab} = -(sigma
// omega)^{ab} and sigma^{gb} omega^{ag} = (omega sigma)^{ab} since omega is antisymmetric, hence
//   co-rotation = omega sigma - sigma omega,
// which is what a stress carried by a rigid rotation R(t) obeys: d(R s0 R^T)/dt = W s - s W with
// W = dR/dt R^T, the spin of eq. 8 (checked in the tests with a rotating uniaxial stress).
#pragma once

#include <Eigen/Core>

namespace porosph::soil {

/// sigma^{ag} omega^{bg} + sigma^{gb} omega^{ag}  (= omega sigma - sigma omega for antisymmetric
/// omega; written in the index form of eq. 12a so it holds for any omega).
inline Eigen::Matrix3d corotational_stress_rate(const Eigen::Matrix3d& sigma,
                                                const Eigen::Matrix3d& spin) {
  return sigma * spin.transpose() + spin * sigma;
}

/// Hooke rate 2 G (eps_dot - tr(eps_dot)/3 delta) + K tr(eps_dot) delta.
inline Eigen::Matrix3d hooke_stress_rate(double bulk_modulus, double shear_modulus,
                                         const Eigen::Matrix3d& strain_rate) {
  const double vol = strain_rate.trace();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  return 2.0 * shear_modulus * (strain_rate - (vol / 3.0) * identity) +
         (bulk_modulus * vol) * identity;
}

/// Elastic Jaumann stress rate: co-rotation + Hooke (eq. 6 solved for dsigma/dt).
inline Eigen::Matrix3d elastic_stress_rate(double bulk_modulus, double shear_modulus,
                                           const Eigen::Matrix3d& sigma,
                                           const Eigen::Matrix3d& strain_rate,
                                           const Eigen::Matrix3d& spin) {
  return corotational_stress_rate(sigma, spin) +
         hooke_stress_rate(bulk_modulus, shear_modulus, strain_rate);
}

}  // namespace porosph::soil
