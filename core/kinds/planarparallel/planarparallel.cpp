// The planar parallel mechanism from a leg library: the validation of a design (its
// parameters are in pptable.cpp), the direct and inverse kinematics in the design's modes, the
// Jacobians, the singularity classes and the report. The leg model is in legs.cpp, the forward problem of a 3-DOF
// platform in forward.cpp, the maps, the scene and the kinematic chain in planarscene.cpp.
#include "planarparallel.h"

#include "text.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
using planar::cross;
using planar::Reach;

/// A leg's number as its names show it ("q2", "leg 3").
std::string number(int leg)
{
    return std::to_string(leg + 1);
}
} // namespace

// -- design --------------------------------------------------------------------------------

namespace {
Failure invalid(const std::string &name, const std::string &message)
{
    return Failure{FailureKind::InvalidParameter, name, message};
}

/// What a leg of this type needs of its own parameters.
Result<bool> checkLeg(const PlanarLeg &leg, int i, PlatformType platform)
{
    const std::string n = number(i);
    const char *prefix = leg.type == LegType::RRR ? "theta" : "q";
    const std::string qMin = joinText({prefix, n, "_min"}), qMax = joinText({prefix, n, "_max"});
    const Interval &range = leg.inputRange();
    if (!(range.min < range.max))
        return invalid(qMin, text::format(text::translate("core", "%1 must be less than %2."), {qMin, qMax}));
    switch (leg.type) {
    case LegType::RRR:
        if (range.max - range.min > 2.0 * pi * (1.0 + 1e-12))
            return invalid(qMax, text::format(text::translate("core", "The range of crank %1 spans more than one turn (360°)."), {n}));
        break;
    case LegType::RPR:
        if (range.min <= 0.0)
            return invalid(qMin, text::format(text::translate("core", "%1 must be positive: it is the length of strut %2."), {qMin, n}));
        break;
    case LegType::PiRR: {
        // the diagonal stays strictly between the folded a|1 − k| and the stretched a(1 + k)
        const double low = leg.lever * std::abs(1.0 - leg.ratio), high = leg.lever * (1.0 + leg.ratio);
        if (range.min <= low || range.max >= high)
            return invalid(range.min <= low ? qMin : qMax,
                           text::format(text::translate("core", "The diagonal of П-joint %1 must stay strictly between %2 mm and %3 mm (θ between −90° and 90°)."),
                                        {n, text::number(low), text::number(high)}));
        break;
    }
    case LegType::PRR:
        break;
    }
    if (platform == PlatformType::Translating && leg.type != LegType::PRR && leg.type != LegType::PiRR)
        return invalid(joinText({"leg", n, "_type"}),
                       text::format(text::translate("core", "A platform of constant orientation needs P̲RR or П̲RR legs: leg %1's distal parallelogram must hang from a body that does not turn."), {n}));
    return true;
}
} // namespace

Result<MechanismPtr> PlanarParallel::create(const PlanarParallelDesign &design)
{
    return assemble(design, nullptr);
}

Result<MechanismPtr> PlanarParallel::assemble(const PlanarParallelDesign &design, const Eigen::Vector3d *reference,
                                              SharedSearch *shared)
{
    if (auto checked = table().checkDesign(design); !checked)
        return checked.failure();
    const int n = design.legCount();
    for (int i = 0; i < n; ++i) {
        if (auto checked = checkLeg(design.legs[std::size_t(i)], i, design.platform); !checked)
            return checked.failure();
    }
    if (n == 2 && design.assembly != 1 && design.assembly != -1)
        return invalid("assembly", text::format(text::translate("core", "%1 = %2 is invalid: it must be -1 or +1."),
                                                {"assembly", text::number(design.assembly)}));
    if (n == 3) {
        if (design.assembly < 1)
            return invalid("assembly", text::translate("core", "The assembly mode of a 3-DOF platform counts the solutions from 1."));
        const auto &legs = design.legs;
        if ((legs[1].platform - legs[0].platform).norm() + (legs[2].platform - legs[0].platform).norm() <= 0.0)
            return invalid("B1x", text::translate("core", "The platform points B₁, B₂, B₃ coincide: the platform's angle is undetermined."));
    }
    std::shared_ptr<PlanarParallel> made(new PlanarParallel(design, shared));
    if (made->m_home.inputs.size() == 0 && reference) {
        // the grid of inputs missed it, but the pose the edit starts from may still assemble
        Coordinates outputs(n == 3 ? 3 : 2);
        outputs[0] = reference->x();
        outputs[1] = reference->y();
        if (n == 3)
            outputs[2] = reference->z();
        if (auto pose = made->solveInverse(outputs))
            made->m_home = *pose;
    }
    if (made->m_home.inputs.size() == 0) {
        const std::string none = text::translate("core", "The mechanism cannot be assembled anywhere in its input ranges and modes.");
        return Failure{FailureKind::Unreachable, "assembly",
                       reference ? joinText({none, " ", made->assemblyFailure(*reference)}) : none};
    }
    return MechanismPtr(made);
}

