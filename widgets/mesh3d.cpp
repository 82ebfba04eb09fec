#include "mesh3d.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm {

namespace {

constexpr double pi = std::numbers::pi;

/// cos and sin of N equal steps around a circle, computed once.
template<int N> const std::array<Eigen::Vector2d, N> &circle()
{
    static const std::array<Eigen::Vector2d, N> table = [] {
        std::array<Eigen::Vector2d, N> points;
        for (int i = 0; i < N; ++i)
            points[std::size_t(i)] = {std::cos(2.0 * pi * i / N), std::sin(2.0 * pi * i / N)};
        return points;
    }();
    return table;
}

std::array<float, 4> vertexColour(const PartFinish &finish)
{
    return {float(finish.colour.redF()), float(finish.colour.greenF()), float(finish.colour.blueF()), finish.specular};
}

std::array<float, 3> toFloat(const Eigen::Vector3d &v)
{
    return {float(v.x()), float(v.y()), float(v.z())};
}

/// Two unit vectors p, q with p × q = u.
void perpendiculars(const Eigen::Vector3d &u, Eigen::Vector3d &p, Eigen::Vector3d &q)
{
    const Eigen::Vector3d other = std::abs(u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    p = u.cross(other).normalized();
    q = u.cross(p);
}

/// 1, 2 or 5 × 10ⁿ, the smallest at least `minimum`.
double roundStep(double minimum)
{
    const double decade = std::pow(10.0, std::floor(std::log10(minimum)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * decade >= minimum * (1.0 - 1e-12))
            return factor * decade;
    return 10.0 * decade;
}

} // namespace

PartFinish partFinish(PartRole role)
{
    // From SceneStyle, deepened where the 2D fill is too pale to shade on a light background.
    switch (role) {
    case PartRole::Ground:
        return {QColor(0x6b, 0x76, 0x85), 0.15f}; // dark grey frame and supports
    case PartRole::Guide:
        return {QColor(0xa9, 0xb3, 0xc1), 0.45f}; // steel rail
    case PartRole::Slider:
        return {QColor(0x7b, 0x8a, 0x9e), 0.3f}; // SceneStyle::carriage
    case PartRole::Link:
        return {QColor(0x2e, 0x8b, 0x57), 0.25f}; // SceneStyle::link
    case PartRole::Rod:
        return {QColor(0x6a, 0x3d, 0x9a), 0.25f}; // SceneStyle::rod
    case PartRole::Platform:
        return {QColor(0x00, 0x83, 0x8f), 0.25f}; // SceneStyle::platform
    case PartRole::Joint:
        return {QColor(0xe8, 0xeb, 0xef), 0.5f}; // the 2D view's white pivots, polished
    case PartRole::Actuator:
        return {QColor(0x4a, 0x51, 0x5c), 0.3f}; // SceneStyle::motorBody, a shade lighter to show its faces
    case PartRole::Screw:
        return {QColor(0xcf, 0xd5, 0xdc), 0.8f}; // a lighter SceneStyle::screw, polished
    case PartRole::Compensation:
        return {QColor(0xc4, 0x8a, 0x3c), 0.25f}; // calm ochre, apart from every other part
    case PartRole::Marker:
        return {QColor(0xd8, 0x1b, 0x60), 0.4f}; // raspberry highlight
    }
    return {QColor(0x80, 0x80, 0x80), 0.2f};
}

void Mesh3D::clear()
{
    m_vertices.clear();
    m_indices.clear();
}

std::uint32_t Mesh3D::addVertex(
    const Eigen::Vector3d &position, const Eigen::Vector3d &normal, const std::array<float, 4> &colour)
{
    m_vertices.push_back({toFloat(position), toFloat(normal), colour});
    return std::uint32_t(m_vertices.size() - 1);
}

void Mesh3D::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    m_indices.insert(m_indices.end(), {a, b, c});
}

void Mesh3D::appendSolid(const Solid &solid, const PartFinish &finish)
{
    if (!solid.from.allFinite() || !solid.to.allFinite())
        return;
    const std::array<float, 4> colour = vertexColour(finish);
    switch (solid.shape) {
    case Solid::Shape::Box:
        appendBox(solid, colour);
        break;
    case Solid::Shape::Cylinder:
        appendCylinder(solid, colour);
        break;
    case Solid::Shape::Sphere:
        appendSphere(solid, colour);
        break;
    }
}

void Mesh3D::appendBox(const Solid &solid, const std::array<float, 4> &colour)
{
    const SolidFrame frame = solidFrame(solid);
    if (!(frame.length > 0.0) || !(solid.section.x() > 0.0) || !(solid.section.y() > 0.0))
        return;
    // A right-handed frame (axis, up, width) with the half sizes along each.
    const std::array<Eigen::Vector3d, 3> axes {frame.axis, frame.up, frame.width};
    const std::array<double, 3> half {0.5 * frame.length, 0.5 * solid.section.y(), 0.5 * solid.section.x()};
    const Eigen::Vector3d centre = 0.5 * (solid.from + solid.to);
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d s = half[std::size_t((k + 1) % 3)] * axes[std::size_t((k + 1) % 3)];
        const Eigen::Vector3d t = half[std::size_t((k + 2) % 3)] * axes[std::size_t((k + 2) % 3)];
        for (double sign : {1.0, -1.0}) {
            // s × t is along +axes[k]: swapping them on the far face keeps it counter-clockwise.
            const Eigen::Vector3d normal = sign * axes[std::size_t(k)];
            const Eigen::Vector3d c = centre + half[std::size_t(k)] * normal;
            const Eigen::Vector3d a = sign > 0.0 ? s : t, b = sign > 0.0 ? t : s;
            const std::uint32_t first = addVertex(c - a - b, normal, colour);
            addVertex(c + a - b, normal, colour);
            addVertex(c + a + b, normal, colour);
            addVertex(c - a + b, normal, colour);
            addTriangle(first, first + 1, first + 2);
            addTriangle(first, first + 2, first + 3);
        }
    }
}

