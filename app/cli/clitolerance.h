#pragma once
/// `pkm tolerance DESIGN --tol NAME=±V… [--samples N] [--seed S] [--normal] [--grid K]
/// [--json]`: the platform's error at the pose from tolerances on the geometric design
/// parameters (core/tolerance.h; reference: docs/cli.md).

#include "cli/clidesign.h"

#include <cstdio>

namespace pkm::cli {

/// Runs the command on the prepared design; prints the table or the JSON on `out`, a
/// one-sentence message naming the culprit on `err`; returns the exit status.
int runToleranceCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err);

/// The tolerances a command works with, in core units: the design file's, then each --tol in
/// order (±0 removes one). The failure names the --tol at fault, or says there are none
/// (`command` names the command in that sentence: "'pkm tolerance'").
Result<ParameterSet> tolerancesOf(const PreparedDesign &prepared, const Invocation &invocation,
                                  const std::string &command);

} // namespace pkm::cli
