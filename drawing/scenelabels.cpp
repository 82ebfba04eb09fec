#include "scenelabels.h"

#include "scenegeometry.h"


#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
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

void SceneLabels::addObstacle(const QPointF &a, const QPointF &b, double halfWidth, bool faint)
{
    m_obstacles.push_back({segmentQuad(a, b, halfWidth), a, b, halfWidth, true, faint});
}

void SceneLabels::addObstacle(const Quad &quad)
{
    m_obstacles.push_back({quad, {}, {}, 0.0, false});
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
    m_labelBoxes.push_back(boxQuad(label.centre, textSize(label.text, label.joint), label.rotationDegrees));
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

/// How long a stretch of the line from `a` to `b`, `2 × halfWidth` wide, lies in the
/// rectangle `box` (corners in order round it).
double detail::coveredLength(const Quad &box, const QPointF &a, const QPointF &b, double halfWidth)
{
    const QPointF e1 = box[1] - box[0], e2 = box[3] - box[0];
    const double w = length(e1), h = length(e2);
    if (w <= 0.0 || h <= 0.0)
        return 0.0;
    const QPointF u = e1 / w, v = e2 / h;
    // Liang–Barsky in the box's own frame, the box grown by the line's half width.
    const QPointF p(dot(a - box[0], u), dot(a - box[0], v)), d(dot(b - a, u), dot(b - a, v));
    double t0 = 0.0, t1 = 1.0;
    const auto clip = [&t0, &t1](double q, double r) { // keeps the part where q·t ≤ r
        if (q == 0.0)
            return r >= 0.0;
        const double t = r / q;
        if (q < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        return t0 <= t1;
    };
    const bool inside = clip(-d.x(), p.x() + halfWidth) && clip(d.x(), w + halfWidth - p.x())
        && clip(-d.y(), p.y() + halfWidth) && clip(d.y(), h + halfWidth - p.y());
    // A point with a width (a pin's ring, which the layout adds as a line of no length) hides
    // its whole disc: as long a stretch as it is wide.
    return inside ? std::max((t1 - t0) * length(b - a), length(b - a) > 0.0 ? 0.0 : 2.0 * halfWidth) : 0.0;
}

double SceneLabels::collisions(const Quad &box, double enough, double perLine) const
{
    // A label over another label hides text, over a pin's ring a joint; over a line it interrupts
    // the line, the more the more of it it hides (a label across a bar costs less than one
    // along it, one over a hatch line less than one over a bar).
    double cost = outside(box) ? coversALabel : 0.0; // cut by the view's edge: as bad as hidden
    if (cost >= enough)
        return cost;
    for (const Quad &q : m_labelBoxes) {
        if (overlap(box, q) && (cost += coversALabel) >= enough)
            return cost;
    }
    for (const Quad &q : m_reserved) {
        if (overlap(box, q) && (cost += 3.0 * perLine) >= enough)
            return cost;
    }
    for (const Obstacle &o : m_obstacles) {
        if (o.faint || !overlap(box, o.quad))
            continue;
        // the area hidden: a bar counts for more than a thin line
        const double hidden = o.line ? coveredLength(box, o.a, o.b, o.halfWidth) * std::max(2.0 * o.halfWidth, 2.0 * m_px) : 0.0;
        if ((cost += perLine * (0.5 + hidden / (80.0 * m_px * m_px))) >= enough)
            return cost;
    }
    return cost;
}

double SceneLabels::thinLinesOnly(const Quad &box) const
{
    double cost = collisions(box, coversALabel, 0.0); // labels only
    for (const Quad &q : m_reserved) // a joint's name's first place counts as a thin line
        cost += overlap(box, q) ? 1.0 : 0.0;
    for (const Obstacle &o : m_obstacles) {
        if (cost < coversALabel && !o.faint && overlap(box, o.quad))
            // bars are 4.5 px wide each side of their axis, dimension lines 3.5, the ground 2.25
            cost += !o.line || o.halfWidth < 4.0 * m_px ? 1.0 : coversALabel;
        else if (o.leader && overlap(box, o.quad))
            cost += 1.5; // worse than one thin line, better than two
    }
    return cost;
}

bool SceneLabels::isFree(const Quad &box, bool faint) const
{
    const auto covers = [&box](const Quad &q) { return overlap(box, q); };
    return !outside(box) && std::none_of(m_labelBoxes.begin(), m_labelBoxes.end(), covers)
        && std::none_of(m_reserved.begin(), m_reserved.end(), covers)
        && std::none_of(m_obstacles.begin(), m_obstacles.end(),
                        [&](const Obstacle &o) { return (faint || !o.faint) && overlap(box, o.quad); });
}

std::optional<QLineF> SceneLabels::leaderToBox(const QPointF &anchor, const QPointF &centre, const QSizeF &size, double slack)
{
    const QPointF d = anchor - centre;
    const double t = std::min(std::abs(d.x()) > 1e-9 ? 0.5 * size.width() / std::abs(d.x()) : 1e300,
        std::abs(d.y()) > 1e-9 ? 0.5 * size.height() / std::abs(d.y()) : 1e300);
    if (t >= 1.0 || length(d) * (1.0 - t) < slack)
        return std::nullopt;
    return QLineF(anchor, centre + t * d);
}

bool SceneLabels::leaderIsClear(const Leader &leader) const
{
    if (leader.nearerAnother)
        return false;
    const Quad line = segmentQuad(leader.line.p1(), leader.line.p2(), 0.5 * m_px);
    const QPointF &from = leader.from, &to = leader.to;
    const auto at = [](const QPointF &p, const QPointF &q) { return length(p - q) < 1.0; };
    const bool joint = at(from, to);
    for (const Quad &q : m_labelBoxes) {
        if (overlap(line, q))
            return false;
    }
    for (const Obstacle &o : m_obstacles) {
        // a bar is 4.5 px wide each side of its axis and a pivot's ring about as wide; the
        // hatching, extension and dimension lines are thinner, and a leader may cross them
        const bool matters = !o.line || (o.halfWidth >= 4.0 * m_px && !(leader.acrossBars && length(o.b - o.a) > 0.0));
        const bool named = o.line
            && (joint ? at(o.a, from) || at(o.b, from) : (at(o.a, from) && at(o.b, to)) || (at(o.a, to) && at(o.b, from)));
        if (!matters || named)
            continue;
        if (overlap(line, o.quad))
            return false;
    }
    return true;
}

bool SceneLabels::onALeader(const Quad &box) const
{
    return std::any_of(m_obstacles.begin(), m_obstacles.end(), [&](const Obstacle &o) { return o.leader && overlap(box, o.quad); });
}

bool SceneLabels::placeFirstFree(SceneLabel label, const std::vector<QPointF> &candidates, double leaveOutAt,
    std::size_t near, double nearEnough, const LeaderFor &leaderFor)
{
    const QSizeF size = textSize(label.text, label.joint) + QSizeF(4.0 * m_px, 4.0 * m_px); // keep a gap
    const auto boxAt = [&](std::size_t k) { return boxQuad(candidates[k], size, label.rotationDegrees); };
    const auto leaderAt = [&](std::size_t k) { return leaderFor ? leaderFor(k) : std::nullopt; };
    // Free and off the angles' leaders (a name over one reads as part of the angle's label:
    // the four-bar's "P −δ = 79.1°"), and where it needs a leader, one that crosses nothing a
    // reader would follow instead.
    const auto clear = [&](std::size_t k) {
        if (!isFree(boxAt(k), false) || onALeader(boxAt(k)))
            return false;
        const std::optional<Leader> leader = leaderAt(k);
        return !leader || leaderIsClear(*leader);
    };
    const std::size_t count = candidates.size();
    near = std::min(near, count);
    // The first free one of the first `near`; else the one of those that covers fewest thin
    // lines (fewer than `nearEnough`) and nothing else; else the first free one after them
    // (with a clear leader where it needs one, if there is such a place); else the one that
    // covers least, earlier ones (nearer to what the label names) first among equals. A free
    // place is the rule: the costs are worked out only when there is none.
    std::size_t chosen = count;
    double best = 0.0;
    // Of the nearest places (all, for a label without leaders), the first clear of the ghosts
    // too; the search below does not see them.
    const std::size_t nearest = near > 0 ? near : leaderFor ? 0 : count;
    for (std::size_t k = 0; k < nearest && chosen == count; ++k) {
        if (isFree(boxAt(k), true) && (!leaderAt(k) || leaderIsClear(*leaderAt(k))))
            chosen = k;
    }
    for (std::size_t k = 0; k < near && chosen == count; ++k)
        chosen = isFree(boxAt(k), false) && !onALeader(boxAt(k)) ? k : count;
    if (chosen == count && near > 0) {
        best = nearEnough;
        for (std::size_t k = 0; k < near; ++k) {
            const double thin = thinLinesOnly(boxAt(k)) + (onALeader(boxAt(k)) ? nearEnough : 0.0);
            if (thin < best) {
                best = thin;
                chosen = k;
            }
        }
    }
    for (std::size_t k = near; k < count && chosen == count; ++k)
        chosen = clear(k) ? k : count;
    for (std::size_t k = near; leaderFor && k < count && chosen == count; ++k)
        chosen = isFree(boxAt(k), false) && !onALeader(boxAt(k)) ? k : count;
    // A label that may be left out (a bar's name) is rather left out than put on an angle's
    // leader, so any place off the leaders that covers less wins: the П-joint's b sat on μ's
    // leader, kept there from frame to frame, while a place beside C was left.
    const double onALeaderCost = std::isfinite(leaveOutAt) ? leaveOutAt : 1.0;
    if (chosen == count) {
        best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < count; ++k) {
            const double cost = collisions(boxAt(k), best) + (onALeader(boxAt(k)) ? onALeaderCost : 0.0);
            if (cost < best) {
                best = cost;
                chosen = k;
            }
        }
    }
    // In motion, unless the place chosen is free with room to spare (keptMargin): where it
    // stood in the frame before (setPrevious()) while that is still free (a ghost moving under
    // it may stay) and off the leaders, with its leader if it had one; else the free place
    // nearest to that, if one is near and no farther from what it names than the one chosen.
    // A label moves no more than what it names rather than to the first free place in the
    // order: during Play MOMA's Z₁, PO₁ and S₂ went from side to side and back.
    if (!label.anchor && count > 0)
        label.anchor = candidates.front();
    const std::optional<QPointF> was = count > 0 ? lastPlace(label.text, *label.anchor) : std::nullopt;
    const bool roomy = chosen < count && best == 0.0
        && isFree(boxQuad(candidates[chosen], size + QSizeF(2.0 * keptMargin, 2.0 * keptMargin) * m_px, label.rotationDegrees));
    if (was && chosen < count && !roomy) {
        const auto away = [&](std::size_t k) { return QLineF(candidates[k], *was).length(); };
        std::vector<std::size_t> nearer;
        for (std::size_t k = 0; k < count; ++k) {
            if (k != chosen && away(k) < away(chosen) && away(k) < size.width() + size.height())
                nearer.push_back(k);
        }
        std::sort(nearer.begin(), nearer.end(), [&](std::size_t a, std::size_t b) { return away(a) < away(b); });
        for (const std::size_t k : nearer) {
            if ((best > 0.0 || k < near || chosen >= near || away(k) < 1.0) && clear(k) && !onALeader(boxAt(k))) {
                chosen = k;
                best = 0.0;
                break;
            }
        }
    }
    if (chosen == count || best >= leaveOutAt)
        return false;
    // A name that may be left out (a bar's) is, where its leader would have to cross what it
    // does not name: the ground under the five-bar's crank angle label.
    const std::optional<Leader> leader = leaderAt(chosen);
    if (leader && std::isfinite(leaveOutAt) && !leaderIsClear(*leader))
        return false;
    label.centre = candidates[chosen];
    place(label);
    if (leader)
        m_nameLeaders.push_back({leader->line, label.colour, false});
    return best == 0.0;
}

namespace {
/// A label as the next frame knows it: a value's symbol ("θ₄" of "θ₄ = 60.7°", whose number
/// changes as it moves), else its text.
QString placeKey(const QString &text)
{
    const qsizetype equals = text.indexOf(QStringLiteral(" = "));
    return equals > 0 ? text.left(equals) : text;
}
} // namespace

std::optional<QPointF> SceneLabels::lastPlace(const QString &text, const QPointF &anchor) const
{
    if (!m_previous)
        return std::nullopt;
    const QString key = placeKey(text);
    const auto was = std::find_if(m_previous->begin(), m_previous->end(), [&](const auto &place) { return place.first == key; });
    return was == m_previous->end() ? std::nullopt : std::optional<QPointF>(anchor + was->second);
}

std::vector<std::pair<QString, QPointF>> SceneLabels::places() const
{
    std::vector<std::pair<QString, QPointF>> placed;
    placed.reserve(m_labels.size());
    for (const SceneLabel &label : m_labels)
        placed.emplace_back(placeKey(label.text), label.centre - label.anchor.value_or(QPointF()));
    return placed;
}

// -- adding to the draw list --------------------------------------------------------------

void SceneLabels::addTo(drawing::DrawList &list) const
{
    if (!m_leaders.empty()) {
        drawing::Lines leaders {m_leaders, {m_style.angle, 1.0 * m_px, Qt::RoundCap}};
        list.add(std::move(leaders), drawing::Layer::Dimensions);
    }
    for (const NameLeader &leader : m_nameLeaders) {
        // fainter than the name: it shows where the name belongs and draws no eye from the drawing
        QColor faint = leader.colour;
        faint.setAlphaF(0.6f * faint.alphaF());
        list.add(drawing::Lines {{leader.line}, {faint, 1.0 * m_px, Qt::RoundCap}}, drawing::Layer::Text,
            leader.screenOnly ? drawing::Medium::Screen : drawing::Medium::All);
    }
    for (const SceneLabel &label : m_labels) {
        drawing::Text text {label.centre, label.rotationDegrees, label.text, label.joint ? m_jointFont : m_font,
            label.colour, textSize(label.text, label.joint), m_style.background, label.cad};
        if (label.cadPlace) {
            drawing::Text onLine = text;
            std::tie(onLine.centre, onLine.rotationDegrees) = *label.cadPlace;
            list.add(std::move(onLine), label.layer, drawing::Medium::Cad);
        }
        list.add(std::move(text), label.layer, label.cadPlace ? drawing::Medium::Screen : drawing::Medium::All);
    }
}

} // namespace pkm
