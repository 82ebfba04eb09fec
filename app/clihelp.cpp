#include "clihelp.h"

namespace pkm::cli {

namespace {

constexpr std::string_view mainHelp = R"(Usage: pkm COMMAND [ARGUMENTS]

PKM Studio without a display: evaluate designs of parallel-kinematic mechanisms from a
shell or a script.

Commands:
  list   [--json]                          the built-in presets: id, mechanism, title
  show   DESIGN [--set N=V]... [--json]    parameters (values, units, allowed ranges),
                                           pose variables and design warnings
  eval   DESIGN [--set N=V]... [--json]    solve one pose: coordinates, Jacobians,
                                           singularity class, derived quantities
  sweep  DESIGN --var N --from A --to B --steps K [--set N=V]... [--csv|--json]
                                           one row per step, the quantities of eval

DESIGN is a preset id (see 'pkm list') or a design file (*.pkm.json).
--set NAME=VALUE (repeatable) changes a design parameter or sets a pose variable;
giving outputs (theta of the П-joint) solves the inverse problem, giving actuated
inputs (d) the direct one.

Units: mm, degrees, N, N·m, s; 'pkm show DESIGN' lists every name with its unit.
Numbers are read and written with '.' as the decimal separator whatever the locale,
with up to 15 significant digits.

Options:
  -h, --help    this help; 'pkm COMMAND --help' describes one command
  --version     the version of pkm

Exit status:
  0  success
  1  the output could not be written
  2  usage error: bad command line, unknown name, not a number, invalid parameter
     value, unreadable or damaged design file
  3  no solution: a pose out of range, unreachable or singular
On an error pkm prints one sentence naming the culprit on stderr and nothing on stdout.
)";

constexpr std::string_view listHelp = R"(Usage: pkm list [--json]

Lists the built-in presets: id (usable as DESIGN), mechanism kind and title.

  --json    {"presets": [{"id", "mechanism", "title"}...],
             "mechanisms": [{"id", "title"}...]}
)";

constexpr std::string_view showHelp = R"(Usage: pkm show DESIGN [--set NAME=VALUE]... [--json]

Shows a design: every parameter with its value, unit, allowed range ('(' and ')' exclude
the bound, '[' and ']' include it) and whether it is stored or derived from the others;
the pose variables with their ranges and whether they are actuated inputs or outputs;
the quantities eval and sweep report, with units; and the design warnings.

  --set NAME=VALUE    applied first, as in 'pkm eval'
  --json              {"design", "title", "description", "mechanism", "parameters",
                       "variables", "quantities", "warnings"}; unbounded limits are null
)";

constexpr std::string_view evalHelp = R"(Usage: pkm eval DESIGN [--set NAME=VALUE]... [--json]

Solves one pose of the design and prints every coordinate, the Jacobians, the singularity
class and the derived quantities, in display units.

  --set NAME=VALUE    NAME is a design parameter (applied in the order given) or a pose
                      variable (solved after all parameters: outputs by inverse
                      kinematics, actuated inputs by direct kinematics; giving both
                      kinds is an error). Without pose variables the design's stored pose
                      is used, re-solved from its outputs when a parameter changed (the
                      home pose, with a note on stderr, if that fails).
  --json              {"mechanism", "parameters", "pose", "jacobian", "singularity",
                       "derived"}; a matrix is a row-major nested array; singularity is
                       {"type": none|inverse|direct|combined, "margin", "undefined"};
                       a quantity that is not finite at the pose (J_inv at a singular
                       pose) is null and named in singularity.undefined
)";

constexpr std::string_view sweepHelp
    = R"(Usage: pkm sweep DESIGN --var NAME --from A --to B --steps K [--set NAME=VALUE]...
                 [--csv|--json]

Evaluates the design at K values of NAME and prints one row per step with the quantities
of 'pkm eval'. NAME is a pose variable (theta or d of the П-joint) or a design parameter;
A and B are in its display unit (see 'pkm show DESIGN').

  --var NAME          the quantity to sweep
  --from A, --to B    the first and the last value (A > B sweeps downwards)
  --steps K           the number of rows: K >= 2 spaces them evenly from A to B
                      inclusive, K = 1 evaluates A alone
  --set NAME=VALUE    applied before the sweep, as in 'pkm eval'
  --csv               comma-separated values with one header line (the default)
  --json              {"mechanism", "parameters", "sweep", "rows": [...]}, each row with
                      "pose", "jacobian", "singularity", "derived" as in 'pkm eval --json'

Each step starts from the previous step's pose, so the mechanism keeps its assembly mode.
Sweeping a pose variable keeps the design fixed; sweeping a parameter re-solves the pose
(from the --set pose variables, else from the stored pose's outputs) for every design and
adds all parameters to each row.

CSV columns, named as the keys of 'pkm eval --json': pose, jacobian, singularity (its
type), singularity_margin, derived; a matrix M gives columns M[i][j] (0-based,
row-major). A value that is not finite (J_inv at a singular pose) is an empty field in CSV
and null in JSON.

Every step is solved before anything is printed: if one cannot be solved (out of range,
unreachable, singular) pkm prints nothing on stdout, names the first failing value on
stderr and exits with status 3 (2 for an invalid parameter value). 'pkm show DESIGN' gives
the ranges.
)";

} // namespace

std::string_view helpText(std::optional<Command> command)
{
    if (!command)
        return mainHelp;
    switch (*command) {
    case Command::List:
        return listHelp;
    case Command::Show:
        return showHelp;
    case Command::Eval:
        return evalHelp;
    case Command::Sweep:
        return sweepHelp;
    }
    return mainHelp;
}

} // namespace pkm::cli
