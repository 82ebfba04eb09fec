// Where each pending label goes, once all geometry is known (SceneLabels::placeAll()): the
// candidate places of dimension text, angle labels (with a leader where one is pushed away from
// its arc), guide and bar names, most constrained first; the joints' names are placed in
// scenejointnames.cpp. What a place costs is in scenelabels.cpp.
#include "scenelabels.h"

#include "scenegeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace pkm {

using namespace detail;

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

bool SceneLabels::nearerAnotherBar(const QPointF &centre, int from, int to) const
{
    const auto distance = [&centre](const QPointF &a, const QPointF &b) { return distanceToSegment(centre, a, b); };
    const double own = distance(point(from), point(to));
    return std::any_of(m_scene.bars.begin(), m_scene.bars.end(), [&](const SceneBar &bar) {
        const bool same = (bar.from == from && bar.to == to) || (bar.from == to && bar.to == from);
        return !same && valid(bar.from) && valid(bar.to) && distance(point(bar.from), point(bar.to)) < own;
    });
}

void SceneLabels::placeAll()
{
    // Most constrained first: dimension text along members, angle labels near their arcs
    // (or with a leader to them), bar names (which may slide along their bar), then joint
    // names (anywhere around).
    for (const PendingFreeLabel &pending : m_freeLabels)
        placeFirstFree(pending.label, pending.candidates);
    settleJointNames();
    reserveJointNames();
    reserveBarNames();
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
    const QPointF centroid = shownCentroid();
    std::vector<QPointF> candidates;
    std::vector<std::optional<QPointF>> anchors; // where a candidate's leader starts, if it needs one
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
            pending.preferReadingUp ? drawing::Layer::Dimensions : drawing::Layer::Text, pending.cad, {}, {}};
        double firstSide = 1.0;
        if (pending.preferReadingUp) {
            // Rotated with the member, above it as read.
            label.rotationDegrees = readableRotation(u);
            const QPointF up = deviceDirection((90.0 - label.rotationDegrees) * degree);
            firstSide = dot(up, left) >= 0.0 ? 1.0 : -1.0;
        } else {
            firstSide = barNameSide(pending, centroid);
        }
        candidates.clear();
        anchors.clear();
        // Beside the member, then a step farther out where a neighbour's text stands there
        // (the П-joint's coupler under the diagonal's dimension in a tight pose).
        // A dimension's text stays near its member, which it would not name from farther out.
        const std::vector<double> extras = pending.preferReadingUp ? std::vector<double> {0.0, 10.0}
                                                                   : std::vector<double> {0.0, 10.0, 22.0, 36.0, 54.0};
        std::size_t near = 0;
        for (double extra : extras) {
            for (double side : {firstSide, -firstSide}) {
                if (extra == 0.0 && side != firstSide)
                    near = candidates.size();
                for (double fraction : {0.5, 0.42, 0.58, 0.34, 0.66, 0.26, 0.74}) {
                    const QPointF normal = side * left;
                    const double extent = pending.preferReadingUp ? 0.5 * size.height() : support(normal, size);
                    const double edge = memberHalfWidth(pending.from, pending.to, fraction) + 1.0 * m_px;
                    const QPointF onMember = p + fraction * (q - p);
                    const QPointF centre = memberLabelCentre(pending, fraction, normal, extent, extra);
                    // a name nearer another bar than its own would name that one (MOMA's S₁
                    // between both links)
                    if (!dimensions && nearerAnotherBar(centre, pending.from, pending.to))
                        continue;
                    candidates.push_back(centre);
                    // a step out, a name could be read as another bar's or the space's between
                    // bars (the five-bar's AE inside the loop): a leader ties it to its own
                    anchors.push_back(extra > 0.0 ? std::optional<QPointF>(onMember + edge * normal) : std::nullopt);
                }
            }
        }
        const auto leaderFor = [&](std::size_t k) -> std::optional<Leader> {
            if (!anchors[k])
                return std::nullopt;
            const std::optional<QLineF> line = leaderToBox(*anchors[k], candidates[k], size, 8.0 * m_px);
            return line ? std::optional<Leader>(Leader {*line, p, q}) : std::nullopt;
        };
        if (dimensions) {
            placeDimensionText(pending, label, candidates);
            continue;
        }
        // A bar's name that would cover another label is left out: the bar is named by its
        // dimension or its joints, and a pile of text names nothing.
        // A name next to its bar on the outside may cover one thin line (a guide's axis, an
        // angle's reference) rather than go inside, where between two bars it names either.
        placeFirstFree(label, candidates, coversALabel, near, 2.0, leaderFor);
    }
}

