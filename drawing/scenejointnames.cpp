// Where the joints' names go (SceneLabels::placeJointLabels(), last of the labels): into the
// gaps between what leaves each joint, outward of the linkage where there is room, else in
// the widest gap, then all round farther out with a leader.
#include "scenelabels.h"

#include "scenegeometry.h"

#include <QPolygonF>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace pkm {

using namespace detail;

std::vector<std::pair<double, double>> SceneLabels::gapsAround(std::size_t joint) const
{
    std::vector<double> taken;
    for (const Ray &ray : m_rays[joint])
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
    return gaps;
}

QPointF SceneLabels::jointNameCentre(std::size_t joint, const QSizeF &size, double angle, double extra) const
{
    const double clear = (m_style.pivotRadius + (m_style.showHandles ? 10.0 : 5.0)) * m_px;
    const QPointF u = deviceDirection(angle);
    return m_points[joint] + (clear + extra + support(u, size)) * u;
}

QPointF SceneLabels::namedMiddle(int *count) const
{
    QPointF sum;
    int shown = 0;
    for (std::size_t j = 0; j < m_points.size(); ++j) {
        if (named(j)) {
            sum += m_points[j];
            ++shown;
        }
    }
    *count = shown;
    return shown > 0 ? sum / double(shown) : sum;
}

std::vector<double> SceneLabels::outwardNameAngles(std::size_t joint) const
{
    // Outward: from the middle of the named joints to this one. A name inside the linkage
    // stands among its bars and ghosts and reads as the space's between them (the 5R's A₁
    // and A₂ between the legs, over the other assembly mode's dashes).
    int named = 0;
    const QPointF middle = namedMiddle(&named);
    const QPointF away = named > 2 ? m_points[joint] - middle : QPointF();
    if (length(away) <= 4.0 * m_style.pivotRadius * m_px)
        return {}; // in the middle: no side is outward
    const double out = sceneAngle(away);
    // The gap wide enough for a name that contains the outward direction or is nearest to
    // it; in it, directions 15° apart that keep 30° from what bounds it, the most outward first.
    double nearest = std::numeric_limits<double>::infinity();
    std::vector<double> angles;
    for (const auto &[width, centre] : gapsAround(joint)) {
        if (width <= 60.0 * degree)
            continue;
        const double half = 0.5 * width - 30.0 * degree;
        const double toward = std::clamp(std::remainder(out - centre, 2.0 * pi), -half, half);
        const double off = std::abs(std::remainder(centre + toward - out, 2.0 * pi));
        if (off >= nearest)
            continue;
        nearest = off;
        angles.clear();
        for (double offset = -half; offset <= half + 1e-9; offset += 15.0 * degree)
            angles.push_back(centre + offset);
        std::stable_sort(angles.begin(), angles.end(), [&](double x, double y) {
            return std::abs(std::remainder(x - centre - toward, 2.0 * pi)) < std::abs(std::remainder(y - centre - toward, 2.0 * pi));
        });
    }
    // only a gap that faces outward, within 60°
    return nearest < 60.0 * degree ? angles : std::vector<double> {};
}

std::array<QPointF, 3> SceneLabels::groundNamePlaces(std::size_t joint, const QSizeF &size) const
{
    const QPointF p = m_points[joint];
    const double symbolHalf = 19.0 * m_px, symbolDepth = 22.0 * m_px; // drawGround()
    const double side = symbolHalf + 4.0 * m_px + 0.5 * size.width();
    int named = 0;
    const double outer = p.x() < namedMiddle(&named).x() && named > 0 ? -1.0 : 1.0;
    // beside it, under the line through the pivot (a ground line, an angle's reference line)
    const double beside = std::max(0.5 * symbolDepth, 0.5 * size.height() + 6.0 * m_px);
    return {p + QPointF(outer * side, beside), p + QPointF(0.0, symbolDepth + 3.0 * m_px + 0.5 * size.height()),
            p + QPointF(-outer * side, beside)};
}

