// Printed verdicts of the closed-form verification cases (verification_checks.h) for
// porosph_validate: a human-readable block, then the machine-readable "summary" lines that
// tools/validation/report.py reads (the format of validate_main.cpp's print_summary).
#pragma once

#include "tools/validation/seepage_embankment_check.h"
#include "tools/validation/seepage_weir_check.h"
#include "tools/validation/still_water_check.h"
#include "tools/validation/verification_checks.h"

namespace porosph::validation {

/// Prints the Taylor-Green verdict; returns 0 when the target is met, else 1.
int report_taylor_green(const TaylorGreenCheck& c);
/// Prints the elastic column verdict; returns 0 when the targets are met, else 1.
int report_elastic_column(const ElasticColumnCheck& c);
/// Prints the hydrostatic tank verdict (per-row table when `rows`); 0 when the targets are met.
int report_hydrostatic(const HydrostaticCheck& h, bool rows);
/// Prints the still-bed verdict; 0 when the targets are met.
int report_still_bed(const StillBedCheck& c);
/// Prints the seepage-under-a-weir verdict; 0 when the targets are met.
int report_seepage_weir(const SeepageWeirCheck& c);
/// Prints the seepage-through-an-embankment verdict; 0 when the targets are met.
int report_seepage_embankment(const SeepageEmbankmentCheck& c);

}  // namespace porosph::validation
