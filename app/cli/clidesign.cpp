#include "cli/clidesign.h"

#include <QString>

#include <algorithm>

#include <map>
#include <utility>
#include <optional>

namespace pkm::cli {

namespace {

QList<QPair<QString, double>> displayValues(const std::vector<Setting> &settings)
{
    QList<QPair<QString, double>> values;
    for (const Setting &setting : settings)
        values.append({QString::fromStdString(setting.name), setting.value});
    return values;
}

/// Refuses --set values that mix actuated inputs and outputs: the pose would be overdetermined.
std::optional<Failure> mixedPoseSets(const Mechanism &mechanism, const std::vector<Setting> &poseSets)
{
    const Setting *input = nullptr;
    const Setting *output = nullptr;
    for (const Setting &setting : poseSets) {
        const auto index = static_cast<std::size_t>(mechanism.variableIndex(setting.name));
        if (mechanism.variableInfo()[index].independent)
            continue; // an axis carrying the mechanism goes with either
        const Setting *&first = mechanism.variableInfo()[index].actuated ? input : output;
        if (!first)
            first = &setting;
    }
    if (!input || !output)
        return std::nullopt;
    return usageFailure(output->name,
        "--set " + input->text + " and --set " + output->text
            + " mix an actuated input and an output: give the inputs (direct "
              "kinematics) or the outputs (inverse kinematics), not both.");
}

} // namespace

Failure unknownSetName(
    const Mechanism &mechanism, const std::string &context, const std::string &name, const std::string &origin)
{
    return Failure {FailureKind::UnknownName, name,
        context + ": a " + std::string(mechanism.kind()) + " has no parameter or pose variable named '" + name
            + "' (see 'pkm show " + origin + "')."};
}

Result<Pose> solvePoseSets(const Mechanism &mechanism, const Pose &current, const std::vector<Setting> &poseSets)
{
    auto solved = designfile::solveDisplayVariables(mechanism, current, displayValues(poseSets));
    if (solved)
        return solved;
    std::string context;
    for (const Setting &setting : poseSets) {
        if (setting.name == solved.failure().culprit)
            context = "--set " + setting.text;
    }
    if (context.empty()) {
        for (const Setting &setting : poseSets)
            context += (context.empty() ? "--set " : " --set ") + setting.text;
    }
    return inContext(solved.failure(), context);
}

Result<PreparedDesign> loadDesign(const std::string &origin)
{
    PreparedDesign prepared;
    prepared.origin = origin;
    auto loaded = designfile::load(QString::fromStdString(origin));
    if (!loaded)
        return loaded.failure();
    prepared.design = *loaded;
    prepared.mechanism = prepared.design.mechanism;
    prepared.pose = prepared.design.pose;
    return prepared;
}

Result<PreparedDesign> prepareDesign(const std::string &origin, const std::vector<Setting> &sets)
{
    auto loaded = loadDesign(origin);
    if (!loaded)
        return loaded.failure();
    return applySettings(std::move(*loaded), sets);
}

Result<PreparedDesign> applySettings(PreparedDesign prepared, const std::vector<Setting> &sets)
{
    const std::string &origin = prepared.origin;
    prepared.poseSets.clear();
    prepared.note.clear();

    // All parameter changes go to the design at once, so their order does not matter (k with a)
    // and contradictions (b with k) are refused; a parameter given twice takes the last value.
    ParameterSet changes;
    std::map<std::string, std::string> contexts;
    for (const Setting &setting : sets) {
        const std::string context = "--set " + setting.text;
        const ParameterInfo *info = prepared.mechanism->findParameter(setting.name);
        if (!setting.word.empty() && (info || prepared.mechanism->variableIndex(setting.name) >= 0)) {
            const auto choice = info ? std::find_if(info->choices.begin(), info->choices.end(),
                                           [&](const auto &c) { return c.first == setting.word; })
                                     : std::vector<std::pair<std::string, double>>::const_iterator {};
            if (!info || choice == info->choices.end()) {
                std::string names;
                if (info) {
                    for (const auto &c : info->choices)
                        names.append(names.empty() ? "" : " or ").append(c.first);
                }
                return usageFailure(setting.name,
                    context + ": '" + setting.word + "' is not a number"
                        + (names.empty() ? std::string(".") : " nor a value of " + setting.name + " (" + names + ")."));
            }
            changes[setting.name] = choice->second;
            contexts[setting.name] = context;
        } else if (info) {
            changes[setting.name] = info->unit.fromDisplay(setting.value);
            contexts[setting.name] = context;
        } else if (prepared.mechanism->variableIndex(setting.name) >= 0) {
            prepared.poseSets.push_back(setting);
        } else {
            return unknownSetName(*prepared.mechanism, context, setting.name, origin);
        }
    }
    const bool parametersChanged = !changes.empty();
    if (parametersChanged) {
        auto changed = prepared.mechanism->withParameters(changes);
        if (!changed) {
            const auto culprit = contexts.find(changed.failure().culprit);
            return inContext(changed.failure(), culprit != contexts.end() ? culprit->second : contexts.begin()->second);
        }
        prepared.mechanism = *changed;
    }

    const Mechanism &mechanism = *prepared.mechanism;
    if (auto mixed = mixedPoseSets(mechanism, prepared.poseSets))
        return *mixed;
    if (parametersChanged) {
        // The stored pose belongs to the old design: keep its outputs if the new one reaches them.
        auto again = mechanism.solveInverse(prepared.pose.outputs, &prepared.pose);
        if (again) {
            prepared.pose = *again;
        } else {
            prepared.pose = mechanism.homePose();
            if (prepared.poseSets.empty())
                prepared.note = "the stored pose does not fit the changed design (" + again.failure().message
                    + "), so the home pose is used.";
        }
    }
    if (!prepared.poseSets.empty()) {
        auto solved = solvePoseSets(mechanism, prepared.pose, prepared.poseSets);
        if (!solved)
            return solved.failure();
        prepared.pose = *solved;
    }
    return prepared;
}

} // namespace pkm::cli
