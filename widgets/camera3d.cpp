#include "camera3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {

constexpr double pi = std::numbers::pi;

/// The 8 corners of a box.
template<class F> void forCorners(const Eigen::AlignedBox3d &box, F &&f)
{
    for (int i = 0; i < 8; ++i)
        f(box.corner(Eigen::AlignedBox3d::CornerType(i)));
}

} // namespace

Camera3D::Camera3D()
{
    setStandardView(StandardView::Front);
}

void Camera3D::setDistance(double distance)
{
    if (std::isfinite(distance))
        m_distance = std::max(distance, 1e-6);
}

void Camera3D::setOrientation(double yaw, double pitch)
{
    if (std::isfinite(yaw))
        m_yaw = std::remainder(yaw, 2.0 * pi);
    if (std::isfinite(pitch))
        m_pitch = std::clamp(pitch, -0.5 * pi, 0.5 * pi);
}

void Camera3D::setFieldOfViewDegrees(double degrees)
{
    if (std::isfinite(degrees))
        m_fieldOfViewDegrees = std::clamp(degrees, 1.0, 120.0);
}

void Camera3D::setViewport(int width, int height)
{
    m_viewportWidth = std::max(width, 1);
    m_viewportHeight = std::max(height, 1);
}

Eigen::Vector3d Camera3D::back() const
{
    return {std::sin(m_yaw) * std::cos(m_pitch), std::sin(m_pitch), std::cos(m_yaw) * std::cos(m_pitch)};
}

Eigen::Vector3d Camera3D::right() const
{
    // Depends on the yaw only, so the frame stays defined looking straight down.
    return {std::cos(m_yaw), 0.0, -std::sin(m_yaw)};
}

Eigen::Vector3d Camera3D::up() const
{
    return back().cross(right());
}

double Camera3D::halfHeight() const
{
    return m_distance * std::tan(0.5 * m_fieldOfViewDegrees * pi / 180.0);
}

Eigen::Matrix4d Camera3D::viewMatrix() const
{
    Eigen::Matrix3d rotation; // rows: the camera axes in world coordinates
    rotation.row(0) = right().transpose();
    rotation.row(1) = up().transpose();
    rotation.row(2) = back().transpose();
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.topLeftCorner<3, 3>() = rotation;
    view.topRightCorner<3, 1>() = -rotation * eye();
    return view;
}

Eigen::Vector2d Camera3D::nearFar() const
{
    double nearest = 0.0, farthest = 0.0;
    if (m_clipBounds.isEmpty()) {
        nearest = 0.01 * m_distance;
        farthest = 100.0 * m_distance;
    } else {
        nearest = std::numeric_limits<double>::infinity();
        farthest = -nearest;
        forCorners(m_clipBounds, [&](const Eigen::Vector3d &corner) {
            const double d = depth(corner);
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        });
        const double pad = 0.02 * (farthest - nearest) + 1e-3 * m_distance;
        nearest -= pad;
        farthest += pad;
    }
    if (m_projection == Projection::Perspective) {
        // The eye may be inside the box: keep the depth buffer's range finite.
        farthest = std::max(farthest, 2e-3 * m_distance);
        nearest = std::max(nearest, 1e-3 * farthest);
    }
    return {nearest, farthest};
}

Eigen::Matrix4d Camera3D::projectionMatrix() const
{
    const Eigen::Vector2d range = nearFar();
    const double n = range.x(), f = range.y();
    Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
    if (m_projection == Projection::Perspective) {
        const double focal = 1.0 / std::tan(0.5 * m_fieldOfViewDegrees * pi / 180.0);
        projection(0, 0) = focal / aspect();
        projection(1, 1) = focal;
        projection(2, 2) = (f + n) / (n - f);
        projection(2, 3) = 2.0 * f * n / (n - f);
        projection(3, 2) = -1.0;
    } else {
        const double h = halfHeight(), w = h * aspect();
        projection(0, 0) = 1.0 / w;
        projection(1, 1) = 1.0 / h;
        projection(2, 2) = -2.0 / (f - n);
        projection(2, 3) = -(f + n) / (f - n);
        projection(3, 3) = 1.0;
    }
    return projection;
}

Eigen::Vector2d Camera3D::project(const Eigen::Vector3d &point, double *ndcDepth) const
{
    const Eigen::Vector4d clip = projectionMatrix() * viewMatrix() * point.homogeneous();
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    if (ndcDepth)
        *ndcDepth = ndc.z();
    return {0.5 * (ndc.x() + 1.0) * m_viewportWidth, 0.5 * (1.0 - ndc.y()) * m_viewportHeight};
}

Camera3D::Ray Camera3D::ray(const Eigen::Vector2d &pixel) const
{
    const double x = 2.0 * pixel.x() / m_viewportWidth - 1.0;
    const double y = 1.0 - 2.0 * pixel.y() / m_viewportHeight;
    const double h = std::tan(0.5 * m_fieldOfViewDegrees * pi / 180.0);
    Ray ray;
    if (m_projection == Projection::Perspective) {
        ray.origin = eye();
        ray.direction = (-back() + x * h * aspect() * right() + y * h * up()).normalized();
    } else {
        // From the near plane, which may lie behind the eye.
        const double scale = halfHeight();
        ray.direction = -back();
        ray.origin = eye() + x * scale * aspect() * right() + y * scale * up() + nearFar().x() * ray.direction;
    }
    return ray;
}