void Mesh3D::appendCylinder(const Solid &solid, const std::array<float, 4> &colour)
{
    constexpr int n = cylinderSegments;
    const Eigen::Vector3d axis = solid.to - solid.from;
    const double length = axis.norm();
    if (!(length > 0.0) || !(solid.radius > 0.0))
        return;
    const Eigen::Vector3d u = axis / length;
    Eigen::Vector3d p, q;
    perpendiculars(u, p, q);
    const auto &ring = circle<n>();
    const double r = solid.radius;
    m_vertices.reserve(m_vertices.size() + 4 * n + 2);
    m_indices.reserve(m_indices.size() + 12 * n);

    // The side: smooth radial normals.
    const std::uint32_t side = std::uint32_t(m_vertices.size());
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d radial = ring[std::size_t(i)].x() * p + ring[std::size_t(i)].y() * q;
        addVertex(solid.from + r * radial, radial, colour);
        addVertex(solid.to + r * radial, radial, colour);
    }
    for (std::uint32_t i = 0; i < std::uint32_t(n); ++i) {
        const std::uint32_t j = (i + 1) % std::uint32_t(n);
        const std::uint32_t b0 = side + 2 * i, t0 = b0 + 1, b1 = side + 2 * j, t1 = b1 + 1;
        addTriangle(b0, b1, t1);
        addTriangle(b0, t1, t0);
    }
    // The caps: flat, a fan about the centre.
    for (double sign : {1.0, -1.0}) {
        const Eigen::Vector3d centre = sign > 0.0 ? solid.to : solid.from;
        const Eigen::Vector3d normal = sign * u;
        const std::uint32_t middle = addVertex(centre, normal, colour);
        for (int i = 0; i < n; ++i)
            addVertex(centre + r * (ring[std::size_t(i)].x() * p + ring[std::size_t(i)].y() * q), normal, colour);
        for (std::uint32_t i = 0; i < std::uint32_t(n); ++i) {
            const std::uint32_t a = middle + 1 + i, b = middle + 1 + (i + 1) % std::uint32_t(n);
            if (sign > 0.0)
                addTriangle(middle, a, b);
            else
                addTriangle(middle, b, a);
        }
    }
}

void Mesh3D::appendSphere(const Solid &solid, const std::array<float, 4> &colour)
{
    constexpr int slices = sphereSlices, stacks = sphereStacks;
    if (!(solid.radius > 0.0))
        return;
    const auto &ring = circle<slices>();
    const Eigen::Vector3d c = solid.from;
    const double r = solid.radius;
    m_vertices.reserve(m_vertices.size() + slices * (stacks - 1) + 2);
    m_indices.reserve(m_indices.size() + 6 * slices * (stacks - 1));

    const std::uint32_t south = addVertex(c - r * Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(), colour);
    const std::uint32_t first = std::uint32_t(m_vertices.size());
    for (int j = 1; j < stacks; ++j) {
        const double latitude = -0.5 * pi + pi * j / stacks;
        for (int i = 0; i < slices; ++i) {
            const Eigen::Vector2d &xy = ring[std::size_t(i)];
            const Eigen::Vector3d normal(std::cos(latitude) * xy.x(), std::cos(latitude) * xy.y(), std::sin(latitude));
            addVertex(c + r * normal, normal, colour);
        }
    }
    const std::uint32_t north = addVertex(c + r * Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(), colour);
    const auto s = std::uint32_t(slices);
    auto at = [&](int stack, std::uint32_t slice) { return first + std::uint32_t(stack - 1) * s + slice % s; };
    for (std::uint32_t i = 0; i < s; ++i) {
        addTriangle(south, at(1, i + 1), at(1, i));
        addTriangle(north, at(stacks - 1, i), at(stacks - 1, i + 1));
        for (int j = 1; j + 1 < stacks; ++j) {
            addTriangle(at(j, i), at(j, i + 1), at(j + 1, i + 1));
            addTriangle(at(j, i), at(j + 1, i + 1), at(j + 1, i));
        }
    }
}

