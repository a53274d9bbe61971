// porosph_validate consolidation: the printed comparison and its exit code.
#pragma once

#include <string>

#include "tools/validation/consolidation_check.h"

namespace porosph::validation {

/// Prints the table, the isochrone errors, B and the final settlement, one summary line per
/// target; writes the series CSVs when `series` is not empty. Returns 0 when every target is met.
int report_consolidation(const ConsolidationCheck& c, const std::string& series);

}  // namespace porosph::validation
