// MOMA (docs/mathematics.md, section 2): its closed forms, the joint variables and the direct
// and inverse kinematics; the design and its checks are in momadesign.cpp, the analysis in
// momaanalysis.cpp, the planar drawing in momascene.cpp, the maps in momamaps.cpp and the
// solid model in moma3d.cpp.

#include "moma.h"
#include "momainternal.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
using moma::cross;
using moma::legName;
using moma::legSubscript;

Eigen::Vector2d normal(const Eigen::Vector2d &a)
{
    return {-a.y(), a.x()};
}
} // namespace

// -- closed forms --------------------------------------------------------------------------

namespace moma {

double projection(const MomaDesign &design, int leg, const Eigen::Vector2d &platform)
{
    return direction(design.alpha[leg]).dot(platform - design.reference[leg]);
}

double discriminant(const MomaDesign &design, int leg, const Eigen::Vector2d &platform)
{
    // B² − C = l² − (distance of P from the guide line)², computed the second way: it does not
    // cancel two large numbers
    const Eigen::Vector2d r = platform - design.reference[leg];
    const double perpendicular = cross(direction(design.alpha[leg]), r);
    return design.length[leg] * design.length[leg] - perpendicular * perpendicular;
}

Eigen::Vector2d sliderJoint(const MomaDesign &design, int leg, double p)
{
    return design.reference[leg] + p * direction(design.alpha[leg]);
}

double constraint(const MomaDesign &design, int leg, double p, const Eigen::Vector2d &platform)
{
    return (platform - sliderJoint(design, leg, p)).squaredNorm() - design.length[leg] * design.length[leg];
}

double side(const Eigen::Vector2d &z1, const Eigen::Vector2d &z2, const Eigen::Vector2d &platform)
{
    return cross(z2 - z1, platform - z1);
}

int innerSide(const MomaDesign &design, int leg)
{
    // The other guide's mid-stroke point decides which side of this guide is "inner".
    const int other = 1 - leg;
    const double mid = 0.5 * (design.strokeMin + design.strokeMax);
    const Eigen::Vector2d target = sliderJoint(design, other, mid) - design.reference[leg];
    const double c = cross(direction(design.alpha[leg]), target);
    const double scale = std::max(1.0, target.norm());
    return std::abs(c) < 1e-9 * scale ? 0 : (c > 0 ? 1 : -1);
}

double inverseMargin(const MomaDesign &design, int leg, double p, const Eigen::Vector2d &platform)
{
    const Eigen::Vector2d link = platform - sliderJoint(design, leg, p);
    return std::abs(link.dot(direction(design.alpha[leg]))) / design.length[leg];
}

double directMargin(const MomaDesign &design, const Eigen::Vector2d &z1, const Eigen::Vector2d &z2,
                    const Eigen::Vector2d &platform)
{
    return std::abs(cross(platform - z1, platform - z2)) / (design.length[0] * design.length[1]);
}

} // namespace moma

// -- joint variables -----------------------------------------------------------------------

const std::vector<VariableInfo> &Moma::variableInfo() const
{
    static const std::vector<VariableInfo> infos = {
        {"p1", "p₁", QT_TRANSLATE_NOOP("core", "slider 1 position (actuated)"), units::millimetre, true, 2},
        {"p2", "p₂", QT_TRANSLATE_NOOP("core", "slider 2 position (actuated)"), units::millimetre, true, 2},
        {"x", "x", QT_TRANSLATE_NOOP("core", "platform x"), units::millimetre, false, 2},
        {"y", "y", QT_TRANSLATE_NOOP("core", "platform y"), units::millimetre, false, 2},
    };
    return infos;
}

Interval Moma::variableRange(int variable) const
{
    switch (variable) {
    case variableP1:
    case variableP2: return {m_design.strokeMin, m_design.strokeMax};
    case variableX: return {m_bounds.min().x(), m_bounds.max().x()};
    default: return {m_bounds.min().y(), m_bounds.max().y()};
    }
}

