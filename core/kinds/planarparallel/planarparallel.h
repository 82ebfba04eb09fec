#pragma once
/// A planar parallel mechanism assembled from a library of legs (docs/mathematics.md,
/// "Planar parallel mechanisms from a leg library").
///
/// Frame: the base frame, y up; units mm and rad. The platform pose is X = (x, y, φ): a point
/// platform (2 DOF, φ ≡ 0, the legs meet at (x, y)), a platform of constant orientation (2 DOF,
/// φ ≡ 0, leg i holds the platform point B_i given in the platform frame), or a free rigid
/// body (3 DOF). The platform point of leg i in the base frame is P_i = (x, y) + R(φ)·B_i.
///
/// Leg i runs from its base point A_i to P_i, its actuated joint first:
///   R̲RR  crank r_i driven at A_i by q_i (angle from +x), distal link l_i;
///   P̲RR  slider at A_i + q_i·u(α_i) on a guide of direction α_i, link l_i (MOMA's leg);
///   RP̲R  a telescopic strut A_i P_i whose length q_i is the input;
///   П̲RR  an active П-joint (the П-joint document) whose crank of length a_i is the proximal
///        link: base pivot of the crank at A_i, the П-joint's base line OB along α_i (O at
///        A_i − k_i·a_i·u(α_i)), input the diagonal length d_i = q_i; the crank angle θ_i from
///        the perpendicular to the base follows from (3–5), the crank points along
///        ψ_i = α_i + 90° − θ_i; distal link l_i.
/// With its input fixed every leg is one circle constraint |P_i − C_i| = ρ_i: C = A, ρ = q
/// (RPR); C = A + r·u(q), ρ = l (RRR); C = A + q·u(α), ρ = l (PRR); C = A + a·u(ψ(q)),
/// ρ = l (П̲RR). The direct kinematics is the intersection of these circles: two circles for
/// 2 DOF, the planar 3-RPR forward problem for 3 DOF — a sextic in t = tan(φ/2) (C. Gosselin,
/// J. Sefrioui, M. J. Richard, "Solutions polynomiales au problème de la cinématique directe
/// des manipulateurs parallèles plans à trois degrés de liberté", Mech. Mach. Theory 27, 1992;
/// M. Husty, "An algorithm for solving the direct kinematics of general Stewart–Gough
/// platforms", 1996, for the planar reduction).
///
/// Modes (design parameters, never changed by the solvers):
///   working_i = ±1: RRR and П̲RR, +1 when the elbow C_i lies left of the directed line
///     A_i→P_i (the five-bar's convention); PRR, the MOMA branch β_i, q = u·(P − A) + β·√…;
///     RPR has one working mode.
///   assembly: 2 DOF, ±1, the platform point left (+1) of the directed line C₁→C₂ between the
///     circle centres (the five-bar's and MOMA's convention). 3 DOF, 1…6: without a pose to
///     follow the direct kinematics takes the assembly-th solution in order of φ; with one it
///     follows that pose's solution by continuation.
///
/// Velocities: g_i(X, q_i) = ½(|P_i − C_i|² − ρ_i²) = 0 differentiated gives
/// J_q·q̇ = J_x·Ẋ with J_q = diag(∂g_i/∂q_i) and J_x rows −∂g_i/∂X, J = J_q⁻¹·J_x. A П̲RR
/// row is multiplied by the П-joint's J = ∂d/∂θ (7), so that its J_q entry is ∂g/∂θ and its
/// J_x row carries the factor J: the П-joint's own singularity (θ = ±90°) is then a direct
/// singularity of the whole mechanism (the П-joint document, section 4).

#include "actuatorparameters.h"
#include "planarworkspace.h"
#include "text.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

