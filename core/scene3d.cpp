#include "scene3d.h"

#include "text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {

/// A closed interval of z, empty until something is added.
struct Span {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();

    void add(double a, double b)
    {
        low = std::min({low, a, b});
        high = std::max({high, a, b});
    }
    bool empty() const { return low > high; }
    double middle() const { return 0.5 * (low + high); }
};

bool finite(const Eigen::Vector3d &v)
{
    return v.allFinite();
}

PartRole barRole(BarKind kind)
{
    switch (kind) {
    case BarKind::Ground:
        return PartRole::Ground;
    case BarKind::Rod:
        return PartRole::Rod;
    case BarKind::Platform:
        return PartRole::Platform;
    case BarKind::Crank:
    case BarKind::Coupler:
    case BarKind::Link:
        break;
    }
    return PartRole::Link;
}

/// The z offset of the stacked parts; every length is a multiple of the link thickness t.
struct Layout {
    double t = 1.0;
    double barHeight = 0.5; ///< a link's size along z
    double pitch = 0.6; ///< from one link layer to the next
    double gap = 0.1; ///< between parts in neighbouring layers
    double overhang = 0.15; ///< of a pin beyond the outermost part it carries
    double low = -0.25; ///< back face of the link stack
    double high = 0.25; ///< front face of the link stack
    int layers = 1;

    explicit Layout(double thickness, int layerCount)
        : t(thickness)
        , barHeight(0.5 * thickness)
        , pitch(0.6 * thickness)
        , gap(0.1 * thickness)
        , overhang(0.15 * thickness)
        , layers(std::max(layerCount, 1))
    {
        low = layerZ(0) - 0.5 * barHeight;
        high = layerZ(layers - 1) + 0.5 * barHeight;
    }
    /// Link layers are centred on the mechanism plane.
    double layerZ(int layer) const { return (layer - 0.5 * (layers - 1)) * pitch; }
    // Behind the links: the carriages, and the rails they run on a little further back.
    double carriageZ() const { return low - gap - 0.35 * t; }
    double carriageHeight() const { return 0.7 * t; }
    double railZ() const { return low - 0.6 * t; }
    double railHeight() const { return 0.7 * t; }
    double railFront() const { return railZ() + 0.5 * railHeight(); }
    double groundZ() const { return low - gap - 0.3 * t; }
};

/// Link layers by greedy colouring: two links that share a joint never share a layer, so
/// they stack like real links on a pin and no two faces lie in one plane.
std::vector<int> barLayers(const Scene &scene, int &layerCount)
{
    const std::size_t n = scene.joints.size();
    std::vector<std::vector<int>> usedAt(n);
    std::vector<int> layers(scene.bars.size(), 0);
    layerCount = 1;
    for (std::size_t b = 0; b < scene.bars.size(); ++b) {
        const SceneBar &bar = scene.bars[b];
        if (bar.from < 0 || bar.to < 0 || std::size_t(bar.from) >= n || std::size_t(bar.to) >= n)
            continue;
        const std::vector<int> &a = usedAt[std::size_t(bar.from)], &c = usedAt[std::size_t(bar.to)];
        int layer = 0;
        while (std::find(a.begin(), a.end(), layer) != a.end() || std::find(c.begin(), c.end(), layer) != c.end())
            ++layer;
        layers[b] = layer;
        usedAt[std::size_t(bar.from)].push_back(layer);
        usedAt[std::size_t(bar.to)].push_back(layer);
        layerCount = std::max(layerCount, layer + 1);
    }
    return layers;
}

