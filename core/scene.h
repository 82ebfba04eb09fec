#pragma once
/// A drawable description of a mechanism in one pose, read by the 2D view, the 3D view and the
/// exporters. Coordinates in mm; the mechanism plane is z = 0, y up.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

#include <string>
#include <vector>

namespace pkm {

enum class JointKind { Ground, Revolute, Spherical, Slider, Point };
enum class BarKind { Ground, Crank, Coupler, Link, Rod, Platform };

struct SceneJoint {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    std::string label;
    JointKind kind = JointKind::Revolute;
};

struct SceneBar {
    int from = 0;
    int to = 0;
    BarKind kind = BarKind::Link;
    std::string label;
};

/// A linear actuator between two joints: a motor body of `bodyLength` × `bodyWidth` at
/// `from`, and a screw of `rodDiameter` from the body to `to`; its visible extension is the
/// distance from→to minus the body length.
struct SceneActuator {
    int from = 0;
    int to = 0;
    double bodyLength = 0.0;
    double bodyWidth = 0.0;
    double rodDiameter = 0.0;
    std::string label;
};

/// A straight guide (rail) of a slider or a linear axis, from `start` to `end` (its stroke),
/// fixed to the ground; `label` names it ("PO₁").
struct SceneGuide {
    Eigen::Vector3d start = Eigen::Vector3d::Zero();
    Eigen::Vector3d end = Eigen::Vector3d::Zero();
    double width = 12.0; ///< drawn width of the rail, mm
    std::string label;
};

/// An angle to mark with an arc at joint `vertex`: from direction angle `start` (rad, from +x,
/// counter-clockwise) over `sweep` rad (signed).
struct SceneAngle {
    int vertex = 0;
    double start = 0.0;
    double sweep = 0.0;
    double radius = 0.0; ///< preferred arc radius, mm
    std::string label;   ///< "θ = 12.0°" (text::fixed for a pose value: the locale's decimal point)
};

/// A dimension line between two joints, offset sideways by `offset` mm (positive: to the left
/// of from→to), with its text.
struct SceneDimension {
    int from = 0;
    int to = 0;
    double offset = 0.0;
    std::string text; ///< "b = 68 mm", translated
};

/// A joint the user may drag; the mechanism's dragHandle() turns the target into a pose.
///
/// An attachment point (a base or platform point of the design) is a handle that edits the
/// design instead: dragging it to a target T sets the parameters `xParameter`, `yParameter`
/// (mm) to R(−frameAngle)·(T − frameOrigin), the target in the frame the point is given in
/// (the base frame: origin 0, angle 0; a platform frame: the platform's pose). The document
/// makes one undoable step of the whole drag.
struct SceneHandle {
    int joint = 0;
    std::string hint; ///< what dragging does ("drag to set θ"), translated
    std::string xParameter {}; ///< empty: a pose handle
    std::string yParameter {};
    Eigen::Vector2d frameOrigin = Eigen::Vector2d::Zero();
    double frameAngle = 0.0; ///< rad

    bool editsDesign() const { return !xParameter.empty(); }
    /// The parameter values (mm) that put the point at `target`.
    Eigen::Vector2d designPoint(const Eigen::Vector2d &target) const
    {
        const double c = std::cos(frameAngle), s = std::sin(frameAngle);
        const Eigen::Vector2d d = target - frameOrigin;
        return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
    }
};

/// What a polyline shows: a path of the mechanism, or one of the actuators' capability
/// shapes at the platform point (capabilityshapes.h), drawn to the scale the legend gives.
enum class PathKind {
    Path,
    VelocityPolygon, ///< the exact velocity polygon, solid
    VelocityEllipse, ///< the velocity ellipse inscribed in it, dashed
    ForcePolygon,
    ForceEllipse,
};

/// A polyline in the mechanism plane (a coupler curve, a trajectory), drawn thin; `closed`
/// joins the last point to the first.
struct ScenePolyline {
    std::vector<Eigen::Vector3d> points;
    bool closed = false;
    std::string label;
    PathKind kind = PathKind::Path;
};

/// A line of the drawing's legend: what the shapes of `kind` are and their scale ("velocity:
/// 10 mm ≙ 50 mm/s"), translated.
struct SceneLegendEntry {
    PathKind kind = PathKind::Path;
    std::string text;
};

struct Scene {
    std::vector<SceneJoint> joints;
    std::vector<SceneBar> bars;
    std::vector<SceneActuator> actuators;
    std::vector<SceneGuide> guides;
    std::vector<SceneAngle> angles;
    std::vector<SceneDimension> dimensions;
    std::vector<SceneHandle> handles;
    std::vector<ScenePolyline> polylines;
    std::vector<SceneLegendEntry> legend; ///< drawn in a corner by the views and pictures
    /// Box holding the mechanism over its whole range of motion, so "fit" does not jump.
    Eigen::AlignedBox3d extent;
    /// Where set, the box of this pose alone, for a mechanism whose range of motion is far
    /// larger than itself: the screen fits it first, so that the mechanism is drawn large, and
    /// widens towards `extent` only when a move would take the mechanism out of sight.
    /// Pictures and animation frames keep `extent`, so that frames share one scale.
    Eigen::AlignedBox3d poseExtent;
};

/// Which joints a drawing or a model shows: all but a free point (an instantaneous centre)
/// that no link, actuator, dimension or angle uses and that lies outside the range of motion
/// by more than `margin` times the extent's size, which would stretch the picture to the
/// horizon. The DXF drawing allows half its size; the 3D model none, since its camera is fitted
/// to the extent once for every pose.
std::vector<bool> shownJoints(const Scene &scene, double margin = 0.5);

/// The box of the scene's joints as they are (not its points of interest), with a margin of
/// `margin` times its larger side all round: a Scene::poseExtent.
Eigen::AlignedBox3d poseBox(const Scene &scene, double margin = 0.2);

} // namespace pkm