Eigen::AlignedBox3d Mesh3D::bounds() const
{
    Eigen::AlignedBox3d box;
    for (const MeshVertex &v : m_vertices)
        box.extend(Eigen::Vector3d(v.position[0], v.position[1], v.position[2]));
    return box;
}

Mesh3D Mesh3D::fromScene(const Scene3D &scene)
{
    Mesh3D mesh;
    // Most solids are boxes and cylinders: reserve for cylinders, the larger of the two.
    mesh.m_vertices.reserve(scene.solids.size() * (4 * cylinderSegments + 2));
    mesh.m_indices.reserve(scene.solids.size() * 12 * cylinderSegments);
    for (const Solid &solid : scene.solids)
        mesh.appendSolid(solid);
    return mesh;
}

GroundGrid groundGrid(const Eigen::AlignedBox3d &extent)
{
    const bool usable = !extent.isEmpty() && extent.min().allFinite() && extent.max().allFinite();
    Eigen::AlignedBox3d box
        = usable ? extent : Eigen::AlignedBox3d(Eigen::Vector3d(-100, 0, -100), Eigen::Vector3d(100, 0, 100));
    const Eigen::Vector3d size = box.sizes();
    const double span = std::max({size.x(), size.z(), 1e-3 * size.y(), 1e-6});
    const double margin = 0.25 * span;

    GroundGrid grid;
    grid.spacing = roundStep(1.5 * span / 16.0);
    grid.y = box.min().y() - (usable ? 1e-3 * std::max(span, size.y()) : 0.0);
    const double step = grid.spacing;
    const double major = std::pow(10.0, std::floor(std::log10(step) + 1e-9) + 1.0);
    const double x0 = std::floor((box.min().x() - margin) / step) * step;
    const double x1 = std::ceil((box.max().x() + margin) / step) * step;
    const double z0 = std::floor((box.min().z() - margin) / step) * step;
    const double z1 = std::ceil((box.max().z() + margin) / step) * step;
    grid.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(x0, grid.y, z0), Eigen::Vector3d(x1, grid.y, z1));

    // Colours over the SceneStyle background (#fbfcfe): gridMinor and a little under gridMajor.
    const std::array<float, 4> minor {0xdf / 255.0f, 0xe4 / 255.0f, 0xeb / 255.0f, 1.0f};
    const std::array<float, 4> strong {0xc6 / 255.0f, 0xce / 255.0f, 0xda / 255.0f, 1.0f};
    auto isMajor = [&](double v) { return std::abs(std::remainder(v, major)) < 1e-6 * step; };
    const auto y = float(grid.y);
    const long columns = std::lround((x1 - x0) / step), rows = std::lround((z1 - z0) / step);
    grid.vertices.reserve(std::size_t(2 * (columns + rows + 2)));
    for (long i = 0; i <= columns; ++i) {
        const double x = x0 + double(i) * step;
        const std::array<float, 4> &colour = isMajor(x) ? strong : minor;
        grid.vertices.push_back({{float(x), y, float(z0)}, colour});
        grid.vertices.push_back({{float(x), y, float(z1)}, colour});
    }
    for (long i = 0; i <= rows; ++i) {
        const double z = z0 + double(i) * step;
        const std::array<float, 4> &colour = isMajor(z) ? strong : minor;
        grid.vertices.push_back({{float(x0), y, float(z)}, colour});
        grid.vertices.push_back({{float(x1), y, float(z)}, colour});
    }
    return grid;
}

Eigen::AlignedBox3d modelBounds(const Scene3D &scene)
{
    Eigen::AlignedBox3d box = scene.extent;
    for (const Solid &solid : scene.solids)
        if (solid.from.allFinite() && solid.to.allFinite())
            box.extend(solidBounds(solid));
    return box;
}

} // namespace pkm
