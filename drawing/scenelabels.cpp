#include "scenelabels.h"

#include "scenegeometry.h"


#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace pkm {

using namespace detail;

// -- quads -------------------------------------------------------------------------------

Quad detail::segmentQuad(const QPointF &a, const QPointF &b, double halfWidth)
{
    const QPointF u = unit(b - a) * halfWidth, n = screenLeft(u);
    return {a - u + n, b + u + n, b + u - n, a - u - n};
}

Quad detail::boxQuad(const QPointF &centre, const QSizeF &size, double rotationDegrees)
{
    const QPointF u = deviceDirection(-rotationDegrees * degree) * (0.5 * size.width());
    const QPointF v = screenLeft(unit(u)) * (0.5 * size.height());
    return {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
}

/// The quads are convex, so two edge normals of each suffice.
bool detail::overlap(const Quad &a, const Quad &b)
{
    auto separated = [](const Quad &p, const Quad &q, const QPointF &axis) {
        double pMin = 1e300, pMax = -1e300, qMin = 1e300, qMax = -1e300;
        for (const QPointF &c : p) {
            const double t = dot(c, axis);
            pMin = std::min(pMin, t);
            pMax = std::max(pMax, t);
        }
        for (const QPointF &c : q) {
            const double t = dot(c, axis);
            qMin = std::min(qMin, t);
            qMax = std::max(qMax, t);
        }
        return pMax < qMin || qMax < pMin;
    };
    for (const Quad *quad : {&a, &b}) {
        for (int i = 0; i < 2; ++i) {
            const QPointF edge = (*quad)[std::size_t(i + 1)] - (*quad)[std::size_t(i)];
            if (separated(a, b, screenLeft(edge)))
                return false;
        }
    }
    return true;
}

QFont detail::labelFont(double pixels, bool bold)
{
    QFont font; // the application's font, so labels match the rest of the UI
    font.setPixelSize(std::max(1, int(std::lround(pixels))));
    font.setBold(bold);
    return font;
}

// -- collecting --------------------------------------------------------------------------

SceneLabels::SceneLabels(const Scene &scene, const std::vector<QPointF> &points, const ViewMapping &mapping,
    const SceneStyle &style, const QPaintDevice *device)
    : m_scene(scene)
    , m_points(points)
    , m_mapping(mapping)
    , m_style(style)
    , m_px(style.pixelSize)
    , m_font(labelFont(style.fontPixels * style.pixelSize, false))
    , m_jointFont(labelFont(style.jointFontPixels * style.pixelSize, true))
    , m_metrics(m_font, device)
    , m_jointMetrics(m_jointFont, device)
{
    m_rays.resize(scene.joints.size());
    m_obstacles.reserve(64);
}

void SceneLabels::addRay(int joint, const QPointF &towards, double reach)
{
    if (valid(joint) && length(towards) > 1e-9)
        m_rays[std::size_t(joint)].push_back({unit(towards), reach});
}

void SceneLabels::addObstacle(const QPointF &a, const QPointF &b, double halfWidth)
{
    m_obstacles.push_back(segmentQuad(a, b, halfWidth));
}

void SceneLabels::addObstacle(const Quad &quad)
{
    m_obstacles.push_back(quad);
}

void SceneLabels::addMemberLabel(const PendingMemberLabel &label)
{
    m_memberLabels.push_back(label);
}

void SceneLabels::addAngleLabel(const PendingAngleLabel &label)
{
    m_angleLabels.push_back(label);
}

void SceneLabels::addGuideLabel(const PendingGuideLabel &label)
{
    m_guideLabels.push_back(label);
}

void SceneLabels::addFreeLabel(const PendingFreeLabel &label)
{
    m_freeLabels.push_back(label);
}

void SceneLabels::place(const SceneLabel &label)
{
    m_labels.push_back(label);
    m_obstacles.push_back(boxQuad(label.centre, textSize(label.text, label.joint), label.rotationDegrees));
}

void SceneLabels::dropDimensionedActuatorLabels()
{
    // A dimension of the same joints already names the actuator: drop the actuator's label.
    std::erase_if(m_memberLabels, [this](const PendingMemberLabel &label) {
        const bool isActuator = std::any_of(m_scene.actuators.begin(), m_scene.actuators.end(), [&](const auto &a) {
            return a.from == label.from && a.to == label.to && QString::fromStdString(a.label) == label.text;
        });
        return isActuator && std::any_of(m_scene.dimensions.begin(), m_scene.dimensions.end(), [&](const auto &d) {
            return (d.from == label.from && d.to == label.to) || (d.from == label.to && d.to == label.from);
        });
    });
}

double SceneLabels::memberReach(int joint, const QPointF &direction) const
{
    double reach = 0.0;
    if (!valid(joint))
        return reach;
    for (const Ray &ray : m_rays[std::size_t(joint)]) {
        if (dot(ray.direction, direction) > std::cos(1.0 * degree))
            reach = std::max(reach, ray.reach);
    }
    return reach;
}

// -- placing -----------------------------------------------------------------------------

QSizeF SceneLabels::textSize(const QString &text, bool joint) const
{
    const QFontMetricsF &metrics = joint ? m_jointMetrics : m_metrics;
    // A little padding so the knock-out box does not touch the glyphs.
    return {metrics.horizontalAdvance(text) + 8.0 * m_px, metrics.height() + 2.0 * m_px};
}

bool SceneLabels::isFree(const Quad &box) const
{
    return std::none_of(m_obstacles.begin(), m_obstacles.end(), [&](const Quad &q) { return overlap(box, q); });
}

void SceneLabels::placeFirstFree(SceneLabel label, const std::vector<QPointF> &candidates)
{
    const QSizeF size = textSize(label.text, label.joint) + QSizeF(4.0 * m_px, 4.0 * m_px); // keep a gap
    bool first = true;
    QPointF fallback;
    for (const QPointF &centre : candidates) {
        if (first) {
            fallback = centre;
            first = false;
        }
        if (isFree(boxQuad(centre, size, label.rotationDegrees))) {
            label.centre = centre;
            place(label);
            return;
        }
    }
    if (!first) {
        label.centre = fallback;
        place(label);
    }
}

/// Half the drawn width (device) of the member joining two joints, `fraction` of the way.
double SceneLabels::memberHalfWidth(int from, int to, double fraction) const
{
    double half = 0.0;
    auto same = [from, to](int a, int b) { return (a == from && b == to) || (a == to && b == from); };
    for (const SceneBar &bar : m_scene.bars) {
        if (same(bar.from, bar.to))
            half = std::max(half, 0.5 * m_px * (bar.kind == BarKind::Ground ? m_style.groundWidth : m_style.barWidth));
    }
    for (const SceneActuator &actuator : m_scene.actuators) {
        if (!same(actuator.from, actuator.to))
            continue;
        const double distance = length(point(to) - point(from)) / m_mapping.scale;
        const double along = actuator.from == from ? fraction * distance : (1.0 - fraction) * distance;
        const double width = along < actuator.bodyLength
            ? actuator.bodyWidth * m_mapping.scale
            : std::max(actuator.rodDiameter * m_mapping.scale, m_style.minimumScrewWidth * m_px);
        half = std::max(half, 0.5 * width);
    }
    return half;
}

void SceneLabels::placeAll()
{
    // Most constrained first: dimension text along members, angle labels near their arcs,
    // bar names (which may slide along their bar), then joint names (anywhere around).
    for (const PendingFreeLabel &pending : m_freeLabels)
        placeFirstFree(pending.label, pending.candidates);
    placeMemberLabels(true);
    placeAngleLabels();
    placeGuideLabels();
    placeMemberLabels(false);
    placeJointLabels();
}

void SceneLabels::placeMemberLabels(bool dimensions)
{
    if (m_points.empty())
        return;
    QPointF centroid;
    int shown = 0;
    for (int j = 0; j < int(m_points.size()); ++j) {
        if (valid(j)) {
            centroid += point(j);
            ++shown;
        }
    }
    if (shown > 0)
        centroid /= double(shown);

    std::vector<QPointF> candidates;
    for (const PendingMemberLabel &pending : m_memberLabels) {
        if (pending.preferReadingUp != dimensions || !valid(pending.from) || !valid(pending.to))
            continue;
        const QPointF p = point(pending.from), q = point(pending.to);
        if (length(q - p) < 1e-6)
            continue;
        const QPointF u = unit(q - p), left = screenLeft(u);
        const QSizeF size = textSize(pending.text);
        // a dimension's text is dimension layer, a member's name text
        SceneLabel label {{}, 0.0, pending.text, false, pending.colour,
            pending.preferReadingUp ? drawing::Layer::Dimensions : drawing::Layer::Text, pending.cad};
        double firstSide = 1.0;
        if (pending.preferReadingUp) {
            // Rotated with the member, above it as read.
            label.rotationDegrees = readableRotation(u);
            const QPointF up = deviceDirection((90.0 - label.rotationDegrees) * degree);
            firstSide = dot(up, left) >= 0.0 ? 1.0 : -1.0;
        } else {
            // Bar names upright, on the outside of the mechanism.
            firstSide = dot(left, 0.5 * (p + q) - centroid) >= 0.0 ? 1.0 : -1.0;
        }
        candidates.clear();
        for (double side : {firstSide, -firstSide}) {
            for (double fraction : {0.5, 0.42, 0.58, 0.34, 0.66, 0.26, 0.74}) {
                const QPointF normal = side * left;
                const double extent = pending.preferReadingUp ? 0.5 * size.height() : support(normal, size);
                const double lift = memberHalfWidth(pending.from, pending.to, fraction) + 5.0 * m_px + extent;
                candidates.push_back(p + fraction * (q - p) + lift * normal);
            }
        }
        placeFirstFree(label, candidates);
    }
}

void SceneLabels::placeAngleLabels()
{
    std::vector<QPointF> candidates;
    for (const PendingAngleLabel &pending : m_angleLabels) {
        const QPointF v = point(pending.vertex);
        const QSizeF size = textSize(pending.text);
        const double gap = 5.0 * m_px;
        const double end = pending.start + pending.sweep;
        const double turn = pending.sweep > 0.0 ? 1.0 : -1.0;
        auto centreAt = [&](double a, double extra) {
            const QPointF u = deviceDirection(a);
            return v + (pending.radius + gap + extra + support(u, size)) * u;
        };
        // Outside the arc at mid-angle; when the arc is too narrow, step round past the end
        // leg, then past the start leg; then farther out.
        const double middle = pending.start + 0.5 * pending.sweep;
        candidates.clear();
        candidates.push_back(centreAt(middle, 0.0));
        // Steps of 4°, or of 12 px along a large arc, so the label stays close to it.
        const double angleStep = std::min(4.0 * degree, 12.0 * m_px / std::max(pending.radius, 1e-9));
        auto stepRound = [&](int first, int last) {
            for (int step = first; step <= last; ++step) {
                const double delta = step * angleStep;
                candidates.push_back(centreAt(end + turn * delta, 0.0));
                candidates.push_back(centreAt(pending.start - turn * delta, 0.0));
            }
        };
        stepRound(1, 5);
        for (int step = 1; step <= 3; ++step)
            candidates.push_back(centreAt(middle, step * 10.0 * m_px));
        stepRound(6, 20);
        for (int step = 4; step <= 8; ++step)
            candidates.push_back(centreAt(middle, step * 10.0 * m_px));
        placeFirstFree(
            SceneLabel {{}, 0.0, pending.text, false, m_style.angle, drawing::Layer::Dimensions, {}}, candidates);
        const QPointF placed = m_labels.back().centre;
        addRay(pending.vertex, placed - v, length(placed - v));
    }
}

void SceneLabels::placeGuideLabels()
{
    std::vector<QPointF> candidates;
    for (const PendingGuideLabel &pending : m_guideLabels) {
        const QSizeF size = textSize(pending.text);
        const QPointF axis = pending.end - pending.start;
        const QPointF u = unit(axis);
        const double gap = 6.0 * m_px;
        candidates.clear();
        // Beside the rail on the hatched side, which the mechanism keeps clear of, from the
        // middle outwards; then on the other side; then past its ends; then farther out.
        for (double extra : {0.0, 14.0 * m_px}) {
            for (double side : {1.0, -1.0}) {
                const QPointF normal = side * pending.outer;
                const double lift = (side > 0.0 ? pending.outerReach : pending.innerReach) + gap + extra;
                for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9})
                    candidates.push_back(pending.start + fraction * axis + (lift + support(normal, size)) * normal);
            }
        }
        for (const QPointF &tip : {pending.end, pending.start}) {
            const QPointF out = tip == pending.end ? u : -u;
            candidates.push_back(tip + (gap + 10.0 * m_px + support(out, size)) * out);
        }
        for (double extra = 30.0 * m_px; extra <= 120.0 * m_px; extra += 15.0 * m_px) {
            for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
                const QPointF normal = pending.outer;
                candidates.push_back(
                    pending.start + fraction * axis + (pending.outerReach + extra + support(normal, size)) * normal);
            }
        }
        placeFirstFree(SceneLabel {{}, 0.0, pending.text, false, pending.colour, drawing::Layer::Text, {}}, candidates);
    }
}

