#pragma once
/// MOMA: the reconfigurable 2-axis planar parallel mechanism (docs/mathematics.md). Two powered
/// linear axes move sliders along guides; links of constant length join the sliders to the
/// platform P. Equation numbers refer to the MOMA document.
///
/// Frame: the base frame {B}, y up. Axis i has reference point R_i, unit direction
/// a_i = (cos α_i, sin α_i), slider position p_i (actuated), slider joint Z_i = R_i + p_i·a_i,
/// link length l_i; the platform P = (x, y) is the output. Units: mm, rad.
///
/// Modes: leg i works in branch β_i = ±1, p_i = B_i + β_i·√(B_i² − C_i) (7–9) — the document's
/// choice is β_i = −1 — and the platform lies on side σ = ±1 of the directed line Z₁→Z₂
/// (σ = +1: to its left). All three are design parameters: a pose of the design always has
/// them, so the mechanism never changes mode without the user asking.
///
/// Velocities: from f_i(p, P) = |P − Z_i|² − l_i² = 0 (5–6), J_p·ṗ + J_x·Ṗ = 0 with the
/// document's J_p = diag(2p_i − 2B_i) (18) and J_x rows 2(P − Z_i) (20). So ṗ = J·Ṗ with
/// J = −J_p⁻¹·J_x; the document's (21) writes J = J_p⁻¹·J_x, which has the opposite sign and
/// the same determinant (a 2×2 matrix).

#include "actuatorparameters.h"
#include "planarworkspace.h"
#include "text.h"

#include <array>
#include <cmath>
#include <limits>

namespace pkm {

struct MomaDesign {
    std::array<Eigen::Vector2d, 2> reference = {Eigen::Vector2d(-100.0, 0.0), Eigen::Vector2d(100.0, 0.0)}; ///< R_i, mm
    std::array<double, 2> alpha = {265.0 * units::degree, 275.0 * units::degree}; ///< α_i, rad
    std::array<double, 2> length = {195.0, 195.0};                                 ///< l_i, mm
    double strokeMin = 0.0;   ///< p_min, mm
    double strokeMax = 200.0; ///< p_max, mm
    std::array<int, 2> branch = {-1, -1}; ///< β_i
    int assembly = -1;                   ///< σ
    bool oneSide = false; ///< the physical constraint: each link stays on the inner side of its guide
    double guideWidth = 20.0; ///< drawn width of a guide, mm
    /// The actuators of the sliders (assumed: the documents give none; actuatorparameters.h)
    std::array<ActuatorSpec, 2> actuators = {assumedLinear, assumedLinear};
    LoadSpec load; ///< the load whose deflection the capability group reports
};

/// Closed forms, no validation (callers check).
namespace moma {
/// a_i = (cos α_i, sin α_i). A solve asks for the same two guides many times (every cell of a
/// capability map, every drag step: a third of a map's time went to sin and cos), so the last
/// two directions are kept per thread: the same bits as computing them, once per design.
inline Eigen::Vector2d direction(double alpha)
{
    struct Memo {
        double alpha = std::numeric_limits<double>::quiet_NaN();
        Eigen::Vector2d value = Eigen::Vector2d::Zero();
    };
    thread_local std::array<Memo, 2> memo;
    thread_local std::size_t next = 0;
    for (const Memo &m : memo)
        if (m.alpha == alpha)
            return m.value;
    Memo &m = memo[next];
    next ^= 1;
    m.alpha = alpha;
    m.value = {std::cos(alpha), std::sin(alpha)};
    return m.value;
}
/// B_i = a_i·(P − R_i) (8)
double projection(const MomaDesign &design, int leg, const Eigen::Vector2d &platform);
/// B_i² − C_i with C_i = |P − R_i|² − l_i² (9); negative: P farther than l_i from the guide line.
double discriminant(const MomaDesign &design, int leg, const Eigen::Vector2d &platform);
/// Z_i = R_i + p_i·a_i
Eigen::Vector2d sliderJoint(const MomaDesign &design, int leg, double p);
/// (5–6) f_i
double constraint(const MomaDesign &design, int leg, double p, const Eigen::Vector2d &platform);
/// The side of line Z₁→Z₂ the platform lies on, as the cross product (Z₂−Z₁)×(P−Z₁), mm².
double side(const Eigen::Vector2d &z1, const Eigen::Vector2d &z2, const Eigen::Vector2d &platform);
/// The inner side of guide i (towards the other guide): +1 left of a_i, −1 right, 0 undefined.
int innerSide(const MomaDesign &design, int leg);
/// Margins (dimensionless, 0 at the singularity): leg i's |cos| between link and guide, and
/// |sin| of the angle between the two links.
double inverseMargin(const MomaDesign &design, int leg, double p, const Eigen::Vector2d &platform);
double directMargin(const MomaDesign &design, const Eigen::Vector2d &z1, const Eigen::Vector2d &z2,
                    const Eigen::Vector2d &platform);
} // namespace moma

class Moma final : public TabledMechanism<Moma, MomaDesign>, public PlanarWorkspace
{
public:
    /// Validates the design (and that its workspace is not empty); the failure names the
    /// culprit.
    static Result<MechanismPtr> create(const MomaDesign &design);
    /// The parameters and the design fields they read and write (createFrom(): missing values
    /// take configuration 3a's). gamma_i, if given, sets α_i = 270° + γ_i.
    static const ParameterTable<MomaDesign> &table();