namespace pkm {

enum class LegType { RRR = 0, PRR = 1, RPR = 2, PiRR = 3 };
enum class PlatformType { Point = 0, Translating = 1, Free = 2 };

struct PlanarLeg {
    LegType type = LegType::RRR;
    Eigen::Vector2d base = Eigen::Vector2d::Zero();     ///< A_i, base frame, mm
    Eigen::Vector2d platform = Eigen::Vector2d::Zero(); ///< B_i, platform frame, mm
    double crank = 80.0;  ///< r_i, mm (RRR)
    double link = 120.0;  ///< l_i, mm (RRR, PRR, П̲RR)
    double alpha = 0.0;   ///< α_i, rad: the guide (PRR) or the П-joint's base line (П̲RR)
    double lever = 170.0; ///< a_i, mm: the П-joint's crank (П̲RR)
    double ratio = 0.4;   ///< k_i = b_i/a_i of the П-joint (П̲RR)
    Interval range{10.0, 200.0}; ///< q_i limits of a slider, a strut or a П-joint's diagonal, mm
    Interval crankRange{-std::numbers::pi, std::numbers::pi}; ///< θ_i limits of an R̲RR crank, rad
    int working = +1;
    /// (cos α, sin α), worked out once by the mechanism (PlanarParallel's constructor) so that a
    /// map does not take the same sine and cosine in every cell; not finite for a leg made
    /// outside a mechanism, which then computes it (guideDirection()).
    Eigen::Vector2d guide = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());

    /// The unit vector along α: the guide of a P̲RR leg, the base line of a П̲RR one.
    Eigen::Vector2d guideDirection() const
    {
        return std::isfinite(guide.x()) ? guide : Eigen::Vector2d(std::cos(alpha), std::sin(alpha));
    }

    /// The limits of q_i: in rad for a crank, in mm otherwise (parameters theta_i_min/max and
    /// q_i_min/max, so that every parameter keeps one unit whatever the leg type).
    const Interval &inputRange() const { return type == LegType::RRR ? crankRange : range; }
};

struct PlanarParallelDesign {
    PlatformType platform = PlatformType::Point;
    /// The default is the five-bar example as two R̲RR legs (elbows out, C above BD).
    std::array<PlanarLeg, 3> legs = {
        PlanarLeg{LegType::RRR, {0.0, 0.0}, {0.0, 0.0}, 80.0, 120.0, 0.0, 170.0, 0.4, {10.0, 200.0}, {-std::numbers::pi, std::numbers::pi}, +1},
        PlanarLeg{LegType::RRR, {100.0, 0.0}, {0.0, 0.0}, 80.0, 120.0, 0.0, 170.0, 0.4, {10.0, 200.0}, {-std::numbers::pi, std::numbers::pi}, -1},
        PlanarLeg{LegType::RPR, {50.0, 150.0}, {0.0, 20.0}, 80.0, 120.0, 0.0, 170.0, 0.4, {10.0, 200.0}, {-std::numbers::pi, std::numbers::pi}, +1},
    };
    int assembly = +1;
    double mapPhi = 0.0; ///< φ of the constant-orientation workspace map of a 3-DOF platform, rad
    /// Leg i's actuator: linear (P̲RR slider, RP̲R strut, П̲RR diagonal) or rotary (R̲RR crank),
    /// as its type says; both are kept so that a change of type keeps them (assumed values:
    /// the documents give none, actuatorparameters.h).
    std::array<ActuatorSpec, 3> linearActuators = {assumedLinear, assumedLinear, assumedLinear};
    std::array<ActuatorSpec, 3> rotaryActuators = {assumedRotary, assumedRotary, assumedRotary};
    LoadSpec load; ///< the load whose deflection the capability group reports

    int legCount() const { return platform == PlatformType::Free ? 3 : 2; }
};

