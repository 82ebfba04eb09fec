#pragma once
/// The active П-joint: a hinged parallelogram driven by a telescopic diagonal (lead screw and
/// stepper motor). Equation numbers refer to the П-joint document (docs/mathematics.md).
///
/// Frame: base pivots O = (0,0) and B = (b,0); crank BA of length a at angle θ from the
/// perpendicular to the base, A = B + a·(sin θ, cos θ); diagonal OA of length d (the actuator).
/// Units: mm, rad, N, N·m, s. θ is the output, d the actuated input.

#include "actuatorparameters.h"
#include "parametertable.h"

namespace pkm {

/// The design: an immutable value. Table 1 values are the prototype's defaults.
struct PJointDesign {
    double a = 170.0;                    ///< crank ("lever") length, mm
    double b = 68.0;                     ///< base link and coupler length, mm (k = b/a)
    double thetaMin = -60.0 * units::degree; ///< rad
    double thetaMax = 60.0 * units::degree;  ///< rad
    double lead = 2.540;                 ///< screw lead h, mm per revolution
    double step = 0.01270;               ///< linear resolution Δd, mm per motor step
    double speedMax = 50.0;              ///< maximum linear speed ḋ_max, mm/s
    double forceMax = 130.0;             ///< recommended thrust F_max, N
    double efficiency = 0.4;             ///< screw efficiency η (not in Table 1: assumed)
    /// Axial stiffness of the screw, nut and bearings k_d, N/mm (not in Table 1: assumed, about
    /// 20 N/µm for a small lead-screw actuator): the actuator's share of the output stiffness.
    double stiffness = 20000.0;
    /// The document's measured mean static stiffness of the whole joint over ±60°, N·m/rad
    /// (section 4.2): reported beside the actuator's share (capability.h).
    double stiffnessMeasured = 3.5e4;
    LoadSpec load; ///< load_torque on the output link, for the deflection
    double motorLength = 45.0;           ///< motor body length along the diagonal, mm
    double motorWidth = 28.0;            ///< motor body width, mm
    double screwDiameter = 4.7752;       ///< mm