QPointF SceneLabels::shownCentroid() const
{
    QPointF centroid;
    int shown = 0;
    for (int j = 0; j < int(m_points.size()); ++j) {
        if (valid(j)) {
            centroid += point(j);
            ++shown;
        }
    }
    return shown > 0 ? centroid / double(shown) : centroid;
}

double SceneLabels::barNameSide(const PendingMemberLabel &pending, const QPointF &centroid) const
{
    // upright, on the outside of the mechanism
    const QPointF p = point(pending.from), q = point(pending.to);
    return dot(screenLeft(unit(q - p)), 0.5 * (p + q) - centroid) >= 0.0 ? 1.0 : -1.0;
}

QPointF SceneLabels::memberLabelCentre(const PendingMemberLabel &pending, double fraction, const QPointF &normal, double extent,
    double extra) const
{
    const QPointF p = point(pending.from), q = point(pending.to);
    const double edge = memberHalfWidth(pending.from, pending.to, fraction) + 1.0 * m_px;
    return p + fraction * (q - p) + (edge + (4.0 + extra) * m_px + extent) * normal;
}

void SceneLabels::reserveBarNames()
{
    // Where each bar's name goes first (beside its middle, outward): an angle label's leader
    // keeps off while it has another way, so that the name is not pushed off or left on it
    // (the П-joint's coupler name b under μ's leader in a tight pose).
    m_barNamePlaces.clear();
    const QPointF centroid = shownCentroid();
    for (const PendingMemberLabel &pending : m_memberLabels) {
        if (pending.preferReadingUp || !valid(pending.from) || !valid(pending.to)
            || length(point(pending.to) - point(pending.from)) < 1e-6)
            continue;
        const QSizeF size = textSize(pending.text);
        const QPointF normal = barNameSide(pending, centroid) * screenLeft(unit(point(pending.to) - point(pending.from)));
        m_barNamePlaces.push_back(boxQuad(memberLabelCentre(pending, 0.5, normal, support(normal, size), 0.0), size, 0.0));
    }
}

void SceneLabels::placeDimensionText(const PendingMemberLabel &pending, const SceneLabel &label, const std::vector<QPointF> &beside)
{
    // Beside its member, along it, where it covers nothing or a thin line or two.
    const std::size_t before = m_labels.size();
    placeFirstFree(label, beside, 1.0, beside.size(), 3.0);
    if (m_labels.size() > before)
        return;
    // Else upright and out of the crowd, with a leader to its member: the П-joint's
    // "d = 183.1 mm" between the bars of a small parallelogram covered one of them.
    const QPointF p = point(pending.from), q = point(pending.to);
    const QPointF left = screenLeft(unit(q - p));
    const QSizeF size = textSize(pending.text);
    std::vector<QPointF> candidates;
    std::vector<QPointF> anchors;
    for (double extra : {12.0, 24.0, 38.0, 54.0, 74.0}) {
        for (double side : {1.0, -1.0}) {
            for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7}) {
                const QPointF normal = side * left;
                const double edge = memberHalfWidth(pending.from, pending.to, fraction) + 1.0 * m_px;
                const QPointF onMember = p + fraction * (q - p);
                candidates.push_back(onMember + (edge + extra * m_px + support(normal, size)) * normal);
                anchors.push_back(onMember + edge * normal);
            }
        }
    }
    // and past either end, where a near-vertical member has room above or below it
    const QPointF u = unit(q - p);
    for (double extra : {10.0, 22.0, 36.0}) {
        for (double end : {1.0, 0.0}) {
            const QPointF out = end > 0.5 ? u : -u;
            const QPointF tip = end > 0.5 ? q : p;
            for (double lateral : {0.0, 1.0, -1.0}) {
                const QPointF aside = lateral * (0.5 * size.width() + 6.0 * m_px) * left;
                candidates.push_back(tip + (m_style.pivotRadius * m_px + extra * m_px + support(out, size)) * out + aside);
                anchors.push_back(p + (end > 0.5 ? 0.85 : 0.15) * (q - p));
            }
        }
    }
    const auto leaderFor = [&](std::size_t k) -> std::optional<Leader> {
        const std::optional<QLineF> line = leaderToBox(anchors[k], candidates[k], size, 4.0 * m_px);
        return line ? std::optional<Leader>(Leader {*line, p, q, true}) : std::nullopt;
    };
    SceneLabel upright = label;
    upright.rotationDegrees = 0.0;
    placeFirstFree(upright, candidates, 0.5, 0, 0.0, leaderFor);
    if (m_labels.size() > before) {
        // a CAD drawing keeps the text on its dimension line, where it reads as that dimension's
        m_labels.back().cadPlace = std::make_pair(beside.front(), label.rotationDegrees);
        if (!m_nameLeaders.empty())
            m_nameLeaders.back().screenOnly = true;
        return;
    }
    // Where neither is free, beside the member where it covers least.
    placeFirstFree(label, beside);
}

