#include "capability.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace pkm::capability {

namespace {

using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, maxActuators, 1>;
constexpr double infinity = std::numeric_limits<double>::infinity();
/// Core torques are N·m, lengths mm: a rotary actuator's torque and stiffness enter the
/// Jacobian products in N·mm and N·mm/rad, a rotary output's come back in N·m.
constexpr double perMetre = 1e3;

enum Slot { SlotForceWorst, SlotForceBest, SlotSpeedWorst, SlotSpeedBest, SlotResolution };

/// The layout of n platform coordinates, rotary (1-DOF angle) or planar, with or without the
/// measured stiffness: the order of the entries is the order of the buffer.
ReportLayout makeLayout(int n, bool rotary, bool measured)
{
    using S = AtSingularity;
    ReportLayout l;
    const auto G = ReportGroup::Derived;
    const Unit force = rotary ? units::newtonMetre : units::newton;
    const Unit speed = rotary ? units::degreePerSecond : units::millimetrePerSecond;
    const Unit length = rotary ? units::angle : units::millimetre;
    const Unit stiffness = rotary ? units::newtonMetrePerRadian : units::newtonPerMillimetre;
    l.add(G, "force_worst", "F_min", QT_TRANSLATE_NOOP("core", "largest force in the weakest direction"), force, 1);
    l.add(G, "force_best", "F_max", QT_TRANSLATE_NOOP("core", "largest force in the strongest direction"), force, 1);
    l.add(G, "speed_worst", "v_min", QT_TRANSLATE_NOOP("core", "largest speed in the slowest direction"), speed, 1);
    l.add(G, "speed_best", "v_max", QT_TRANSLATE_NOOP("core", "largest speed in the fastest direction"), speed, 1);
    l.add(G, "resolution_worst", "Δx_max", QT_TRANSLATE_NOOP("core", "largest error from half a step per actuator"), length,
          rotary ? 5 : 4);
    if (n == 3)
        l.add(G, "stiffness", "K", QT_TRANSLATE_NOOP("core", "stiffness K = Jᵀ·K_q·J (N/mm, N/rad, N·mm/rad)"), units::none, 1,
              3, 3);
    else
        l.add(G, "stiffness", "K", QT_TRANSLATE_NOOP("core", "stiffness K = Jᵀ·K_q·J"), stiffness, 1, n, n);
    l.add(G, "stiffness_worst", "K_min", QT_TRANSLATE_NOOP("core", "stiffness in the weakest direction"), stiffness, 1);
    if (n == 1) {
        l.add(G, "deflection", "Δθ_L", QT_TRANSLATE_NOOP("core", "deflection under the load (actuators' compliance)"),
              rotary ? units::angle : units::millimetre, 4);
    } else {
        l.add(G, "deflection", "Δx_L", QT_TRANSLATE_NOOP("core", "deflection of the platform point under the load"),
              units::millimetre, 4, 2, 1);
        l.add(G, "deflection_norm", "|Δx_L|", QT_TRANSLATE_NOOP("core", "length of the deflection under the load"),
              units::millimetre, 4);
        if (n == 3)
            l.add(G, "deflection_angle", "Δφ_L", QT_TRANSLATE_NOOP("core", "rotation of the platform under the load"),
                  units::angle, 4);
    }
    if (measured)
        l.add(G, "stiffness_measured", "K_m",
              QT_TRANSLATE_NOOP("core", "measured static stiffness of the whole joint (the document)"), units::newtonMetrePerRadian,
              0);
    // where J is unbounded (inverse) or singular (direct): see capability.h
    l.atSingularity("force_worst", S::Computed, S::Zero);
    l.atSingularity("force_best", S::Infinite, S::Computed);
    l.atSingularity("speed_worst", S::Zero, S::Computed);
    l.atSingularity("speed_best", S::Computed, S::Infinite);
    l.atSingularity("resolution_worst", S::Computed, S::Infinite);
    l.atSingularity("stiffness", S::Infinite, S::Computed);
    l.atSingularity("stiffness_worst", S::Computed, S::Zero);
    for (const char *deflection : {"deflection", "deflection_norm", "deflection_angle"}) {
        if (l.find(deflection))
            l.atSingularity(deflection, S::Computed, S::Infinite);
    }
    return l;
}

/// Inscribed radius about the origin of {v : |a_i·v| ≤ b_i}, a_i the first `t` entries of
/// row i of `rows`: the ball of radius r lies in slab i exactly when r·|a_i| ≤ b_i.
template <class Rows, class Limits>
double inscribedRadius(const Rows &rows, const Limits &b, int t)
{
    double radius = infinity;
    for (int i = 0; i < rows.rows(); ++i) {
        const double norm = rows.row(i).head(t).norm();
        if (norm > 0.0)
            radius = std::min(radius, b[i] / norm);
    }
    return radius;
}

/// The farthest point from the origin of M·box (box |u_i| ≤ l_i), measured on the first `t`
/// rows of M. With `cut`, only the part of the image where row t of M·u is 0 counts (zero
/// moment or zero rotation of a 3-DOF platform): its vertices are where the box's edges cross
/// that plane. A polytope's farthest point is one of its vertices, so this is exact.
template <class Mat, class Limits>
double farthestVertex(const Mat &M, const Limits &l, int t, bool cut)
{
    using V = typename Limits::PlainObject;
    const int m = static_cast<int>(M.cols());
    double best = 0.0;
    const auto measure = [&](const V &u) { best = std::max(best, (M.topRows(t) * u).norm()); };
    for (int signs = 0; signs < (1 << m); ++signs) {
        V u = l; // (its size; every entry set below)
        for (int j = 0; j < m; ++j)
            u[j] = (signs >> j & 1) ? l[j] : -l[j];
        if (!cut) {
            measure(u);
            continue;
        }
        const auto c = M.row(t);
        const double scale = (c.cwiseAbs().transpose().cwiseProduct(l)).sum();
        if (std::abs(c.dot(u)) <= 1e-12 * scale) // a vertex of the box on the plane
            measure(u);
        for (int k = 0; k < m; ++k) { // the edge along u_k through this vertex
            if (c[k] == 0.0 || (signs >> k & 1))
                continue; // each edge once
            const double rest = c.dot(u) - c[k] * u[k];
            const double uk = -rest / c[k];
            if (std::abs(uk) <= l[k]) {
                V v = u;
                v[k] = uk;
                measure(v);
            }
        }
    }
    return best;
}

/// The largest eigenvalue of the leading t×t (1×1 or 2×2) block of a symmetric matrix, in
/// closed form.
template <class Mat>
double largestEigenvalue(const Mat &C, int t)
{
    if (t == 1)
        return C(0, 0);
    const double mean = 0.5 * (C(0, 0) + C(1, 1)), half = 0.5 * (C(0, 0) - C(1, 1));
    return mean + std::hypot(half, C(0, 1));
}

} // namespace