/// The leg model: closed forms, no validation (callers check).
namespace planar {
inline Eigen::Vector2d direction(double angle) { return {std::cos(angle), std::sin(angle)}; }
inline double cross(const Eigen::Vector2d &u, const Eigen::Vector2d &v) { return u.x() * v.y() - u.y() * v.x(); }

/// One leg at input q: its circle |P − centre| = radius and the derivatives of both by q.
struct LegCircle {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double radius = 0.0;
    Eigen::Vector2d centreRate = Eigen::Vector2d::Zero(); ///< ∂centre/∂q (П̲RR: ∂/∂θ)
    double radiusRate = 0.0;                              ///< ∂radius/∂q
    double pjointRate = 1.0; ///< П̲RR: J = ∂d/∂θ of the П-joint (7); 1 for the others
    double theta = 0.0;      ///< П̲RR: the П-joint's crank angle θ
    bool valid = true;       ///< false: the П-joint cannot take this d
};
LegCircle circle(const PlanarLeg &leg, double q);

/// П̲RR: the П-joint's θ from d (3–5) (NaN outside), d from θ (2), J = ∂d/∂θ (7).
double pjointAngle(const PlanarLeg &leg, double d);
double pjointDiagonal(const PlanarLeg &leg, double theta);
double pjointJacobian(const PlanarLeg &leg, double theta);

/// Why a platform point is not reachable by a leg in its working mode.
enum class Reach { Yes, TooFar, TooNear, Range, Undetermined };
/// Inverse kinematics of one leg in closed form: the input that puts its distal end at P in
/// the leg's working mode. For a crank (RRR, П̲RR) the angle is taken nearest `reference`.
Reach inverse(const PlanarLeg &leg, const Eigen::Vector2d &P, double reference, double &q);
/// The working mode a leg is in with input q and distal end P: +1, −1 (0: on the border).
int workingOf(const PlanarLeg &leg, double q, const Eigen::Vector2d &P);
/// The scale-free inverse-singularity margin of a leg (0 when its J_q entry vanishes).
double inverseMargin(const PlanarLeg &leg, double q, const Eigen::Vector2d &P);

/// The point P_i of the platform pose X = (x, y, φ).
Eigen::Vector2d platformPoint(const PlanarLeg &leg, const Eigen::Vector3d &X);

/// Every real solution X = (x, y, φ) of |P_i(X) − C_i| = ρ_i, i = 1, 2, 3 (the 3-RPR forward
/// problem), polished by Newton's method on these equations, in order of φ ∈ (−π, π].
std::vector<Eigen::Vector3d> threeCircleSolutions(const std::array<PlanarLeg, 3> &legs,
                                                  const std::array<LegCircle, 3> &circles);
/// The largest residual | |P_i − C_i| − ρ_i | of a pose, mm.
double residual(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles, int count,
                const Eigen::Vector3d &X);
/// The Jacobian of the circle equations ½(|P_i − C_i|² − ρ_i²) in X = (x, y, φ) (the rows of
/// J_x, each scaled by its leg's length) and, if `F` is given, their values.
Eigen::Matrix3d circleJacobian(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles,
                               const Eigen::Vector3d &X, Eigen::Vector3d *F = nullptr);
/// Newton's method on the three circle equations from X; false when it does not converge.
bool polish(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles, Eigen::Vector3d &X);
/// How a pose followed from one set of inputs to another ends.
enum class Followed {
    Along,   ///< on the same branch throughout
    Lost,    ///< the branch ends between (two assembly modes meet and vanish)
    Crossed, ///< a step reached another branch: a direct singularity lies between
};
/// Continuation: X, a solution at circlesAt(0), followed to circlesAt(1) in `steps` equal steps
/// of the inputs by Newton's method from the previous solution, the sign of the circle
/// equations' Jacobian (of det J_x's) kept.
Followed follow(const std::array<PlanarLeg, 3> &legs, const std::function<std::array<LegCircle, 3>(double)> &circlesAt,
                int steps, Eigen::Vector3d &X);
} // namespace planar

class PlanarParallel final : public TabledMechanism<PlanarParallel, PlanarParallelDesign>, public PlanarWorkspace
{
public:
    /// Validates the design and finds its home pose; the failure names the culprit.
    static Result<MechanismPtr> create(const PlanarParallelDesign &design);
    static const ParameterTable<PlanarParallelDesign> &table();

    const PlanarParallelDesign &design() const { return m_design; }
    /// The changed design, validated; when it cannot be assembled anywhere, the message names
    /// the leg that cannot reach this design's home pose and why (planardesign.cpp).
    Result<MechanismPtr> withParameters(const ParameterSet &changes) const override;
    /// Only the parameters of the legs the platform has, and of each leg only those its type
    /// uses (a crank's length for R̲RR, a guide's direction for P̲RR and П̲RR, …).
    bool parameterApplies(std::string_view name) const override;
    /// The parameter changes (core units) that give this design the platform `platform` and
    /// the leg types `types` while it holds the platform where `pose` has it: the number of
    /// legs follows the platform (a third leg, a strut, is placed opposite the other two), a
    /// leg whose type changes or that no longer reaches its platform point gets dimensions
    /// that reach it (fitLeg), and the platform points are zero for a point, a bar for a
    /// platform of constant orientation (whose legs become П̲RR unless they are P̲RR) and a
    /// triangle for a free one. The editor applies them as one step (planardesign.cpp).
    ParameterSet restructure(const Pose &pose, PlatformType platform, const std::array<LegType, 3> &types) const;
    /// `leg` as a leg of type `type` whose distal end reaches P in its working mode, away from
    /// its singular poses: the base point and the working mode are kept, the lengths and the
    /// limits scale with |P − A|.
    static PlanarLeg fitLeg(PlanarLeg leg, LegType type, const Eigen::Vector2d &P);
    std::string_view kind() const override { return "planar-parallel"; }