/// The guide a slider or point joint lies on (within a quarter of the rail's width of its axis
/// and no farther past the stroke than a carriage overhangs), or −1; as the 2D view decides.
int guideOf(const Scene &scene, const SceneJoint &joint)
{
    int found = -1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t g = 0; g < scene.guides.size(); ++g) {
        const SceneGuide &guide = scene.guides[g];
        const Eigen::Vector2d a = guide.start.head<2>(), b = guide.end.head<2>(), p = joint.position.head<2>();
        const double span = (b - a).norm();
        if (!std::isfinite(span) || !p.allFinite())
            continue;
        const double width = std::max(guide.width, 0.0);
        const Eigen::Vector2d u = span > 1e-12 ? Eigen::Vector2d((b - a) / span) : Eigen::Vector2d::UnitX();
        const double along = u.dot(p - a);
        const double across = std::abs(u.x() * (p - a).y() - u.y() * (p - a).x());
        const double tolerance = std::max({0.25 * width, 1e-6 * span, 1e-9});
        const double overrun = 0.9 * width + tolerance;
        if (across <= tolerance && along >= -overrun && along <= span + overrun && across < best) {
            best = across;
            found = int(g);
        }
    }
    return found;
}

/// The name of a kind of part, translated once per model: alone ("link") and with the scene
/// label it carries ("link a").
struct PartName {
    std::string bare;
    std::string pattern; ///< "link %1"
    std::string operator()(const std::string &label) const
    {
        return label.empty() ? bare : text::format(pattern, {label});
    }
};

} // namespace

std::vector<Label3D> jointLabels(const Scene &scene, const std::vector<Solid> &solids)
{
    Eigen::AlignedBox3d drawn;
    for (const Solid &solid : solids)
        drawn.extend(solidBounds(solid));
    const Eigen::Vector3d margin = Eigen::Vector3d::Constant(0.02 * drawn.sizes().maxCoeff());
    drawn.extend(drawn.min() - margin).extend(drawn.max() + margin);
    std::vector<Label3D> labels;
    for (const SceneJoint &joint : scene.joints) {
        if (joint.label.empty() || !finite(joint.position) || drawn.isEmpty() || !drawn.contains(joint.position))
            continue;
        const bool named = std::any_of(labels.begin(), labels.end(),
                                       [&](const Label3D &label) { return label.text == joint.label; });
        if (named)
            continue;
        const int index = int(&joint - scene.joints.data());
        const bool corner = std::any_of(scene.bars.begin(), scene.bars.end(), [&](const SceneBar &bar) {
            return bar.kind == BarKind::Platform && (bar.from == index || bar.to == index);
        });
        labels.push_back({joint.position, joint.label, corner && joint.kind != JointKind::Point});
    }
    return labels;
}