Actuators actuatorsOf(const Mechanism &mechanism)
{
    Actuators a;
    const std::vector<VariableInfo> &variables = mechanism.variableInfo();
    for (int v = 0; v < static_cast<int>(variables.size()); ++v) {
        const VariableInfo &info = variables[std::size_t(v)];
        if (info.actuated && !info.independent && a.count < maxActuators) {
            a.items[std::size_t(a.count)].rotary = info.unit.symbol == units::angle.symbol;
            a.inputs[std::size_t(a.count++)] = v;
        } else if (!info.actuated) {
            a.outputs++;
            if (info.unit.symbol == units::angle.symbol)
                a.rotaryOutput = true;
        }
    }
    // a 3-DOF platform has x, y and φ: only a 1-DOF output that is an angle is a rotary one
    a.rotaryOutput = a.rotaryOutput && a.outputs == 1;
    if (a.count == 0 || a.count != a.outputs || a.outputs > 3) {
        a.count = 0;
        return a;
    }
    const ParameterSet values = mechanism.parameters();
    const auto value = [&](const std::string &name, double &out) {
        const auto it = values.find(name);
        if (it == values.end())
            return false;
        out = it->second;
        return true;
    };
    for (int i = 0; i < a.count; ++i) {
        Actuator &item = a.items[std::size_t(i)];
        const std::string index = std::to_string(i + 1);
        const bool indexed = value("force_max" + index, item.force);
        const bool found = item.rotary && value("torque_max" + index, item.force)
            ? value("rate_max" + index, item.speed) && value("angle_step" + index, item.step)
                && value("torsion" + index, item.stiffness)
            : indexed ? value("speed_max" + index, item.speed) && value("step" + index, item.step)
                    && value("stiffness" + index, item.stiffness)
                      : a.count == 1 && value("force_max", item.force) && value("speed_max", item.speed)
                    && value("step", item.step) && value("stiffness", item.stiffness);
        if (!found) {
            a.count = 0;
            return a;
        }
    }
    value("stiffness_measured", a.measuredStiffness);
    if (a.rotaryOutput) {
        value("load_torque", a.load[0]);
    } else {
        value("load_x", a.load[0]);
        value("load_y", a.load[1]);
        value("load_moment", a.load[2]);
    }
    const Pose home = mechanism.homePose();
    const Jacobians j = mechanism.jacobians(home);
    Matrix jq(a.count, a.count), jx(a.count, a.count);
    for (int r = 0; r < a.count; ++r) {
        for (int c = 0; c < a.count; ++c) {
            jq(r, c) = j.inputs(a.inputs[std::size_t(r)], a.inputs[std::size_t(c)]);
            jx(r, c) = j.outputs(a.inputs[std::size_t(r)], c);
        }
    }
    const Matrix G = jx.partialPivLu().solve(jq);
    for (int i = 0; i < a.count; ++i) {
        const double norm = G.col(i).norm();
        a.transmission[std::size_t(i)] = std::isfinite(norm) ? norm : 0.0;
    }
    return a;
}