void SceneLabels::placeAngleLabels()
{
    std::vector<QPointF> near, around;
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
        // leg, then past the start leg, then a little farther out.
        const double middle = pending.start + 0.5 * pending.sweep;
        near.assign(1, centreAt(middle, 0.0));
        // Steps of 4°, or of 12 px along a large arc, so the label stays close to it.
        const double angleStep = std::min(4.0 * degree, 12.0 * m_px / std::max(pending.radius, 1e-9));
        auto stepRound = [&](int first, int last) {
            for (int step = first; step <= last; ++step) {
                const double delta = step * angleStep;
                near.push_back(centreAt(end + turn * delta, 0.0));
                near.push_back(centreAt(pending.start - turn * delta, 0.0));
            }
        };
        stepRound(1, 5);
        for (int step = 1; step <= 3; ++step)
            near.push_back(centreAt(middle, step * 10.0 * m_px));
        stepRound(6, 20);
        const QSizeF room = size + QSizeF(4.0 * m_px, 4.0 * m_px); // keep a gap
        // The first near candidate that covers nothing. When none does, the one all round
        // that costs least, a leader counting for its length and for what it crosses, near
        // candidates first among equals. A leader that is long or crosses much of the drawing
        // would tie the label to the wrong thing: such a place is not taken.
        // A near place a little off the arc has a leader to it; one whose leader runs under
        // another label is not free while another is (the П-joint's θ leader ran under
        // "a = 170 mm", of which a stray tick was left).
        const auto leaderClear = [&](const QPointF &candidate) {
            const std::optional<QLineF> line = leaderTo(pending, candidate, size);
            if (!line)
                return true;
            const QPointF start = line->p1() + 5.0 * m_px * unit(line->p2() - line->p1());
            return collisions(segmentQuad(start, line->p2(), 1.0 * m_px), coversALabel, 0.0) < coversALabel;
        };
        double best = std::numeric_limits<double>::infinity();
        QPointF centre;
        // A free place that reads as another joint's costs as much as a short leader: at a
        // large text size the five-bar's θ₁ went under the ground beside E, and E inside.
        constexpr double readsAsAnother = 2.0;
        // A leader across where a bar's or a joint's name goes first leaves the name on it or
        // pushes it off (the П-joint's b under μ's leader, the four-bar's A under α's).
        const auto overAName = [&](const QLineF &line) {
            const Quad path = segmentQuad(line.p1() + 5.0 * m_px * unit(line.p2() - line.p1()), line.p2(), 1.0 * m_px);
            const auto under = [&](const Quad &place) { return overlap(path, place); };
            return std::any_of(m_barNamePlaces.begin(), m_barNamePlaces.end(), under)
                || std::any_of(m_reserved.begin(), m_reserved.end(), under);
        };
        const auto leaderOverAName = [&](const QPointF &candidate) {
            const std::optional<QLineF> line = leaderTo(pending, candidate, size);
            return line && overAName(*line);
        };
        // An earlier angle label's leader is no obstacle to a joint's name, but an angle label
        // over it hides where it goes.
        const auto onALeader = [&](const QPointF &candidate) {
            const Quad box = boxQuad(candidate, room, 0.0);
            return std::any_of(m_leaders.begin(), m_leaders.end(),
                [&](const QLineF &line) { return overlap(box, segmentQuad(line.p1(), line.p2(), 1.0 * m_px)); });
        };
        for (const QPointF &candidate : near) {
            if (!isFree(boxQuad(candidate, room, 0.0)) || onALeader(candidate) || !leaderClear(candidate) || leaderOverAName(candidate))
                continue;
            if (!nearerAnotherJoint(candidate, size, pending.vertex)) {
                best = 0.0;
                centre = candidate;
                break;
            }
            if (best > readsAsAnother) {
                best = readsAsAnother;
                centre = candidate;
            }
        }
        for (std::size_t k = 0; best > 0.0 && k < near.size(); ++k) {
            const double cost = collisions(boxQuad(near[k], room, 0.0), best)
                + (nearerAnotherJoint(near[k], size, pending.vertex) ? readsAsAnother : 0.0)
                + (onALeader(near[k]) ? coversALabel : 0.0);
            if (cost < best) {
                best = cost;
                centre = near[k];
            }
        }
        // In motion, where it stood in the frame before while that is still free, reads as its
        // own angle and has a short, clear leader if it needs one, unless the place beside its
        // arc found above is free with room to spare (a margin, so that a place freed by a
        // pixel does not pull it back and forth): the five-bar's θ₁ went from under the ground
        // to beside its arc and back within three frames of Play.
        const bool roomy = best == 0.0 && isFree(boxQuad(centre, room + QSizeF(2.0 * keptMargin, 2.0 * keptMargin) * m_px, 0.0));
        if (const std::optional<QPointF> was = lastPlace(pending.text, v);
            was && !roomy && isFree(boxQuad(*was, room, 0.0)) && !onALeader(*was) && leaderClear(*was)
            && !leaderOverAName(*was) && !nearerAnotherJoint(*was, size, pending.vertex)) {
            const std::optional<QLineF> line = leaderTo(pending, *was, size);
            const bool shortAndClear = !line
                || (line->length() <= 80.0 * m_px
                    && collisions(segmentQuad(line->p1() + 5.0 * m_px * unit(line->p2() - line->p1()), line->p2(), 1.0 * m_px), 3.0) < 3.0);
            if (shortAndClear) {
                best = 0.0;
                centre = *was;
            }
        }
        // a leader that would run under another label shows only a stray tick beside it: the
        // label, a few pixels off its arc, goes without
        std::optional<QLineF> leader = leaderClear(centre) ? leaderTo(pending, centre, size) : std::nullopt;
        // Where none of those is free (a narrow angle inside a tight pose), all round the
        // vertex ring by ring. A label away from its arc gets a leader to it, so that it still
        // names its angle rather than the joint it lands near (μ at A, not at C).
        around.clear();
        if (best > 0.0) {
            for (double extra : {15.0, 30.0, 45.0, 60.0, 80.0, 100.0, 130.0, 160.0}) {
                for (int k = 0; k < 24; ++k) {
                    const double turnBy = (k % 2 == 0 ? 1.0 : -1.0) * ((k + 1) / 2) * 15.0 * degree;
                    around.push_back(centreAt(middle + turnBy, extra * m_px));
                }
            }
        }
        for (std::size_t k = 0; best > 0.0 && k < around.size(); ++k) {
            const std::optional<QLineF> line = leaderTo(pending, around[k], size);
            double cost = collisions(boxQuad(around[k], room, 0.0), best) + (onALeader(around[k]) ? coversALabel : 0.0);
            if (line && cost < best) {
                // It starts a little off the arc, which it touches.
                const QPointF start = line->p1() + 5.0 * m_px * unit(line->p2() - line->p1());
                const Quad path = segmentQuad(start, line->p2(), 1.0 * m_px);
                const double crossed = collisions(path, 3.0);
                if (crossed >= 3.0 || line->length() > 80.0 * m_px)
                    continue;
                cost += 0.5 + 0.02 * line->length() / m_px + 1.5 * crossed + (overAName(*line) ? readsAsAnother : 0.0);
            }
            if (cost < best) {
                best = cost;
                centre = around[k];
                leader = line;
            }
        }
        // A label that would cover another one anywhere (a drawing too small for its text)
        // is left out: the values panel states the angle, and a pile of text states nothing.
        if (best >= coversALabel)
            continue;
        place(SceneLabel {centre, 0.0, pending.text, false, m_style.angle, drawing::Layer::Dimensions, {}, {}, v});
        if (leader) {
            m_leaders.push_back(*leader);
            // Only a bar's name keeps off it (the five-bar's "AE" sat on θ₁'s leader): a
            // joint's name may cover a little of a leader rather than move off its joint.
            addObstacle(leader->p1(), leader->p2(), 1.0 * m_px, true);
            m_obstacles.back().leader = true;
        }
        addRay(pending.vertex, centre - v, length(centre - v));
    }
}