Scene3D extrudeScene(const Scene &scene, double thickness)
{
    const double t = std::isfinite(thickness) && thickness > 0.0 ? thickness : 1.0;
    const std::size_t n = scene.joints.size();
    auto valid = [&](int joint) {
        return joint >= 0 && std::size_t(joint) < n && finite(scene.joints[std::size_t(joint)].position);
    };
    auto at = [&](int joint, double z) {
        return Eigen::Vector3d(scene.joints[std::size_t(joint)].position + Eigen::Vector3d(0.0, 0.0, z));
    };
    const Eigen::Vector3d zAxis = Eigen::Vector3d::UnitZ();

    int layerCount = 1;
    const std::vector<int> layers = barLayers(scene, layerCount);
    const Layout layout(t, layerCount);

    const PartName linkName{text::translate("core", "link"), text::translate("core", "link %1")};
    const PartName motorName{text::translate("core", "motor"), text::translate("core", "motor %1")};
    const PartName screwName{text::translate("core", "screw"), text::translate("core", "screw %1")};
    const PartName guideName{text::translate("core", "guide"), text::translate("core", "guide %1")};
    const PartName endStopName{text::translate("core", "end stop"), text::translate("core", "end stop %1")};
    const PartName sliderName{text::translate("core", "slider"), text::translate("core", "slider %1")};
    const PartName supportName{text::translate("core", "support"), text::translate("core", "support %1")};
    const PartName pointName{text::translate("core", "point"), text::translate("core", "point %1")};
    const PartName jointName{text::translate("core", "joint"), text::translate("core", "joint %1")};

    Scene3D model;
    std::vector<Solid> &solids = model.solids;
    solids.reserve(3 * scene.bars.size() + 3 * scene.actuators.size() + 4 * scene.guides.size() + 4 * n);
    std::vector<Span> pins(n); // the z range of the parts each joint's pin carries
    // The parts that never move (ground links, rails, end stops, supports) as index ranges.
    std::vector<std::pair<std::size_t, std::size_t>> fixedSolids;

    // Links: a flat bar with a round eye at each end, like a machined link.
    for (std::size_t b = 0; b < scene.bars.size(); ++b) {
        const SceneBar &bar = scene.bars[b];
        if (!valid(bar.from) || !valid(bar.to))
            continue;
        const double z = layout.layerZ(layers[b]);
        const double h = 0.5 * layout.barHeight;
        const PartRole role = barRole(bar.kind);
        const Eigen::Vector3d p = at(bar.from, z), q = at(bar.to, z);
        const std::size_t first = solids.size();
        if ((q - p).norm() > 1e-9 * t)
            solids.push_back(Solid::box(p, q, t, layout.barHeight, zAxis, role, linkName(bar.label)));
        for (const Eigen::Vector3d &end : {p, q})
            solids.push_back(
                Solid::cylinder(end - h * zAxis, end + h * zAxis, 0.5 * t, role, linkName(bar.label)));
        pins[std::size_t(bar.from)].add(z - h, z + h);
        pins[std::size_t(bar.to)].add(z - h, z + h);
        if (role == PartRole::Ground)
            fixedSolids.insert(fixedSolids.end(), {first, solids.size()});
    }

    // Actuators in front of the links: the motor body at `from`, the screw on to `to`.
    for (const SceneActuator &actuator : scene.actuators) {
        if (!valid(actuator.from) || !valid(actuator.to))
            continue;
        const double screwRadius = std::max(0.5 * actuator.rodDiameter, 0.08 * t);
        const double width = std::max({actuator.bodyWidth, 2.0 * screwRadius, 0.5 * t});
        const double z = layout.high + layout.gap + 0.5 * width;
        const Eigen::Vector3d p = at(actuator.from, z), q = at(actuator.to, z);
        const double distance = (q - p).norm();
        if (!(distance > 1e-9 * t))
            continue;
        const Eigen::Vector3d u = (q - p) / distance;
        const double body = std::clamp(actuator.bodyLength, 0.0, distance);
        if (body > 0.0)
            solids.push_back(
                Solid::box(p, p + body * u, width, width, zAxis, PartRole::Actuator, motorName(actuator.label)));
        if (body < distance) {
            // The bearing boss where the screw leaves an unclipped body.
            const double boss = std::min(0.12 * width, distance - body);
            if (body >= actuator.bodyLength && boss > 0.0)
                solids.push_back(Solid::cylinder(p + body * u, p + (body + boss) * u,
                    std::min(0.3 * width, 3.0 * screwRadius), PartRole::Screw, motorName(actuator.label)));
            solids.push_back(
                Solid::cylinder(p + body * u, q, screwRadius, PartRole::Screw, screwName(actuator.label)));
        }
        pins[std::size_t(actuator.from)].add(z, z);
        pins[std::size_t(actuator.to)].add(z, z);
    }

    // Guides behind the links: a rail with an end stop at each end, and a carriage on every
    // slider joint that lies on it. The rail runs half a carriage past each end of the stroke.
    std::vector<int> jointGuide(n, -1);
    for (std::size_t j = 0; j < n; ++j) {
        const SceneJoint &joint = scene.joints[j];
        if ((joint.kind == JointKind::Slider || joint.kind == JointKind::Point) && finite(joint.position))
            jointGuide[j] = guideOf(scene, joint);
    }
    auto guideAxis = [](const SceneGuide &guide) {
        const Eigen::Vector3d d = guide.end - guide.start;
        return d.norm() > 1e-12 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d(Eigen::Vector3d::UnitX());
    };
    auto carriageLength = [&](const SceneGuide &guide) { return std::max(1.8 * guide.width, 2.0 * t); };
    for (const SceneGuide &guide : scene.guides) {
        if (!finite(guide.start) || !finite(guide.end))
            continue;
        const double width = std::max(guide.width, 0.2 * t);
        const Eigen::Vector3d u = guideAxis(guide);
        const double overrun = 0.5 * carriageLength(guide), stop = 0.3 * t;
        const Eigen::Vector3d back = layout.railZ() * zAxis;
        const Eigen::Vector3d a = guide.start + back - overrun * u, b = guide.end + back + overrun * u;
        const std::size_t first = solids.size();
        // The rail ends inside its stops, so no two faces meet in one plane.
        solids.push_back(Solid::box(a - 0.5 * stop * u, b + 0.5 * stop * u, width, layout.railHeight(), zAxis,
            PartRole::Guide, guideName(guide.label)));
        for (const Eigen::Vector3d &end : {Eigen::Vector3d(a - stop * u), Eigen::Vector3d(b)}) {
            solids.push_back(Solid::box(end, end + stop * u, width + 0.4 * t, layout.railHeight() + 0.2 * t, zAxis,
                PartRole::Ground, endStopName(guide.label)));
        }
        fixedSolids.emplace_back(first, solids.size());
    }

    // Joints: pins through everything they carry, balls, carriages, supports and markers; a
    // far free point (the four-bar's instantaneous centre near AB ∥ DC) is left out, as the
    // DXF drawing leaves it out, so that it does not shrink the fitted model to a speck.
    const std::vector<bool> shown = shownJoints(scene, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        const SceneJoint &joint = scene.joints[j];
        if (!finite(joint.position) || !shown[j])
            continue;
        const int jointIndex = int(j);
        const std::string &label = joint.label;
        Span &span = pins[j];
        const Eigen::Vector3d p = joint.position;
        switch (joint.kind) {
        case JointKind::Slider: {
            const int g = jointGuide[j];
            const SceneGuide *guide = g >= 0 ? &scene.guides[std::size_t(g)] : nullptr;
            const Eigen::Vector3d u = guide ? guideAxis(*guide) : Eigen::Vector3d(Eigen::Vector3d::UnitX());
            const double length = guide ? carriageLength(*guide) : 2.0 * t;
            const double across = guide ? std::max(1.3 * guide->width, guide->width + 0.4 * t) : 1.2 * t;
            const Eigen::Vector3d centre = at(jointIndex, layout.carriageZ());
            solids.push_back(Solid::box(centre - 0.5 * length * u, centre + 0.5 * length * u, across,
                layout.carriageHeight(), zAxis, PartRole::Slider, sliderName(label)));
            span.add(layout.carriageZ(), layout.carriageZ());
            break;
        }
        case JointKind::Ground: {
            // A support behind the pin, standing on a foot plate.
            const double z = layout.groundZ(), bottom = p.y() - 1.6 * t;
            const Eigen::Vector3d top(p.x(), p.y() + 0.6 * t, p.z() + z), foot(p.x(), bottom, p.z() + z);
            fixedSolids.emplace_back(solids.size(), solids.size() + 2);
            solids.push_back(Solid::box(foot - 0.1 * t * Eigen::Vector3d::UnitY(), top, 1.4 * t, 0.6 * t, zAxis,
                PartRole::Ground, supportName(label)));
            const Eigen::Vector3d footCentre = foot - 0.3 * t * Eigen::Vector3d::UnitY();
            solids.push_back(Solid::box(footCentre - 1.3 * t * Eigen::Vector3d::UnitX(),
                footCentre + 1.3 * t * Eigen::Vector3d::UnitX(), 0.4 * t, 1.4 * t, zAxis, PartRole::Ground,
                supportName(label)));
            span.add(z, z);
            break;
        }
        case JointKind::Point: {
            // On a rail: half sunk into its front face; else in the plane of what it joins.
            const double z = jointGuide[j] >= 0 ? layout.railFront() : (span.empty() ? 0.0 : span.middle());
            solids.push_back(Solid::sphere(at(jointIndex, z), 0.3 * t, PartRole::Marker, pointName(label)));
            continue;
        }
        case JointKind::Spherical: {
            const double z = span.empty() ? 0.0 : span.middle();
            const double radius = 0.55 * t;
            if (!span.empty() && span.high - span.low > 2.0 * radius)
                solids.push_back(Solid::cylinder(at(jointIndex, span.low - layout.overhang),
                    at(jointIndex, span.high + layout.overhang), 0.3 * t, PartRole::Joint, jointName(label)));
            solids.push_back(Solid::sphere(at(jointIndex, z), radius, PartRole::Joint, jointName(label)));
            continue;
        }
        case JointKind::Revolute:
            break;
        }
        if (span.empty())
            span.add(-0.5 * layout.barHeight, 0.5 * layout.barHeight);
        solids.push_back(Solid::cylinder(at(jointIndex, span.low - layout.overhang),
            at(jointIndex, span.high + layout.overhang), 0.45 * t, PartRole::Joint, jointName(label)));
    }

    // The 2D extent thickened in z, and grown to hold the fixed parts and the stack of layers
    // (which depends only on the topology), so that it is the same in every pose.
    Eigen::AlignedBox3d extent = scene.extent;
    if (extent.isEmpty()) {
        for (const SceneJoint &joint : scene.joints)
            if (finite(joint.position))
                extent.extend(joint.position);
    }
    if (!extent.isEmpty()) {
        extent.min().z() -= 2.0 * t;
        extent.max().z() += 2.0 * t;
        for (const Solid &solid : solids) {
            const Eigen::AlignedBox3d box = solidBounds(solid);
            extent.min().z() = std::min(extent.min().z(), box.min().z());
            extent.max().z() = std::max(extent.max().z(), box.max().z());
        }
    }
    for (const auto &[first, last] : fixedSolids)
        for (std::size_t s = first; s < last; ++s)
            extent.extend(solidBounds(solids[s]));
    model.extent = extent;
    model.labels = jointLabels(scene, model.solids);
    return model;
}

