#pragma once
/// The planar five-bar linkage (the four-bar and mobility document's fig. 1): a 2-DOF planar parallel mechanism with
/// two driven cranks, the classroom example of a parallel mechanism whose output is a point.
///
/// Frame: ground joints A = (0, 0) and E = (AE, 0), y up. Units: mm, rad.
///   Leg 1: crank AB driven at A by θ₁, distal link BC; leg 2: crank ED driven at E by θ₄,
///   distal link DC. Both angles are measured counter-clockwise from +x:
///   B = A + AB·(cos θ₁, sin θ₁), D = E + DE·(cos θ₄, sin θ₄). The distal links meet at the
///   output point C = (x, y) (the end-effector, the pen).
///   In the code a leg i ∈ {0, 1} has ground joint G_i (A, E), crank length a_i (AB, DE),
///   distal length b_i (BC, CD), crank angle θ_i (θ₁, θ₄) and elbow P_i (B, D).
///
/// Modes (design parameters, each ±1; the mechanism never changes them by itself):
///   working_i = +1 "left": the elbow P_i lies to the left of the directed line G_i→C, so that
///     (C − G_i)×(P_i − G_i) > 0; −1 "right": to its right. The inverse-kinematics choice of
///     leg i. With C above the ground, elbows out is working1 = left, working2 = right.
///   assembly = +1 "left": C lies to the left of the directed line B→D, (D − B)×(C − B) > 0
///     (above BD while B is left of D); −1 "right". The direct-kinematics choice.
///   A pose of the design is always in its three modes: the solvers refuse a pose in another
///   mode and say which singularity lies between, instead of switching.
///
/// Crank ranges: θ_i ∈ [theta_min, theta_max] of its crank (a span of at most one turn; the
/// default is the full turn [−180°, 180°]). The inverse kinematics returns the representative
/// of θ_i inside the range nearest to `near` (else to the home pose).
///
/// Velocities: the loop constraints f_i(θ_i, C) = |C − P_i(θ_i)|² − b_i² = 0 differentiated,
/// halved, give J_q·θ̇ = J_x·Ċ with
///   J_x rows (C − B)ᵀ and (C − D)ᵀ (mm),
///   J_q = diag(k₁, k₄), k_i = (P_i − G_i)×(C − P_i) = −½·∂f_i/∂θ_i (mm²; k_i = a_i·b_i·sin of
///   the angle from the crank to the distal link, and sign k_i = −working_i),
///   J = J_q⁻¹·J_x (rad/mm): θ̇ = J·Ċ. det J_x = (C − B)×(C − D) has the sign of `assembly`, so
///   det J = det J_x/(k₁k₄) has the sign assembly·working1·working2 throughout the workspace
///   (rad²/mm²: the five-bar's J maps lengths to angles, so det J is not dimensionless).
///   k_i = 0 (crank and distal link of a leg in line, C on the circle of radius a_i + b_i or
///   |a_i − b_i| about G_i): inverse singularity, where the two working modes meet.
///   det J_x = 0 (the distal links in line): direct singularity, where the two assembly modes
///   meet and C gains a freedom. Scale-free margins: |k_i|/(a_i·b_i) = |sin| of the elbow
///   angle, |det J_x|/(BC·CD) = |sin| of the angle between the distal links.

#include "actuatorparameters.h"
#include "planarworkspace.h"
#include "text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

struct FiveBarDesign {
    double ground = 100.0;                       ///< AE, mm
    std::array<double, 2> crank = {80.0, 80.0};  ///< a_i: AB, DE, mm
    std::array<double, 2> link = {120.0, 120.0}; ///< b_i: BC, CD, mm
    /// θ₁ and θ₄ limits, rad (min < max, max − min ≤ 2π)
    std::array<Interval, 2> range = {Interval{-std::numbers::pi, std::numbers::pi},
                                     Interval{-std::numbers::pi, std::numbers::pi}};
    std::array<int, 2> working = {+1, -1}; ///< working_i (+1 left, −1 right): elbows out
    int assembly = +1;                     ///< +1 left (C above BD), −1 right
    /// The actuators of the cranks at A and E (assumed: the documents give none; actuatorparameters.h)
    std::array<ActuatorSpec, 2> actuators = {assumedRotary, assumedRotary};
    LoadSpec load; ///< the load whose deflection the capability group reports
};

