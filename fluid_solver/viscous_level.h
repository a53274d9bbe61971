// Time level of the viscous terms (Morris 1997 viscosity, Monaghan 1992 artificial viscosity) in
// the modified Verlet scheme (sph/integrator.h).
//
// A Verlet step is a leapfrog step, v^{n+1} = v^{n-1} + 2 dt a^n. For a damping term a = -lambda v
// evaluated at v^n the amplification factors z solve z^2 + 2 lambda dt z - 1 = 0: besides the
// physical root z = 1 - lambda dt + ... there is a computational mode z = -(1 + lambda dt + ...)
// that grows by (1 + lambda dt) per step whatever dt is: the leapfrog scheme is unstable for
// damping terms (Durran 2010, Numerical Methods for Fluid Dynamics, 2nd ed., Springer, ch. 2). Only
// the Euler step every euler_every = N steps (which restarts the two chains) holds it down: for N =
// 40 the spectral radius of one cycle exceeds 1 once lambda dt > ~0.1 (0.09 at 0.086, 6.8 at
// 0.172). The stiffest mode of the Morris Laplacian has lambda_max = 5.68 nu / h^2 (cubic spline, h
// = 1.2 dp, square lattice), and dt is set by the sound speed, so lambda_max dt = 5.68 C_cfl nu /
// (h c0) grows as the resolution is refined: 0.043 / 0.086 / 0.172 in the Taylor-Green vortex (Re
// 100, c0 = 10 U) at dp = L/50 / L/100 / L/200, where the finest level broke down at t ~ 0.12 s.
//
// The standard remedy (Durran, same place) evaluates the damping terms of a Verlet step at the
// level n-1 the step starts from: for them the step is then a forward step of length 2 dt,
//   v^{n+1} = v^{n-1} + 2 dt (a_rest(v^n) + a_visc(v^{n-1})),
// with z = 1 - 2 lambda dt for a pure damping: no growing mode while lambda dt <= 1, which the
// viscous limit dt <= 0.125 h^2 / nu (lambda_max dt <= 0.71) guarantees. Its time error, lambda^2
// dt^2 per step, is far below the spatial error for the physical modes (lambda dt = 3e-4 for the
// Taylor-Green mode at L/50). An Euler step evaluates them at v^n, as before. The wall particles'
// mirrored velocities (wall_boundary.h) follow the water velocities of the same level. The stored
// v^{n-1} is the "folded" level of verlet_step_coupled (v^{n-1} plus the coupling impulse): the
// level the step starts from.
//
// The density diffusion (density_diffusion.h) is a damping term of the continuity equation with
// lambda_max dt = 5.68 delta C_cfl c0 / (c0 + |v|) ~ 0.10 at delta = 0.1 at every resolution. At
// rho^n the N = 40 cycle kept it stable (spectral radius 0.18), but euler_every = 100 did not, nor
// delta = 0.2 (the Taylor-Green vortex blew up at t ~ 0.1 s at L/50 and L/100). Since 2026-12-05 a
// Verlet step evaluates it at the stored rho^{n-1} too (fill_diffusion_states), a forward step of
// 2 dt for it, stable while lambda dt <= 1: delta up to 1 / (5.68 C_cfl) = 0.88 at run.cfl = 0.2.
#pragma once

namespace porosph::water {

/// The velocity level the viscous terms act on: v^n (Current; Euler steps) or the stored v^{n-1}
/// (Previous; Verlet steps).
enum class ViscousLevel { Current, Previous };

}  // namespace porosph::water