    const std::vector<VariableInfo> &variableInfo() const override { return m_variables; }
    Interval variableRange(int variable) const override;
    Pose homePose() const override { return m_home; }
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    Result<Pose> followDirect(const Coordinates &inputs, const Pose &current) const override;
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;
    /// Every assembly mode at these inputs in the design's working modes (3 DOF: in order of φ;
    /// 2 DOF: the design's assembly mode first), without range checks.
    std::vector<Pose> assemblies(const Coordinates &inputs) const;

    const ReportLayout &reportLayout() const override { return m_layout; }
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    Jacobians jacobians(const Pose &pose) const override;
    std::vector<ModeAlternative> modeNeighbours() const override;
    /// assemblies() at the pose's inputs: every real solution, in order of φ for 3 DOF.
    std::vector<Pose> assemblyModes(const Pose &pose) const override { return assemblies(pose.inputs); }
    const PlanarWorkspace *planarWorkspace() const override { return this; }
    KinematicChain kinematicChain(const Pose &pose) const override;

    Scene scene(const Pose &pose) const override;
    /// Handle 0 (the platform) solves the inverse problem at the target.
    Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const override;

    /// The class of a pose from the scale-free margins: per leg the inverse margin, and
    /// |det N|/Π|N_i| of J_x with each row normalised (the five-bar's and MOMA's |sin| of the
    /// angle between the distal links for 2 DOF), times |cos θ| of every П-joint.
    Singularity singularity(const Pose &pose) const;
    static constexpr double singularTolerance = 1e-7;

    // PlanarWorkspace: the point (x, y); for 3 DOF at φ = phi_map.
    Eigen::AlignedBox2d workspaceBounds() const override { return m_bounds; }
    void fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                    std::span<float> margins) const override;
    bool fillsCapabilityRows() const override { return true; }
    void fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                           std::span<float> values, std::span<float> margins) const override;
    /// Inverse curves (a leg's crank and link in line, a link ⟂ its guide) and, for 2 DOF,
    /// direct ones (the distal links in line), traced in closed form (ppcurves.cpp); for 3 DOF
    /// those of the slice at φ = phi_map (the direct ones contoured, directSlice).
    std::vector<SingularCurve> singularCurves() const override;
    bool offers(MapQuantity quantity) const override
    {
        return quantity == MapQuantity::Determinant || quantity == MapQuantity::Condition
            || (quantity == MapQuantity::OrientationRange && m_design.legCount() == 3);
    }
    /// The platform angles at which a 3-DOF platform can be held at (x, y) in the design's
    /// working modes and input ranges: up to intervals.size() disjoint intervals, each with its
    /// min in [−π, π) and its max up to min + 2π (one that runs through ±π is one interval);
    /// the count is returned. Found on a scan of φ in steps of 3°, the ends refined by bisection
    /// (an interval narrower than the step can be missed). `margin`, if given, receives the
    /// singularity margin at the middle of the widest interval (ppcurves.cpp).
    int orientationIntervals(const Eigen::Vector2d &xy, std::span<Interval> intervals, double *margin = nullptr) const;
    std::string singularityMeaning(SingularCurve::Type type) const override
    {
        return type == SingularCurve::Type::Inverse ? QT_TRANSLATE_NOOP("core", "a leg's proximal and distal links in line")
                                                    : QT_TRANSLATE_NOOP("core", "the platform gains a freedom");
    }

    /// The outputs as (x, y, φ) (φ = 0 for 2 DOF).
    Eigen::Vector3d platformPose(const Coordinates &outputs) const;

