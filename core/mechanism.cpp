#include "mechanism.h"


#include "text.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <cmath>
#include <numbers>

namespace pkm {

std::string_view parameterGroupKey(ParameterGroup group)
{
    switch (group) {
    case ParameterGroup::Geometry:
        return "geometry";
    case ParameterGroup::Range:
        return "range";
    case ParameterGroup::Actuator:
        return "actuator";
    case ParameterGroup::Drawing:
        return "drawing";
    case ParameterGroup::Mode:
        return "mode";
    }
    return "geometry";
}

const ReportEntry *ReportLayout::find(std::string_view name) const
{
    for (const ReportEntry &entry : entries) {
        if (entry.name == name)
            return &entry;
    }
    return nullptr;
}

void ReportLayout::add(ReportGroup group, const char *name, const char *symbol, const char *label, Unit unit,
                       int decimals, int rows, int cols)
{
    ReportEntry e;
    e.group = group;
    e.name = name;
    e.symbol = symbol;
    e.label = label;
    e.unit = unit;
    e.rows = rows;
    e.cols = cols;
    e.offset = size;
    e.decimals = decimals;
    size += rows * cols;
    entries.push_back(std::move(e));
}

std::string_view singularityName(SingularityType type)
{
    switch (type) {
    case SingularityType::None: return "none";
    case SingularityType::Inverse: return "inverse";
    case SingularityType::Direct: return "direct";
    case SingularityType::Combined: return "combined";
    }
    return "none";
}

Singularity classifySingularity(double inverseMargin, double directMargin, double tolerance)
{
    const bool inverse = inverseMargin < tolerance, direct = directMargin < tolerance;
    Singularity s;
    s.type = inverse && direct ? SingularityType::Combined
           : inverse           ? SingularityType::Inverse
           : direct            ? SingularityType::Direct
                               : SingularityType::None;
    s.margin = std::min(inverseMargin, directMargin);
    s.directMargin = directMargin;
    return s;
}

void ReportLayout::atSingularity(const char *name, AtSingularity inverse, AtSingularity direct)
{
    for (ReportEntry &entry : entries) {
        if (entry.name == name) {
            entry.atInverse = inverse;
            entry.atDirect = direct;
            return;
        }
    }
}

void ReportLayout::atSingularityOfJ(const char *inputDeterminant)
{
    using S = AtSingularity;
    atSingularity("J", S::Infinite, S::Computed);
    atSingularity("det_J", S::Infinite, S::Zero);
    atSingularity("cond", S::Infinite, S::Infinite);
    atSingularity(inputDeterminant, S::Zero, S::Computed);
    atSingularity("det_Jx", S::Computed, S::Zero);
}

void settleSingularValues(const ReportLayout &layout, std::span<double> values, SingularityType type)
{
    if (type == SingularityType::None)
        return;
    using A = AtSingularity;
    for (const ReportEntry &entry : layout.entries) {
        A mark = type == SingularityType::Inverse ? entry.atInverse
               : type == SingularityType::Direct  ? entry.atDirect
                                                  : A::Computed;
        double value = 0.0;
        if (type == SingularityType::Combined) {
            const A a = entry.atInverse, b = entry.atDirect;
            if (a == A::Computed || b == A::Computed || a == b) {
                mark = a == A::Computed ? b : a;
            } else {
                mark = A::Infinite; // 0·∞: neither value holds
                value = std::numeric_limits<double>::quiet_NaN();
            }
        }
        if (mark == A::Computed)
            continue;
        if (mark == A::Infinite && value == 0.0)
            value = std::numeric_limits<double>::infinity();
        const std::size_t first = static_cast<std::size_t>(entry.offset);
        const std::size_t count = static_cast<std::size_t>(entry.rows * entry.cols);
        for (std::size_t i = first; i < first + count && i < values.size(); ++i)
            values[i] = mark == A::Zero ? 0.0 : value;
    }
}

int Mechanism::inputCount() const
{
    int count = 0;
    for (const VariableInfo &info : variableInfo())
        count += info.actuated ? 1 : 0;
    return count;
}

int Mechanism::outputCount() const
{
    return static_cast<int>(variableInfo().size()) - inputCount();
}

const ParameterInfo *Mechanism::findParameter(std::string_view name) const
{
    for (const ParameterInfo &info : parameterInfo()) {
        if (info.name == name)
            return &info;
    }
    return nullptr;
}

int Mechanism::variableIndex(std::string_view name) const
{
    const auto &infos = variableInfo();
    for (std::size_t i = 0; i < infos.size(); ++i) {
        if (infos[i].name == name)
            return static_cast<int>(i);
    }
    return -1;
}

double Mechanism::variableValue(const Pose &pose, int variable) const
{
    const int inputs = inputCount();
    return variable < inputs ? pose.inputs[variable] : pose.outputs[variable - inputs];
}

Scene3D Mechanism::scene3d(const Pose &pose) const
{
    const Scene flat = scene(pose);
    // links as thick as a twentieth of the machine, within readable limits
    const double size = flat.extent.isEmpty() ? 100.0 : flat.extent.sizes().head<2>().maxCoeff();
    return extrudeScene(flat, std::clamp(size / 20.0, 4.0, 40.0));
}

Result<Pose> Mechanism::solveWith(const Pose &current, int variable, double value) const
{
    const int inputs = inputCount();
    if (variable < 0 || variable >= static_cast<int>(variableInfo().size()))
        return Failure{FailureKind::UnknownName, {}, text::translate("core", "No joint variable with that index.")};
    if (!std::isfinite(value)) {
        const std::string &name = variableInfo()[variable].name;
        return Failure{FailureKind::OutOfRange, name,
                       text::format(text::translate("core", "%1 must be a finite number."), {name})};
    }
    if (variable < inputs) {
        Coordinates q = current.inputs;
        q[variable] = value;
        return followDirect(q, current);
    }
    Coordinates x = current.outputs;
    x[variable - inputs] = value;
    return solveInverse(x, &current);
}

std::vector<ModeAlternative> Mechanism::modeAlternatives(const Pose &pose) const
{
    return solveAlternatives(modeNeighbours(), pose, this);
}

std::vector<ModeAlternative> Mechanism::solveAlternatives(const std::vector<ModeAlternative> &neighbours,
                                                          const Pose &pose, const Mechanism *current)
{
    bool meeting = false; // two assembly modes meet at this pose
    ParameterSet parameters;
    if (current) {
        std::vector<double> values(current->reportLayout().size);
        const SingularityType type = current->evaluate(pose, values).type;
        meeting = type == SingularityType::Direct || type == SingularityType::Combined;
        if (meeting)
            parameters = current->parameters();
    }
    // a neighbour whose changes hold already is the mode the design is in
    const auto isCurrentMode = [&](const ModeAlternative &neighbour) {
        return std::all_of(neighbour.changes.begin(), neighbour.changes.end(), [&](const auto &change) {
            const auto it = parameters.find(change.first);
            return it != parameters.end() && it->second == change.second;
        });
    };
    std::vector<ModeAlternative> solved;
    for (const ModeAlternative &neighbour : neighbours) {
        const bool taken = std::any_of(solved.begin(), solved.end(),
                                       [&](const ModeAlternative &s) { return s.label == neighbour.label; });
        if (taken || !neighbour.mechanism)
            continue;
        // A neighbour keeping the inputs is solved without the pose to follow: a kind whose
        // direct kinematics continues from that pose (the 3-DOF planar parallel mechanism)
        // would return to it, and the neighbour's own mode parameters would have no say.
        auto pose2 = neighbour.sameInputs ? neighbour.mechanism->solveDirect(pose.inputs, nullptr)
                                          : neighbour.mechanism->solveInverse(pose.outputs, &pose);
        if (!pose2)
            continue;
        // a mode whose pose is the current one (the solution the design is in already) is no ghost
        if (neighbour.sameInputs && pose2->outputs.size() == pose.outputs.size()
            && (pose2->outputs - pose.outputs).norm() <= 1e-9 * std::max(1.0, pose.outputs.norm())
            && (!meeting || isCurrentMode(neighbour)))
            continue;
        ModeAlternative alternative = neighbour;
        alternative.pose = *pose2;
        solved.push_back(std::move(alternative));
    }
    return solved;
}

std::vector<Pose> Mechanism::assemblyModes(const Pose &pose) const
{
    std::vector<Pose> modes {pose};
    for (const ModeAlternative &neighbour : modeNeighbours()) {
        if (!neighbour.sameInputs || !neighbour.mechanism)
            continue;
        auto other = neighbour.mechanism->solveDirect(pose.inputs, &pose);
        if (!other)
            continue;
        // one entry per pose: neighbours may reach the same one
        const bool known = std::any_of(modes.begin(), modes.end(), [&](const Pose &m) {
            return (m.outputs - other->outputs).norm() <= 1e-9 * std::max(1.0, m.outputs.norm());
        });
        if (!known)
            modes.push_back(*other);
    }
    return modes;
}

Result<MechanismPtr> Mechanism::withParameters(const ParameterSet &changes) const
{
    Result<MechanismPtr> current = MechanismPtr(shared_from_this());
    for (const auto &[name, value] : changes) {
        current = (*current)->withParameter(name, value);
        if (!current)
            return current;
    }
    return current;
}

Result<MechanismPtr> Mechanism::blameChange(Result<MechanismPtr> made, const ParameterSet &changes)
{
    if (!made && changes.size() == 1 && made.failure().culprit != changes.begin()->first) {
        Failure f = made.failure();
        f.culprit = changes.begin()->first;
        return f;
    }
    return made;
}

std::string joinText(std::initializer_list<std::string_view> parts)
{
    std::string text;
    for (std::string_view part : parts)
        text.append(part);
    return text;
}

std::string formatMillimetres(double value)
{
    // For messages only (never files): the locale's decimal point and unit once hooks are in.
    return text::millimetres(value);
}

Result<double> Mechanism::checkDomain(const ParameterInfo &info, double value)
{
    const Interval &d = info.domain;
    const bool tooLow = info.openMin ? !(value > d.min) : !(value >= d.min);
    const bool tooHigh = info.openMax ? !(value < d.max) : !(value <= d.max);
    if (!std::isfinite(value) || tooLow || tooHigh) {
        const std::string label = text::label(info.label);
        const std::string shown = std::isfinite(value) ? text::number(info.unit.toDisplay(value))
                                                       : text::translate("core", "not a number");
        // the unit follows the bound: "0 mm", "90°"
        const std::string unit = info.unit.symbol.empty()
                                   ? std::string()
                                   : joinText({info.unit.symbol == units::angle.symbol ? "" : " ",
                                               text::label(info.unit.symbol)});
        const std::string lo = text::number(info.unit.toDisplay(d.min));
        std::string message;
        if (std::isinf(d.max)) {
            const std::string bound = joinText({lo, unit});
            message = info.openMin
                        ? text::format(text::translate("core", "%1 (%2) = %3 is invalid: it must be greater than %4."),
                                       {info.name, label, shown, bound})
                        : text::format(text::translate("core", "%1 (%2) = %3 is invalid: it must be at least %4."),
                                       {info.name, label, shown, bound});
        } else {
            // the brackets say whether the ends are allowed; a locale with a decimal comma may
            // separate the ends with "; "
            const std::string hi = text::number(info.unit.toDisplay(d.max));
            const std::string ends = info.openMin
                                       ? (info.openMax ? text::translate("core", "(%1, %2)")
                                                       : text::translate("core", "(%1, %2]"))
                                       : (info.openMax ? text::translate("core", "[%1, %2)")
                                                       : text::translate("core", "[%1, %2]"));
            const std::string interval = joinText({text::format(ends, {lo, hi}), unit});
            message = text::format(text::translate("core", "%1 (%2) = %3 is invalid: it must be %4."),
                                   {info.name, label, shown, interval});
        }
        return Failure{FailureKind::InvalidParameter, info.name, message};
    }
    return value;
}

std::string formatNumber(double value, int decimals)
{
    if (!std::isfinite(value))
        return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
    char buffer[400];
    // Very large or very small magnitudes read better, and fit, in scientific notation.
    const double magnitude = std::abs(value);
    if (magnitude >= 1e9 || (magnitude > 0 && magnitude < 1e-6)) {
        auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
        return ec == std::errc() ? std::string(buffer, end) : std::string("?");
    }
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    if (ec != std::errc())
        return "?";
    std::string text(buffer, end);
    if (text.find('.') != std::string::npos) {
        while (!text.empty() && text.back() == '0')
            text.pop_back();
        if (!text.empty() && text.back() == '.')
            text.pop_back();
    }
    if (text == "-0")
        text = "0";
    return text;
}

bool turnsFully(const Mechanism &mechanism, int i)
{
    const VariableInfo &info = mechanism.variableInfo()[std::size_t(i)];
    const Interval range = mechanism.variableRange(i);
    return info.unit.symbol == units::angle.symbol && range.max - range.min >= 2.0 * std::numbers::pi - 1e-9;
}

} // namespace pkm
