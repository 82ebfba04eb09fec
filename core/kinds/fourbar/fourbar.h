#pragma once
/// The planar four-bar linkage ABCD (the four-bar and mobility document, which labels it ABED): ground AD,
/// crank AB (input α), coupler BC, rocker CD (output δ). Equation numbers refer to that document.
///
/// Frame: A = (0, 0), D = (AD, 0), y up. Units: mm, rad, s.
///   α: the angle at A from A→D to A→B, counter-clockwise, so B = AB·(cos α, sin α).
///   δ: the angle at D from D→A to D→C, clockwise (the interior angle ADC when C is above the
///      ground), so C = D + CD·(−cos δ, sin δ). The rocker's direction from +x is θ₃ = π − δ.
///   γ: the oriented angle at C from C→B to C→D, counter-clockwise, in (−180°, 180°]: the
///      transmission angle. It is positive in the open branch and negative in the crossed one,
///      so that every formula of the document, (3)–(9), holds as printed in both branches:
///      (5) cos γ = e + f·cos α, (3, 6) δ = δ₁ + atan2(BC·sin γ, CD − BC·cos γ) (mod 360°; the
///      document's arctan of the ratio is wrong by 180° when CD − BC·cos γ < 0).
///   δ₁: the angle at D from D→A to D→B, clockwise (4): δ₁ = atan2(AB·sin α, AD − AB·cos α).
///   β: the oriented angle at B from B→A to B→C, counter-clockwise, in [0°, 360°);
///      β ≡ 360° − (α + γ + δ) (mod 360°) holds exactly.
///
/// Branch (a design parameter, `branch` = σ): σ = +1 "open": C lies to the left of the directed
/// diagonal B→D (for B above the ground, ABCD is then a convex quadrilateral); σ = −1 "crossed":
/// C mirrored across BD. A pose of the design is always in its branch: the mechanism stops at
/// the dead points where the branches meet (C on the line BD) instead of changing branch.
///
/// Input range: the crank turns fully (α ∈ [0°, 360°]) when |BD| stays within
/// [|BC − CD|, BC + CD] for every α; else α is limited by the law of cosines,
/// BD² = AB² + AD² − 2·AB·AD·cos α, to an interval around 0° ([−α₀, α₀]), around 180°, or —
/// when both limits bind — to the upper one of two mirror-image intervals (B above the ground;
/// the lower one is the mirror image of the other branch, so nothing is lost).
/// Output range: the interval δ sweeps in the branch over the input range (the full turn
/// [0°, 360°] for a double-crank).
///
/// Inverse kinematics δ → α: B is a circle–circle intersection of (A, AB) and (C, BC); of the
/// two, those in the design's branch and α-range are kept and the one nearest to `near`'s α
/// (else to the home pose's α) is chosen. Both may be valid (a crank-rocker passes each rocker
/// angle twice per turn); they merge where crank and coupler are collinear (δ at its limit).
///
/// Velocities: the loop closure F(α, δ) = |C(δ) − B(α)|² − BC² = 0 gives J_q·α̇ = J_x·δ̇ with
/// J_q = ∂F/∂α = 2·AB·BC·sin β and J_x = −∂F/∂δ = −2·BC·CD·sin γ; J = J_q⁻¹·J_x = dα/dδ and
/// i₃₁ = dδ/dα = 1/J = −(AB·sin β)/(CD·sin γ).
///   J_q = 0 (sin β = 0, crank and coupler collinear, δ at its limit): inverse singularity;
///   J_x = 0 (sin γ = 0, coupler and rocker collinear, α at its limit: the dead point where the
///   crank cannot drive): direct singularity. Margins |sin β| and |sin γ|.
/// ω₃ = dδ/dt and ε₃ = d²δ/dt² at constant ω₁ = dα/dt are solved exactly from the vector loop
/// AB·e^{iα} + BC·e^{iθ₂} = AD + CD·e^{iθ₃} differentiated once and twice (2×2 systems).
/// The document's (8) ω₃ = ω₁·(AB/CD)·sin β/sin γ is the rocker's angular velocity dθ₃/dt
/// (counter-clockwise, like ω₁), so it equals −dδ/dt: our ω₃ = −(8). Its (14) for ε₃ agrees
/// with neither sign of the exact second derivative (docs/mathematics.md): see fourbar::document*.

