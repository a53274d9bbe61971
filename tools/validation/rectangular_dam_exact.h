// The exact solution of the rectangular dam (rectangular_dam.h) by Polubarinova-Kochina
// ("Theory of Ground Water Movement", Princeton 1962, ch. VII; hodograph and Riemann
// P-functions), in the parametrisation of Shadab, Hiatt & Hesse (2022, "Polubarinova-Kochina
// solutions for steady unconfined groundwater flow: a free tool and its applicability"; their
// PKgui, github.com/mashadab/Polubarinova-Kochina-solutions, checked against P-K's tables). With
// K(m) the complete elliptic integral of parameter m (modulus sqrt(m)), s = sin φ, c = cos φ, all
// integrals over φ in (0, pi/2) unless noted, three parameters 0 < alpha < beta < 1 and a length C:
//   L   = C int K(alpha + (beta - alpha) s^2) / sqrt(1 - alpha - (beta - alpha) s^2)
//   h2  = C sqrt(alpha) int K(alpha s^2) s / sqrt((1 - alpha s^2)(beta - alpha s^2))
//   h0  = C int K(c^2) s c / sqrt((1 - (1 - alpha) s^2)(1 - (1 - beta) s^2))   (seepage face)
//   h1  = h2 + h0 + C int K(c^2) s / sqrt((1 - alpha s^2)(1 - beta s^2))
// and the free surface, for psi in (0, pi/2) (psi = 0: the exit point, psi = pi/2: x = 0):
//   x(psi) = L - C int_0^psi K(s^2) s / sqrt((1 - alpha s^2)(1 - beta s^2)),
//   y(psi) = h2 + h0 + C int_0^psi K(c^2) s / sqrt((1 - alpha s^2)(1 - beta s^2)).
// Given L, h1, h2, alpha, beta and C follow from the first, second and fourth equation (Newton).
// The integrands' endpoint singularities (K(1) = infinity, logarithmic) are integrable; the
// integrals use tanh-sinh quadrature. The exit point is h2 + h0.
#pragma once

namespace porosph::validation {

struct RectangularDam;

/// Polubarinova-Kochina's exact rectangular dam.
class RectangularDamExact {
 public:
  /// Solves for alpha, beta, C; throws std::runtime_error when Newton does not converge.
  explicit RectangularDamExact(const RectangularDam& dam);
  /// The exit point h2 + h0 [m]: the top of the seepage face.
  double exit_height() const;
  /// The free-surface height [m] at x (0 <= x <= L).
  double free_surface(double x) const;
  double alpha() const { return alpha_; }
  double beta() const { return beta_; }

 private:
  double length_, h1_, h2_, alpha_ = 0, beta_ = 0, c_ = 0;
};

}  // namespace porosph::validation