void SceneLabels::settleJointNames()
{
    m_jointNames.assign(m_points.size(), QString());
    m_crowdedPlatform = QRectF();
    m_crowdedCorners.clear();
    for (std::size_t j = 0; j < m_points.size(); ++j) {
        if (!m_scene.joints[j].label.empty() && valid(int(j)))
            m_jointNames[j] = QString::fromStdString(m_scene.joints[j].label);
    }
    // A platform's corners drawn closer than one and a half times a name and two pivots side
    // by side leave no room beside each for its name: pushed a leg's length away with leaders, P₁…P₃ crossed
    // the base's names and read as theirs. A drawing that small names the platform by its
    // reference point alone (Oₚ, which is not a corner) and its legs by their bars; zoomed in,
    // the corners get their names back. Two corners (the O-X glide's A′B′ and C′D′ at the ends
    // of s) always have the outward side each.
    std::vector<std::size_t> corners;
    for (const SceneBar &bar : m_scene.bars) {
        for (const int end : {bar.from, bar.to}) {
            const std::size_t j = std::size_t(end);
            if (bar.kind == BarKind::Platform && named(j) && m_scene.joints[j].kind != JointKind::Point
                && std::find(corners.begin(), corners.end(), j) == corners.end())
                corners.push_back(j);
        }
    }
    double shortest = std::numeric_limits<double>::infinity(), widest = 0.0;
    for (std::size_t a = 0; a < corners.size(); ++a) {
        const QSizeF size = textSize(m_jointNames[corners[a]], true);
        widest = std::max({widest, size.width(), size.height()});
        for (std::size_t b = a + 1; b < corners.size(); ++b)
            shortest = std::min(shortest, length(m_points[corners[a]] - m_points[corners[b]]));
    }
    if (corners.size() >= 3 && shortest < 1.5 * (widest + 2.0 * m_style.pivotRadius * m_px)) {
        for (const std::size_t j : corners) {
            m_jointNames[j].clear();
            m_crowdedCorners.push_back(m_points[j]);
        }
        m_crowdedPlatform = QPolygonF(QList<QPointF>(m_crowdedCorners.begin(), m_crowdedCorners.end())).boundingRect();
    }
    // Joints on one spot by design (the 3-RP̲R's reference point Oₚ at its corner P₁) share
    // one name: the second, pushed off by the first, stood a leg's length away with a leader.
    // Two joints passing each other keep their own.
    const double together = 0.5 * m_px;
    for (std::size_t j = 0; j < m_points.size(); ++j) {
        for (std::size_t k = j + 1; k < m_points.size() && named(j); ++k) {
            if (named(k) && length(m_points[j] - m_points[k]) < together) {
                m_jointNames[j] += QStringLiteral(" = ") + m_jointNames[k];
                m_jointNames[k].clear();
            }
        }
    }
}

void SceneLabels::reserveJointNames()
{
    // Where each joint's name would go first (the middle of the widest gap at its joint): the
    // angle labels and bar names keep off while they have room elsewhere, so that "E" is not
    // pushed away from E by an angle measured at A.
    m_reserved.clear();
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        if (!named(i))
            continue;
        const QString &text = m_jointNames[i];
        const QSizeF size = textSize(text, true);
        // In motion, where it stood in the frame before instead: the widest gap can turn to
        // another side from one frame to the next and push the other labels with it.
        if (const std::optional<QPointF> was = lastPlace(text, m_points[i])) {
            m_reserved.push_back(boxQuad(*was, size, 0.0));
            continue;
        }
        // a ground pivot's beside its symbol (groundNamePlaces()), which the angle labels then
        // leave to it
        const QPointF place = m_scene.joints[i].kind == JointKind::Ground ? groundNamePlaces(i, size)[0]
                                                                          : jointNameCentre(i, size, gapsAround(i).front().second, 0.0);
        m_reserved.push_back(boxQuad(place, size, 0.0));
    }
}