Eigen::AlignedBox3d solidBounds(const Solid &solid)
{
    Eigen::AlignedBox3d box;
    switch (solid.shape) {
    case Solid::Shape::Sphere:
        box.extend(solid.from - Eigen::Vector3d::Constant(solid.radius));
        box.extend(solid.from + Eigen::Vector3d::Constant(solid.radius));
        break;
    case Solid::Shape::Cylinder: {
        // Each end is a disc of the radius across the axis u: it reaches r·√(1 − u_i²) along i.
        const Eigen::Vector3d axis = solid.to - solid.from;
        const Eigen::Vector3d u = axis.norm() > 0.0 ? Eigen::Vector3d(axis.normalized()) : Eigen::Vector3d::UnitZ();
        const Eigen::Vector3d reach
            = solid.radius * (Eigen::Vector3d::Ones() - u.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
        box.extend(solid.from - reach).extend(solid.from + reach).extend(solid.to - reach).extend(solid.to + reach);
        break;
    }
    case Solid::Shape::Box: {
        const SolidFrame frame = solidFrame(solid);
        for (int corner = 0; corner < 8; ++corner) {
            const double along = (corner & 1) ? 1.0 : 0.0;
            const double across = (corner & 2) ? 0.5 : -0.5, up = (corner & 4) ? 0.5 : -0.5;
            box.extend(solid.from + along * frame.length * frame.axis + across * solid.section.x() * frame.width
                + up * solid.section.y() * frame.up);
        }
        break;
    }
    }
    return box;
}

SolidFrame solidFrame(const Solid &solid)
{
    SolidFrame frame;
    const Eigen::Vector3d axis = solid.to - solid.from;
    frame.length = axis.norm();
    frame.axis = frame.length > 0.0 ? Eigen::Vector3d(axis / frame.length) : Eigen::Vector3d::UnitX();
    // `up` made perpendicular to the axis; when it is (nearly) along the axis, any normal.
    Eigen::Vector3d up = solid.up - solid.up.dot(frame.axis) * frame.axis;
    if (!(up.norm() > 1e-9 * std::max(1.0, solid.up.norm()))) {
        const Eigen::Vector3d other
            = std::abs(frame.axis.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
        up = other - other.dot(frame.axis) * frame.axis;
    }
    frame.up = up.normalized();
    frame.width = frame.axis.cross(frame.up);
    return frame;
}

} // namespace pkm
