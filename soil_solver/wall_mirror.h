// Stress divergence of eq. 5 against a straight wall, summed over mirror images of the soil
// (ghost particles: Libersky et al. 1993, "High strain Lagrangian hydrodynamics", J. Comput. Phys.
// 109, 67-75; Randles & Libersky 1996, Comput. Methods Appl. Mech. Eng. 139, 375-408).
//
// Why not the wall particles: a wall pair's zeroth-order term 2 sigma_i sum_w V_w grad W is how a
// wall holds the soil, and along the wall's normal it depends on where the soil's lattice sits
// along the wall. Once the soil has slid by a fraction o of a spacing, the normal sum of the first
// soil column grows by about 0.05 / 0.22 / 0.88 % at o / dp = 0.05 / 0.1 / 0.2 (cubic spline,
// h = 1.2 dp, a lattice sum): the wall pushes that column away with 2 sigma_nn / rho times that
// share of its sum, an acceleration that grows as (o / dp)^2 / dp. A column settling 0.52 mm
// between frictionless walls ends with its wall column offset from the interior by 1.7 / 13 / 45 Pa
// of vertical stress at dp 10 / 5 / 2.5 mm (0.74 % of its horizontal stress at 2.5 mm, the lattice
// sum's 0.88 %), an error that grows as dp falls (docs/validation-studies.md, soil_column).
//
// The images slide with the soil: the image of free neighbour j (and of i itself) across the
// wall's face is x_j' = x_j - 2 ((x_j - x_f) . n) n, with the mass and density of j and the stress
//   sigma_j' = R sigma_j R - r_j rho_j (g . (x_j' - x_j)) I,
// R = I - 2 n n (the shear on the face changes sign, so the face carries no shear traction); the
// second term continues the weight linearly into
// the wall, as update_soil_wall_state does for the wall particles (Adami et al. 2012 eq. 27), with
// the weight that the stress carries: r_j rho_j g, r_j = weight_ratio (the submerged share of
// eq. 16 under water, 1 when dry; the wall particles take the full rho_f). For
// a soil lattice in registry with the wall's the images are the wall particles (same places and,
// for a uniform state, the same stress), so nothing changes at rest; once the soil slides the
// images slide with it. The face is half a spacing beyond the wall layer nearest to i, where the
// wall layers are generated (walls and the soil fill their boxes from dp / 2 inside the faces).
//
// The kinematics (eq. 7-8 and the continuity equation) sum over the same images, with the velocity
// mirrored about the wall's: v_j' = v_j - 2 ((v_j - v_w) . n) n (the normal part reflected). With
// the wall particles instead, the
// continuity term v_i . sum_w V_w grad W (the wall's own velocity, Adami et al. 2012) integrates,
// as the soil settles along the wall, to the change of the wall's kernel sum with the lattice
// offset: with images in eq. 5 alone, the soil_column's two wall columns still ended 0.05 % denser
// than the interior at dp 2.5 mm (0.17 / 0.34 % with the wall particles everywhere), and the
// interior moved 3 um towards them.
//
// Used where i sees one straight free-slip wall only (sees_one_straight_wall: every fixed neighbour
// lies in a straight stretch, on one axis) and all of them lie on one side of i: near corners, wall
// ends and gaps between two walls the wall particles stay (stress_divergence.h). The artificial
// viscosity and the artificial stress keep the wall particles (they act only on approach and in
// tension). No-slip walls keep them too: with images (R = I, v_j' = 2 v_w - v_j) the granular
// collapse on its rough base went unstable at dp 1.25 mm after 0.5 s (time step collapsed; it runs
// to 1 s with the wall particles, and at dp 5 / 2.5 mm with images), not understood yet.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "soil_solver/soil_particles.h"
#include "soil_solver/straight_walls.h"
#include "soil_solver/stress_divergence.h"
#include "soil_solver/velocity_gradient.h"
#include "sph/vector.h"

