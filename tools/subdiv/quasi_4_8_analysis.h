#pragma once
// subdiv analyze -s quasi-4-8: the eigenstructure experiment on n-regular
// neighbourhoods (analysis/quasi_4_8_experiment.h), one row per n.

namespace subdiv::cli {

/// Prints the table for n = first .. last after `warmup` binary steps.
int run_quasi_4_8_analysis(int first, int last, int warmup);

}  // namespace subdiv::cli