Moma::Moma(const MomaDesign &design)
    : m_design(design)
{
    // Home: the pose of the slider positions farthest from both the singularities and the
    // ends of the strokes; none means the workspace is empty (create() refuses the design).
    // A coarse grid of slider positions, then a pattern search around its best: a design costs
    // ~300 direct solutions instead of the 61² of a fine grid (an optimiser makes thousands).
    // Where the coarse grid finds no pose, the fine grid looks for a workspace it slipped past.
    const double stroke = design.strokeMax - design.strokeMin;
    double best = -1.0;
    double bestP1 = 0.0, bestP2 = 0.0;
    const auto consider = [&](double p1, double p2) {
        auto pose = direct(p1, p2, false);
        if (!pose)
            return;
        const double centrality = std::min({p1 - design.strokeMin, design.strokeMax - p1, p2 - design.strokeMin,
                                            design.strokeMax - p2}) / stroke;
        const double score = std::min(singularity(*pose).margin, 4.0 * centrality) + 1e-3 * centrality;
        if (score > best) {
            best = score;
            m_home = *pose;
            bestP1 = p1;
            bestP2 = p2;
        }
    };
    const auto searchGrid = [&](int samples) {
        for (int i = 0; i < samples; ++i) {
            for (int j = 0; j < samples; ++j)
                consider(design.strokeMin + stroke * i / (samples - 1), design.strokeMin + stroke * j / (samples - 1));
        }
    };
    constexpr int coarse = 16;
    searchGrid(coarse);
    if (!m_home.inputs.size())
        searchGrid(61);
    if (m_home.inputs.size()) {
        const auto inStroke = [&](double p) { return std::clamp(p, design.strokeMin, design.strokeMax); };
        for (double step = stroke / (coarse - 1) / 2; step > stroke * 1e-3; step /= 2) {
            const double p1 = bestP1, p2 = bestP2;
            for (int di = -1; di <= 1; ++di) {
                for (int dj = -1; dj <= 1; ++dj) {
                    if (di || dj)
                        consider(inStroke(p1 + di * step), inStroke(p2 + dj * step));
                }
            }
        }
        m_bounds = computeBounds();
    }
}

Eigen::AlignedBox2d Moma::computeBounds() const
{
    // Each leg reaches a capsule around its stroke; the workspace lies in both. Sample that box
    // and keep the reachable cells, widened by two cells for what the grid misses.
    Eigen::AlignedBox2d box;
    for (int leg = 0; leg < 2; ++leg) {
        Eigen::AlignedBox2d capsule;
        capsule.extend(moma::sliderJoint(m_design, leg, m_design.strokeMin));
        capsule.extend(moma::sliderJoint(m_design, leg, m_design.strokeMax));
        capsule.min().array() -= m_design.length[leg];
        capsule.max().array() += m_design.length[leg];
        box = leg == 0 ? capsule : box.intersection(capsule);
    }
    constexpr int n = 256;
    const MapGrid grid = squareGrid(box, n);
    std::vector<float> row(static_cast<std::size_t>(grid.columns));
    Eigen::AlignedBox2d reached;
    for (int r = 0; r < grid.rows; ++r) {
        fillMapRow(MapQuantity::Determinant, grid.y(r), grid.x(0), grid.dx(), row, {});
        if (const auto ends = reachableEnds(row)) {
            reached.extend(Eigen::Vector2d(grid.x(ends->first), grid.y(r)));
            reached.extend(Eigen::Vector2d(grid.x(ends->second), grid.y(r)));
        }
    }
    reached.extend(m_home.outputs.head<2>());
    // Thin parts of the workspace can slip between grid points: its boundary is made of the
    // stroke ends and the singular curves, so trace those too.
    constexpr int edgeSamples = 512;
    const double stroke = m_design.strokeMax - m_design.strokeMin;
    for (int k = 0; k <= edgeSamples; ++k) {
        const double p = m_design.strokeMin + stroke * k / edgeSamples;
        for (const double end : {m_design.strokeMin, m_design.strokeMax}) {
            for (const auto &[p1, p2] : {std::pair{p, end}, std::pair{end, p}}) {
                if (auto pose = direct(p1, p2, false))
                    reached.extend(pose->outputs.head<2>());
            }
        }
    }
    for (const SingularCurve &curve : singularCurves()) {
        for (const Eigen::Vector2d &point : curve.points)
            reached.extend(point);
    }
    const Eigen::Vector2d pad(2.0 * grid.dx(), 2.0 * grid.dy());
    Eigen::AlignedBox2d bounds(reached.min() - pad, reached.max() + pad);
    return bounds.intersection(box);
}

// -- kinematics ----------------------------------------------------------------------------

