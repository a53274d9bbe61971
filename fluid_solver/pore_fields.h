// The water's view of the soil it flows through, for water.h5 (docs/water-in-soil.md). The water
// continuum fills the whole volume, so inside soil its velocity is the Darcy (superficial)
// velocity q; the pore (seepage) velocity is q / n with n the soil porosity around the particle,
// which the coupler computes (n_a = 1 - sum_i V_i (1 - n_i) W_ia) and sends with the commands
// that ask for a snapshot (StepCommand.porosity). Written only in scenes with soil; recomputed
// once per snapshot, never in the step loop.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/snapshot_writer.h"
#include "sph/particle_fields.h"
#include "sph/vector.h"

namespace porosph::water {

template <int D>
class PoreFields {
 public:
  using Vec = sph::Vec<D>;
  explicit PoreFields(bool with_soil = false) : active_(with_soil) {}
  bool active() const { return active_; }

  /// Porosity 1 for every particle, then `overlap_porosity[k]` for particle overlap_index[k] (an
  /// empty vector: no soil near, 1 everywhere); pore velocity = velocity / porosity (0 where the
  /// porosity is 0). Throws std::invalid_argument on a size mismatch. Does nothing when inactive.
  void update(const std::vector<double>& overlap_porosity,
              const std::vector<std::int32_t>& overlap_index, const std::vector<Vec>& velocity) {
    if (!active_) return;
    if (!overlap_porosity.empty() && overlap_porosity.size() != overlap_index.size()) {
      throw std::invalid_argument("porosity: " + std::to_string(overlap_porosity.size()) +
                                  " values for " + std::to_string(overlap_index.size()) +
                                  " overlap particles");
    }
    porosity_.assign(velocity.size(), 1.0);
    for (std::size_t k = 0; k < overlap_porosity.size(); ++k)
      porosity_[overlap_index[k]] = overlap_porosity[k];
    pore_velocity_.resize(velocity.size());
    for (std::size_t a = 0; a < velocity.size(); ++a)
      pore_velocity_[a] = porosity_[a] > 0.0 ? Vec(velocity[a] / porosity_[a]) : Vec::Zero();
  }

  /// Appends `porosity` and `pore_velocity` (when active). Before the first update() (a
  /// snapshot without a command, in tests) they read 1 and the velocity itself.
  void append_fields(std::vector<io::FieldView>& fields, const std::vector<Vec>& velocity) {
    if (!active_) return;
    if (porosity_.size() != velocity.size()) update({}, {}, velocity);
    fields.push_back(sph::scalar_field("porosity", porosity_));
    fields.push_back(sph::packed_field("pore_velocity", pore_velocity_, "m/s"));
  }

  const std::vector<double>& porosity() const { return porosity_; }

 private:
  bool active_ = false;
  std::vector<double> porosity_;
  std::vector<Vec> pore_velocity_;
};

}  // namespace porosph::water
