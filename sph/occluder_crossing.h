// A guard for thin walls (sph/wall_occluders.h): a free particle whose step carries it across a
// thin wall's mid-plane is on the wrong side of the wall's tagged particles from then on, seen by
// the other side's pairs and hidden from its own: its state, and the run, are no longer the scene.
// A wall of max(L, m) layers per side holds a particle off with its pressure or stress as long as
// the steps are short against the layers; when it does not (a step too long, a wall too thin for
// the load), the solver stops the run and names the particle (solver_runtime.h reports it with
// the non-finite checks) instead of going on with a result that is wrong. The water and soil
// solvers check every free particle's move near an occluder, each step.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

#include "sph/vector.h"
#include "sph/wall_occluders.h"

namespace porosph::sph {

/// The occluder whose mid-plane patch the move from `before` to `after` crosses, or -1. Both
/// positions unwrapped (the move itself, not the minimum image).
template <int D>
inline int crossed_occluder(const WallOccluders<D>& occluders, const Vec<D>& before,
                            const Vec<D>& after) {
  for (std::size_t k = 0; k < occluders.size(); ++k)
    if (occluders[k].crossed_by(before, after)) return static_cast<int>(k);
  return -1;
}

/// The crossing with the lowest particle index of one step's drift loop (offer() is thread-safe;
/// crossings are rare, so a critical section costs nothing in a step without one).
template <int D>
struct FirstCrossing {
  std::int64_t index = -1;  ///< the particle's index; -1: none
  int wall = -1;            ///< the occluder crossed
  Vec<D> before = Vec<D>::Zero(), after = Vec<D>::Zero();
  void offer(std::int64_t i, int k, const Vec<D>& from, const Vec<D>& to) {
#pragma omp critical(porosph_first_crossing)
    if (index < 0 || i < index) index = i, wall = k, before = from, after = to;
  }
};

/// "<kind> particle <id> crossed the thin wall at x<axis> = <plane> (from ... to ...) in step N,
/// t = T s: ..." with what to change.
template <int D>
std::string occluder_crossing_message(const char* kind, long long id, const WallOccluder<D>& wall,
                                      const Vec<D>& before, const Vec<D>& after,
                                      unsigned long long step, double time) {
  std::ostringstream msg;
  msg << kind << " particle " << id << " crossed the thin wall at x" << wall.axis << " = "
      << wall.plane << " (from ";
  for (int k = 0; k < D; ++k) msg << (k ? ", " : "") << before[k];
  msg << " to ";
  for (int k = 0; k < D; ++k) msg << (k ? ", " : "") << after[k];
  msg << ") in step " << step << ", t = " << time
      << " s: the wall did not hold it off, and from here its pairs would be the other side's "
         "(a smaller run.cfl, or a wall of at least four layers)";
  return msg.str();
}

}  // namespace porosph::sph
