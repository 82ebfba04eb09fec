#pragma once
/// Mobility (degrees of freedom) of a kinematic chain (docs/mathematics.md), two ways:
///
/// Structural formulas, from the numbers of links and pairs alone:
///   Chebyshev (planar chains):  W = 3n − 2P₅ − P₄
///     n moving links, P₅ lower pairs (R, P: one freedom left in the plane), P₄ planar higher
///     pairs (CamPlanar: two freedoms in the plane).
///   Somov–Malyshev (spatial):   W = 6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁
///     P_c the pairs of class c (a pair of class c leaves 6 − c freedoms: R, P, screw are P₅,
///     cylindrical P₄, spherical P₃). The four-bar and mobility document prints "+P₁", a typo (docs/mathematics.md):
///     documentSomovMalyshev() keeps it for the test that shows it wrong.
///   Both count 6 (or 3) independent constraints per loop, so both fail for overconstrained
///   ("paradoxical") chains whose loops impose fewer: the spatial parallelogram, the Bennett
///   linkage, and every planar chain for Somov–Malyshev.
///
/// Numerical mobility, from the rank of the loop-closure (constraint) Jacobian at a pose:
///   The links are the vertices and the pairs the edges of a graph; a spanning tree from the
///   ground leaves L = pairs − links + components chords, one independent loop each. Every
///   freedom of a pair is a unit twist ξ = (ω; v) in the mechanism frame, the motion of link2
///   relative to link1, v being the velocity of the body point at the origin:
///     revolute R      ξ = (a; p × a)                   (axis a through the point p)
///     prismatic P     ξ = (0; a)
///     screw H         ξ = (a; p × a + h·a)             (pitch h, mm/rad)
///     cylindrical C   R and P on the same axis
///     spherical S     three R through the centre p, along x, y and z
///     CamPlanar       R about z through the contact point p, and P along z × n, where the
///                     pair's `axis` is the common normal n of the contact (in the plane z = 0)
///   Loop k (the chord c from link u to link v) closes when the velocity of v reached through
///   the tree equals the one reached through c:
///     Σ_{tree path to u} ξ_j·q̇_j + Σ_{c} ξ_c·q̇_c − Σ_{tree path to v} ξ_j·q̇_j = 0,
///   six rows per loop (ω first, then v). Stacked: the 6L × F matrix J, F = Σ freedoms.
///   Mobility M = F − rank J; redundant (overconstraint) equations 6L − rank J. Since
///   Somov–Malyshev's W = F − 6L, M = W + (6L − rank J): the formula is right exactly when
///   no loop equation is redundant. For planar chains the rows ω_z, v_x, v_y are the planar
///   loop equations (the others vanish): 3L − their rank are the planar redundancies, and
///   M = Chebyshev's W + (3L − planar rank).
///
/// Units and tolerance: the analysis moves the origin to the centroid of the pair points and
/// divides lengths by the chain's size ℓ (the largest distance of a pair point from the
/// centroid), so the moment rows are dimensionless and the prismatic freedoms are measured in
/// ℓ: the rank does not depend on the unit of length. A singular value counts when it exceeds
/// `tolerance`·σ_max (default 10⁻⁶: a geometric defect of one part per million of the size).
///
/// Instantaneous and finite mobility: at a singular pose the rank drops and F − rank is only
/// the instantaneous (first-order) mobility. analyseMobility() therefore also steps from the
/// pose along a few random first-order motions, brings the chain back onto its loop closures
/// (Newton on the finite displacements: products of exponentials of the twists) and takes the
/// rank there: that is the mobility (finite, near the pose); the pose is singular when the
/// instantaneous one is larger. With the actuated pairs locked the same is done for the
/// passive freedoms: a mechanism controlled by its actuators keeps no freedom (idle ones
/// apart); keeping one at this pose only is a direct singularity (a four-bar at its dead
/// point, MOMA with its links in line).

#include "kinematicchain.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>