PlanarParallel::PlanarParallel(const PlanarParallelDesign &design, SharedSearch *shared)
    : m_design(design)
    , m_shared(shared)
{
    // the search's shared solutions serve the constructor only: the mechanism made is a value
    // that many threads may read
    struct Forget {
        SharedSearch *&shared;
        ~Forget() { shared = nullptr; }
    } forget{m_shared};
    for (PlanarLeg &leg : m_design.legs)
        leg.guide = planar::direction(leg.alpha);
    const int n = design.legCount();
    static const std::array<const char *, 3> inputLabels = {QT_TRANSLATE_NOOP("core", "input of leg 1 (actuated)"),
                                                             QT_TRANSLATE_NOOP("core", "input of leg 2 (actuated)"),
                                                             QT_TRANSLATE_NOOP("core", "input of leg 3 (actuated)")};
    static const std::array<const char *, 3> subscripts = {"₁", "₂", "₃"};
    for (int i = 0; i < n; ++i) {
        const bool angle = design.legs[std::size_t(i)].type == LegType::RRR;
        m_variables.push_back({joinText({"q", number(i)}), joinText({"q", subscripts[std::size_t(i)]}), inputLabels[std::size_t(i)],
                               angle ? units::angle : units::millimetre, true, 2});
    }
    m_variables.push_back({"x", "x", QT_TRANSLATE_NOOP("core", "platform x"), units::millimetre, false, 2});
    m_variables.push_back({"y", "y", QT_TRANSLATE_NOOP("core", "platform y"), units::millimetre, false, 2});
    if (n == 3)
        m_variables.push_back({"phi", "φ", QT_TRANSLATE_NOOP("core", "platform angle"), units::angle, false, 2});
    buildReport();
    // the bounds depend on the working modes, not on the assembly mode (SharedSearch)
    const std::array<int, 3> working = {design.legs[0].working, design.legs[1].working, design.legs[2].working};
    const std::pair<Eigen::AlignedBox2d, Eigen::AlignedBox2d> *known = nullptr;
    if (m_shared) {
        if (const auto found = m_shared->bounds.find(working); found != m_shared->bounds.end())
            known = &found->second;
    }
    m_bounds = known ? known->first : computeBounds();
    m_outputBounds = known ? known->second : computeOutputBounds();
    if (m_shared && !known)
        m_shared->bounds.emplace(working, std::pair(m_bounds, m_outputBounds));

    // The home pose: the inputs in the middle of their ranges if the mechanism assembles there
    // in its modes away from singularities, else the best of a grid of inputs.
    Coordinates mid(n);
    for (int i = 0; i < n; ++i)
        mid[i] = 0.5 * (design.legs[std::size_t(i)].inputRange().min + design.legs[std::size_t(i)].inputRange().max);
    if (auto pose = solveDirect(mid); pose && singularity(*pose).margin >= 0.2) {
        m_home = *pose;
        return;
    }
    // Three legs: a coarse grid of inputs, then a pattern search around its best. Each direct
    // solution finds every assembly mode (a polynomial of degree 6), and a 9³ grid made
    // creating a 3-DOF design take ~30 ms, on every edit. The fine grid is kept for a
    // mechanism that assembles only where the coarse grid does not look.
    double best = -1.0;
    Coordinates bestInputs(n);
    const auto consider = [&](const Coordinates &q) {
        if (auto pose = solveDirect(q)) {
            const double margin = singularity(*pose).margin;
            if (margin > best) {
                best = margin;
                m_home = *pose;
                bestInputs = q;
            }
        }
    };
    const auto searchGrid = [&](int samples) {
        Coordinates q(n);
        const int total = n == 2 ? samples * samples : samples * samples * samples;
        for (int index = 0; index < total; ++index) {
            int rest = index;
            for (int i = 0; i < n; ++i) {
                const Interval &r = design.legs[std::size_t(i)].inputRange();
                q[i] = r.min + (r.max - r.min) * (0.5 + rest % samples) / samples;
                rest /= samples;
            }
            consider(q);
        }
    };
    if (n == 2) { // a two-leg platform's direct solution is closed-form: the fine grid is cheap
        searchGrid(17);
        return;
    }
    constexpr int coarse = 5;
    searchGrid(coarse);
    if (m_home.inputs.size() == 0) {
        searchGrid(9);
        return;
    }
    constexpr int neighbours = 27;
    for (double step = 0.5 / coarse; step > 0.02 / coarse; step /= 2) {
        const Coordinates around = bestInputs;
        for (int index = 0; index < neighbours; ++index) {
            Coordinates q = around;
            int rest = index;
            bool centre = true;
            for (int i = 0; i < n; ++i) {
                const int direction = rest % 3 - 1;
                rest /= 3;
                centre = centre && direction == 0;
                // no nearer the ends of a range than the fine grid goes: a home at a stop
                // could not be moved both ways
                const Interval &r = design.legs[std::size_t(i)].inputRange();
                const double inset = 0.5 / 9 * (r.max - r.min);
                q[i] = std::clamp(q[i] + direction * step * (r.max - r.min), r.min + inset, r.max - inset);
            }
            if (!centre)
                consider(q);
        }
    }
}