#include "actuatorparameters.h"

#include <array>

#include <vector>

namespace pkm {

struct FourBarDesign {
    double crank = 40.0;       ///< AB, mm
    double coupler = 120.0;    ///< BC, mm
    double rocker = 100.0;     ///< CD, mm
    double ground = 140.0;     ///< AD, mm
    double omega1 = 10.0;      ///< ω₁ = dα/dt, rad/s (constant)
    double couplerPoint = 0.5; ///< λ = BM/BC of the coupler point M on BC
    int branch = +1;           ///< σ: +1 open, −1 crossed
    /// The actuators of the crank at A (assumed: the documents give none; actuatorparameters.h)
    std::array<ActuatorSpec, 1> actuators = {assumedRotary};
    LoadSpec load; ///< the load whose deflection the capability group reports
};

namespace fourbar {
constexpr int open = +1;
constexpr int crossed = -1;
/// "open" or "crossed": the word of files, reports and JSON (English, marked for translation:
/// text::label() translates it for a person).
const char *branchName(int branch);

/// Grashof's classes, from s + l against p + q (s the shortest link, l the longest).
enum class Grashof {
    CrankRocker,  ///< s + l < p + q, the crank AB shortest: AB turns fully, CD rocks
    RockerCrank,  ///< s + l < p + q, the rocker CD shortest: CD turns fully, AB rocks
    DoubleCrank,  ///< s + l < p + q, the ground AD shortest (drag link): both turn fully
    DoubleRocker, ///< s + l < p + q, the coupler BC shortest (Grashof double-rocker)
    TripleRocker, ///< s + l > p + q: no link turns fully (non-Grashof)
    ChangePoint,  ///< s + l = p + q: the links can fold flat, the branches meet there
};
Grashof classify(double AB, double BC, double CD, double AD);
/// "crank-rocker", "rocker-crank", "double-crank", "double-rocker", "triple-rocker",
/// "change-point": English words of reports and JSON, marked for translation (text::label()).
const char *grashofName(Grashof g);

/// B and C at input α in branch σ by circle–circle intersection, no range checks; `valid` is
/// false where the loop does not close (or B = D, where C is undetermined).
struct Position {
    Eigen::Vector2d B = Eigen::Vector2d::Zero();
    Eigen::Vector2d C = Eigen::Vector2d::Zero();
    bool valid = false;
};
Position position(const FourBarDesign &design, double alpha);

/// The angles of a pose (rad), as defined above.
struct Angles {
    double gamma = 0, delta1 = 0, beta = 0;
};
Angles angles(const FourBarDesign &design, double alpha, double delta);

/// Exact velocities and accelerations at constant ω₁ (rad/s, rad/s²): ω₂, ε₂ of the coupler
/// (counter-clockwise), ω₃ = dδ/dt, ε₃ = d²δ/dt². Not finite at a direct singularity.
struct Motion {
    double omega2 = 0, omega3 = 0, epsilon2 = 0, epsilon3 = 0;
};
Motion motion(const FourBarDesign &design, double alpha, double delta, double omega1);

/// The instantaneous centre P of the coupler: lines AB and DC meet there; NaN when parallel.
Eigen::Vector2d instantCentre(const FourBarDesign &design, double alpha, double delta);

// The document's formulas exactly as printed (for the tests that check them):
/// (5) cos γ = (BC² + CD² − AB² − AD²)/(2·BC·CD) + (AB·AD)/(BC·CD)·cos α
double documentCosGamma(double AB, double BC, double CD, double AD, double alpha);
/// (8) ω₃ = ω₁·(AB/CD)·sin β/sin γ: the rocker's counter-clockwise angular velocity, −dδ/dt.
double documentOmega3(double AB, double CD, double omega1, double beta, double gamma);
/// (9) i₃₁ = AB·sin β/(CD·sin γ)
double documentI31(double AB, double CD, double beta, double gamma);
/// (14) ε₃ = ω₁²·(AB·AD)/(BC·CD)·(sin δ·cos β − (AB/CD)·sin α·cos β·ctg γ)/sin²γ — wrong.
double documentEpsilon3(double AB, double BC, double CD, double AD, double omega1, double alpha, double beta,
                        double gamma, double delta);
} // namespace fourbar

class FourBar final : public TabledMechanism<FourBar, FourBarDesign>
{
public:
    /// Validates the design; the failure names the culprit (a length ≤ 0 or NaN, a link
    /// longer than the other three together, a branch other than ±1).
    static Result<MechanismPtr> create(const FourBarDesign &design);
    /// The parameters and the design fields they read and write (createFrom(): missing values
    /// take the example's: 40, 120, 100, 140 mm).
    static const ParameterTable<FourBarDesign> &table();
    /// Grashof's class of a design.
    static fourbar::Grashof grashof(const FourBarDesign &design);

