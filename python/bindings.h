#pragma once
/// The C++ side of the Python module (pkmstudio._core): a design and its poses as Python
/// objects over the command line's own computations (cli/), so that every number Python gets
/// is the number `pkm` prints. The pure-Python package (pkmstudio/__init__.py) turns the JSON
/// reports into dictionaries with NumPy matrices and gives the sweeps their columns.
///
/// Designs are values: with_parameters() and at() return new designs, a design never
/// changes. Long computations (sweeps, maps, workspaces) release the GIL.

#include "cli/clidesign.h"
#include "mechanism.h"

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace pkm::python {

namespace py = pybind11;

/// pkmstudio.NoSolution (a ValueError): the pose is out of range, unreachable or singular —
/// what `pkm` reports with exit status 3.
struct NoSolutionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Throws the failure as the exception that fits it: NoSolutionError where `pkm` exits with
/// status 3, ValueError (std::invalid_argument) for the rest. The message is the command
/// line's sentence, made safe to print as `pkm` makes it.
[[noreturn]] void raise(const Failure &failure);

/// Unwraps a result or raises its failure.
template <class T>
T take(Result<T> result)
{
    if (!result)
        raise(result.failure());
    return std::move(*result);
}

/// A pose of a design. It keeps the design's mechanism, which names its variables and
/// converts their units.
struct PosePy {
    MechanismPtr mechanism;
    Pose pose;
};

/// A design: what `pkm` calls DESIGN after its --set arguments.
struct DesignPy {
    cli::PreparedDesign prepared;
};

/// `value` as `pkm` writes it in JSON and CSV, to 15 significant digits: -60 for the
/// -59.99999999999999 that −π/3 rad gives in degrees. Parameters and poses are given so.
double asWritten(double value);

/// Keyword arguments as --set arguments: NAME=VALUE with the value as `pkm` would have been
/// given it, a number or the name of a mode ("X"). A value that is neither is a TypeError.
std::vector<cli::Setting> settingsOf(const py::kwargs &changes);

/// {name: value in display units} of the pose's variables, inputs first; `actuated`: only
/// the inputs (true) or only the outputs (false), or all.
py::dict poseDict(const Mechanism &mechanism, const Pose &pose, std::optional<bool> actuated = std::nullopt);

void bindPose(py::module_ &module);
void bindDesign(py::module_ &module);
void bindMaps(py::module_ &module);

} // namespace pkm::python