Interval PlanarParallel::variableRange(int variable) const
{
    const int n = m_design.legCount();
    if (variable < n)
        return m_design.legs[std::size_t(variable)].inputRange();
    if (variable - n == 2)
        return {-pi, pi};
    const Eigen::AlignedBox2d &b = m_outputBounds;
    return variable == n ? Interval{b.min().x(), b.max().x()} : Interval{b.min().y(), b.max().y()};
}

Eigen::Vector3d PlanarParallel::platformPose(const Coordinates &outputs) const
{
    return {outputs[0], outputs[1], m_design.legCount() == 3 ? outputs[2] : 0.0};
}

std::array<planar::LegCircle, 3> PlanarParallel::circles(const Coordinates &inputs) const
{
    std::array<planar::LegCircle, 3> c;
    for (int i = 0; i < m_design.legCount(); ++i)
        c[std::size_t(i)] = planar::circle(m_design.legs[std::size_t(i)], inputs[i]);
    return c;
}

// -- kinematics ----------------------------------------------------------------------------

namespace {
Pose makePose(const Coordinates &inputs, const Eigen::Vector3d &X, int n)
{
    Pose pose;
    pose.inputs = inputs;
    pose.outputs.resize(n);
    pose.outputs[0] = X.x();
    pose.outputs[1] = X.y();
    if (n == 3)
        pose.outputs[2] = X.z();
    return pose;
}
} // namespace

