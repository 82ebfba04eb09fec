#pragma once
/// What the actuators deliver at the platform (or the output link) at one pose: the largest
/// force and speed in the weakest and the strongest direction, the worst resolution and the
/// stiffness (docs/mathematics.md, "Actuator capability"). One computation for every kind: it
/// needs only J_q and J_x of the pose (Mechanism::jacobians()) and the actuator limits, which
/// every kind declares as design parameters named by the convention below.
///
/// With q̇ = J·ẋ (J = J_q⁻¹·J_x) and G = J⁻¹ = J_x⁻¹·J_q:
///   force   F = Jᵀ·τ, |τ_i| ≤ τ_max,i  — the force polytope is {F : |(Gᵀ·F)_i| ≤ τ_max,i};
///   speed   ẋ = G·q̇, |q̇_i| ≤ q̇_max,i — the velocity polytope is {ẋ : |(J·ẋ)_i| ≤ q̇_max,i};
///   error   Δx = G·Δq, |Δq_i| ≤ step_i/2;
///   stiffness K = Jᵀ·K_q·J, K_q = diag(k_i), compliance C = K⁻¹ = G·K_q⁻¹·Gᵀ.
/// Both polytopes are intersections of slabs |a_i·v| ≤ b_i, so the weakest direction is exact:
/// the inscribed radius about the origin is min_i b_i/|a_i|. The strongest is the farthest
/// vertex, found among the images of the actuator box's vertices (or, for a 3-DOF platform,
/// of the points where the box's edges cross the plane of zero moment or rotation) — exact,
/// no sampling.
///
/// A 3-DOF platform (x, y in mm, φ in rad) has no single norm over its mixed units. The
/// choice here: force and stiffness are those of a pure force at the platform point (no
/// moment; the platform free to turn: the translational block of the compliance C), speed is
/// that of a pure translation (φ̇ = 0), the resolution is the translational part of Δx. The
/// stiffness matrix is given whole, in N/mm, N/rad and N·mm/rad blocks.
///
/// Each value is computed from the factor that stays bounded where it is finite (J near a
/// direct singularity, G near an inverse one); at a pose classified singular the marks of the
/// layout (AtSingularity) give the exact 0 or ∞.
///
/// Actuator parameters (core units), actuator i = 1, 2, 3 in the order of the actuated inputs
/// that move the platform (an independent serial axis, the O-X glide's z, is not one of them):
///   linear  force_max{i} N, speed_max{i} mm/s, step{i} mm, stiffness{i} N/mm;
///   rotary  the same names in N·m, rad/s, rad, N·m/rad — except where a parameter must keep
///           one unit whatever the leg type (planar-parallel): there a rotary actuator reads
///           torque_max{i}, rate_max{i}, angle_step{i}, torsion{i};
///   a single actuator (the П-joint) may drop the index: force_max, speed_max, step, stiffness.
/// An optional `stiffness_measured` (N·m/rad) is reported beside the computed stiffness.
///
/// The deflection under the design's load (load_x, load_y in N and load_moment in N·m on the
/// platform, load_torque in N·m on an angular output) is Δx = C·F with the compliance C of the
/// actuators alone (the links rigid): `deflection` (mm, or ° for an angle), its length
/// `deflection_norm` and, for a platform that turns, `deflection_angle`. Unbounded at a direct
/// singularity unless there is no load.

#include "mechanism.h"

#include <Eigen/Core>

#include <array>
#include <span>