namespace porosph::soil {

/// The face of the wall that particle i sees, relative to i.
template <int D>
struct MirrorFace {
  sph::Vec<D> normal;    ///< unit normal of the face, from the wall into the soil
  double distance = 0;   ///< distance of i from the face along the normal [m]
  sph::Vec<D> velocity;  ///< the wall's own velocity (of its particle nearest to i)
  Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity();  ///< R = I - 2 n n, embedded in 3D
};

/// Finds the face of the one straight wall free particle i sees (`axis_normal` from
/// sees_one_straight_wall): false unless all fixed neighbours lie on one side of i along that axis
/// and are all free-slip.
template <int D, class NeighbourList>
bool find_mirror_face(const NeighbourList& nl, std::int64_t i, const SoilParticles<D>& P, double dp,
                      const sph::Vec<D>& axis_normal, MirrorFace<D>& face) {
  double nearest = INFINITY;
  int side = 0;
  for (auto it = nl.mid(i); it != nl.end(i); ++it) {
    const double along = axis_normal.dot(it->x_ab);  // x_i - x_w along the axis
    const int s = along > 0.0 ? 1 : (along < 0.0 ? -1 : 0);
    if (s == 0 || (side != 0 && s != side) || P.no_slip[it->b]) return false;
    side = s;
    if (std::abs(along) < nearest) {
      nearest = std::abs(along);
      face.velocity = P.velocity[it->b];
    }
  }
  if (side == 0) return false;
  face.normal = static_cast<double>(side) * axis_normal;
  face.distance = nearest - 0.5 * dp;
  const Eigen::Vector3d n3 = embed_in_3d<D>(face.normal);
  face.reflection = Eigen::Matrix3d::Identity() - 2.0 * n3 * n3.transpose();
  return face.distance > 0.0;
}

/// How free particle i sees its fixed neighbours in eq. 5 and the kinematics: through the images
/// of `face` (wall_mirror.h), through the wall form of one straight wall (`straight`, normal
/// `plane_normal`; stress_divergence.h), or, when neither, as plain wall particles.
template <int D>
struct WallView {
  bool straight = false, images = false;
  sph::Vec<D> plane_normal = sph::Vec<D>::Zero();
  MirrorFace<D> face;
};

template <int D, class NeighbourList>
WallView<D> view_walls(const NeighbourList& nl, std::int64_t i, const SoilParticles<D>& P,
                       double dp, bool images_on) {
  WallView<D> view;
  view.straight =
      sees_one_straight_wall<D>(nl, i, P.wall_normal, P.straight_wall, view.plane_normal);
  view.images =
      view.straight && images_on && find_mirror_face<D>(nl, i, P, dp, view.plane_normal, view.face);
  return view;
}

/// sigma_j' of the file comment: the image of a free particle's stress across the face.
template <int D>
inline Eigen::Matrix3d mirrored_stress(const Eigen::Matrix3d& sigma_j, double rho_weight_j,
                                       const sph::Vec<D>& gravity, const MirrorFace<D>& face,
                                       double height_j) {
  // r_j rho_j g . (x_j' - x_j), x_j' - x_j = -2 height_j n, height_j = (x_j - x_f) . n
  const double weight = rho_weight_j * gravity.dot((-2.0 * height_j) * face.normal);
  return face.reflection * sigma_j * face.reflection - weight * Eigen::Matrix3d::Identity();
}

/// Calls visit(j, height_j, x_image, r) for the image of i itself and of each free neighbour j of
/// i that lies on i's side of `face` (height_j > 0: not a thin wall's other side) and within the
/// kernel's support of i: x_image = x_i - x_j' = x_ij + 2 height_j n, r = |x_image|, with
/// height_j = (x_j - x_f) . n = distance_i - n . x_ij (x_ij = x_i - x_j).
template <int D, class NeighbourList, class Visit>
void visit_images(const NeighbourList& nl, double support, std::int64_t i,
                  const MirrorFace<D>& face, Visit&& visit) {
  using Vec = sph::Vec<D>;
  const auto image = [&](std::int64_t j, const Vec& x_ij) {
    const double height_j = face.distance - face.normal.dot(x_ij);
    if (height_j <= 0.0) return;
    const Vec x_image = x_ij + (2.0 * height_j) * face.normal;
    const double r = x_image.norm();
    if (r < support) visit(j, height_j, x_image, r);
  };
  image(i, Vec::Zero());
  for (auto it = nl.begin(i); it != nl.mid(i); ++it) image(it->b, it->x_ab);
}

/// Acceleration of free particle i from the images of itself and of its free neighbours across
/// `face` (eq. 5 with sigma_j' above). `rho_weight_i` as in the pair terms (rho^s when submerged).
template <int D, class NeighbourList, class Kernel>
sph::Vec<D> mirror_stress_divergence_acceleration(const NeighbourList& nl, const Kernel& kernel,
                                                  std::int64_t i, const SoilParticles<D>& P,
                                                  double rho_weight_i, const sph::Vec<D>& gravity,
                                                  const MirrorFace<D>& face) {
  using Vec = sph::Vec<D>;
  const Eigen::Matrix3d& sigma_i = P.stress[i];
  Vec acc = Vec::Zero();
  visit_images<D>(nl, kernel.support(), i, face,
                  [&](std::int64_t j, double height_j, const Vec& x_image, double r) {
                    const Eigen::Matrix3d sigma_image = mirrored_stress<D>(
                        P.stress[j], P.weight_ratio[j] * P.density[j], gravity, face, height_j);
                    acc += stress_divergence_acceleration<D>(P.mass[j], sigma_i, sigma_image,
                                                             rho_weight_i, P.density[j],
                                                             Vec(kernel.grad_factor(r) * x_image));
                  });
  return acc;
}

/// Velocity gradient (eq. 7-8) and divergence (continuity) contributions of the images of i and of
/// its free neighbours across `face`, added to `grad_v` and `divergence` as the solver's pair loop
/// adds a neighbour's (velocity_gradient.h; drho_i/dt = rho_i divergence).
template <int D, class NeighbourList, class Kernel>
void add_mirror_kinematics(const NeighbourList& nl, const Kernel& kernel, std::int64_t i,
                           const SoilParticles<D>& P, const MirrorFace<D>& face, MatD<D>& grad_v,
                           double& divergence) {
  using Vec = sph::Vec<D>;
  const Vec& v_i = P.velocity[i];
  visit_images<D>(
      nl, kernel.support(), i, face, [&](std::int64_t j, double, const Vec& x_image, double r) {
        const Vec& v_j = P.velocity[j];
        const Vec v_image = v_j - (2.0 * (v_j - face.velocity).dot(face.normal)) * face.normal;
        const Vec grad_w = kernel.grad_factor(r) * x_image;
        const double volume_j = P.mass[j] / P.density[j];
        accumulate_velocity_gradient<D>(grad_v, volume_j, Vec(v_image - v_i), grad_w);
        divergence += volume_j * (v_i - v_image).dot(grad_w);
      });
}

}  // namespace porosph::soil