bool SceneLabels::nearerAnotherJoint(const QPointF &centre, const QSizeF &size, int vertex) const
{
    // the gap from the label's box to a joint: a wide label reads by its edge, not its centre
    const auto gap = [&](const QPointF &joint) {
        const double dx = std::max(std::abs(joint.x() - centre.x()) - 0.5 * size.width(), 0.0);
        const double dy = std::max(std::abs(joint.y() - centre.y()) - 0.5 * size.height(), 0.0);
        return std::hypot(dx, dy);
    };
    const double own = gap(point(vertex));
    for (std::size_t j = 0; j < m_points.size(); ++j) {
        if (int(j) != vertex && named(j) && gap(m_points[j]) < own)
            return true;
    }
    return false;
}

std::optional<QLineF> SceneLabels::leaderTo(const PendingAngleLabel &pending, const QPointF &centre, const QSizeF &size) const
{
    // From the point of the arc nearest the label to the edge of the label's box.
    const QPointF v = point(pending.vertex);
    const double middle = pending.start + 0.5 * pending.sweep;
    const double half = 0.5 * std::abs(pending.sweep);
    const double along = std::clamp(std::remainder(sceneAngle(centre - v) - middle, 2.0 * pi), -half, half);
    const QPointF onArc = v + pending.radius * deviceDirection(middle + along);
    const QPointF d = onArc - centre;
    const double t = std::min(std::abs(d.x()) > 1e-9 ? 0.5 * size.width() / std::abs(d.x()) : 1e300,
        std::abs(d.y()) > 1e-9 ? 0.5 * size.height() / std::abs(d.y()) : 1e300);
    if (t >= 1.0 || length(d) * (1.0 - t) < 8.0 * m_px)
        return std::nullopt; // the label touches its arc, or nearly
    return QLineF(onArc, centre + t * d);
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
        // middle outwards; then past its ends; then on the other side, where the mechanism
        // stands (the O-X glide's "D · 0" went inside its triangle, between the links, rather
        // than past the rail's end with the other rails' names); then farther out.
        const auto beside = [&](double side, double extra) {
            const QPointF normal = side * pending.outer;
            const double lift = (side > 0.0 ? pending.outerReach : pending.innerReach) + gap + extra;
            for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9})
                candidates.push_back(pending.start + fraction * axis + (lift + support(normal, size)) * normal);
        };
        beside(1.0, 0.0);
        for (const QPointF &tip : {pending.end, pending.start}) {
            const QPointF out = tip == pending.end ? u : -u;
            candidates.push_back(tip + (gap + 10.0 * m_px + support(out, size)) * out);
        }
        beside(-1.0, 0.0);
        beside(1.0, 14.0 * m_px);
        beside(-1.0, 14.0 * m_px);
        for (double extra = 30.0 * m_px; extra <= 120.0 * m_px; extra += 15.0 * m_px) {
            for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
                const QPointF normal = pending.outer;
                candidates.push_back(
                    pending.start + fraction * axis + (pending.outerReach + extra + support(normal, size)) * normal);
            }
        }
        placeFirstFree(SceneLabel {{}, 0.0, pending.text, false, pending.colour, drawing::Layer::Text, {}, {}, {}}, candidates);
    }
}

} // namespace pkm
