// The sheet's dimensioned drawing: the mechanism in the sheet's pose with every rigid link
// dimensioned, at the largest standard scale at which it fits an A4 page (docs/architecture.md,
// the parameter sheet).

#include "export/sheet.h"
#include "export/sheetparts.h"

#include "text.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace pkm::sheet::detail {

namespace {
/// What the drawing of one pose covers, mm: its joints, links, guides, paths, and the
/// dimension lines and angle arcs with their offsets.
Eigen::AlignedBox2d drawingBounds(const Scene &scene)
{
    Eigen::AlignedBox2d box;
    const auto joint = [&](int i) -> std::optional<Eigen::Vector2d> {
        if (i < 0 || i >= static_cast<int>(scene.joints.size()) || !scene.joints[std::size_t(i)].position.allFinite())
            return std::nullopt;
        return scene.joints[std::size_t(i)].position.head<2>();
    };
    // A marked point far outside the range of motion (a four-bar's instantaneous centre when the
    // crank and the rocker are nearly parallel) would shrink the drawing: it is left out.
    Eigen::AlignedBox2d near;
    if (!scene.extent.isEmpty()) {
        const Eigen::Vector2d centre = scene.extent.center().head<2>(), half = scene.extent.sizes().head<2>();
        near = Eigen::AlignedBox2d(centre - half, centre + half);
    }
    for (const SceneJoint &j : scene.joints) {
        if (j.position.allFinite() && (near.isEmpty() || j.kind != JointKind::Point || near.contains(j.position.head<2>())))
            box.extend(j.position.head<2>());
    }
    for (const SceneGuide &guide : scene.guides) {
        const Eigen::Vector2d a = guide.start.head<2>(), b = guide.end.head<2>();
        Eigen::Vector2d normal = b - a;
        normal = normal.norm() > 0.0 ? Eigen::Vector2d(-normal.y(), normal.x()).normalized() * guide.width : normal;
        for (const Eigen::Vector2d &p : {a, b})
            box.extend(p + normal).extend(p - normal);
    }
    for (const SceneDimension &dimension : scene.dimensions) {
        const auto a = joint(dimension.from), b = joint(dimension.to);
        if (!a || !b || (*b - *a).norm() <= 0.0)
            continue;
        const Eigen::Vector2d direction = (*b - *a).normalized();
        const Eigen::Vector2d offset = Eigen::Vector2d(-direction.y(), direction.x()) * dimension.offset;
        box.extend(*a + offset).extend(*b + offset);
    }
    for (const SceneAngle &angle : scene.angles) {
        if (const auto v = joint(angle.vertex))
            box.extend(*v + Eigen::Vector2d::Constant(angle.radius)).extend(*v - Eigen::Vector2d::Constant(angle.radius));
    }
    for (const ScenePolyline &line : scene.polylines) {
        for (const Eigen::Vector3d &p : line.points) {
            if (p.allFinite())
                box.extend(p.head<2>());
        }
    }
    if (box.isEmpty() && !scene.extent.isEmpty())
        box.extend(scene.extent.min().head<2>()).extend(scene.extent.max().head<2>());
    return box;
}

/// The largest standard scale at which `box` fits the drawing area with room for labels.
std::pair<int, int> drawingScale(const Eigen::AlignedBox2d &extent, bool guides)
{
    // A guide's end stop and its name sit beyond its end, at a fixed size on paper.
    const double room = drawingLabelRoom + (guides ? 12.0 : 0.0);
    static constexpr std::array<std::pair<int, int>, 17> scales {{{50, 1}, {20, 1}, {10, 1}, {5, 1}, {2, 1}, {1, 1},
        {1, 2}, {1, 5}, {1, 10}, {1, 20}, {1, 50}, {1, 100}, {1, 200}, {1, 500}, {1, 1000}, {1, 2000}, {1, 5000}}};
    if (extent.isEmpty())
        return {1, 1};
    const Eigen::Vector2d size = extent.sizes();
    const double width = drawingWidth - 2.0 * room, height = drawingHeight - 2.0 * room;
    for (const auto &scale : scales) {
        const double ratio = double(scale.first) / scale.second;
        if (size.x() * ratio <= width && size.y() * ratio <= height)
            return scale;
    }
    return scales.back();
}

/// Dimensions every rigid link the scene leaves undimensioned (a link of the same length as a
/// dimensioned one counts as dimensioned), outside the mechanism: the drawing then gives every
/// length the workshop needs.
void dimensionLinks(Scene &scene, const Scene &home)
{
    const auto position = [](const Scene &s, int i) -> std::optional<Eigen::Vector2d> {
        if (i < 0 || i >= static_cast<int>(s.joints.size()) || !s.joints[std::size_t(i)].position.allFinite())
            return std::nullopt;
        return s.joints[std::size_t(i)].position.head<2>();
    };
    std::vector<double> shown;
    std::vector<std::pair<int, int>> pairs;
    for (const SceneDimension &dimension : scene.dimensions) {
        const auto a = position(scene, dimension.from), b = position(scene, dimension.to);
        if (a && b)
            shown.push_back((*b - *a).norm());
        pairs.emplace_back(std::min(dimension.from, dimension.to), std::max(dimension.from, dimension.to));
    }
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    int count = 0;
    for (const SceneJoint &joint : scene.joints) {
        if (joint.kind != JointKind::Point && joint.position.allFinite()) {
            centroid += joint.position.head<2>();
            ++count;
        }
    }
    if (count == 0)
        return;
    centroid /= count;
    const double size = scene.extent.isEmpty() ? 100.0 : scene.extent.sizes().head<2>().maxCoeff();
    for (std::size_t b = 0; b < scene.bars.size(); ++b) {
        const SceneBar &bar = scene.bars[b];
        const auto from = position(scene, bar.from), to = position(scene, bar.to);
        const auto homeFrom = position(home, bar.from), homeTo = position(home, bar.to);
        if (!from || !to || !homeFrom || !homeTo)
            continue;
        const double length = (*to - *from).norm();
        if (!(length > 1e-9) || std::abs((*homeTo - *homeFrom).norm() - length) > 1e-6 * std::max(1.0, length))
            continue; // not a rigid link
        const std::pair<int, int> pair(std::min(bar.from, bar.to), std::max(bar.from, bar.to));
        const bool done = std::find(pairs.begin(), pairs.end(), pair) != pairs.end()
            || std::any_of(shown.begin(), shown.end(),
                [&](double other) { return std::abs(other - length) <= 1e-6 * std::max(1.0, length); });
        if (done)
            continue;
        const Eigen::Vector2d direction = (*to - *from) / length;
        const Eigen::Vector2d left(-direction.y(), direction.x());
        const double side = left.dot(0.5 * (*from + *to) - centroid) >= 0.0 ? 1.0 : -1.0;
        const std::string name = bar.label.empty() ? std::string() : bar.label + " = ";
        scene.dimensions.push_back({bar.from, bar.to, side * 0.07 * size, name + text::millimetres(length)});
        shown.push_back(length);
        pairs.push_back(pair);
    }
}
} // namespace