std::vector<Pose> PlanarParallel::assemblies(const Coordinates &inputs) const
{
    const int n = m_design.legCount();

    const auto c = circles(inputs);
    std::vector<Eigen::Vector3d> candidates;
    for (int i = 0; i < n; ++i) {
        if (!c[std::size_t(i)].valid)
            return {};
    }
    if (n == 2) {
        // two circles in the plane of (x, y): leg i's about C_i − B_i (B_i = 0 for a point)
        const Eigen::Vector2d p = c[0].centre - m_design.legs[0].platform, q = c[1].centre - m_design.legs[1].platform;
        const double rp = c[0].radius, rq = c[1].radius;
        const Eigen::Vector2d between = q - p;
        const double distance = between.norm(), scale = rp + rq;
        if (distance < 1e-9 * scale || distance > scale * (1.0 + 1e-9) || distance < std::abs(rp - rq) - 1e-9 * scale)
            return {};
        const Eigen::Vector2d u = between / distance;
        const double along = (rp * rp - rq * rq + distance * distance) / (2.0 * distance);
        const double across = std::sqrt(std::max(0.0, rp * rp - along * along));
        for (const int side : {m_design.assembly, -m_design.assembly}) {
            const Eigen::Vector2d X = p + along * u + side * across * Eigen::Vector2d(-u.y(), u.x());
            candidates.emplace_back(X.x(), X.y(), 0.0);
        }
    } else if (m_shared) {
        // solved once for every design that shares the search (SharedSearch)
        const auto key = std::make_tuple(inputs[0], inputs[1], inputs[2]);
        auto found = m_shared->solutions.find(key);
        if (found == m_shared->solutions.end())
            found = m_shared->solutions.emplace(key, planar::threeCircleSolutions(m_design.legs, c)).first;
        candidates = found->second;
    } else {
        candidates = planar::threeCircleSolutions(m_design.legs, c);
    }
    std::vector<Pose> poses;
    for (const Eigen::Vector3d &X : candidates) {
        bool modes = true;
        for (int i = 0; i < n; ++i) {
            const PlanarLeg &leg = m_design.legs[std::size_t(i)];
            modes = modes && planar::workingOf(leg, inputs[i], planar::platformPoint(leg, X)) * leg.working >= 0;
        }
        if (modes)
            poses.push_back(makePose(inputs, X, n));
    }
    return poses;
}

Result<Pose> PlanarParallel::solveDirect(const Coordinates &inputs, const Pose *near) const
{
    const int n = m_design.legCount();
    if (inputs.size() != n)
        return Failure{FailureKind::OutOfRange, "q1", text::translate("core", "The number of inputs does not match the legs.")};
    for (int i = 0; i < n; ++i) {
        const std::string name = joinText({"q", number(i)});
        const Interval &range = m_design.legs[std::size_t(i)].inputRange();
        if (!std::isfinite(inputs[i]))
            return Failure{FailureKind::OutOfRange, name, text::format(text::translate("core", "%1 must be a finite number."), {name})};
        if (!range.contains(inputs[i], 1e-9 * std::max(1.0, std::abs(range.max - range.min))))
            return Failure{FailureKind::OutOfRange, name,
                           text::format(text::translate("core", "%1 = %2 is outside its range [%3, %4]."),
                                        {name, text::numberOutside(m_variables[std::size_t(i)].unit.toDisplay(inputs[i]),
                                                                   m_variables[std::size_t(i)].unit.toDisplay(range.min),
                                                                   m_variables[std::size_t(i)].unit.toDisplay(range.max)),
                                         text::number(m_variables[std::size_t(i)].unit.toDisplay(range.min)),
                                         text::number(m_variables[std::size_t(i)].unit.toDisplay(range.max))})};
        if (!planar::circle(m_design.legs[std::size_t(i)], inputs[i]).valid)
            return Failure{FailureKind::OutOfRange, name,
                           text::format(text::translate("core", "The П-joint of leg %1 cannot take the diagonal %2 = %3 mm."),
                                        {number(i), name, text::number(inputs[i])})};
    }
    const std::vector<Pose> poses = assemblies(inputs);
    const Failure none{FailureKind::Unreachable, "q1",
                       text::translate("core", "The legs cannot be assembled at these inputs in the design's working and assembly modes.")};
    if (poses.empty())
        return none;
    if (n == 2) {
        // the first candidate is the design's assembly mode: the second is the other one
        const Eigen::Vector3d X = platformPose(poses.front().outputs);
        const auto c = circles(inputs);
        const Eigen::Vector2d p = c[0].centre - m_design.legs[0].platform, q = c[1].centre - m_design.legs[1].platform;
        if (cross(q - p, X.head<2>() - p) * m_design.assembly < -1e-9 * c[0].radius * c[1].radius)
            return none;
        return poses.front();
    }
    // 3 DOF: continuation from the pose to follow (Newton's method from it on the new inputs,
    // then the nearest solution), else the assembly-th solution in order of φ
    if (near && near->outputs.size() == 3) {
        Eigen::Vector3d start = platformPose(near->outputs);
        Eigen::Vector3d X = start;
        if (planar::polish(m_design.legs, circles(inputs), X))
            start = X;
        const double L = std::max(1.0, m_bounds.sizes().norm());
        const Pose *best = nullptr;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Pose &pose : poses) {
            const Eigen::Vector3d Y = platformPose(pose.outputs);
            const double distance = (Y.head<2>() - start.head<2>()).norm() / L + std::abs(std::remainder(Y.z() - start.z(), 2 * pi));
            if (distance < nearest) {
                nearest = distance;
                best = &pose;
            }
        }
        Pose chosen = *best;
        // keep φ on the same turn as the pose followed
        chosen.outputs[2] = near->outputs[2] + std::remainder(chosen.outputs[2] - near->outputs[2], 2 * pi);
        return chosen;
    }
    if (m_design.assembly > int(poses.size()))
        return Failure{FailureKind::Unreachable, "assembly",
                       text::format(text::translate("core", "At these inputs the platform has %1 assembly modes in the design's working modes, fewer than assembly = %2."),
                                    {std::to_string(poses.size()), std::to_string(m_design.assembly)})};
    return poses[std::size_t(m_design.assembly - 1)];
}