    const FourBarDesign &design() const { return m_design; }

    std::string_view kind() const override { return "fourbar"; }
    /// A poor transmission (|γ| or 180° − |γ| below 40° somewhere in the range), a change point.
    std::vector<std::string> designWarnings() const override;

    const std::vector<VariableInfo> &variableInfo() const override;
    Interval variableRange(int variable) const override;
    Pose homePose() const override { return m_home; }
    /// The dead point that limits α when the crank does not turn fully.
    std::string rangeLimitReason(int variable, bool upper) const override;
    /// α → δ in the design's branch; α outside variableRange(α) is refused with the reason.
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    /// δ → α: of the crank angles in the design's branch, the one nearest `near` (or home).
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;

    const ReportLayout &reportLayout() const override;
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    Jacobians jacobians(const Pose &pose) const override;
    /// "branch" (Pose: open/crossed) and "grashof" (Derived: crank-rocker, …).
    std::vector<ReportText> reportText(const Pose &pose) const override;
    /// The other branch at the same α.
    std::vector<ModeAlternative> modeNeighbours() const override;
    /// Ground AD, crank AB, coupler BC, rocker CD; revolute pairs A (actuated), B, C, D.
    KinematicChain kinematicChain(const Pose &pose) const override;

    Scene scene(const Pose &pose) const override;
    /// Handle 0 (B) turns the crank (direct kinematics); handle 1 (C) swings the rocker
    /// (inverse kinematics).
    Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const override;

    Singularity singularity(const Pose &pose) const;
    /// The coupler curve: M over the input range in the design's branch.
    const std::vector<Eigen::Vector2d> &couplerCurve() const { return m_curve; }
    /// True when α ranges over the full turn [0°, 360°].
    bool crankTurnsFully() const { return m_fullTurn; }

    static constexpr int variableAlpha = 0;
    static constexpr int variableDelta = 1;
    static constexpr double singularTolerance = 1e-7;
    /// Below this transmission angle (deg) designWarnings() warns.
    static constexpr double poorTransmission = 40.0;

private:
    explicit FourBar(const FourBarDesign &design);
    /// The representative of δ (any turn) in the output range's convention.
    double wrapDelta(double delta) const;
    /// Why α cannot go past `limit` (the law-of-cosines reason), for messages.
    std::string limitReason(double limit) const;

    FourBarDesign m_design;
    Interval m_alphaRange;
    Interval m_deltaRange;
    bool m_fullTurn = false;
    bool m_outputFullTurn = false;
    Pose m_home;
    std::vector<Eigen::Vector2d> m_curve;
    Eigen::AlignedBox2d m_motionBox; ///< the joints over the motion, both branches
};

} // namespace pkm