namespace pkm {

/// Numbers of pairs by class: [c] = P_c for c = 1…5; [0] is unused (always 0).
using PairClassCounts = std::array<int, 6>;

/// The mobility of a chain at a pose: the formulas and the rank (see the top of this header).
struct MobilityReport {
    bool valid = false; ///< false: no chain, or an inconsistent one (the verdict says why)
    bool planar = false; ///< the chain says all its links move in parallel planes
    int movingLinks = 0; ///< n
    PairClassCounts pairsByClass {}; ///< P₁…P₅
    int pairs = 0;
    int loops = 0; ///< L, independent loops
    int freedoms = 0; ///< F, freedoms of all pairs
    std::optional<int> chebyshev; ///< W = 3n − 2P₅ − P₄; planar chains of R, P, CamPlanar only
    int somovMalyshev = 0; ///< W = 6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁
    int rank = 0; ///< rank of the 6L × F constraint Jacobian at the pose
    int numerical = 0; ///< F − rank: the instantaneous mobility at the pose
    int mobility = 0; ///< F − rank at regular poses next to this one: the finite mobility
    bool singular = false; ///< numerical > mobility: the rank drops at this pose
    int redundantConstraints = 0; ///< 6L − rank (near the pose) = mobility − somovMalyshev
    std::optional<int> planarRedundantConstraints; ///< 3L − planar rank = mobility − chebyshev
    int idleFreedoms = 0; ///< counted in all the numbers above, reported apart
    int actuators = 0; ///< freedoms of the actuated pairs
    int lockedMobility = 0; ///< instantaneous mobility at the pose with the actuators locked
    int lockedMobilityNearby = 0; ///< the same near the pose
    /// The actuators determine the motion, and each is needed: mobility − idle = actuators and
    /// nothing but idle freedoms moves with them locked (near the pose).
    bool fullyActuated = false;
    bool chebyshevFails = false; ///< planar: Chebyshev's W ≠ mobility
    bool somovMalyshevFails = false; ///< Somov–Malyshev's W ≠ mobility
    bool formulaFails = false; ///< either formula fails for this chain
    std::string verdict; ///< one sentence for the classroom, translated (English without text hooks)
};

namespace mobility {

/// Default relative rank tolerance (see the top of this header).
inline constexpr double defaultTolerance = 1e-6;

/// The class c of a pair (6 − its freedoms): 5 for R, P, screw; 4 for C and CamPlanar; 3 for S.
int pairClass(PairType type);
/// The freedoms a pair leaves, 6 − class.
int pairFreedoms(PairType type);
/// P₁…P₅ of a chain.
PairClassCounts countPairs(const KinematicChain &chain);

/// Chebyshev: W = 3n − 2P₅ − P₄.
int chebyshev(int movingLinks, int lowerPairs, int higherPairs);
/// Chebyshev of a planar chain of R, P and CamPlanar pairs; empty for any other chain.
std::optional<int> chebyshev(const KinematicChain &chain);
/// Somov–Malyshev: W = 6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁.
int somovMalyshev(int movingLinks, const PairClassCounts &pairs);
/// The four-bar and mobility document as printed: W = 6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ + P₁ — wrong (docs/mathematics.md).
int documentSomovMalyshev(int movingLinks, const PairClassCounts &pairs);

/// The constraint Jacobian of a chain at its pose, in the scaled frame (see above).
struct ConstraintJacobian {
    Eigen::MatrixXd matrix; ///< 6L × F; rows ω then v per loop, ℓ-scaled
    std::vector<int> columnPair; ///< the pair of each column
    int loops = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< the centroid of the pair points, mm
    double size = 1.0; ///< ℓ, mm
};
/// Empty (0 × 0) when the chain is inconsistent (a pair naming a missing link, a zero axis).
ConstraintJacobian constraintJacobian(const KinematicChain &chain);
/// Singular values above tolerance·σ_max.
int numericalRank(const Eigen::MatrixXd &matrix, double tolerance = defaultTolerance);

// -- building chains ------------------------------------------------------------------------

/// A pair of `type` joining link1 and link2 with its axis through `point` (mm).
KinematicPair makePair(PairType type, std::string name, int link1, int link2, const Eigen::Vector3d &point,
    const Eigen::Vector3d &axis = Eigen::Vector3d::UnitZ(), bool actuated = false);
/// A revolute pair of a planar chain: axis z through (point, 0).
KinematicPair planarRevolute(
    std::string name, int link1, int link2, const Eigen::Vector2d &point, bool actuated = false);
/// A prismatic pair of a planar chain: sliding along `direction` (in the plane), through (point, 0).
KinematicPair planarPrismatic(std::string name, int link1, int link2, const Eigen::Vector2d &point,
    const Eigen::Vector2d &direction, bool actuated = false);

// -- classroom chains -----------------------------------------------------------------------

/// The П-joint's hinged parallelogram O, B, A, C as a spatial chain of four parallel R axes
/// (z): O = (0,0,0), B = (b,0,0), A = B + a·(sin θ, cos θ, 0), C = O + a·(sin θ, cos θ, 0).
/// planar = false, so only Somov–Malyshev applies: W = 6·3 − 5·4 = −2, the rank gives 1.
KinematicChain spatialParallelogram(double a, double b, double theta);

/// Denavit–Hartenberg: Rz(θ)·Tz(d)·Tx(a)·Rx(α), the frame of link i in the frame of link i−1.
Eigen::Isometry3d denavitHartenberg(double theta, double d, double a, double alpha);
/// The joint angles θ₁…θ₄ of the Bennett linkage at input θ₁: link lengths a, b, a, b with
/// twists α, β, α, β (a/sin α = b/sin β), offsets 0. The closure of
/// DH(θ₁,0,a,α)·DH(θ₂,0,b,β)·DH(θ₃,0,a,α)·DH(θ₄,0,b,β) = I gives
///   tan(θ₁/2)·tan(θ₂/2) = sin((β + α)/2) / sin((β − α)/2),  θ₃ = −θ₁,  θ₄ = −θ₂.
std::array<double, 4> bennettAngles(double alpha, double beta, double theta1);
/// The Bennett linkage at input θ₁ (b = a·sin β / sin α): joint i on the z axis of frame i−1
/// (frame 0 the ground's). Somov–Malyshev: 6·3 − 5·4 = −2; the rank gives 1.
KinematicChain bennettLinkage(double a, double alpha, double beta, double theta1);
/// A spatial 4R loop with random axes (lines through points in a cube of edge `size`, mm):
/// not a Bennett linkage, so the rank is 4 and the chain cannot move (M = 0). Deterministic
/// for a seed.
KinematicChain randomSpatial4R(unsigned seed, double size = 100.0);
/// The planar five-bar with joints A, B, C, D, E (A, E on the ground, cranks AB and ED driven,
/// distal links BC and DC): Chebyshev W = 3·4 − 2·5 = 2.
KinematicChain planarFiveBar(const std::array<Eigen::Vector2d, 5> &joints);

} // namespace mobility

/// The formulas, the rank at the pose and near it, and the verdict. `tolerance`: see above.
MobilityReport analyseMobility(const KinematicChain &chain, double tolerance = mobility::defaultTolerance);

} // namespace pkm
