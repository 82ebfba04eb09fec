// The analysis of a pose of the planar parallel mechanism: the Jacobians from the leg
// constraints, the singularity class with its scale-free margins, the report and the other
// working and assembly modes.
#include "planarparallel.h"

#include "text.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
using planar::cross;
std::string number(int leg)
{
    return std::to_string(leg + 1);
}

/// Powers of mm and rad (units::power) of the determinants, which follow the legs' types.
/// Row i of J_q is ∂g_i/∂q_i with g_i in mm²: mm²/rad for a crank (R̲RR, and П̲RR, whose row
/// is by θ), mm for a slider or strut. Row i of J_x is mm, times ∂d/∂θ (mm/rad) for a П̲RR;
/// its columns x, y are bare and φ's is mm (a moment arm). J maps Ẋ (mm, mm, rad) onto q̇.
struct DeterminantUnits {
    Unit J, Jq, Jx;
};
DeterminantUnits determinantUnits(const PlanarParallelDesign &design)
{
    const int n = design.legCount();
    int jLength = -2, jAngle = n == 3 ? -1 : 0, qLength = 0, qAngle = 0, xLength = n == 3 ? 1 : 0, xAngle = 0;
    for (int i = 0; i < n; ++i) {
        const LegType type = design.legs[std::size_t(i)].type;
        const bool crank = type == LegType::RRR || type == LegType::PiRR;
        (type == LegType::RRR ? jAngle : jLength) += 1;
        qLength += crank ? 2 : 1;
        qAngle -= crank ? 1 : 0;
        xLength += type == LegType::PiRR ? 2 : 1;
        xAngle -= type == LegType::PiRR ? 1 : 0;
    }
    return {units::power(jLength, jAngle), units::power(qLength, qAngle), units::power(xLength, xAngle)};
}
} // namespace

void PlanarParallel::jacobianParts(const Pose &pose, Eigen::Matrix3d &jq, Eigen::Matrix3d &jx) const
{
    const int n = m_design.legCount();
    const Eigen::Vector3d X = platformPose(pose.outputs);
    jq.setZero();
    jx.setZero();
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = m_design.legs[std::size_t(i)];
        const planar::LegCircle c = planar::circle(leg, pose.inputs[i]);
        const Eigen::Vector2d P = planar::platformPoint(leg, X), e = P - c.centre;
        // g = ½(|P − C(q)|² − ρ(q)²): ∂g/∂q = −e·∂C/∂q − ρ·∂ρ/∂q (for П̲RR by θ, see the header)
        jq(i, i) = -e.dot(c.centreRate) - c.radius * c.radiusRate;
        // J_x = −∂g/∂X, ∂g/∂φ = e·∂P/∂φ = (P − O)×e
        jx(i, 0) = -c.pjointRate * e.x();
        jx(i, 1) = -c.pjointRate * e.y();
        if (n == 3)
            jx(i, 2) = -c.pjointRate * cross(P - X.head<2>(), e);
    }
}

Jacobians PlanarParallel::jacobians(const Pose &pose) const
{
    const int n = m_design.legCount();
    Eigen::Matrix3d jq, jx;
    jacobianParts(pose, jq, jx);
    Jacobians j;
    j.inputs = jq.topLeftCorner(n, n);
    j.outputs = jx.topLeftCorner(n, n);
    j.full = j.outputs;
    for (int i = 0; i < n; ++i)
        j.full.row(i) /= jq(i, i);
    return j;
}

Singularity PlanarParallel::singularity(const Pose &pose) const
{
    const int n = m_design.legCount();
    const Eigen::Vector3d X = platformPose(pose.outputs);
    // the platform's size makes the rotation column of J_x a length, as the others
    double size = 0.0;
    if (n == 3) {
        const Eigen::Vector2d centre = (m_design.legs[0].platform + m_design.legs[1].platform + m_design.legs[2].platform) / 3.0;
        for (const PlanarLeg &leg : m_design.legs)
            size = std::max(size, (leg.platform - centre).norm());
    }
    double inverse = 1.0, pjoint = 1.0, product = 1.0;
    Eigen::Matrix3d N = Eigen::Matrix3d::Identity();
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = m_design.legs[std::size_t(i)];
        const planar::LegCircle c = planar::circle(leg, pose.inputs[i]);
        const Eigen::Vector2d P = planar::platformPoint(leg, X), e = P - c.centre;
        const double length = e.norm();
        inverse = std::min(inverse, planar::inverseMargin(leg, pose.inputs[i], P));
        if (leg.type == LegType::PiRR)
            pjoint = std::min(pjoint, std::abs(std::cos(c.theta)));
        const Eigen::Vector2d u = length > 0.0 ? Eigen::Vector2d(e / length) : Eigen::Vector2d::Zero();
        N(i, 0) = u.x();
        N(i, 1) = u.y();
        if (n == 3)
            N(i, 2) = cross(P - X.head<2>(), u) / size;
        product *= N.row(i).head(n).norm();
    }
    const double det = n == 2 ? N.topLeftCorner<2, 2>().determinant() : N.determinant();
    const double direct = (product > 0.0 ? std::abs(det) / product : 0.0) * pjoint;
    return classifySingularity(inverse, direct, singularTolerance);
}

