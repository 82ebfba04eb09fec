#pragma once
/// A solid model of a mechanism in one pose, read by the 3D view and its picture export:
/// boxes, cylinders and spheres in mm, each with the role that gives it its colour.
///
/// Frame: the 2D scene's frame (the mechanism plane is z = 0, x right, y up) extended by z
/// towards the viewer; a mechanism with depth (the O-X glide's stacked guides, the П-joint's
/// two parallelograms) uses z for it.

#include "scene.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace pkm {

/// What a part is; the renderer picks its colour and finish from this.
enum class PartRole {
    Ground,       ///< frame, base plate, supports
    Guide,        ///< a rail a slider runs on
    Slider,       ///< a carriage on a guide
    Link,         ///< a rigid link or bar (crank, coupler, rocker, lever)
    Rod,          ///< a rod of constant length between two spherical or revolute joints
    Platform,     ///< the moving platform / end effector
    Joint,        ///< a pin or ball of a joint
    Actuator,     ///< a motor body
    Screw,        ///< a lead screw or the moving part of a linear actuator
    Compensation, ///< an element that brings a joint into the mechanism plane (O-X glide)
    Marker,       ///< a point of interest (tool centre, coupler point)
};

struct Solid {
    enum class Shape { Box, Cylinder, Sphere };
    Shape shape = Shape::Box;
    /// Box and Cylinder: the end points of the centre line; Sphere: `from` is the centre.
    Eigen::Vector3d from = Eigen::Vector3d::Zero();
    Eigen::Vector3d to = Eigen::Vector3d::Zero();
    /// Cylinder and Sphere radius, mm.
    double radius = 1.0;
    /// Box: its size across the centre line, (width, height) in mm; the height is measured
    /// along `up` (made perpendicular to the centre line), the width along centre × up.
    Eigen::Vector2d section = Eigen::Vector2d(1.0, 1.0);
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    PartRole role = PartRole::Link;
    std::string label; ///< what it is ("guide C", "rod A"), translated, for picking and tooltips

    static Solid box(const Eigen::Vector3d &from, const Eigen::Vector3d &to, double width, double height,
                     const Eigen::Vector3d &up, PartRole role, std::string label = {})
    {
        Solid s;
        s.shape = Shape::Box;
        s.from = from;
        s.to = to;
        s.section = {width, height};
        s.up = up;
        s.role = role;
        s.label = std::move(label);
        return s;
    }
    static Solid cylinder(const Eigen::Vector3d &from, const Eigen::Vector3d &to, double radius, PartRole role,
                          std::string label = {})
    {
        Solid s;
        s.shape = Shape::Cylinder;
        s.from = from;
        s.to = to;
        s.radius = radius;
        s.role = role;
        s.label = std::move(label);
        return s;
    }
    static Solid sphere(const Eigen::Vector3d &centre, double radius, PartRole role, std::string label = {})
    {
        Solid s;
        s.shape = Shape::Sphere;
        s.from = centre;
        s.to = centre;
        s.radius = radius;
        s.role = role;
        s.label = std::move(label);
        return s;
    }
};

/// A name drawn beside a point of the model ("A", "Z₁", "P"): the 2D scene's joint labels, so
/// that the 3D view names the points the equations and the 2D view name.
struct Label3D {
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    std::string text;
    /// A corner of a platform (an end of a platform bar): the corners of a platform drawn too
    /// small for a name at each go unnamed, as in the 2D view.
    bool platformCorner = false;
};

struct Scene3D {
    std::vector<Solid> solids;
    std::vector<Label3D> labels;
    /// Box holding the model over the whole range of motion, so "fit" does not jump as the
    /// pose changes.
    Eigen::AlignedBox3d extent;
};

/// A solid model built from a 2D scene: bars as flat links of `thickness`, joints as pins
/// (balls for spherical joints), guides as rails with a carriage on each slider joint, and
/// actuators as a motor body with its screw; the extent is the 2D extent thickened in z. For
/// mechanisms that have no model of their own.
Scene3D extrudeScene(const Scene &scene, double thickness);

/// The named joints of a 2D scene as labels of its 3D model `solids` (whose frame is the
/// scene's, see above): each name once, at its joint. Joints without a name or position, and
/// points the model does not reach (a four-bar's pole far off), are left out.
std::vector<Label3D> jointLabels(const Scene &scene, const std::vector<Solid> &solids);

/// The orthonormal frame of a solid's centre line: `axis` from `from` to `to` (+x when they
/// coincide), `up` the solid's up made perpendicular to it, `width` = axis × up.
struct SolidFrame {
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    Eigen::Vector3d width = Eigen::Vector3d::UnitZ();
    double length = 0.0; ///< |to − from|, mm
};
SolidFrame solidFrame(const Solid &solid);
/// The exact axis-aligned bounding box of a solid, mm.
Eigen::AlignedBox3d solidBounds(const Solid &solid);

} // namespace pkm