void SceneLabels::placeJointLabels()
{
    m_reserved.clear();
    std::vector<QPointF> candidates;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        if (!named(i))
            continue;
        // A joint out of sight (the four-bar's instant centre P when AB and DC are nearly
        // parallel) keeps its name out too: in sight with a leader, it named nothing.
        if (!m_room.isEmpty() && !m_room.contains(m_points[i]))
            continue;
        // Preferred: outward beside the joint (outwardNameAngles()); else the middles of the angular
        // gaps between what leaves the joint (members, ground, extension lines, arc labels),
        // widest first; then all round, farther out.
        const QString &text = m_jointNames[i];
        const QSizeF size = textSize(text, true);
        const auto centreAt = [&](double a, double extra) { return jointNameCentre(i, size, a, extra); };
        const double clear = (m_style.pivotRadius + (m_style.showHandles ? 10.0 : 5.0)) * m_px;
        // Out there a name nearer another joint than its own reads as that one's, leader or
        // not (the five-bar's "E" under A): such places come last.
        const auto nearerAnother = [&](const QPointF &centre) {
            const double own = length(centre - m_points[i]);
            for (std::size_t j = 0; j < m_points.size(); ++j) {
                if (j != i && named(j) && length(centre - m_points[j]) < own)
                    return true;
            }
            return false;
        };
        candidates.clear();
        // Outward beside the joint, covering a little of one thin line at most (the ground's
        // hatching under a pivot), rather than free inside the linkage.
        const SceneLabel label {{}, 0.0, text, true, m_style.ink, drawing::Layer::Text, {}, {}, m_points[i]};
        const QSizeF room = size + QSizeF(4.0 * m_px, 4.0 * m_px); // keep a gap, as placeFirstFree()
        std::optional<QPointF> outside;
        double least = 1.0; // a little of a thin line (collisions()), never a bar, a pivot or a label
        for (const double angle : outwardNameAngles(i)) {
            if (least == 0.0)
                break;
            const QPointF centre = centreAt(angle, 0.0);
            // an angle's leader under a name reads as part of it ("P −δ = 79.1°")
            const double cost = collisions(boxQuad(centre, room, 0.0), least) + (onALeader(boxQuad(centre, room, 0.0)) ? 1.0 : 0.0);
            if (cost < least) {
                least = cost;
                outside = centre;
            }
        }
        // In motion, unless the outward place found is free with room to spare (keptMargin):
        // where it stood beside its joint in the frame before, while that is still free and
        // still nearest its own joint; else, of the outward places as good as the best, the
        // nearest to it if one is near (the best if none is: the nearest of those far
        // away put MOMA's Z₁ on R₁'s place as the slider left it).
        const std::optional<QPointF> was = lastPlace(text, m_points[i]);
        const bool roomy = outside && least == 0.0
            && isFree(boxQuad(*outside, room + QSizeF(2.0 * keptMargin, 2.0 * keptMargin) * m_px, 0.0));
        if (was && !roomy && length(*was - m_points[i]) < length(centreAt(0.0, 8.0 * m_px) - m_points[i]) + size.width()) {
            if (isFree(boxQuad(*was, room, 0.0), false) && !nearerAnother(*was)) {
                SceneLabel placed = label;
                placed.centre = *was;
                place(placed);
                continue;
            }
        }
        if (outside && was && !roomy) {
            for (const double angle : outwardNameAngles(i)) {
                const QPointF centre = centreAt(angle, 0.0);
                const double away = QLineF(centre, *was).length();
                if (away < QLineF(*outside, *was).length() && away < size.width() + size.height() && !nearerAnother(centre)
                    && collisions(boxQuad(centre, room, 0.0), least + 1e-9) <= least)
                    outside = centre;
            }
        }
        if (outside) {
            SceneLabel placed = label;
            placed.centre = *outside;
            place(placed);
            continue;
        }
        // A ground pivot's name beside its symbol, the outer side first, or under it, as a
        // drawing names it: the middle of the widest free gap put the five-bar's "E" inside
        // the linkage, among the ghosts, when its angle label took the place outward.
        if (m_scene.joints[i].kind == JointKind::Ground) {
            for (const QPointF &centre : groundNamePlaces(i, size))
                candidates.push_back(centre);
        }
        const std::vector<std::pair<double, double>> gaps = gapsAround(i);
        for (const auto &[width, middle] : gaps) {
            if (width > 25.0 * degree)
                candidates.push_back(centreAt(middle, 0.0));
        }
        // The far rings clear a large neighbour such as a zoomed-in carriage. Before going
        // there, a name next to its joint may cover a few thin lines, never a bar (in a
        // crowded pose a "B" far from B names the wrong joint).
        std::size_t near = 0;
        std::vector<QPointF> last;
        for (double extra : {0.0, 8.0 * m_px, 16.0 * m_px, 26.0 * m_px, 40.0 * m_px, 60.0 * m_px, 90.0 * m_px}) {
            for (int k = 0; k < 24; ++k) {
                const QPointF centre = centreAt(gaps.front().second + k * 15.0 * degree, extra);
                (extra < 16.0 * m_px || !nearerAnother(centre) ? candidates : last).push_back(centre);
            }
            if (extra == 8.0 * m_px)
                near = candidates.size();
        }
        const std::size_t firstLast = candidates.size();
        candidates.insert(candidates.end(), last.begin(), last.end());
        // A name pushed out past the near rings gets a leader from its joint's ring, so a "D"
        // among other joints still names D (the five-bar's small view, with its handles).
        const QPointF joint = m_points[i];
        const double ring = (m_style.pivotRadius + 1.0) * m_px;
        const auto leaderFor = [&](std::size_t k) -> std::optional<Leader> {
            if (k < near)
                return std::nullopt;
            const QPointF start = joint + ring * unit(candidates[k] - joint);
            const std::optional<QLineF> line = leaderToBox(start, candidates[k], size, clear - ring + 12.0 * m_px);
            return line ? std::optional<Leader>(Leader {*line, joint, joint, false, k >= firstLast}) : std::nullopt;
        };
        // The reference point inside a crowded platform: just outside the platform, over thin
        // lines at most, with a leader across the platform's edge to the point (without one,
        // Oₚ read as the corner's it stood beside), or not at all (farther out, a leader from
        // that small a triangle crossed the legs and the base's names).
        if (m_crowdedPlatform.contains(joint)) {
            // across an edge of the platform, between its corners: past a corner it named that
            const auto pastACorner = [&](const QPointF &centre) {
                const QPointF end = leaderToBox(joint, centre, size, 0.0).value_or(QLineF(joint, joint)).p2();
                return std::any_of(m_crowdedCorners.begin(), m_crowdedCorners.end(), [&](const QPointF &corner) {
                    return distanceToSegment(corner, joint, end) < (m_style.pivotRadius + 2.0) * m_px;
                });
            };
            candidates.resize(near);
            candidates.erase(std::remove_if(candidates.begin(), candidates.end(), pastACorner), candidates.end());
            const std::size_t before = m_labels.size();
            placeFirstFree(label, candidates, coversALabel, candidates.size(), 4.0);
            if (m_labels.size() > before) {
                const QPointF centre = m_labels.back().centre;
                if (const std::optional<QLineF> line = leaderToBox(joint + ring * unit(centre - joint), centre, size, 0.0))
                    m_nameLeaders.push_back({*line, label.colour, false});
            }
            continue;
        }
        placeFirstFree(label, candidates,
            std::numeric_limits<double>::infinity(), near, 4.0, leaderFor);
    }
}

} // namespace pkm