void PlanarParallel::buildReport()
{
    using G = ReportGroup;
    const int n = m_design.legCount();
    static const std::array<const char *, 3> names = {"q1", "q2", "q3"};
    static const std::array<const char *, 3> symbols = {"q₁", "q₂", "q₃"};
    static const std::array<const char *, 3> labels = {QT_TRANSLATE_NOOP("core", "input of leg 1"),
                                                       QT_TRANSLATE_NOOP("core", "input of leg 2"),
                                                       QT_TRANSLATE_NOOP("core", "input of leg 3")};
    ReportLayout &l = m_layout;
    for (int i = 0; i < n; ++i)
        l.add(G::Pose, names[std::size_t(i)], symbols[std::size_t(i)], labels[std::size_t(i)], m_variables[std::size_t(i)].unit, 3);
    l.add(G::Pose, "x", "x", QT_TRANSLATE_NOOP("core", "platform x"), units::millimetre, 3);
    l.add(G::Pose, "y", "y", QT_TRANSLATE_NOOP("core", "platform y"), units::millimetre, 3);
    if (n == 3)
        l.add(G::Pose, "phi", "φ", QT_TRANSLATE_NOOP("core", "platform angle"), units::angle, 3);
    l.add(G::Jacobian, "Jq", "J_q", QT_TRANSLATE_NOOP("core", "J_q = diag(∂g_i/∂q_i)"), units::none, 3, n, n);
    l.add(G::Jacobian, "Jx", "J_x", QT_TRANSLATE_NOOP("core", "J_x rows −∂g_i/∂X"), units::none, 3, n, n);
    l.add(G::Jacobian, "J", "J", QT_TRANSLATE_NOOP("core", "q̇ = J·Ẋ, J = J_q⁻¹·J_x"), units::none, 4, n, n);
    // det J of a five-bar is about 10⁻⁴ rad²/mm²: two more decimals per power of mm⁻¹ keep
    // four figures of it (five-bar kind: 8).
    const DeterminantUnits du = determinantUnits(m_design);
    const int jLength = int(std::count_if(m_design.legs.begin(), m_design.legs.begin() + n,
                                          [](const PlanarLeg &leg) { return leg.type != LegType::RRR; }));
    l.add(G::Jacobian, "det_J", "det J", QT_TRANSLATE_NOOP("core", "determinant of J (0: direct, ∞: inverse singularity)"), du.J,
          4 + 2 * (2 - jLength));
    l.add(G::Jacobian, "det_Jq", "det J_q", QT_TRANSLATE_NOOP("core", "0 at an inverse singularity"), du.Jq, 1);
    l.add(G::Jacobian, "det_Jx", "det J_x", QT_TRANSLATE_NOOP("core", "0 at a direct singularity"), du.Jx, 1);
    l.add(G::Jacobian, "cond", "κ(J)", QT_TRANSLATE_NOOP("core", "condition number of J"), units::none, 3);
    l.add(G::Derived, "margin", "m", QT_TRANSLATE_NOOP("core", "distance from the nearest singularity (0 … 1)"), units::none, 4);
    // exact values at singular poses (mechanism.h: AtSingularity)
    l.atSingularityOfJ("det_Jq");
}

