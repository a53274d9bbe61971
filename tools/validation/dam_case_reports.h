// porosph_validate rockfill_overtopping and hydraulic_heave: the printed comparison, the summary
// lines read by tools/validation/report.py, the series CSVs and the exit code.
#pragma once

#include <string>

#include "tools/validation/dam_case_checks.h"

namespace porosph::validation {

/// B at three displacement thresholds, the water table against Dupuit-Forchheimer; writes
/// SERIES (t, B_wet, B_all) and SERIES_dupuit.csv when `series` is not empty. Returns 0 when B
/// (wet, D15) is within 10 % of the experiment (or there is no experiment for this Q).
int report_rockfill(const RockfillCheck& c, const std::string& series);

/// The gravel's advance beside the pile and the two bulk measures over time, the failure time
/// against the experiment's 4.4 s; writes SERIES (t, gravel_bottom, sand_crossed,
/// gravel_settlement) when `series` is not empty. Returns 0 when the failure time is within 10 %.
int report_heave(const HeaveCheck& c, const std::string& series);

}  // namespace porosph::validation
