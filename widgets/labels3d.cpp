#include "labels3d.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pkm {

namespace {
const QColor ink(0x1c, 0x20, 0x26); // the 2D view's text colour (SceneStyle::ink)
const QColor knockOut(255, 255, 255, 210);
} // namespace

QFont labelFont3D(const QFont &base)
{
    QFont font = base;
    font.setBold(true);
    if (font.pixelSize() > 0)
        font.setPixelSize(int(std::lround(font.pixelSize() * 1.15)));
    else
        font.setPointSizeF(font.pointSizeF() * 1.15);
    return font;
}

void paintLabels3D(QPainter &painter, const std::vector<Label3D> &labels, const Camera3D &camera, const QFont &font)
{
    const QFont shown = labelFont3D(font);
    const QFontMetricsF metrics(shown, painter.device());
    const QRectF picture(0.0, 0.0, camera.viewportWidth(), camera.viewportHeight());
    const double gap = 0.35 * metrics.height(), pad = 0.15 * metrics.height();
    std::vector<QRectF> placed;
    // A platform of three or more corners drawn closer than one and a half times a name and
    // a point's dot leaves its corners unnamed (the 2D view's rule, settleJointNames()): the
    // 3-R̲RR's P₁…P₃ piled on Oₚ in the small 3D view.
    std::vector<Eigen::Vector2d> corners;
    double widest = 0.0;
    for (const Label3D &label : labels) {
        if (label.platformCorner) {
            corners.push_back(camera.project(label.at));
            widest = std::max({widest, metrics.horizontalAdvance(QString::fromStdString(label.text)) + 2.0 * pad, metrics.height()});
        }
    }
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < corners.size(); ++a) {
        for (std::size_t b = a + 1; b < corners.size(); ++b)
            shortest = std::min(shortest, (corners[a] - corners[b]).norm());
    }
    const bool crowded = corners.size() >= 3 && shortest < 1.5 * (widest + gap);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setFont(shown);
    for (const Label3D &label : labels) {
        if (crowded && label.platformCorner)
            continue;
        double depth = 0.0;
        const Eigen::Vector2d at = camera.project(label.at, &depth);
        if (!std::isfinite(at.x()) || !std::isfinite(at.y()) || depth < -1.0 || depth > 1.0
            || !picture.contains(at.x(), at.y()))
            continue;
        const QString text = QString::fromStdString(label.text);
        const QSizeF size(metrics.horizontalAdvance(text) + 2.0 * pad, metrics.height());
        // up-right first, as the 2D view puts a joint's name; then the other corners
        const std::array<QPointF, 4> corners {QPointF(gap, -gap - size.height()), QPointF(-gap - size.width(), -gap - size.height()),
                                              QPointF(gap, gap), QPointF(-gap - size.width(), gap)};
        QRectF box;
        for (const QPointF &corner : corners) {
            box = QRectF(QPointF(at.x(), at.y()) + corner, size);
            const bool free = std::none_of(placed.begin(), placed.end(),
                                           [&](const QRectF &other) { return other.intersects(box); });
            if (free && picture.contains(box))
                break;
        }
        placed.push_back(box);
        QPainterPath back;
        back.addRoundedRect(box, 0.25 * size.height(), 0.25 * size.height());
        painter.fillPath(back, knockOut);
        painter.setPen(ink);
        painter.drawText(box, Qt::AlignCenter, text);
        // the point itself, so the name is not read as belonging to a part nearby
        painter.setBrush(ink);
        painter.setPen(Qt::NoPen);
        painter.drawEllipse(QPointF(at.x(), at.y()), 0.12 * size.height(), 0.12 * size.height());
    }
    painter.restore();
}

} // namespace pkm