    const MomaDesign &design() const { return m_design; }

    std::string_view kind() const override { return "moma"; }
    std::vector<std::string> designWarnings() const override;

    const std::vector<VariableInfo> &variableInfo() const override;
    Interval variableRange(int variable) const override;
    Pose homePose() const override { return m_home; }
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;

    const ReportLayout &reportLayout() const override;
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    Jacobians jacobians(const Pose &pose) const override;
    std::vector<ModeAlternative> modeNeighbours() const override;
    /// Ground, sliders K₁ and K₂, links S₁ and S₂: prismatic pairs on the guides PO₁, PO₂
    /// (actuated), revolute pairs Z₁, Z₂ at the sliders and P between the two links.
    KinematicChain kinematicChain(const Pose &pose) const override;
    const PlanarWorkspace *planarWorkspace() const override { return this; }

    Scene scene(const Pose &pose) const override;
    /// The solid model (core/models3d.cpp).
    Scene3D scene3d(const Pose &pose) const override;
    /// Handle 0 (P) solves the inverse problem; handles 1 and 2 (Z₁, Z₂) move a slider along
    /// its guide and solve the direct problem.
    Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const override;

    /// Singularity class at a solved pose, with the scale-free margins above.
    Singularity singularity(const Pose &pose) const;

    // PlanarWorkspace
    Eigen::AlignedBox2d workspaceBounds() const override { return m_bounds; }
    void fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                    std::span<float> margins) const override;
    bool fillsCapabilityRows() const override { return true; }
    void fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                           std::span<float> values, std::span<float> margins) const override;
    std::vector<SingularCurve> singularCurves() const override;
    std::string singularityMeaning(SingularCurve::Type type) const override
    {
        // the GUI translates the meaning (context "core")
        return type == SingularCurve::Type::Inverse ? QT_TRANSLATE_NOOP("core", "link ⟂ guide")
                                                    : QT_TRANSLATE_NOOP("core", "links collinear");
    }

    static constexpr int variableP1 = 0;
    static constexpr int variableP2 = 1;
    static constexpr int variableX = 2;
    static constexpr int variableY = 3;
    /// Below this margin a pose is classed singular (margins are scale-free, so one
    /// tolerance serves every size of machine).
    static constexpr double singularTolerance = 1e-7;

private:
    explicit Moma(const MomaDesign &design);
    /// The pose at (p₁, p₂) if it exists in the design's modes, else why not.
    Result<Pose> direct(double p1, double p2) const;
    /// The same; without `explain` a failure carries no sentence (a search that only counts).
    Result<Pose> direct(double p1, double p2, bool explain) const;
    /// The pose at P if it exists in the design's modes, else why not.
    Result<Pose> inverse(const Eigen::Vector2d &platform) const;
    /// Checks the one-side constraint; empty when it holds or is off.
    std::string oneSideViolation(const Eigen::Vector2d &platform, const std::array<Eigen::Vector2d, 2> &z) const;
    Eigen::AlignedBox2d computeBounds() const;

    MomaDesign m_design;
    Eigen::AlignedBox2d m_bounds;
    Pose m_home;
};

} // namespace pkm
