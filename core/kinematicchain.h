#pragma once
/// The structure of a mechanism as links and kinematic pairs, with each pair's axis at a pose:
/// what the mobility analysis counts (Chebyshev, Somov–Malyshev) and what it ranks (the screw
/// constraint Jacobian of the loops). See mobility.h and docs/mathematics.md.
///
/// Units: mm. Axes are in the mechanism's 3D frame (the frame of scene3d(); planar mechanisms
/// lie in the plane z = 0 with their revolute axes along z).

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pkm {

/// The kinematic pairs the counts distinguish, by the freedom they leave (class = 6 − freedom).
enum class PairType {
    Revolute,    ///< 1 DOF, class 5 (P₅), lower pair
    Prismatic,   ///< 1 DOF, class 5 (P₅), lower pair
    Screw,       ///< 1 DOF, class 5 (P₅): rotation and translation coupled by `pitch` (mm/rad)
    Cylindrical, ///< 2 DOF, class 4 (P₄)
    Spherical,   ///< 3 DOF, class 3 (P₃)
    CamPlanar,   ///< planar higher pair (rolling with slipping): 2 DOF, class 4 (P₄)
};

struct KinematicPair {
    std::string name;             ///< "A", "slider 1", "rod end"
    PairType type = PairType::Revolute;
    int link1 = 0;                ///< link indices into KinematicChain::links; 0 is the ground
    int link2 = 0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< a point on the axis (the centre of a sphere), mm
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< unit direction of the axis (R, P, screw, C)
    double pitch = 0.0;           ///< Screw pairs: mm of travel per radian
    bool actuated = false;        ///< driven by an actuator
};

struct KinematicChain {
    /// Link names, the ground first ("ground", "crank AB", …), translated (text::translate).
    std::vector<std::string> links;
    std::vector<KinematicPair> pairs;
    /// All links move in parallel planes (Chebyshev's formula applies).
    bool planar = true;
    /// Freedoms that do not move the mechanism's other links (a rod spinning about its own axis
    /// between two spheres): counted by the formulas, reported apart.
    int idleFreedoms = 0;
    /// A short description for reports ("planar four-bar: ground, crank, coupler, rocker"),
    /// translated.
    std::string description;
    /// Why the mechanism keeps freedoms with its actuators locked, where its model knows (the
    /// O-X glide's platform tilt), translated: the mobility panel adds it when the rank says
    /// the mechanism is under-actuated.
    std::string underActuation;

    int movingLinks() const { return static_cast<int>(links.size()) - 1; }
};

} // namespace pkm