std::string Moma::oneSideViolation(const Eigen::Vector2d &platform, const std::array<Eigen::Vector2d, 2> &z) const
{
    if (!m_design.oneSide)
        return {};
    for (int leg = 0; leg < 2; ++leg) {
        const int inner = moma::innerSide(m_design, leg);
        const double c = cross(moma::direction(m_design.alpha[leg]), platform - z[leg]);
        if (inner != 0 && c * inner < -1e-9 * m_design.length[leg]) {
            return text::format(
                text::translate("core", "link S%1 would lie on the outer side of guide %2 (the one-side constraint is on)"),
                {legSubscript(leg), legName(leg)});
        }
    }
    return {};
}

Result<Pose> Moma::direct(double p1, double p2) const
{
    return direct(p1, p2, true);
}

Result<Pose> Moma::direct(double p1, double p2, bool explain) const
{
    // A failure's sentence is made only when someone reads it: the home search and the bounds
    // try thousands of inputs, most of them outside the workspace, and formatting why was a
    // third of what a new design cost.
    const auto why = [explain](auto &&sentence) { return explain ? sentence() : std::string(); };
    const MomaDesign &d = m_design;
    const std::array<Eigen::Vector2d, 2> z = {moma::sliderJoint(d, 0, p1), moma::sliderJoint(d, 1, p2)};
    const Eigen::Vector2d between = z[1] - z[0];
    const double distance = between.norm();
    const double l1 = d.length[0], l2 = d.length[1];
    const double scale = std::max(l1, l2);
    // Circle–circle intersection measured along Z₁→Z₂ (no division by x_Z2 − x_Z1, where the document's (10–12) fail: docs/mathematics.md, section 2).
    if (distance < 1e-9 * scale) {
        return Failure{FailureKind::Singular, "p1", why([&] {
                           return text::format(text::translate("core", "The slider joints Z₁ and Z₂ coincide at p₁ = %1 mm, "
                                                                       "p₂ = %2 mm: the platform position is undetermined."),
                                               {text::number(p1), text::number(p2)});
                       })};
    }
    if (distance > l1 + l2 + 1e-12 * scale || distance < std::abs(l1 - l2) - 1e-12 * scale) {
        const std::string message = !explain ? std::string()
            : distance > l1 + l2
            ? text::format(text::translate("core", "The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm "
                                                   "is more than l₁ + l₂ = %4 mm."),
                           {text::number(p1), text::number(p2), text::number(distance), text::number(l1 + l2)})
            : text::format(text::translate("core", "The links cannot meet at p₁ = %1 mm, p₂ = %2 mm: |Z₁Z₂| = %3 mm "
                                                   "is less than |l₁ − l₂| = %4 mm."),
                           {text::number(p1), text::number(p2), text::number(distance), text::number(std::abs(l1 - l2))});
        return Failure{FailureKind::Unreachable, "p1", message};
    }
    const Eigen::Vector2d u = between / distance;
    const double along = (l1 * l1 - l2 * l2 + distance * distance) / (2.0 * distance);
    const double across = std::sqrt(std::max(0.0, l1 * l1 - along * along));
    const Eigen::Vector2d platform = z[0] + along * u + d.assembly * across * normal(u);
    // The working modes: leg i's link component along its guide, (P − Z_i)·a_i = B_i − p_i, is
    // −β_i·√(B_i² − C_i): it must not have the sign of β_i.
    for (int leg = 0; leg < 2; ++leg) {
        const double w = (platform - z[leg]).dot(moma::direction(d.alpha[leg]));
        if (w * d.branch[leg] > 1e-9 * d.length[leg]) {
            return Failure{FailureKind::Unreachable, joinText({"p", legName(leg)}), why([&] {
                               return text::format(text::translate("core", "At p₁ = %1 mm, p₂ = %2 mm leg %3 would be past "
                                                                           "perpendicular to its guide, in its other working mode (an "
                                                                           "inverse singularity lies between); switch the mode to go on."),
                                                   {text::number(p1), text::number(p2), legName(leg)});
                           })};
        }
    }
    if (auto violation = oneSideViolation(platform, z); !violation.empty()) {
        return Failure{FailureKind::Unreachable, "p1", why([&] {
                           return text::format(text::translate("core", "At p₁ = %1 mm, p₂ = %2 mm %3."),
                                               {text::number(p1), text::number(p2), violation});
                       })};
    }
    Pose pose;
    pose.inputs.resize(2);
    pose.inputs << p1, p2;
    pose.outputs.resize(2);
    pose.outputs << platform.x(), platform.y();
    return pose;
}

