// The poses a design file keeps: a bookmark taken at a pose, the saved pose solved again for the
// design as loaded (its inputs kept where the file's outputs give them back to the digits
// written), and a pose given by display values ("pkm … --pose NAME=VALUE", a bookmark).
#include "document/designfile.h"
#include "document/designfileinternal.h"

#include "quantityformat.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace pkm {
namespace designfile {

using detail::numberText;

Bookmark bookmarkOf(const Mechanism &mechanism, const Pose &pose, const QString &name)
{
    Bookmark bookmark;
    bookmark.name = name;
    const auto &variables = mechanism.variableInfo();
    // At the 15 digits a file keeps, so that a saved bookmark reads back as the same one.
    for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
        const double display = variables[i].unit.toDisplay(mechanism.variableValue(pose, i));
        bookmark.pose.append({toQString(variables[i].name), QString::number(display, 'g', 15).toDouble()});
    }
    return bookmark;
}

namespace {
/// Below this (relative) a saved output differs from its inputs' by round-off only.
constexpr double exactPoseTolerance = 1e-12;
/// The inputs of a pose solved from the file's outputs are the file's when they differ by no
/// more than the 15 significant digits written (and what a solver adds to that).
constexpr double writtenDigitsTolerance = 1e-11;
} // namespace

Result<Pose> solveSavedPose(const Mechanism &mechanism, const Pose &home, const QList<QPair<QString, double>> &values)
{
    const auto &variables = mechanism.variableInfo();
    const int inputs = mechanism.inputCount();
    std::vector<bool> given(variables.size(), false);
    for (const auto &value : values) {
        const int index = mechanism.variableIndex(value.first.toStdString());
        if (index >= 0)
            given[index] = true;
    }
    const bool allInputs = std::all_of(given.begin(), given.begin() + inputs, [](bool g) { return g; });
    const bool anyOutput = std::any_of(given.begin() + inputs, given.end(), [](bool g) { return g; });
    if (!allInputs || !anyOutput)
        return solveDisplayVariables(mechanism, home, values);

    // Every variable given (as version 2 writes them): the inputs decide, the outputs must agree.
    QList<QPair<QString, double>> inputValues;
    for (const auto &value : values) {
        if (mechanism.variableIndex(value.first.toStdString()) < inputs)
            inputValues.append(value);
    }
    // Solved near the file's own pose, so that of several assembly modes at these inputs (a
    // 3-RPR has up to six) the one saved comes back.
    Pose saved = home;
    for (const auto &[name, display] : values) {
        const int index = mechanism.variableIndex(name.toStdString());
        if (index < 0)
            continue;
        const double value = variables[std::size_t(index)].unit.fromDisplay(display);
        if (index < inputs && index < saved.inputs.size())
            saved.inputs[index] = value;
        else if (index >= inputs && index - inputs < saved.outputs.size())
            saved.outputs[index - inputs] = value;
    }
    auto solved = solveDisplayVariables(mechanism, saved, inputValues);
    if (!solved)
        return solved;
    Pose pose = *solved;
    // The pose at the file's own outputs, if its inputs are the file's to the digits written,
    // with the file's inputs as written (the recomputed ones may not be: q = 40 came back as
    // 40.0000000000003, and every save moved it on). It is as true to the file as the pose
    // solved from the inputs: where the outputs drift by more than round-off (θ = 0 of a
    // П-joint comes back as 1e-12), and at a direct singularity, where the inputs hold more
    // than one pose (a platform whose points coincide turns freely: any φ holds its inputs).
    const auto filePose = [&]() -> std::optional<Pose> {
        auto exact = mechanism.solveInverse(saved.outputs, &pose);
        if (!exact || exact->inputs.size() != pose.inputs.size())
            return std::nullopt;
        for (int i = 0; i < inputs; ++i) {
            const double file = saved.inputs[i];
            if (std::abs(exact->inputs[i] - file) > writtenDigitsTolerance * std::max(1.0, std::abs(file)))
                return std::nullopt;
        }
        Pose kept = *exact;
        for (int i = 0; i < inputs; ++i)
            kept.inputs[i] = saved.inputs[i];
        return kept;
    };
    bool keptOutputs = true;
    for (const auto &[name, display] : values) {
        const int index = mechanism.variableIndex(name.toStdString());
        if (index < inputs)
            continue;
        const VariableInfo &info = variables[index];
        const double fromInputs = info.unit.toDisplay(mechanism.variableValue(*solved, index));
        if (std::abs(fromInputs - display) > savedPoseTolerance * std::max(1.0, std::abs(display))) {
            if (auto kept = filePose())
                return *kept;
            return Failure{FailureKind::InvalidParameter, info.name,
                           QCoreApplication::translate("pkm::designfile",
                                                       "the pose's %1 = %2 %4 does not agree with its inputs, which "
                                                       "give %3 %4.")
                               .arg(toQString(info.name), numberText(display), numberText(fromInputs),
                                    unitText(info.unit))
                               .toStdString()};
        }
        // Agreeing to round-off: keep the file's value, so that save → open is exact.
        if (std::abs(fromInputs - display) <= exactPoseTolerance * std::max(1.0, std::abs(display)))
            pose.outputs[index - inputs] = info.unit.fromDisplay(display);
        else
            keptOutputs = false;
    }
    if (keptOutputs)
        return pose;
    if (auto kept = filePose())
        return *kept;
    return pose;
}

Result<Pose> solveDisplayVariables(const Mechanism &mechanism, const Pose &current,
                                   const QList<QPair<QString, double>> &values)
{
    const auto &variables = mechanism.variableInfo();
    const int inputs = mechanism.inputCount();
    Coordinates q = current.inputs;
    Coordinates x = current.outputs;
    bool anyInput = false;
    bool anyOutput = false;
    for (const auto &[name, display] : values) {
        const int index = mechanism.variableIndex(name.toStdString());
        if (index < 0) {
            return Failure{FailureKind::UnknownName, name.toStdString(),
                           QCoreApplication::translate("pkm::designfile", "Unknown pose variable '%1'.")
                               .arg(name)
                               .toStdString()};
        }
        const double value = variables[index].unit.fromDisplay(display);
        if (index < inputs) {
            q[index] = value;
            anyInput = anyInput || !variables[index].independent;
        } else {
            x[index - inputs] = value;
            anyOutput = true;
        }
    }
    if (anyInput && anyOutput) {
        return Failure{FailureKind::InvalidParameter, values.front().first.toStdString(),
                       QCoreApplication::translate("pkm::designfile",
                                                   "Give either the actuated inputs or the outputs of the pose, not "
                                                   "both.")
                           .toStdString()};
    }
    if (anyInput || !anyOutput)
        return mechanism.solveDirect(q, &current);
    Pose near = current; // with the independent axes (z) already moved
    near.inputs = q;
    return mechanism.solveInverse(x, &near);
}

} // namespace designfile
} // namespace pkm