namespace pkm {

namespace units {
inline constexpr Unit newtonPerMillimetre{QT_TRANSLATE_NOOP("core", "N/mm"), 1.0};
inline constexpr Unit degreePerSecond{QT_TRANSLATE_NOOP("core", "°/s"), 180.0 / std::numbers::pi}; ///< core: rad/s
} // namespace units

namespace capability {

inline constexpr int maxActuators = 3;

/// One actuator's limits in core units (rotary: N·m, rad/s, rad, N·m/rad).
struct Actuator {
    double force = 0.0;
    double speed = 0.0;
    double step = 0.0;
    double stiffness = 0.0;
    bool rotary = false;
};

struct Actuators {
    std::array<Actuator, maxActuators> items{};
    /// Indices into Pose::inputs (and rows of J) of the actuators.
    std::array<int, maxActuators> inputs{};
    int count = 0;
    bool rotaryOutput = false; ///< the output is an angle (the П-joint, the four-bar)
    int outputs = 0;           ///< platform coordinates: 1, 2 or 3 (x, y, φ)
    double measuredStiffness = 0.0; ///< stiffness_measured, N·m/rad; 0: none given
    /// |G·e_i| at the home pose: how far actuator i moves the platform per unit of its own
    /// motion at a typical pose, the scale against which a pose classified inverse-singular
    /// tells an actuator that no longer moves the platform (0: unknown).
    std::array<double, maxActuators> transmission{};
    /// The load on the platform (load_x, load_y N; load_moment N·m) or on an angular output
    /// (load_torque N·m), in the order of the outputs; zero where the design gives none.
    std::array<double, maxActuators> load{};
};

/// Small matrices on the stack (at most 3×3), so that evaluate() does not allocate.
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, maxActuators, maxActuators>;

/// The actuators of `mechanism` from its parameters (the names above); count 0 when it does
/// not declare them all. Allocates (parameters()): read it once per design.
Actuators actuatorsOf(const Mechanism &mechanism);

/// The entries of the "capability" group for actuators like `actuators` (one of a few shared
/// layouts, by output kind and count); nullptr when there are none. Entry groups are unused:
/// the layout is the group.
const ReportLayout *layoutFor(const Actuators &actuators);

/// How far from what it does at the home pose an actuator's effect on the platform may be
/// before what the actuators deliver is reported as at a singular pose. The rigid model's
/// numbers a hair from a singularity are exact but meaningless for a workshop: the five-bar
/// with both legs 10⁻⁵° from stretched "holds" 6.6·10⁷ N with 2 N·m motors, where its links
/// would have bent long before. So an actuator that moves the platform less than 1/1000 of
/// what it does at home counts as not moving it (as at an inverse singularity: forces ∞,
/// speeds 0), and one that moves it more than 1000 times as much marks a direct singularity
/// (forces 0, speeds and errors ∞). The factor 1000 is far outside what a design meets in
/// its working range (the П-joint's ratio varies by 2 over ±60°, MOMA's by less than 20).
inline constexpr double nearSingular = 1e3;

/// The class of the pose for this group: `type` (the kind's class), made inverse or direct
/// where an actuator's column of G = J⁻¹ is below or above the bounds above (its
/// `transmission`, nearSingular). The columns of actuators that no longer move the platform
/// are set to exactly 0 in `G`.
template <class Mat>
SingularityType deliveryClass(const Actuators &actuators, Mat &G, SingularityType type)
{
    bool inverse = type == SingularityType::Inverse || type == SingularityType::Combined;
    bool direct = type == SingularityType::Direct || type == SingularityType::Combined;
    for (int i = 0; i < int(G.cols()); ++i) {
        const double norm = G.col(i).norm(), home = actuators.transmission[std::size_t(i)];
        if (norm <= home / nearSingular) {
            G.col(i).setZero();
            inverse = true;
        } else if (home > 0.0 && !(norm < home * nearSingular)) { // NaN, ∞ or too large
            direct = true;
        }
    }
    return inverse && direct ? SingularityType::Combined
         : inverse           ? SingularityType::Inverse
         : direct            ? SingularityType::Direct
                             : SingularityType::None;
}

/// Fills `values` (layoutFor(actuators)->size) from J_q and J_x of the pose (rows and columns
/// of the actuators only, as selected by `actuators.inputs`), then settles the exact values
/// of a singular pose of the class deliveryClass() gives from `type`, and returns that class.
/// Does not allocate.
SingularityType evaluate(const Actuators &actuators, const Matrix &jq, const Matrix &jx, SingularityType type,
                         std::span<double> values);

/// The same from a mechanism and a pose (allocates: Mechanism::jacobians()).
SingularityType evaluate(const Mechanism &mechanism, const Actuators &actuators, const Pose &pose,
                         SingularityType type, std::span<double> values);

/// Settles the kind's own report `values` (Mechanism::evaluate(), `layout`) for `delivered`,
/// the class evaluate() above gave, where it is not the kind's `kindType`: a hair from a
/// singularity J and det J then read ∞ or 0 as the capability group does, not the rigid
/// model's −2.2·10⁹ rad²/mm² (the five-bar 10⁻¹¹ mm below its stretched legs). One rule for
/// every report of a pose: the values panel, eval, sweep rows. Does not allocate.
inline void settleNearSingular(const ReportLayout &layout, std::span<double> values, SingularityType delivered,
                               SingularityType kindType)
{
    if (delivered != kindType)
        settleSingularValues(layout, values, delivered);
}

/// A sentence on why the values of a pose of class `type` are 0 or ∞ where the kind's own class
/// of the pose is `kindType` (untranslated, "core" context); nullptr where they agree.
const char *nearSingularReason(SingularityType type, SingularityType kindType);

} // namespace capability
} // namespace pkm
