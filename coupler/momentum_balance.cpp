#include "coupler/momentum_balance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace porosph::coupler {
namespace {

double norm(const std::vector<double>& v, std::size_t begin, std::size_t count) {
  double s = 0;
  for (std::size_t k = begin; k < begin + count && k < v.size(); ++k) s += v[k] * v[k];
  return std::sqrt(s);
}

double component(const std::vector<double>& v, std::size_t k) { return k < v.size() ? v[k] : 0.0; }

}  // namespace

void ExternalImpulseRecord::add(const coupling::Diagnostics& d, int dimension,
                                const std::string& phase) {
  if (unknown) return;
  if (!d.impulse_sources.empty() && d.impulse_sources != sources) {
    sources = d.impulse_sources;
    impulse.assign(sources.size() * static_cast<std::size_t>(dimension), 0.0);
  }
  if (d.external_impulse.empty()) return;
  if (d.external_impulse.size() != impulse.size()) {
    throw std::runtime_error("the " + phase + " solver sent " +
                             std::to_string(d.external_impulse.size()) +
                             " external impulse values for " + std::to_string(sources.size()) +
                             " sources in " + std::to_string(dimension) + " dimensions");
  }
  for (std::size_t k = 0; k < impulse.size(); ++k) impulse[k] += d.external_impulse[k];
}

const std::vector<double>& balance_momentum(const coupling::Diagnostics& d) {
  return d.balance_momentum.empty() ? d.momentum : d.balance_momentum;
}

MomentumBalance momentum_balance(const ExternalImpulseRecord& books,
                                 const coupling::Diagnostics& initial,
                                 const coupling::Diagnostics& last,
                                 const std::vector<double>* exchange, int dimension) {
  const std::size_t dims = static_cast<std::size_t>(dimension);
  MomentumBalance b;
  b.change.assign(dims, 0.0);
  b.external.assign(dims, 0.0);
  b.exchange.assign(dims, 0.0);
  b.residual.assign(dims, 0.0);
  const std::vector<double>& p0 = balance_momentum(initial);
  const std::vector<double>& p1 = balance_momentum(last);
  for (std::size_t s = 0; s < books.sources.size(); ++s) {
    for (std::size_t k = 0; k < dims; ++k) b.external[k] += books.impulse[s * dims + k];
    b.scale = std::max(b.scale, norm(books.impulse, s * dims, dims));
  }
  for (std::size_t k = 0; k < dims; ++k) {
    b.change[k] = component(p1, k) - component(p0, k);
    b.exchange[k] = exchange != nullptr ? component(*exchange, k) : 0.0;
    b.residual[k] = b.change[k] - b.external[k] - b.exchange[k];
  }
  b.scale = std::max(b.scale, norm(b.exchange, 0, dims));
  // Where nothing external acts (a closed periodic box) the phase's motion sets the scale.
  for (const coupling::Diagnostics* d : {&initial, &last})
    b.scale = std::max(b.scale, std::sqrt(std::max(0.0, 2.0 * d->mass * d->kinetic_energy)));
  b.relative = b.scale > 0 ? norm(b.residual, 0, dims) / b.scale : 0.0;
  return b;
}

}  // namespace porosph::coupler
