#pragma once
/// The 3D view's camera as pure maths (no GL, no widget), so it is unit tested: a turntable
/// orbit about a target, pan, zoom towards the cursor, fitting a box, the standard views, and
/// projection of points to pixels and pixels to rays for picking.
///
/// Frame (core/scene3d.h): x right, y up, the mechanism plane z = 0 with +z towards the viewer
/// of the Front view, which looks along −z and so shows the 2D view's picture. Top looks down
/// along −y (the front at the bottom of the screen), Side along −x, Isometric from (+x, +y, +z).
///
/// Pixels are the viewport's logical pixels: x right, y down, (0, 0) at the top-left corner.
/// Angles are radians unless the name says degrees.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <numbers>
#include <optional>
#include <vector>

namespace pkm {

class Camera3D
{
public:
    enum class Projection { Perspective, Orthographic };
    enum class StandardView { Front, Top, Side, Isometric };

    /// A half line through a pixel: every point origin + s·direction (s ≥ 0) projects to it.
    struct Ray {
        Eigen::Vector3d origin = Eigen::Vector3d::Zero();
        Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ(); ///< unit
        Eigen::Vector3d at(double s) const { return origin + s * direction; }
    };

    static constexpr double maximumPitch = 89.5 * std::numbers::pi / 180.0; ///< orbit stops here
    static constexpr double orbitRadiansPerPixel = 0.4 * std::numbers::pi / 180.0;
    static constexpr double zoomStep = 1.2; ///< distance factor per wheel notch
    static constexpr double fitMargin = 0.06; ///< of the viewport's half size, each side

    Camera3D();

    // -- state ----------------------------------------------------------------------------
    const Eigen::Vector3d &target() const { return m_target; }
    void setTarget(const Eigen::Vector3d &target) { m_target = target; }
    /// From the target to the eye, mm (in orthographic also the scale: see halfHeight()).
    double distance() const { return m_distance; }
    void setDistance(double distance);
    /// Turn about world +y; 0 looks along −z.
    double yaw() const { return m_yaw; }
    /// Elevation of the eye above the target's horizontal plane, in [−90°, 90°].
    double pitch() const { return m_pitch; }
    /// Sets yaw and pitch; the pitch is clamped to [−90°, 90°] (the standard Top view is 90°).
    void setOrientation(double yaw, double pitch);
    /// Vertical field of view of the perspective projection, degrees.
    double fieldOfViewDegrees() const { return m_fieldOfViewDegrees; }
    void setFieldOfViewDegrees(double degrees);
    Projection projection() const { return m_projection; }
    /// Keeps target and distance, so the target plane keeps its scale in both projections.
    void setProjection(Projection projection) { m_projection = projection; }
    /// Viewport in logical pixels; sets the aspect ratio.
    void setViewport(int width, int height);
    int viewportWidth() const { return m_viewportWidth; }
    int viewportHeight() const { return m_viewportHeight; }
    double aspect() const { return double(m_viewportWidth) / double(m_viewportHeight); }
    /// The box that must never be clipped by the near and far planes (fit() extends it).
    void setClipBounds(const Eigen::AlignedBox3d &bounds) { m_clipBounds = bounds; }
    const Eigen::AlignedBox3d &clipBounds() const { return m_clipBounds; }

    // -- derived --------------------------------------------------------------------------
    Eigen::Vector3d eye() const { return m_target + m_distance * back(); }
    /// Unit vectors of the camera frame in world coordinates: right × up = back.
    Eigen::Vector3d right() const;
    Eigen::Vector3d up() const;
    /// From the target towards the eye; the camera looks along −back().
    Eigen::Vector3d back() const;
    Eigen::Vector3d viewDirection() const { return -back(); }
    /// Half the height of the view at the target's depth, mm: the orthographic scale.
    double halfHeight() const;
    /// World mm per viewport pixel at the target's depth.
    double millimetresPerPixel() const { return 2.0 * halfHeight() / double(m_viewportHeight); }
    /// Depth of a world point in front of the eye along the view direction, mm.
    double depth(const Eigen::Vector3d &point) const { return (eye() - point).dot(back()); }

    /// World → eye: a rigid transform (rotation and translation).
    Eigen::Matrix4d viewMatrix() const;
    /// Eye → clip, OpenGL conventions; near and far hold clipBounds() with a margin.
    Eigen::Matrix4d projectionMatrix() const;
    /// Near and far plane distances along the view direction (orthographic: may be negative).
    Eigen::Vector2d nearFar() const;

    /// The pixel a world point projects to; `depth`, when given, gets its NDC depth in [−1, 1].
    Eigen::Vector2d project(const Eigen::Vector3d &point, double *ndcDepth = nullptr) const;
    /// The ray through a pixel: from the eye (perspective) or from the eye's plane (orthographic).
    Ray ray(const Eigen::Vector2d &pixel) const;
    /// The world point under `pixel` at the target's depth.
    Eigen::Vector3d pointAtTargetDepth(const Eigen::Vector2d &pixel) const;

    // -- navigation -----------------------------------------------------------------------
    /// Turntable: a drag of dx pixels turns about world y, dy tilts (pitch kept within
    /// ±maximumPitch); the target and the distance stay.
    void orbit(double dxPixels, double dyPixels);
    /// Moves target and eye across the view so that the point under the cursor at the
    /// target's depth follows the cursor.
    void pan(double dxPixels, double dyPixels, double viewportHeight);
    void pan(double dxPixels, double dyPixels) { pan(dxPixels, dyPixels, m_viewportHeight); }
    /// Zooms in by zoomStep per step (negative: out). With a cursor pixel the camera moves
    /// towards the point under the cursor at the target's depth, which stays under the cursor.
    void zoom(double steps, const std::optional<Eigen::Vector2d> &cursorPixel = std::nullopt);
    /// Keeps the view direction, centres the box and sets the distance so that all of it is
    /// inside the viewport with fitMargin to spare, in the current projection. Extends
    /// clipBounds() by the box. An empty box changes nothing.
    void fit(const Eigen::AlignedBox3d &box);
    /// As fit(box), for the points themselves (a model's vertices): the view is centred on
    /// their projected outline rather than on a box around them, so a tall or slanted model
    /// seen from an angle fills the view instead of a box corner's worth of empty space.
    void fitPoints(const std::vector<Eigen::Vector3d> &points);
    /// Sets the orientation of a standard view; target and distance stay (fit() after it).
    void setStandardView(StandardView view);
    static void standardOrientation(StandardView view, double &yaw, double &pitch);

private:
    /// The distance limits for zooming, from the clip bounds' size.
    Eigen::Vector2d distanceRange() const;

    Eigen::Vector3d m_target = Eigen::Vector3d::Zero();
    double m_distance = 500.0;
    double m_yaw = 0.0;
    double m_pitch = 0.0;
    double m_fieldOfViewDegrees = 30.0;
    Projection m_projection = Projection::Perspective;
    int m_viewportWidth = 800;
    int m_viewportHeight = 600;
    Eigen::AlignedBox3d m_clipBounds;
};

} // namespace pkm