void addDrawing(const Mechanism &mechanism, const Pose &pose, const QString &poseDescription, Parts &parts)
{
    Section &section = parts.drawing;
    section.key = "drawing";
    section.title = QCoreApplication::translate("Sheet", "Dimensioned drawing");
    section.newPage = true;
    Figure figure;
    figure.key = "drawing";
    figure.kind = FigureKind::Drawing;
    figure.scene = mechanism.scene(pose);
    dimensionLinks(figure.scene, mechanism.scene(mechanism.homePose()));
    figure.imageBounds = drawingBounds(figure.scene);
    figure.scale = drawingScale(figure.imageBounds, !figure.scene.guides.empty());
    // With fonts at hand the drawing itself is measured: the largest scale whose picture, labels
    // and all, fits the frame, centred on what is drawn.
    static constexpr std::array<std::pair<int, int>, 8> larger {{{20, 1}, {10, 1}, {5, 1}, {2, 1}, {1, 1}, {1, 2}, {1, 5}, {1, 10}}};
    constexpr double margin = 3.0; // mm of paper inside the frame
    for (const auto &scale : larger) {
        const double ratio = double(scale.first) / scale.second;
        if (ratio < double(figure.scale.first) / figure.scale.second)
            break; // the estimate's scale is the least
        // labels only add to the geometry: a scale at which the geometry alone overflows the
        // frame is not worth painting (painting costs grow with the drawing's size in mm)
        const Eigen::Vector2d geometry = figure.imageBounds.sizes() * ratio;
        if (geometry.x() > drawingWidth - 2.0 * margin || geometry.y() > drawingHeight - 2.0 * margin)
            continue;
        const auto drawn = drawnBounds(figure.scene, ratio);
        if (!drawn)
            break;
        if (drawn->sizes().x() <= drawingWidth - 2.0 * margin && drawn->sizes().y() <= drawingHeight - 2.0 * margin) {
            figure.scale = scale;
            figure.imageBounds = Eigen::AlignedBox2d(drawn->min() / ratio, drawn->max() / ratio);
            break;
        }
    }
    figure.title = QCoreApplication::translate("Sheet", "The mechanism in the pose of this sheet, scale %1")
                       .arg(scaleText(figure.scale));
    figure.caption = QCoreApplication::translate("Sheet",
        "Pose: %1. Scale %2 on A4 (the scale bar holds on any print size). Lengths in mm, angles in degrees; "
        "the dimensions are those of the pose shown.")
                         .arg(poseDescription, scaleText(figure.scale));
    section.figures.push_back(std::move(figure));
}

} // namespace pkm::sheet::detail
