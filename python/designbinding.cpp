// pkmstudio._core.Design: loading, parameters, poses, the JSON reports of `pkm eval` and
// `pkm show`, modes, sweeps and saving. The sweep's table is handed to NumPy without a copy.

#include "bindings.h"

#include "cli/cli.h"
#include "cli/clishow.h"
#include "cli/clisweep.h"
#include "document/designfile.h"
#include "report/report.h"
#include "text.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

namespace pkm::python {

namespace {

/// The pose `pose` names for `design`: its own pose (None), a Pose solved for this very
/// design, or a dictionary of pose variables solved as --set solves them.
Pose resolvePose(const DesignPy &design, const py::object &pose)
{
    if (pose.is_none())
        return design.prepared.pose;
    if (py::isinstance<PosePy>(pose)) {
        const auto &given = pose.cast<const PosePy &>();
        if (given.mechanism != design.prepared.mechanism)
            throw std::invalid_argument("This pose was solved for another design: solve it on this one, "
                                        "design.solve(**pose.as_dict()).");
        return given.pose;
    }
    if (py::isinstance<py::dict>(pose)) {
        py::kwargs values = py::reinterpret_borrow<py::kwargs>(pose);
        return take(cli::applySettings(design.prepared, settingsOf(values))).pose;
    }
    throw py::type_error("pose must be None, a Pose or a dict of pose variables");
}

/// Refuses a name of the wrong kind before --set would take it: parameters go to
/// with_parameters(), pose variables to solve() and at().
void checkSettings(const Mechanism &mechanism, const std::vector<cli::Setting> &settings, bool parameters)
{
    for (const cli::Setting &setting : settings) {
        const bool isParameter = mechanism.findParameter(setting.name) != nullptr;
        const bool isVariable = mechanism.variableIndex(setting.name) >= 0;
        if (parameters && isVariable && !isParameter)
            throw std::invalid_argument("'" + setting.name + "' is a pose variable, not a design parameter: give it to "
                "solve() or at().");
        if (!parameters && isParameter)
            throw std::invalid_argument("'" + setting.name + "' is a design parameter, not a pose variable: give it to "
                "with_parameters().");
    }
}

py::dict parameterDict(const Mechanism &mechanism)
{
    py::dict values;
    const ParameterSet parameters = mechanism.parameters();
    for (const ParameterInfo &info : mechanism.parameterInfo())
        values[py::str(info.name)] = asWritten(report::parameterDisplayValue(parameters, info));
    return values;
}

py::list parameterInfoList(const Mechanism &mechanism)
{
    py::list list;
    for (const ParameterInfo &info : mechanism.parameterInfo()) {
        py::dict entry;
        entry["name"] = info.name;
        entry["symbol"] = info.symbol;
        entry["label"] = info.label;
        entry["unit"] = info.unit.symbol;
        entry["group"] = std::string(parameterGroupKey(info.group));
        entry["min"] = asWritten(info.unit.toDisplay(info.domain.min));
        entry["max"] = asWritten(info.unit.toDisplay(info.domain.max));
        entry["stored"] = info.stored;
        entry["applies"] = mechanism.parameterApplies(info.name);
        py::dict choices;
        for (const auto &[name, value] : info.choices)
            choices[py::str(name)] = value;
        entry["choices"] = choices;
        list.append(entry);
    }
    return list;
}

py::list variableList(const Mechanism &mechanism)
{
    py::list list;
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        const Interval range = mechanism.variableRange(static_cast<int>(i));
        py::dict entry;
        entry["name"] = info.name;
        entry["symbol"] = info.symbol;
        entry["label"] = info.label;
        entry["unit"] = info.unit.symbol;
        entry["actuated"] = info.actuated;
        entry["min"] = asWritten(info.unit.toDisplay(range.min));
        entry["max"] = asWritten(info.unit.toDisplay(range.max));
        list.append(entry);
    }
    return list;
}

/// The design at the pose the keyword arguments give, as --set solves pose variables.
DesignPy designAt(const DesignPy &design, const py::kwargs &pose)
{
    const auto settings = settingsOf(pose);
    checkSettings(*design.prepared.mechanism, settings, false);
    return DesignPy {take(cli::applySettings(design.prepared, settings))};
}

DesignPy withPose(const DesignPy &design, MechanismPtr mechanism, const Pose &pose)
{
    DesignPy changed = design;
    changed.prepared.mechanism = std::move(mechanism);
    changed.prepared.pose = pose;
    changed.prepared.poseSets.clear();
    changed.prepared.note.clear();
    return changed;
}

/// The sweep's table as (columns, 2-D array of columns × steps, singularity column); the
/// array's memory is the table's.
py::tuple sweepTable(const DesignPy &design, const std::string &var,
    const py::array_t<double, py::array::c_style | py::array::forcecast> &values)
{
    if (values.ndim() != 1)
        throw std::invalid_argument("the values of a sweep are a 1-D sequence of numbers");
    std::vector<double> steps(values.data(), values.data() + values.size());
    if (steps.empty())
        throw std::invalid_argument("a sweep needs at least one value");
    std::unique_ptr<cli::SweepTable> table;
    {
        py::gil_scoped_release unlocked;
        auto solved = cli::Sweep::table(design.prepared, var, std::move(steps));
        if (solved)
            table = std::make_unique<cli::SweepTable>(std::move(*solved));
        else {
            py::gil_scoped_acquire locked;
            raise(solved.failure());
        }
    }
    const auto columns = static_cast<py::ssize_t>(table->columns.size());
    const auto count = static_cast<py::ssize_t>(table->steps);
    py::list names = py::cast(table->columns);
    const auto singularity = table->singularityColumn;
    double *data = table->values.data();
    py::capsule owner(table.release(), [](void *pointer) { delete static_cast<cli::SweepTable *>(pointer); });
    py::array_t<double> array({columns, count}, {count * py::ssize_t(sizeof(double)), py::ssize_t(sizeof(double))},
        data, owner);
    return py::make_tuple(names, array, singularity);
}

} // namespace