void SceneLabels::placeJointLabels()
{
    std::vector<QPointF> candidates;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        const std::string &name = m_scene.joints[i].label;
        if (name.empty() || !valid(int(i)))
            continue;
        // Preferred: the middles of the angular gaps between what leaves the joint (members,
        // ground, extension lines, arc labels), widest first; then all round, farther out.
        std::vector<double> taken;
        for (const Ray &ray : m_rays[i])
            taken.push_back(sceneAngle(ray.direction));
        std::sort(taken.begin(), taken.end());
        std::vector<std::pair<double, double>> gaps; // (width, middle)
        for (std::size_t k = 0; k < taken.size(); ++k) {
            const double a = taken[k];
            const double b = k + 1 < taken.size() ? taken[k + 1] : taken.front() + 2.0 * pi;
            gaps.emplace_back(b - a, 0.5 * (a + b));
        }
        std::sort(gaps.begin(), gaps.end(), [](const auto &x, const auto &y) { return x.first > y.first; });
        if (gaps.empty())
            gaps.emplace_back(2.0 * pi, 45.0 * degree);

        const QString text = QString::fromStdString(name);
        const QSizeF size = textSize(text, true);
        const double clear = (m_style.pivotRadius + (m_style.showHandles ? 10.0 : 5.0)) * m_px;
        auto centreAt = [&](double a, double extra) {
            const QPointF u = deviceDirection(a);
            return m_points[i] + (clear + extra + support(u, size)) * u;
        };
        candidates.clear();
        for (const auto &[width, middle] : gaps) {
            if (width > 25.0 * degree)
                candidates.push_back(centreAt(middle, 0.0));
        }
        // The far rings clear a large neighbour such as a zoomed-in carriage.
        for (double extra : {0.0, 8.0 * m_px, 16.0 * m_px, 26.0 * m_px, 40.0 * m_px, 60.0 * m_px, 90.0 * m_px}) {
            for (int k = 0; k < 24; ++k)
                candidates.push_back(centreAt(gaps.front().second + k * 15.0 * degree, extra));
        }
        placeFirstFree(SceneLabel {{}, 0.0, text, true, m_style.ink, drawing::Layer::Text, {}}, candidates);
    }
}

// -- adding to the draw list --------------------------------------------------------------

void SceneLabels::addTo(drawing::DrawList &list) const
{
    for (const SceneLabel &label : m_labels) {
        drawing::Text text {label.centre, label.rotationDegrees, label.text, label.joint ? m_jointFont : m_font,
            label.colour, textSize(label.text, label.joint), m_style.background, label.cad};
        list.add(std::move(text), label.layer);
    }
}

} // namespace pkm
