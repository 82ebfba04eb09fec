// The sheet's "capability" section: what the actuators deliver at the sheet's pose
// (core/capability.h), with the notes on assumed actuators and on a measured stiffness.
#include "export/sheetparts.h"

#include "quantityformat.h"
#include "registry.h"
#include "report/report.h"

#include <QCoreApplication>
#include <QLocale>

#include <string>

namespace pkm::sheet::detail {

namespace {

/// Whether `name` is one of actuator i's limits (core/actuatorparameters.h): force_max1, torsion2 …
bool isActuatorLimit(const std::string &name)
{
    const std::size_t digit = name.find_first_of("123");
    if (digit == std::string::npos || digit + 1 != name.size())
        return false;
    const std::string prefix = name.substr(0, digit);
    for (const char *limit : {"force_max", "speed_max", "step", "stiffness", "torque_max", "rate_max", "angle_step", "torsion"}) {
        if (prefix == limit)
            return true;
    }
    return false;
}

} // namespace

/// What the actuators deliver at the sheet's pose (core/capability.h): the scalar values of the
/// capability group (the stiffness matrix is in `pkm eval --json`), and for a design with a
/// measured stiffness what the two stiffnesses together say.
void addCapability(const Mechanism &mechanism, const Pose &pose, Parts &parts)
{
    const Singularity singularity = evaluateAt(mechanism, pose).singularity;
    const report::CapabilityReport capability = report::evaluateCapability(mechanism, pose, singularity.type);
    if (!capability.layout)
        return;
    Section &section = parts.capability;
    section.key = "capability";
    section.title = QCoreApplication::translate("Sheet", "Actuator capability");
    section.intro = QCoreApplication::translate("Sheet",
        "What the actuators deliver at the platform at this pose, every actuator within its limits: the force "
        "and the speed in the weakest and the strongest direction, the error from half a step per actuator and "
        "the stiffness from the actuators alone.");
    for (const ReportEntry &entry : capability.layout->entries) {
        if (entry.rows * entry.cols != 1)
            continue;
        const double value = entry.unit.toDisplay(capability.values[std::size_t(entry.offset)]);
        section.items.push_back({entry.name, utf8(entry.symbol), coreLabel(entry.label), numberCell(value, entry.decimals),
            std::string(entry.unit.symbol), {}});
    }
    // the actuators the documents do not give take assumed defaults: say so where they are used
    const MechanismKind *kind = findMechanismKind(mechanism.kind());
    const auto defaults = kind ? kind->create({}) : Result<MechanismPtr>(Failure{});
    if (defaults) {
        const ParameterSet mine = mechanism.parameters(), assumed = (*defaults)->parameters();
        const bool pjoint = mechanism.kind() == "pjoint"; // Table 1 gives all but its stiffness
        bool anyAssumed = false;
        for (const ParameterInfo &info : mechanism.parameterInfo()) {
            const bool actuator = info.group == ParameterGroup::Actuator && mechanism.parameterApplies(info.name)
                && (pjoint ? info.name == "stiffness" : isActuatorLimit(info.name));
            if (actuator && mine.at(info.name) == assumed.at(info.name))
                anyAssumed = true;
        }
        if (anyAssumed)
            section.notes.push_back(pjoint
                    ? QCoreApplication::translate("Sheet",
                          "The actuator's axial stiffness is an assumed value (about 20 N/µm for a small lead screw "
                          "with its nut and bearings): Table 1 gives none.")
                    : QCoreApplication::translate("Sheet",
                          "Actuator values left at their defaults are assumed, plausible ones (a NEMA 17 stepper with "
                          "a 5:1 gearbox, a small lead-screw slide): the source documents give none."));
    }
    const ReportEntry *computed = capability.layout->find("stiffness_worst");
    const ReportEntry *measured = capability.layout->find("stiffness_measured");
    if (computed && measured) {
        const double actuator = capability.values[std::size_t(computed->offset)];
        const double joint = capability.values[std::size_t(measured->offset)];
        // springs in series: 1/K_joint = 1/K_actuator + 1/K_rest
        section.notes.push_back(actuator > joint
                ? QCoreApplication::translate("Sheet",
                      "The actuator alone would make the joint %1 N·m/rad stiff here; the measured %2 N·m/rad is "
                      "lower because the hinges, links and frame yield in series with it (1/K = 1/K_actuator + "
                      "1/K_rest): together they are about %3 N·m/rad.")
                      .arg(QLocale().toString(actuator, 'f', 0), QLocale().toString(joint, 'f', 0),
                          QLocale().toString(1.0 / (1.0 / joint - 1.0 / actuator), 'f', 0))
                : QCoreApplication::translate("Sheet",
                      "The actuator alone gives %1 N·m/rad here, less than the measured %2 N·m/rad of the whole "
                      "joint: the assumed axial stiffness of the actuator is too low for the measurement, or the "
                      "pose is near a singularity where the actuator cannot hold the output.")
                      .arg(QLocale().toString(actuator, 'f', 0), QLocale().toString(joint, 'f', 0)));
    }
}

} // namespace pkm::sheet::detail