Singularity PlanarParallel::evaluate(const Pose &pose, std::span<double> v) const
{
    const int n = m_design.legCount();
    int at = 0;
    for (int i = 0; i < n; ++i)
        v[std::size_t(at++)] = pose.inputs[i];
    for (int i = 0; i < n; ++i)
        v[std::size_t(at++)] = pose.outputs[i];
    Eigen::Matrix3d jq, jx;
    jacobianParts(pose, jq, jx);
    Eigen::Matrix3d J = jx;
    for (int i = 0; i < n; ++i)
        J.row(i) /= jq(i, i);
    for (const Eigen::Matrix3d *m : {&jq, &jx, &J}) {
        for (int r = 0; r < n; ++r) {
            for (int c = 0; c < n; ++c)
                v[std::size_t(at++)] = (*m)(r, c);
        }
    }
    const double detJq = jq.diagonal().head(n).prod();
    const double detJx = n == 2 ? jx.topLeftCorner<2, 2>().determinant() : jx.determinant();
    v[std::size_t(at++)] = detJx / detJq;
    v[std::size_t(at++)] = detJq;
    v[std::size_t(at++)] = detJx;
    double cond = std::numeric_limits<double>::infinity();
    if (n == 2) {
        const Eigen::Matrix2d j2 = J.topLeftCorner<2, 2>();
        const double f = j2.squaredNorm(), d = std::abs(j2.determinant());
        const double spread = std::sqrt(std::max(0.0, f * f - 4.0 * d * d));
        if (d > 0.0 && std::isfinite(f))
            cond = (f + spread) / (2.0 * d);
    } else if (J.allFinite()) {
        const Eigen::JacobiSVD<Eigen::Matrix3d> svd(J);
        const Eigen::Vector3d s = svd.singularValues();
        if (s[2] > 0.0)
            cond = s[0] / s[2];
    }
    v[std::size_t(at++)] = cond;
    const Singularity s = singularity(pose);
    v[std::size_t(at++)] = s.margin;
    settleSingularValues(m_layout, v, s.type);
    return s;
}

std::vector<ModeAlternative> PlanarParallel::modeNeighbours() const
{
    std::vector<ModeAlternative> neighbours;
    // A 3-DOF platform's neighbours differ from this design in their modes only: one search of
    // their home poses (every solution of the three circles at each input tried) serves them
    // all, where a search each made every edit of a 3-R̲RR take ~85 ms (SharedSearch)
    SharedSearch shared;
    auto add = [&](const std::string &label, const ParameterSet &changes, bool sameInputs, SharedSearch *search = nullptr) {
        if (auto other = withParameters(changes, search))
            neighbours.push_back({label, changes, *other, sameInputs, {}});
    };
    const int n = m_design.legCount();
    if (n == 2) {
        const std::string label = QT_TRANSLATE_NOOP("core", "other assembly mode (same inputs)");
        add(label, {{"assembly", -double(m_design.assembly)}}, true);
        for (int i = 0; i < n; ++i) // mirrored across C₁C₂, a leg may flip its working mode too
            add(label, {{"assembly", -double(m_design.assembly)}, {joinText({"working", number(i)}), -double(m_design.legs[std::size_t(i)].working)}}, true);
    }
    if (n == 3) {
        // every real solution of the direct kinematics at the pose's inputs: the neighbour with
        // assembly = k, solved without a pose to follow, takes the k-th in order of φ (a 3-RPR
        // has up to six; Mechanism::solveAlternatives drops the one the pose is in)
        static const std::array<const char *, 6> assemblyLabels = {
            QT_TRANSLATE_NOOP("core", "assembly mode 1 (same inputs)"), QT_TRANSLATE_NOOP("core", "assembly mode 2 (same inputs)"),
            QT_TRANSLATE_NOOP("core", "assembly mode 3 (same inputs)"), QT_TRANSLATE_NOOP("core", "assembly mode 4 (same inputs)"),
            QT_TRANSLATE_NOOP("core", "assembly mode 5 (same inputs)"), QT_TRANSLATE_NOOP("core", "assembly mode 6 (same inputs)")};
        for (int k = 1; k <= 6; ++k)
            add(assemblyLabels[std::size_t(k - 1)], {{"assembly", double(k)}}, true, &shared);
    }
    static const std::array<const char *, 3> labels = {QT_TRANSLATE_NOOP("core", "leg 1: other working mode (same platform pose)"),
                                                       QT_TRANSLATE_NOOP("core", "leg 2: other working mode (same platform pose)"),
                                                       QT_TRANSLATE_NOOP("core", "leg 3: other working mode (same platform pose)")};
    for (int i = 0; i < n; ++i) {
        const PlanarLeg &leg = m_design.legs[std::size_t(i)];
        if (leg.type == LegType::RPR)
            continue;
        add(labels[std::size_t(i)], {{joinText({"working", number(i)}), -double(leg.working)}}, false, n == 3 ? &shared : nullptr);
        if (n == 2)
            add(labels[std::size_t(i)], {{joinText({"working", number(i)}), -double(leg.working)}, {"assembly", -double(m_design.assembly)}}, false);
    }
    return neighbours;
}

} // namespace pkm