Result<Pose> Moma::inverse(const Eigen::Vector2d &platform) const
{
    const MomaDesign &d = m_design;
    std::array<double, 2> p{};
    std::array<Eigen::Vector2d, 2> z;
    // made only for a message: a solve that succeeds (every drag step, every map cell) formats nothing
    const auto where = [&] {
        // to the hundredth, as the fields and the values panel give a position
        return text::format(text::translate("core", "(%1, %2) mm"), {text::number(platform.x(), 2), text::number(platform.y(), 2)});
    };
    for (int leg = 0; leg < 2; ++leg) {
        const double D = moma::discriminant(d, leg, platform); // (9)
        const double l = d.length[leg];
        if (D < -1e-9 * l * l) {
            return Failure{FailureKind::Unreachable, "x",
                           text::format(text::translate("core", "The platform cannot reach %1: it lies more than "
                                                                "l%2 = %3 mm from guide %4."),
                                        {where(), legSubscript(leg), text::number(l), legName(leg)})};
        }
        p[leg] = moma::projection(d, leg, platform) + d.branch[leg] * std::sqrt(std::max(0.0, D)); // (7)
        // √D of a D that is zero up to rounding is ~1e-8·l: allow for it at the stroke ends
        const double tolerance = 1e-7 * std::max({1.0, d.strokeMax - d.strokeMin, l});
        if (p[leg] < d.strokeMin - tolerance || p[leg] > d.strokeMax + tolerance) {
            return Failure{FailureKind::OutOfRange, joinText({"p", legName(leg)}),
                           text::format(text::translate("core", "The platform cannot reach %1: slider %2 would have to "
                                                                "be at p%3 = %4 mm, outside its stroke [%5, %6] mm."),
                                        {where(), legName(leg), legSubscript(leg),
                                         text::numberOutside(p[leg], d.strokeMin, d.strokeMax),
                                         text::number(d.strokeMin), text::number(d.strokeMax)})};
        }
        p[leg] = std::clamp(p[leg], d.strokeMin, d.strokeMax);
        z[leg] = moma::sliderJoint(d, leg, p[leg]);
    }
    const double s = moma::side(z[0], z[1], platform);
    if (s * d.assembly < -1e-9 * d.length[0] * d.length[1]) {
        return Failure{FailureKind::Unreachable, "x",
                       text::format(text::translate("core", "The platform cannot reach %1 in this assembly mode: it "
                                                            "would cross the line Z₁Z₂, where the links are collinear "
                                                            "(a direct singularity); switch the assembly mode to go on."),
                                    {where()})};
    }
    if (auto violation = oneSideViolation(platform, z); !violation.empty())
        return Failure{FailureKind::Unreachable, "x",
                       text::format(text::translate("core", "The platform cannot reach %1: %2."), {where(), violation})};
    Pose pose;
    pose.inputs.resize(2);
    pose.inputs << p[0], p[1];
    pose.outputs.resize(2);
    pose.outputs << platform.x(), platform.y();
    return pose;
}

Result<Pose> Moma::solveDirect(const Coordinates &inputs, const Pose *) const
{
    for (int leg = 0; leg < 2; ++leg) {
        const double p = inputs[leg];
        if (!std::isfinite(p))
            return Failure{FailureKind::OutOfRange, joinText({"p", legName(leg)}),
                           text::format(text::translate("core", "%1 must be a finite number."), {joinText({"p", legName(leg)})})};
        if (p < m_design.strokeMin || p > m_design.strokeMax) {
            return Failure{FailureKind::OutOfRange, joinText({"p", legName(leg)}),
                           text::format(text::translate("core", "%1 = %2 mm is outside the stroke [%3, %4] mm."),
                                        {joinText({"p", legName(leg)}), text::numberOutside(p, m_design.strokeMin, m_design.strokeMax),
                                         text::number(m_design.strokeMin),
                                         text::number(m_design.strokeMax)})};
        }
    }
    return direct(inputs[0], inputs[1]);
}

Result<Pose> Moma::solveInverse(const Coordinates &outputs, const Pose *) const
{
    for (int i = 0; i < 2; ++i) {
        if (!std::isfinite(outputs[i])) {
            const std::string name = i == 0 ? "x" : "y";
            return Failure{FailureKind::OutOfRange, name,
                           text::format(text::translate("core", "%1 must be a finite number."), {name})};
        }
    }
    return inverse(outputs.head<2>());
}

} // namespace pkm
