// pkmstudio._core: the module, its exceptions, the presets and kinds, and the Pose type.
// Design (designbinding.cpp) and Map/Workspace (mapbinding.cpp) are bound from their files.

#include "bindings.h"

#include "cli/cli.h"
#include "document/designfile.h"
#include "registry.h"
#include "report/numberformat.h"
#include "text.h"

#include <pybind11/stl.h>

#include <cmath>
#include <cstdlib>

namespace pkm::python {

namespace {

/// An error message is one sentence: as `pkm` cuts it (cli.cpp).
constexpr std::size_t maxMessageCharacters = 1000;

std::string settingText(const std::string &name, const std::string &value)
{
    return name + "=" + value;
}

} // namespace

void raise(const Failure &failure)
{
    const std::string message = text::printable(failure.message, maxMessageCharacters);
    if (cliExitCode(failure) == CliNoSolution)
        throw NoSolutionError(message);
    throw std::invalid_argument(message);
}

double asWritten(double value)
{
    if (!std::isfinite(value))
        return value;
    return std::strtod(report::numberText(value).c_str(), nullptr);
}

std::vector<cli::Setting> settingsOf(const py::kwargs &changes)
{
    std::vector<cli::Setting> settings;
    for (const auto &[key, value] : changes) {
        cli::Setting setting;
        setting.name = py::cast<std::string>(key);
        if (py::isinstance<py::str>(value)) {
            // a mode by its name, as in --set mode=X
            setting.word = py::cast<std::string>(value);
            setting.value = std::nan("");
            setting.text = settingText(setting.name, setting.word);
        } else {
            try {
                setting.value = py::cast<double>(value);
            } catch (const py::cast_error &) {
                throw py::type_error(setting.name + " must be a number or the name of a mode, not "
                    + py::cast<std::string>(py::str(py::type::of(value).attr("__name__"))));
            }
            setting.text = settingText(setting.name, report::numberText(setting.value));
        }
        settings.push_back(std::move(setting));
    }
    return settings;
}

py::dict poseDict(const Mechanism &mechanism, const Pose &pose, std::optional<bool> actuated)
{
    py::dict values;
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (actuated && variables[i].actuated != *actuated)
            continue;
        values[py::str(variables[i].name)]
            = asWritten(variables[i].unit.toDisplay(mechanism.variableValue(pose, static_cast<int>(i))));
    }
    return values;
}

void bindPose(py::module_ &module)
{
    py::class_<PosePy>(module, "Pose",
        "A solved pose of a design: every joint variable in display units (mm, degrees), "
        "read like a dictionary (pose['theta'], dict(pose)). The actuated inputs come first.")
        .def("__getitem__",
            [](const PosePy &self, const std::string &name) {
                const int index = self.mechanism->variableIndex(name);
                if (index < 0)
                    throw py::key_error(name);
                const VariableInfo &info = self.mechanism->variableInfo()[static_cast<std::size_t>(index)];
                return asWritten(info.unit.toDisplay(self.mechanism->variableValue(self.pose, index)));
            })
        .def("__contains__",
            [](const PosePy &self, const std::string &name) { return self.mechanism->variableIndex(name) >= 0; })
        .def("__len__", [](const PosePy &self) { return self.mechanism->variableInfo().size(); })
        .def("__iter__", [](const PosePy &self) { return py::iter(poseDict(*self.mechanism, self.pose)); })
        .def("keys", [](const PosePy &self) { return poseDict(*self.mechanism, self.pose).attr("keys")(); })
        .def("values", [](const PosePy &self) { return poseDict(*self.mechanism, self.pose).attr("values")(); })
        .def("items", [](const PosePy &self) { return poseDict(*self.mechanism, self.pose).attr("items")(); })
        .def("as_dict", [](const PosePy &self) { return poseDict(*self.mechanism, self.pose); },
            "Every joint variable, {name: value in display units}.")
        .def_property_readonly("inputs", [](const PosePy &self) { return poseDict(*self.mechanism, self.pose, true); },
            "The actuated inputs, {name: value}.")
        .def_property_readonly("outputs",
            [](const PosePy &self) { return poseDict(*self.mechanism, self.pose, false); }, "The outputs, {name: value}.")
        .def_property_readonly("mode", [](const PosePy &self) { return self.pose.mode; },
            "The assembly or working mode index, where the mechanism has several.")
        .def("__repr__", [](const PosePy &self) {
            std::string text = "Pose(";
            const auto &variables = self.mechanism->variableInfo();
            for (std::size_t i = 0; i < variables.size(); ++i) {
                const double value = variables[i].unit.toDisplay(self.mechanism->variableValue(self.pose, int(i)));
                text += (i ? ", " : "") + variables[i].name + "=" + report::numberText(value);
            }
            return text + ")";
        });
}

} // namespace pkm::python

PYBIND11_MODULE(_core, module)
{
    using namespace pkm;
    using namespace pkm::python;
    module.doc() = "PKM Studio's kinematics core: designs, poses, sweeps and maps (use the pkmstudio package).";
    module.attr("__version__") = PKM_VERSION;
    py::register_exception<NoSolutionError>(module, "NoSolution", PyExc_ValueError);

    module.def("presets", [] {
        py::list list;
        for (const PresetInfo &preset : designfile::presets()) {
            py::dict entry;
            entry["id"] = preset.id.toStdString();
            entry["mechanism"] = preset.kind.toStdString();
            entry["title"] = preset.title.toStdString();
            entry["description"] = preset.description.toStdString();
            list.append(entry);
        }
        return list;
    }, "The built-in designs, as `pkm list` gives them: [{'id', 'mechanism', 'title', 'description'}, …].");
    module.def("kinds", [] {
        py::list list;
        for (const MechanismKind &kind : mechanismKinds()) {
            py::dict entry;
            entry["id"] = std::string(kind.id);
            entry["title"] = std::string(kind.title);
            list.append(entry);
        }
        return list;
    }, "The mechanism kinds PKM Studio knows: [{'id', 'title'}, …].");
    module.def("singularity_names", [] {
        std::vector<std::string> names;
        for (SingularityType type : {SingularityType::None, SingularityType::Inverse, SingularityType::Direct,
                                     SingularityType::Combined})
            names.emplace_back(singularityName(type));
        return names;
    }, "The singularity classes by their number in a sweep's table: none, inverse, direct, combined.");

    bindPose(module);
    bindDesign(module);
    bindMaps(module);
}
