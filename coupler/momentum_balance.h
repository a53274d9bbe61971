// The external-impulse ledger of a phase (docs/coupling.md, "The external-impulse ledger"): the
// impulses its solver books each step by source (gravity, walls, inflow, ...; Diagnostics.
// external_impulse) summed over the run, and the momentum balance they close with the interaction
// the coupler booked to the phase (ConservationLedger):
//   residual = (P - P_0) - sum_s J_s - I_exchange,   P the phase's balance momentum
//   relative residual = |residual| / max(|J_s|, |I_exchange|, sqrt(2 M E_k))
// (norms of the run's totals; M E_k the mass times the kinetic energy at the start or the end,
// whichever is larger: the momentum of the phase's motion, the scale where nothing external acts,
// e.g. in a closed periodic box). Round-off where the solver books everything it applies and its
// pair forces are antisymmetric.
#pragma once

#include <string>
#include <vector>

#include "proto/coupling_client.h"

namespace porosph::coupler {

/// The books one phase's solver reported, summed.
struct ExternalImpulseRecord {
  std::vector<std::string> sources;  ///< from the solver's first state; empty: it books none
  std::vector<double> impulse;       ///< sources x D (row-major), summed over the steps [N s]
  double relative_residual_max = 0;  ///< the largest relative residual at a timeseries row
  /// Resumed from a checkpoint written before the books existed: the earlier steps' impulses are
  /// unknown, so the run reports no balance for the phase.
  bool unknown = false;

  bool booked() const { return !sources.empty() && !unknown; }
  /// Takes the source names (when `d` carries them) and adds the step's impulses. A state with no
  /// impulses books nothing. Throws std::runtime_error (naming `phase`) when their number is not
  /// sources x dimension.
  void add(const coupling::Diagnostics& d, int dimension, const std::string& phase);
};

/// The momentum the books balance: Diagnostics.balance_momentum, or its momentum when empty.
const std::vector<double>& balance_momentum(const coupling::Diagnostics& d);

struct MomentumBalance {
  std::vector<double> change;    ///< balance momentum, last - initial
  std::vector<double> external;  ///< sum over the sources
  std::vector<double> exchange;  ///< the interaction's impulse to the phase (the ledger)
  std::vector<double> residual;  ///< change - external - exchange
  double scale = 0;     ///< max of |impulse| over the sources and the exchange, and sqrt(2 M E_k)
  double relative = 0;  ///< |residual| / scale (0 when scale is 0)
};

/// The balance of `books` between the diagnostics `initial` and `last` with the `exchange`
/// impulse (D values; null: none).
MomentumBalance momentum_balance(const ExternalImpulseRecord& books,
                                 const coupling::Diagnostics& initial,
                                 const coupling::Diagnostics& last,
                                 const std::vector<double>* exchange, int dimension);

}  // namespace porosph::coupler