/// Closed forms, no validation (callers check).
namespace fivebar {
constexpr int left = +1;
constexpr int right = -1;
/// "left" or "right"
const char *sideName(int side);

/// True when a crank range spans the whole turn (the crank turns fully).
bool fullTurn(const Interval &range);

/// The ground joint G_i: A (leg 0) or E (leg 1).
Eigen::Vector2d groundJoint(const FiveBarDesign &design, int leg);
/// The elbow P_i at crank angle θ: B (leg 0) or D (leg 1).
Eigen::Vector2d elbow(const FiveBarDesign &design, int leg, double theta);
/// f_i = |C − P_i|² − b_i²
double constraint(const FiveBarDesign &design, int leg, double theta, const Eigen::Vector2d &C);
/// k_i = (P_i − G_i)×(C − P_i), the diagonal entry of J_q.
double inputJacobian(const FiveBarDesign &design, int leg, double theta, const Eigen::Vector2d &C);

/// Why two circles have no common point, or none: see circleIntersection().
enum class Meet { Yes, TooFar, TooNear, Concentric };
/// The point X with |X − p| = rp and |X − q| = rq on side `side` of the directed line p→q
/// (+1: to its left). `tolerance` (relative to rp + rq) lets circles that touch up to rounding
/// meet. Concentric: p = q with rp = rq, where X is anywhere on the circle.
Meet circleIntersection(const Eigen::Vector2d &p, double rp, const Eigen::Vector2d &q, double rq, int side,
                        Eigen::Vector2d &X, double tolerance);

/// σ_max/σ_min of a 2×2 matrix from its squared Frobenius norm and |det|; +∞ when det = 0.
inline double conditionNumber(double frobeniusSquared, double absDeterminant)
{
    const double f = frobeniusSquared, d = absDeterminant;
    const double spread = std::sqrt(std::max(0.0, f * f - 4.0 * d * d));
    return d > 0.0 ? (f + spread) / (2.0 * d) : std::numeric_limits<double>::infinity();
}
} // namespace fivebar

class FiveBar final : public TabledMechanism<FiveBar, FiveBarDesign>, public PlanarWorkspace
{
public:
    /// Validates the design; the failure names the culprit (a length ≤ 0 or NaN, a link not
    /// shorter than the other four together, a crank range inverted or over a turn, a mode
    /// other than ±1, modes and ranges in which the loop never closes).
    static Result<MechanismPtr> create(const FiveBarDesign &design);
    /// The parameters and the design fields they read and write (createFrom(): missing values
    /// take the example's: AE = 100, AB = DE = 80, BC = CD = 120 mm, elbows out, C above BD,
    /// full-turn cranks).
    static const ParameterTable<FiveBarDesign> &table();

    const FiveBarDesign &design() const { return m_design; }

    std::string_view kind() const override { return "fivebar"; }
    /// Direct singularities in the workspace of the design's modes (C can lose control there).
    std::vector<std::string> designWarnings() const override;

    const std::vector<VariableInfo> &variableInfo() const override;
    Interval variableRange(int variable) const override;
    Pose homePose() const override { return m_home; }
    /// (θ₁, θ₄) → C in the design's assembly mode; refused, with the reason, where the distal
    /// links cannot meet or a leg would be in its other working mode.
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    /// C → (θ₁, θ₄), each leg in its working mode; refused, with the reason, where a leg cannot
    /// reach C, a crank would leave its range, or C would be in the other assembly mode.
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;