const ReportLayout *layoutFor(const Actuators &actuators)
{
    // every layout a kind can need, made once (thread-safe static initialisation)
    static const std::array<ReportLayout, 8> layouts = {
        makeLayout(1, true, false), makeLayout(1, true, true),  makeLayout(1, false, false),
        makeLayout(1, false, true), makeLayout(2, false, false), makeLayout(2, false, true),
        makeLayout(3, false, false), makeLayout(3, false, true),
    };
    if (actuators.count == 0)
        return nullptr;
    const bool measured = actuators.measuredStiffness > 0.0;
    const int n = actuators.outputs;
    const int index = n == 1 ? (actuators.rotaryOutput ? 0 : 2) : (n == 2 ? 4 : 6);
    return &layouts[std::size_t(index + (measured ? 1 : 0))];
}

namespace {

/// evaluate() for N actuators: fixed-size matrices, so that the solves and products are
/// inlined (a sweep evaluates this once per row).
template <int N>
SingularityType evaluateFixed(const Actuators &actuators, const Matrix &jqIn, const Matrix &jxIn, SingularityType type,
                   std::span<double> values, const ReportLayout *layout)
{
    using Matrix = Eigen::Matrix<double, N, N>;
    using Vector = Eigen::Matrix<double, N, 1>;
    const Matrix jq = jqIn, jx = jxIn;
    constexpr int n = N;
    const int t = std::min(n, 2); // the translational coordinates (or the one output)
    const bool cut = n == 3;
    Vector effort, speed, halfStep, compliance, stiffness;
    for (int i = 0; i < n; ++i) {
        const Actuator &a = actuators.items[std::size_t(i)];
        const double toMillimetre = a.rotary ? perMetre : 1.0;
        effort[i] = a.force * toMillimetre;
        speed[i] = a.speed;
        halfStep[i] = 0.5 * a.step;
        stiffness[i] = a.stiffness * toMillimetre;
        compliance[i] = 1.0 / stiffness[i];
    }
    // J = J_q⁻¹·J_x and G = J_x⁻¹·J_q; each is inf/NaN only where the marks replace what uses it
    const Matrix J = jq.partialPivLu().solve(jx);
    Matrix G = jx.partialPivLu().solve(jq);
    // An actuator whose leg is (nearly) stretched moves the platform no more: its column of G
    // is exactly 0, not the 10⁻⁸ of a hair inside, which would make the weakest force 10⁸ N
    // (both legs of a five-bar stretched: the platform is locked, and holds any force)
    type = deliveryClass(actuators, G, type);
    const double toOutput = actuators.rotaryOutput ? 1.0 / perMetre : 1.0;

    values[SlotForceWorst] = inscribedRadius(G.transpose(), effort, t) * toOutput;
    values[SlotForceBest] = farthestVertex(J.transpose(), effort, t, cut) * toOutput;
    values[SlotSpeedWorst] = inscribedRadius(J, speed, t);
    values[SlotSpeedBest] = farthestVertex(G, speed, t, cut);
    values[SlotResolution] = farthestVertex(G, halfStep, t, false);
    const Matrix K = J.transpose() * stiffness.asDiagonal() * J;
    const Matrix C = G * compliance.asDiagonal() * G.transpose();
    int slot = SlotResolution + 1;
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c)
            values[std::size_t(slot++)] = 0.5 * (K(r, c) + K(c, r)) * toOutput; // symmetric up to rounding
    }
    // the weakest direction of a pure force: the largest compliance of the translational block
    values[std::size_t(slot++)] = toOutput / largestEigenvalue(C, t);
    // Δx = C·F: a torque or moment enters in N·mm, as the compliance's angular rows take it
    Vector load;
    for (int i = 0; i < n; ++i)
        load[i] = actuators.load[std::size_t(i)] * (i == 2 || actuators.rotaryOutput ? perMetre : 1.0);
    const Vector deflection = C * load;
    const std::size_t firstDeflection = std::size_t(slot);
    for (int i = 0; i < t; ++i)
        values[std::size_t(slot++)] = deflection[i];
    if constexpr (N > 1)
        values[std::size_t(slot++)] = deflection.template head<2>().norm();
    if constexpr (N == 3)
        values[std::size_t(slot++)] = deflection[2];
    const std::size_t endDeflection = std::size_t(slot);
    if (actuators.measuredStiffness > 0.0)
        values[std::size_t(slot++)] = actuators.measuredStiffness;
    settleSingularValues(*layout, values, type);
    // no load, no deflection, whatever the pose (0·∞ would be undefined, not unbounded)
    if (load.isZero(0.0))
        std::fill(values.begin() + std::ptrdiff_t(firstDeflection), values.begin() + std::ptrdiff_t(endDeflection), 0.0);
    return type;
}

} // namespace

