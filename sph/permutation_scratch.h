// Re-ordering a phase's structure of arrays (new[i] = old[order[i]], after the cell sort of
// cell_order.h) through one scratch array per element type: no allocation once they have grown.
#pragma once

#include <cstdint>
#include <tuple>
#include <vector>

namespace porosph::sph {

template <class... Elements>
class PermutationScratch {
 public:
  /// array = its elements in `order`; its capacity is kept (the scratch takes it on).
  template <class T>
  void permute(std::vector<T>& array, const std::vector<std::int32_t>& order) {
    std::vector<T>& scratch = std::get<std::vector<T>>(buffers_);
    scratch.reserve(array.capacity());
    scratch.resize(order.size());
    const std::int64_t n = static_cast<std::int64_t>(order.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) scratch[i] = array[order[i]];
    array.swap(scratch);
  }

 private:
  std::tuple<std::vector<Elements>...> buffers_;
};

}  // namespace porosph::sph