    double k() const { return b / a; }
};

/// Closed forms of the П-joint; free functions of (design, θ or d), no validation.
namespace pjoint {
/// (1) F(θ,d) = a²(1 + k² + 2k·sinθ) − d²
double constraint(const PJointDesign &design, double theta, double d);
/// (2) d = a·√(1 + k² + 2k·sinθ)
double diagonal(const PJointDesign &design, double theta);
/// (3–5) θ from d on the branch −90° < θ < 90°; NaN when |sinθ| > 1 (callers check).
double angle(const PJointDesign &design, double d);
/// (7) J = ∂d/∂θ = a²k·cosθ / d, mm/rad
double jacobian(const PJointDesign &design, double theta);
/// (10) J_d = −∂F/∂d = 2d, mm
double jacobianD(const PJointDesign &design, double theta);
/// (11) J_θ = ∂F/∂θ = 2a²k·cosθ, mm²/rad
double jacobianTheta(const PJointDesign &design, double theta);
/// ∂J/∂θ = −a·k·(k + sinθ)(1 + k·sinθ)/(1+k²+2k·sinθ)^{3/2}, mm/rad²
double jacobianDerivative(const PJointDesign &design, double theta);
/// (16–18), corrected (docs/mathematics.md, section 1): d̈ = J·θ̈ + (∂J/∂θ)·θ̇²
double diagonalAcceleration(const PJointDesign &design, double theta, double thetaDot, double thetaDDot);
/// Inverse of the above: θ̈ = (d̈ − (∂J/∂θ)·θ̇²)/J
double angularAcceleration(const PJointDesign &design, double theta, double thetaDot, double dDDot);
/// Passive angle φ: direction of the diagonal OA from the base line OB, rad.
double passiveAngle(const PJointDesign &design, double theta);
/// Transmission angle μ at A between the diagonal AO and the crank AB:
/// cos μ = (a² + d² − b²)/(2ad); J = a·sin μ.
double transmissionAngle(const PJointDesign &design, double theta);
/// (13) T = J·F, output torque in N·m from actuator force F in N.
double outputTorque(const PJointDesign &design, double theta, double force);
/// (14) F = T/J, actuator force in N for output torque T in N·m.
double actuatorForce(const PJointDesign &design, double theta, double torque);
/// (15) T_M = F·h/(2π·η), motor torque in N·m for actuator force F in N.
double motorTorque(const PJointDesign &design, double force);
/// (8) Output speed θ̇ = ḋ/J in rad/s for the actuator speed ḋ in mm/s (fig. 16).
double outputSpeed(const PJointDesign &design, double theta, double dDot);
/// Output resolution Δθ = Δd/J in rad for one actuator step Δd in mm (fig. 15).
double outputResolution(const PJointDesign &design, double theta, double step);
/// Share of the best output torque that the recommended range keeps (see recommendedRange).
inline constexpr double recommendedTorqueShare = 0.6;
/// The recommended working range, rad: the part of [θ_min, θ_max] where J — and with it the
/// output torque, speed and resolution — stays within `share` of its best over the range.
/// Beyond it the characteristics change steeply. For the prototype this gives −60°…39.2°,
/// the document's "θ = [−60°, 40°]" (section 4.2). J is unimodal in θ, so this is one interval.
Interval recommendedRange(const PJointDesign &design, double share = recommendedTorqueShare);
} // namespace pjoint

class PJoint final : public TabledMechanism<PJoint, PJointDesign>
{
public:
    /// Validates the design; the failure names the first invalid parameter.
    static Result<MechanismPtr> create(const PJointDesign &design);
    /// The parameters and the design fields they read and write (createFrom(): missing values
    /// take the prototype's). k, if changed, sets b = k·a with the new a; b and k together are
    /// refused.
    static const ParameterTable<PJointDesign> &table();

    const PJointDesign &design() const { return m_design; }

    std::string_view kind() const override { return "pjoint"; }
    /// A failure of a check across parameters names the parameter changed, and says so.
    Result<MechanismPtr> withParameter(std::string_view name, double value) const override;
    std::vector<std::string> designWarnings() const override;

    const std::vector<VariableInfo> &variableInfo() const override;
    Interval variableRange(int variable) const override;
    Pose homePose() const override;
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;

    const ReportLayout &reportLayout() const override;
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    /// 1×1: J_q = J_d, J_x = J_θ, J = J_d⁻¹·J_θ (9–11).
    Jacobians jacobians(const Pose &pose) const override;
    /// The parallelogram O, B, A, C (ground OB, cranks OC and BA, coupler CA) and the
    /// telescopic diagonal as two links, the motor body hinged at O and the screw hinged to the
    /// crank at A, joined by an actuated prismatic pair along OA: 5 moving links, 7 pairs.
    KinematicChain kinematicChain(const Pose &pose) const override;

    Scene scene(const Pose &pose) const override;
    /// The solid model (core/models3d.cpp).
    Scene3D scene3d(const Pose &pose) const override;
    Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const override;

    /// Singularity class at θ ((9–11) of the П-joint document; docs/mathematics.md, section 1): J_θ = 0 direct, J_d = 0 inverse, both combined.
    Singularity singularity(double theta) const;
    double dMin() const; ///< d(θ_min)
    double dMax() const; ///< d(θ_max)
    /// pjoint::recommendedRange of the design, computed once.
    const Interval &recommendedRange() const { return m_recommended; }

    static constexpr int variableD = 0;     ///< index of d in variableInfo()
    static constexpr int variableTheta = 1; ///< index of θ in variableInfo()

private:
    explicit PJoint(const PJointDesign &design);

    PJointDesign m_design;
    Interval m_recommended;
};

} // namespace pkm
