// The 2D picture of a mechanism in a pose, on any paint device: background, grid, the scene
// fitted above a band for the scale bar and the caption. `pkm render`, the GUI's File ▸ Save
// 2D View Picture, the animation frames and the parameter sheet all draw it so.

#include "export/scenepicture.h"

#include "linkageview.h"
#include "report/texttable.h"
#include "scenepainter.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace pkm::pictures {

namespace {

/// "30.00°", "187.13 mm", "0.40"
std::string valueWithUnit(double value, int decimals, std::string_view unit)
{
    std::string text = report::fixedText(value, decimals);
    if (unit.empty())
        return text;
    if (unit != "°")
        text.append(" ");
    return text.append(unit);
}

/// What the 2D drawing keeps free at the bottom for the scale bar and the caption: the scale
/// bar's margin, tick, text and knock-out (ScenePainter::paintScaleBar), device units.
double bottomBand(const QPaintDevice *device, const SceneStyle &style)
{
    return ScenePainter::scaleBarHeight(style, device);
}

} // namespace

QFont captionFont(const SceneStyle &style)
{
    QFont font; // the application's font, as the scene's labels
    font.setPixelSize(std::max(1, static_cast<int>(std::lround(style.fontPixels * style.pixelSize))));
    return font;
}

/// What the 3D picture keeps free at the bottom for the caption: its margin, text and knock-out.
double captionBand(const SceneStyle &style)
{
    const QImage probe(1, 1, QImage::Format_RGB32); // a raster device's font metrics
    const QFontMetricsF metrics(captionFont(style), &probe);
    return (16.0 + 6.0 + 4.0) * style.pixelSize + metrics.height();
}

QString poseCaption(const Mechanism &mechanism, const Pose &at, const QString &name)
{
    std::string pose;
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        const double value = info.unit.toDisplay(mechanism.variableValue(at, static_cast<int>(i)));
        pose.append(pose.empty() ? "" : ", ").append(info.symbol).append(" = ");
        pose.append(valueWithUnit(value, info.decimals, info.unit.symbol));
    }
    for (const ReportText &word : mechanism.reportText(at)) {
        if (word.group == ReportGroup::Pose)
            pose.append(pose.empty() ? "" : ", ").append(word.name).append(" ").append(word.text);
    }
    if (name.isEmpty())
        return QString::fromStdString(pose);
    return pose.empty() ? name : name + QStringLiteral(" — ") + QString::fromStdString(pose);
}

void paintCaption(
    QPainter &painter, const QRectF &area, const QString &caption, const SceneStyle &style, double rightReserve)
{
    if (caption.isEmpty())
        return;
    const double px = style.pixelSize;
    const QFont font = captionFont(style);
    const QFontMetricsF metrics(font, painter.device());
    const double margin = 16.0 * px, pad = 6.0 * px;
    const double available = area.width() - 2.0 * margin - 2.0 * pad - rightReserve;
    if (available < 40.0 * px)
        return; // no room beside the scale bar
    const QString shown = metrics.elidedText(caption, Qt::ElideRight, available);
    const QRectF text(area.left() + margin + pad, area.bottom() - margin - metrics.height(),
        metrics.horizontalAdvance(shown), metrics.height());

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    ScenePainter::paintKnockout(painter, text.adjusted(-pad, -pad, pad, pad), style);
    painter.setFont(font);
    painter.setPen(style.ink);
    painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, shown);
    painter.restore();
}

ViewMapping pictureMapping(const QRectF &area, const Scene &scene, const SceneStyle &style, PictureFit fit,
    const QPaintDevice *device)
{
    if (fit == PictureFit::LabelsWhole)
        return LinkageView::screenMapping(scene, scene.extent, area, style); // above the same scale bar
    // The scale bar's margin overlaps the fit's own margin.
    QRectF fitted = area;
    const double band = std::max(0.0, bottomBand(device, style) - 16.0 * style.pixelSize);
    fitted.setBottom(area.bottom() - std::min(band, 0.25 * area.height()));
    return LinkageView::fittedMapping(scene, fitted, style);
}

void paintScenePicture(QPainter &painter, const QRectF &area, const Scene &scene, const SceneStyle &sceneStyle,
    const QString &caption, PictureFit fit)
{
    SceneStyle style = sceneStyle;
    style.showHandles = false; // rings are an affordance of the screen, not of a picture
    const double px = style.pixelSize;
    const ViewMapping mapping = pictureMapping(area, scene, style, fit, painter.device());

    ScenePainter::paintPicture(painter, area, scene, mapping, style);
    painter.save();
    painter.setClipRect(area, Qt::IntersectClip);
    // the scale bar: at most 2.5 × its minimum length (1-2-5 steps), its knock-out and a gap
    const double bar = ScenePainter::niceStep(90.0 * px, mapping.scale) * mapping.scale;
    paintCaption(painter, area, caption, style, bar + (6.0 + 24.0) * px);
    painter.restore();
}

} // namespace pkm::pictures