private:
    /// What designs that differ only in a 3-DOF platform's modes share while they are made
    /// (modeNeighbours): every solution of the three circles at each input the home search
    /// tries (the modes only choose among them) and, per set of working modes, the workspace
    /// bounds (found by inverse kinematics, which has no assembly mode). The designs come out
    /// exactly as create() makes them; nine searches cost little more than one.
    struct SharedSearch {
        std::map<std::tuple<double, double, double>, std::vector<Eigen::Vector3d>> solutions;
        std::map<std::array<int, 3>, std::pair<Eigen::AlignedBox2d, Eigen::AlignedBox2d>> bounds; ///< map, outputs
    };
    explicit PlanarParallel(const PlanarParallelDesign &design, SharedSearch *shared = nullptr);
    /// create() that, given the platform pose an edit starts from, takes it as the home pose
    /// when the grid of inputs finds none, and otherwise says which leg fails there.
    static Result<MechanismPtr> assemble(const PlanarParallelDesign &design, const Eigen::Vector3d *reference,
                                         SharedSearch *shared = nullptr);
    /// withParameters(), the search shared with the other designs that differ in the assembly
    /// mode only.
    Result<MechanismPtr> withParameters(const ParameterSet &changes, SharedSearch *shared) const;
    /// Why this design cannot hold the platform at X: the first leg that cannot reach it and
    /// why, or the other assembly mode (planardesign.cpp).
    std::string assemblyFailure(const Eigen::Vector3d &X) const;
    /// The Jacobians without allocation: J_q (diagonal) and J_x, n × n in the top-left corner.
    void jacobianParts(const Pose &pose, Eigen::Matrix3d &jq, Eigen::Matrix3d &jx) const;
    /// Inverse kinematics of every leg and the 2-DOF assembly check; the culprit leg on failure.
    planar::Reach inverseCheck(const Eigen::Vector3d &X, const Coordinates *reference, Coordinates &q, int &culprit) const;
    std::array<planar::LegCircle, 3> circles(const Coordinates &inputs) const;
    /// The platform pose X of `near` followed to `inputs` (planar::follow()); none where
    /// `near` is not a pose of this design at its inputs. `size`: the workspace's, mm.
    std::optional<planar::Followed> followedFrom(const Pose &near, const Coordinates &inputs, double size,
                                                 Eigen::Vector3d &X) const;
    /// One map row of `quantity` (det J, κ, or with `limits` what the actuators deliver): a
    /// 2-DOF platform's in blocks of cells, branch-free and vectorised, the rest cell by cell
    /// (ppmaprow.cpp).
    void fillRow(MapQuantity quantity, const capability::CellLimits *limits, double y, double x0, double dx,
                 std::span<float> values, std::span<float> margins) const;
    /// The det J row of a 3-DOF platform's slice at φ = phi_map, vectorised as fillRow()'s
    /// 2-DOF rows (ppmaprow3.cpp).
    /// The det J row, or with `limits` what the actuators deliver (ppmaprow3.cpp).
    void fillThreeLegDeterminantRow(double y, double x0, double dx, std::span<float> values, std::span<float> margins,
                                    const capability::CellLimits *limits = nullptr) const;
    /// One cell of a map as the pose at X (φ = phi_map for 3 DOF) evaluates it: NaN in both
    /// where the design does not reach X in its modes; `pose` is the caller's scratch.
    void mapCell(MapQuantity quantity, const capability::CellLimits *limits, const Eigen::Vector3d &X, Pose &pose,
                 float &value, float &margin) const;
    /// The box of the reference points reachable at platform angle `phi`, from a grid of
    /// `samples`² over the legs' reach, padded by two cells; empty where none is. With no
    /// samples, the legs' common reach itself (a unit box where they have none).
    Eigen::AlignedBox2d reachableBox(double phi, int samples) const;
    /// The maps' bounds: the reachable box at φ = phi_map (0 for two legs).
    Eigen::AlignedBox2d computeBounds() const;
    /// The ranges of the outputs x and y: for three legs, the reachable boxes over the whole
    /// turn of φ, with the maps' bounds.
    Eigen::AlignedBox2d computeOutputBounds() const;
    /// The direct singular curves of a 3-DOF platform's slice at φ = phi_map: the zero set of
    /// det J_x over a grid of the slice (marching squares, each crossing refined by bisection).
    void directSlice(std::vector<SingularCurve> &curves) const;
    void buildReport();

    PlanarParallelDesign m_design;
    std::vector<VariableInfo> m_variables;
    ReportLayout m_layout;
    Eigen::AlignedBox2d m_bounds;
    Eigen::AlignedBox2d m_outputBounds;
    Pose m_home;
    /// Only while the constructor searches the home pose (SharedSearch); null after.
    mutable SharedSearch *m_shared = nullptr;
};

} // namespace pkm