Reach PlanarParallel::inverseCheck(const Eigen::Vector3d &X, const Coordinates *reference, Coordinates &q, int &culprit) const
{
    const int n = m_design.legCount();
    q.resize(n);
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = m_design.legs[std::size_t(i)];
        const double ref = reference && reference->size() == n ? (*reference)[i]
            : m_home.inputs.size() == n                        ? m_home.inputs[i]
                                                               : 0.5 * (leg.inputRange().min + leg.inputRange().max);
        const Reach r = planar::inverse(leg, planar::platformPoint(leg, X), ref, q[i]);
        if (r != Reach::Yes) {
            culprit = i;
            return r;
        }
    }
    if (n == 2) {
        const PlanarLeg &a = m_design.legs[0], &b = m_design.legs[1];
        const planar::LegCircle ca = planar::circle(a, q[0]), cb = planar::circle(b, q[1]);
        const Eigen::Vector2d p = ca.centre - a.platform, o = cb.centre - b.platform;
        if (cross(o - p, X.head<2>() - p) * m_design.assembly < -1e-9 * ca.radius * cb.radius) {
            culprit = -1;
            return Reach::Undetermined; // the other assembly mode
        }
    }
    culprit = 0;
    return Reach::Yes;
}

Result<Pose> PlanarParallel::solveInverse(const Coordinates &outputs, const Pose *near) const
{
    const int n = m_design.legCount();
    for (int i = 0; i < n; ++i) {
        const std::string name = m_variables[std::size_t(n + i)].name;
        if (i >= outputs.size() || !std::isfinite(outputs[i]))
            return Failure{FailureKind::OutOfRange, name, text::format(text::translate("core", "%1 must be a finite number."), {name})};
    }
    const Eigen::Vector3d X = platformPose(outputs);
    Coordinates q;
    int culprit = 0;
    const Reach r = inverseCheck(X, near ? &near->inputs : nullptr, q, culprit);
    if (r != Reach::Yes) {
        const std::string where = n == 3
            ? text::format(text::translate("core", "(%1, %2) mm, φ = %3°"), {text::number(X.x()), text::number(X.y()), text::number(X.z() / units::degree)})
            : text::format(text::translate("core", "(%1, %2) mm"), {text::number(X.x()), text::number(X.y())});
        if (culprit < 0)
            return Failure{FailureKind::Unreachable, "x",
                           text::format(text::translate("core", "The platform cannot reach %1 in this assembly mode: the legs would pass through a direct singularity; switch the assembly mode to go on."), {where})};
        const std::string leg = number(culprit);
        const std::string why = r == Reach::Range
            ? text::format(text::translate("core", "the input of leg %1 would leave its range"), {leg})
            : r == Reach::Undetermined ? text::format(text::translate("core", "the input of leg %1 is undetermined there"), {leg})
                                       : text::format(text::translate("core", "leg %1 cannot reach it"), {leg});
        return Failure{r == Reach::Range ? FailureKind::OutOfRange : FailureKind::Unreachable, "x",
                       text::format(text::translate("core", "The platform cannot reach %1: %2."), {where, why})};
    }
    Pose pose = makePose(q, X, n);
    pose.outputs = outputs;
    return pose;
}

} // namespace pkm