SingularityType evaluate(const Actuators &actuators, const Matrix &jq, const Matrix &jx, SingularityType type,
                         std::span<double> values)
{
    const ReportLayout *layout = layoutFor(actuators);
    if (!layout)
        return type;
    switch (actuators.count) {
    case 1:
        return evaluateFixed<1>(actuators, jq, jx, type, values, layout);
    case 2:
        return evaluateFixed<2>(actuators, jq, jx, type, values, layout);
    default:
        return evaluateFixed<3>(actuators, jq, jx, type, values, layout);
    }
}

SingularityType evaluate(const Mechanism &mechanism, const Actuators &actuators, const Pose &pose,
                         SingularityType type, std::span<double> values)
{
    if (actuators.count == 0)
        return type;
    const Jacobians j = mechanism.jacobians(pose);
    const int n = actuators.count;
    Matrix jq(n, n), jx(n, n);
    for (int r = 0; r < n; ++r) {
        const int row = actuators.inputs[std::size_t(r)];
        for (int c = 0; c < n; ++c) {
            jq(r, c) = j.inputs(row, actuators.inputs[std::size_t(c)]);
            jx(r, c) = j.outputs(row, c);
        }
    }
    return evaluate(actuators, jq, jx, type, values);
}

const char *nearSingularReason(SingularityType type, SingularityType kindType)
{
    if (type == kindType)
        return nullptr;
    switch (type) {
    case SingularityType::Inverse:
        return QT_TRANSLATE_NOOP("core", "near an inverse singularity: an actuator moves the platform less than "
                                         "1/1000 of what it does at the home pose");
    case SingularityType::Direct:
        return QT_TRANSLATE_NOOP("core", "near a direct singularity: an actuator moves the platform more than "
                                         "1000 times what it does at the home pose");
    default:
        return QT_TRANSLATE_NOOP("core", "near a combined singularity: one actuator moves the platform less than "
                                         "1/1000, another more than 1000 times what it does at the home pose");
    }
}

} // namespace pkm::capability