Eigen::Vector3d Camera3D::pointAtTargetDepth(const Eigen::Vector2d &pixel) const
{
    const Ray r = ray(pixel);
    const double s = (m_distance - depth(r.origin)) / r.direction.dot(-back());
    return r.at(s);
}

void Camera3D::orbit(double dxPixels, double dyPixels)
{
    // Dragging right turns the model's front to the right: the eye moves left.
    double yaw = m_yaw - dxPixels * orbitRadiansPerPixel;
    double pitch = m_pitch;
    if (dyPixels != 0.0) // a horizontal drag leaves a standard Top view looking straight down
        pitch = std::clamp(m_pitch + dyPixels * orbitRadiansPerPixel, -maximumPitch, maximumPitch);
    setOrientation(yaw, pitch);
}

void Camera3D::pan(double dxPixels, double dyPixels, double viewportHeight)
{
    if (!(viewportHeight > 0.0))
        return;
    const double scale = 2.0 * halfHeight() / viewportHeight;
    // The model follows the cursor: the target moves the other way (pixel y is down).
    m_target += scale * (-dxPixels * right() + dyPixels * up());
}

Eigen::Vector2d Camera3D::distanceRange() const
{
    if (m_clipBounds.isEmpty())
        return {1e-3, 1e9};
    const double size = std::max(m_clipBounds.diagonal().norm(), 1e-3);
    return {1e-2 * size, 1e2 * size};
}

void Camera3D::zoom(double steps, const std::optional<Eigen::Vector2d> &cursorPixel)
{
    if (!std::isfinite(steps))
        return;
    const Eigen::Vector2d range = distanceRange();
    const double distance = std::clamp(m_distance * std::pow(zoomStep, -steps), range.x(), range.y());
    const double factor = distance / m_distance;
    if (cursorPixel) {
        // Scaling the whole camera about the cursor's point keeps that point on its pixel, in
        // both projections (the orthographic scale follows the distance).
        const Eigen::Vector3d anchor = pointAtTargetDepth(*cursorPixel);
        m_target = anchor + factor * (m_target - anchor);
    }
    m_distance = distance;
}

void Camera3D::fit(const Eigen::AlignedBox3d &box)
{
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite())
        return;
    const Eigen::Vector3d centre = box.center();
    const double tanY = std::tan(0.5 * m_fieldOfViewDegrees * pi / 180.0), tanX = tanY * aspect();
    const double inside = 1.0 - fitMargin;
    const Eigen::Vector3d r = right(), u = up(), b = back();
    double distance = 0.0;
    forCorners(box, [&](const Eigen::Vector3d &corner) {
        const Eigen::Vector3d offset = corner - centre;
        const double x = std::abs(offset.dot(r)), y = std::abs(offset.dot(u)), z = offset.dot(b);
        // Perspective: the corner at depth D − z must be within ±inside·tan of the axis.
        // Orthographic: the half sizes D·tan must hold it.
        const double depthOffset = m_projection == Projection::Perspective ? z : 0.0;
        distance = std::max({distance, depthOffset + x / (inside * tanX), depthOffset + y / (inside * tanY)});
    });
    m_target = centre;
    m_distance = std::max(distance, 1e-3);
    m_clipBounds.extend(box);
}

void Camera3D::fitPoints(const std::vector<Eigen::Vector3d> &points)
{
    const Eigen::Vector3d r = right(), u = up(), b = back();
    Eigen::AlignedBox3d frame; // the points in the camera's axes
    for (const Eigen::Vector3d &point : points) {
        if (point.allFinite())
            frame.extend(Eigen::Vector3d(point.dot(r), point.dot(u), point.dot(b)));
    }
    if (frame.isEmpty())
        return;
    // The centre of the outline across the view, and of the depth along it.
    const Eigen::Vector3d c = frame.center();
    const Eigen::Vector3d centre = c.x() * r + c.y() * u + c.z() * b;
    const double tanY = std::tan(0.5 * m_fieldOfViewDegrees * pi / 180.0), tanX = tanY * aspect();
    const double inside = 1.0 - fitMargin;
    double distance = 0.0;
    for (const Eigen::Vector3d &point : points) {
        if (!point.allFinite())
            continue;
        const Eigen::Vector3d offset = point - centre;
        const double x = std::abs(offset.dot(r)), y = std::abs(offset.dot(u)), z = offset.dot(b);
        const double depthOffset = m_projection == Projection::Perspective ? z : 0.0;
        distance = std::max({distance, depthOffset + x / (inside * tanX), depthOffset + y / (inside * tanY)});
        m_clipBounds.extend(point);
    }
    m_target = centre;
    m_distance = std::max(distance, 1e-3);
}

void Camera3D::standardOrientation(StandardView view, double &yaw, double &pitch)
{
    switch (view) {
    case StandardView::Front:
        yaw = 0.0;
        pitch = 0.0;
        return;
    case StandardView::Top:
        yaw = 0.0;
        pitch = 0.5 * pi;
        return;
    case StandardView::Side:
        yaw = 0.5 * pi;
        pitch = 0.0;
        return;
    case StandardView::Isometric:
        // Along −(1, 1, 1): 45° about y, elevation atan(1/√2) ≈ 35.26°.
        yaw = 0.25 * pi;
        pitch = std::atan(1.0 / std::sqrt(2.0));
        return;
    }
}

void Camera3D::setStandardView(StandardView view)
{
    double yaw = 0.0, pitch = 0.0;
    standardOrientation(view, yaw, pitch);
    setOrientation(yaw, pitch);
}

} // namespace pkm
