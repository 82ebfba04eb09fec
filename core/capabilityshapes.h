#pragma once
/// The actuators' capability drawn at the platform point: the exact velocity and force
/// polygons of capability.h (for a 3-DOF platform their translational sections: no rotation,
/// no moment) and the ellipses inscribed in them, to a scale fixed once per design, so that
/// during a drag or Play the shapes grow and shrink truly (docs/mathematics.md, "Actuator
/// capability").
///
/// Both polygons are intersections of slabs |a_i·v| ≤ b_i (velocity: a_i the rows of J and
/// b_i the speed limits; force: a_i the columns of G = J⁻¹ and b_i the force limits). The
/// ellipse {v : Σ (a_i·v / b_i)² ≤ 1} lies inside every slab, so inside the polygon; with two
/// actuators it touches every edge at its middle, with three the polygon lies within √3 times it. Where the slab form's matrix is
/// unbounded (J at an inverse singularity, G at a direct one) a 2-actuator polygon is drawn as
/// the image of the actuator box instead (velocity G·box, force Jᵀ·box), which stays finite:
/// it collapses onto a segment there. A shape that is unbounded is cut by a clip box and says
/// so in the legend.

#include "capability.h"
#include "scene.h"

#include <Eigen/Core>

#include <vector>

namespace pkm::capability {

/// One quantity's polygon and ellipse in platform units (mm/s or N), about the origin.
struct Shape {
    std::vector<Eigen::Vector2d> polygon; ///< counter-clockwise; empty: none to draw
    std::vector<Eigen::Vector2d> ellipse; ///< closed outline; empty: none
    bool unbounded = false;               ///< cut by the clip box: infinite in some direction
};

struct Shapes {
    Shape velocity;
    Shape force;
};

/// The drawing scales of a design: mm of drawing per mm/s and per N, and the half-size of the
/// clip box around the platform point, mm of drawing. Zero scales: nothing is drawn (an output
/// that is an angle, or actuators without limits).
struct ShapeScales {
    double velocity = 0.0;
    double force = 0.0;
    double clip = 0.0;
    double velocityUnits = 0.0; ///< mm/s shown by 1 mm of drawing (a 1/2/5·10ⁿ number)
    double forceUnits = 0.0;    ///< N shown by 1 mm of drawing
    bool valid() const { return velocity > 0.0 && force > 0.0; }
};

/// The shapes at a pose from J_q and J_x (as capability::evaluate() takes them). `velocityClip`
/// and `forceClip` are the clip box's half-sizes in platform units. Does not allocate beyond
/// the shapes' point lists.
Shapes shapesOf(const Actuators &actuators, const Matrix &jq, const Matrix &jx, SingularityType type,
                double velocityClip, double forceClip);

/// The exact polygons at `pose` for a report (pkm eval's "velocity_polygon" and
/// "force_polygon"), in mm/s and N: a polygon that is unbounded at this pose comes back empty
/// with `unbounded` set, one that is undefined empty without it. Nothing (both empty, not
/// unbounded) where the output is not a point of the plane or there are fewer than two
/// actuators. Allocates (Mechanism::jacobians()).
Shapes polygonsAt(const Mechanism &mechanism, const Actuators &actuators, const Pose &pose, SingularityType type);

/// Scales for a design: the fastest and strongest directions at the home pose drawn about
/// 0.3 of the size of the mechanism's extent, rounded so that the legend reads 1/2/5·10ⁿ.
ShapeScales scalesFor(const Mechanism &mechanism, const Actuators &actuators);

/// Adds the velocity and force shapes at the pose's platform point to `scene` (polylines of the
/// capability kinds) and their legend lines, translated. Nothing when the scales are not valid
/// or the pose is not a pose of the mechanism.
void addShapes(Scene &scene, const Mechanism &mechanism, const Actuators &actuators, const ShapeScales &scales,
               const Pose &pose, SingularityType type);

} // namespace pkm::capability