    const ReportLayout &reportLayout() const override;
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    Jacobians jacobians(const Pose &pose) const override;
    /// The other assembly mode (same crank angles) and each leg's other working mode (same C).
    std::vector<ModeAlternative> modeNeighbours() const override;
    const PlanarWorkspace *planarWorkspace() const override { return this; }
    /// Ground, crank AB, link BC, link CD, crank DE; revolute pairs A and E (actuated), B, C, D.
    KinematicChain kinematicChain(const Pose &pose) const override;

    Scene scene(const Pose &pose) const override;
    /// Handle 0 (C) solves the inverse problem; handles 1 and 2 (B, D) turn crank AB or DE
    /// towards the target and solve the direct problem.
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
    /// The legs stretched or folded (inverse) and the distal links in line (direct), where
    /// they are poses of the design.
    std::vector<SingularCurve> singularCurves() const override;
    std::string singularityMeaning(SingularCurve::Type type) const override
    {
        // the GUI translates the meaning (context "core")
        return type == SingularCurve::Type::Inverse ? QT_TRANSLATE_NOOP("core", "crank and distal link in line")
                                                    : QT_TRANSLATE_NOOP("core", "distal links in line");
    }

    static constexpr int variableTheta1 = 0;
    static constexpr int variableTheta4 = 1;
    static constexpr int variableX = 2;
    static constexpr int variableY = 3;
    /// Below this margin a pose is classed singular (margins are scale-free).
    static constexpr double singularTolerance = 1e-7;

    /// Why a pair of crank angles or a point C is not a pose of the design (solveDirect and
    /// solveInverse turn it into a message; the maps and curves only need the verdict).
    struct Check {
        enum class Reason {
            None,         ///< a pose
            LinksApart,   ///< |BD| > BC + CD
            LinksClose,   ///< |BD| < |BC − CD|
            ElbowsMeet,   ///< B = D with BC = CD: C undetermined
            WorkingMode,  ///< leg `leg` would be in its other working mode
            LegTooShort,  ///< C farther than a_i + b_i from G_i
            LegTooLong,   ///< C nearer than |a_i − b_i| to G_i
            OnGroundJoint,///< C on G_i with a_i = b_i: θ_i undetermined
            CrankRange,   ///< θ_i (`theta`) outside the crank's range
            AssemblyMode, ///< C in the other assembly mode
        } reason = Reason::None;
        int leg = 0;
        double theta = 0.0;                       ///< CrankRange: the angle the crank would need
        std::array<double, 2> thetas = {0.0, 0.0}; ///< the pose's crank angles
        std::array<Eigen::Vector2d, 2> elbows = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()}; ///< B, D
        Eigen::Vector2d C = Eigen::Vector2d::Zero();
        bool ok() const { return reason == Reason::None; }
    };
    /// The direct problem at (θ₁, θ₄) without range checks; `tolerance` is relative.
    Check checkDirect(double theta1, double theta4, double tolerance) const;
    /// The inverse problem at C; the crank angles are the representatives nearest `reference`.
    Check checkInverse(const Eigen::Vector2d &C, double tolerance, const std::array<double, 2> &reference) const;

private:
    explicit FiveBar(const FiveBarDesign &design);
    /// The message for a failed check, at the inputs (direct) or at C (inverse).
    Failure explain(const Check &check, bool direct, const std::string &culprit) const;
    /// The crank angles to prefer: `near`'s, else the home pose's, else the ranges' middles.
    std::array<double, 2> referenceAngles(const Pose *near) const;
    Eigen::AlignedBox2d computeBounds() const;
    /// The singular curves sampled `samples` times over each parameter's range.
    std::vector<SingularCurve> tracedCurves(int samples) const;

    FiveBarDesign m_design;
    Eigen::AlignedBox2d m_bounds;
    Pose m_home;
};

} // namespace pkm
