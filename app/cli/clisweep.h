#pragma once
/// `pkm sweep`: the design evaluated at K evenly spaced values of one pose variable or design
/// parameter, one CSV or JSON row per step.

#include "cli/cliarguments.h"
#include "cli/clidesign.h"
#include "mechanism.h"

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace pkm::cli {

/// A sweep's numbers as a table (the Python module's sweeps): the CSV's columns, each a run of
/// `steps` numbers in display units, NaN where the CSV field is empty; the "singularity"
/// column holds SingularityType values.
struct SweepTable {
    std::vector<std::string> columns;
    std::size_t singularityColumn = 0;
    std::size_t steps = 0;
    std::vector<double> values; ///< column c, step i at [c·steps + i]
};

/// A sweep whose every step has been solved: writing it cannot fail for want of a solution.
class Sweep
{
public:
    /// Solves every step of the sweep `invocation` asks for on `design`, which must outlive
    /// the Sweep. The failure names the first step without a solution, or an unknown --var.
    static Result<Sweep> solve(const PreparedDesign &design, const Invocation &invocation);

    /// The sweep of `var` over the display values `values`, in their order, each step solved
    /// from the previous one as in `pkm sweep`; the failure names the first step without a
    /// solution (as `pkm sweep` does) or an unknown `var`.
    static Result<SweepTable> table(const PreparedDesign &design, const std::string &var, std::vector<double> values);

    enum class Outcome {
        Written,
        OutputError, ///< `out` could not be written
        NotDeterministic, ///< a step solved by solve() failed when solved again (a bug)
    };
    /// Writes the header, every row and the trailer to `out`, solving the steps again: solve()
    /// keeps no poses, so the memory does not grow with the number of steps.
    Outcome write(std::FILE *out) const;

private:
    /// One step: the design (a new one per step when a parameter is swept) and its pose.
    struct Step {
        MechanismPtr owner;
        const Mechanism *mechanism = nullptr;
        Pose pose;
    };

    explicit Sweep(const PreparedDesign &design)
        : m_design(&design)
    {
    }

    /// Checks `var` and takes its unit; the failure names an unknown one.
    std::optional<Failure> setVariable(const std::string &var);
    /// "sweep step 3 of 10 (theta = 75°)": the context of a failure at step i.
    std::string stepContext(std::int64_t i) const;
    /// Display value of step i: m_values[i] if given, else evenly from m_from to m_to, both exactly.
    double valueAt(std::int64_t i) const;
    /// Solves step i from the pose `near` (the previous step's). Never allocates in a
    /// pose-variable sweep unless it fails.
    std::optional<Failure> solveStep(std::int64_t i, const Pose &near, Step &step) const;
    /// The JSON text before the rows.
    void jsonHeader(std::string &out) const;

    const PreparedDesign *m_design;
    std::string m_var;
    const ParameterInfo *m_parameter = nullptr; ///< set when a design parameter is swept
    int m_variable = -1; ///< else the swept pose variable
    Unit m_unit;
    double m_from = 0.0;
    double m_to = 0.0;
    std::vector<double> m_values; ///< the steps' values when given one by one
    std::int64_t m_steps = 1;
    bool m_json = false;
};

} // namespace pkm::cli