void bindDesign(py::module_ &module)
{
    py::class_<DesignPy>(module, "Design",
        "A mechanism design: a preset or a design file, with its parameters and its pose. A design "
        "never changes: with_parameters() and at() return new ones.")
        .def_static("load", [](const std::string &origin) { return DesignPy {take(cli::loadDesign(origin))}; },
            py::arg("preset_or_path"), "Loads a preset (by its id, see presets()) or a .pkm.json design file.")
        .def_property_readonly("origin", [](const DesignPy &self) { return self.prepared.origin; },
            "The preset id or the path it was loaded from.")
        .def_property_readonly("kind", [](const DesignPy &self) { return std::string(self.prepared.mechanism->kind()); },
            "The mechanism kind ('pjoint', 'moma', …; see kinds()).")
        .def_property_readonly("title", [](const DesignPy &self) { return self.prepared.design.title.toStdString(); })
        .def_property_readonly("description",
            [](const DesignPy &self) { return self.prepared.design.description.toStdString(); })
        .def_property_readonly("parameters", [](const DesignPy &self) { return parameterDict(*self.prepared.mechanism); },
            "Every parameter, stored and derived, {name: value in display units}, as `pkm eval --json` gives them.")
        .def_property_readonly("parameter_info", [](const DesignPy &self) { return parameterInfoList(*self.prepared.mechanism); },
            "Each parameter's symbol, label, unit, group, allowed interval and named values.")
        .def_property_readonly("variables", [](const DesignPy &self) { return variableList(*self.prepared.mechanism); },
            "Each joint variable's symbol, label, unit, whether it is actuated, and its range.")
        .def_property_readonly("pose", [](const DesignPy &self) { return PosePy {self.prepared.mechanism, self.prepared.pose}; },
            "The design's current pose.")
        .def_property_readonly("note", [](const DesignPy &self) { return self.prepared.note; },
            "Why the stored pose was given up for the home pose after a parameter change, or ''.")
        .def_property_readonly("warnings", [](const DesignPy &self) { return self.prepared.mechanism->designWarnings(); },
            "Warnings about a valid but questionable design.")
        .def("with_parameters",
            [](const DesignPy &self, const py::kwargs &changes) {
                const auto settings = settingsOf(changes);
                checkSettings(*self.prepared.mechanism, settings, true);
                return DesignPy {take(cli::applySettings(self.prepared, settings))};
            },
            "A new design with the parameters changed (display units, as `pkm --set`): all at once, so "
            "their order does not matter. The pose keeps its outputs where the new design reaches them. "
            "A bad value raises ValueError with the command line's message.")
        .def("at",
            &designAt,
            "The same design at another pose: give the outputs (inverse kinematics) or the actuated "
            "inputs (direct kinematics), as `pkm --set` does. Raises NoSolution where there is none.")
        .def("solve",
            [](const DesignPy &self, const py::kwargs &pose) {
                const DesignPy solved = designAt(self, pose);
                return PosePy {solved.prepared.mechanism, solved.prepared.pose};
            },
            "The pose with the given outputs (inverse kinematics) or inputs (direct kinematics), in the "
            "design's current assembly mode. Raises NoSolution where there is none.")
        .def("_eval_json",
            [](const DesignPy &self, const py::object &pose, bool allModes, bool equations) {
                const Pose solved = resolvePose(self, pose);
                return cli::evalJson(*self.prepared.mechanism, solved, allModes, equations);
            },
            py::arg("pose") = py::none(), py::arg("all_modes") = false, py::arg("equations") = false)
        .def("_show_json", [](const DesignPy &self) { return cli::showJson(self.prepared); })
        .def("assembly_modes",
            [](const DesignPy &self, const py::object &pose) {
                py::list modes;
                for (const Pose &mode : self.prepared.mechanism->assemblyModes(resolvePose(self, pose)))
                    modes.append(PosePy {self.prepared.mechanism, mode});
                return modes;
            },
            py::arg("pose") = py::none(), "Every real assembly mode at the inputs of the pose, as `pkm eval --all-modes`.")
        .def("mode_alternatives",
            [](const DesignPy &self, const py::object &pose) {
                py::list list;
                for (const ModeAlternative &alternative : self.prepared.mechanism->modeAlternatives(resolvePose(self, pose))) {
                    py::dict entry;
                    entry["label"] = alternative.label;
                    py::dict changes;
                    for (const auto &[name, value] : alternative.changes) {
                        const ParameterInfo *info = alternative.mechanism->findParameter(name);
                        changes[py::str(name)] = asWritten(info ? info->unit.toDisplay(value) : value);
                    }
                    entry["changes"] = changes;
                    entry["same_inputs"] = alternative.sameInputs;
                    entry["design"] = withPose(self, alternative.mechanism, alternative.pose);
                    entry["pose"] = PosePy {alternative.mechanism, alternative.pose};
                    list.append(entry);
                }
                return list;
            },
            py::arg("pose") = py::none(),
            "The other working and assembly modes the mechanism could be in at the pose (the GUI's "
            "ghosts): [{'label', 'changes', 'same_inputs', 'design', 'pose'}, …].")
        .def("_sweep", &sweepTable, py::arg("var"), py::arg("values"))
        .def("save",
            [](const DesignPy &self, const std::string &path) {
                Design design = self.prepared.design;
                design.mechanism = self.prepared.mechanism;
                design.pose = self.prepared.pose;
                const auto saved = designfile::save(design, QString::fromStdString(path));
                if (!saved) {
                    PyErr_SetString(PyExc_OSError, text::printable(saved.failure().message, 1000).c_str());
                    throw py::error_already_set();
                }
            },
            py::arg("path"), "Saves the design and its pose as a .pkm.json file, atomically.")
        .def("__repr__", [](const DesignPy &self) {
            return "<pkmstudio.Design " + self.prepared.origin + " (" + std::string(self.prepared.mechanism->kind()) + ")>";
        });
}

} // namespace pkm::python
