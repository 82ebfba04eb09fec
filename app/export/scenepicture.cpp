// The 2D picture of a mechanism in a pose, on any paint device: background, grid, the scene
// fitted above a band for the scale bar and the caption. `pkm render`, the GUI's File ▸ Save
// 2D View Picture, the animation frames and the parameter sheet all draw it so.

#include "export/scenepicture.h"

#include "linkageview.h"
#include "quantityformat.h"
#include "scenepainter.h"
#include "symboltext.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace pkm::pictures {

namespace {

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
    // As the window's read-out writes them: the language's decimal sign and unit ("21,95 мм"),
    // the typographic minus ("θ = −7.40°"), ∞ or — at a singular pose.
    QStringList pose;
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableInfo &info = variables[i];
        pose << QStringLiteral("%1 = %2").arg(QString::fromStdString(info.symbol),
                    formatQuantity(mechanism.variableValue(at, static_cast<int>(i)), info.unit, info.decimals));
    }
    for (const ReportText &word : mechanism.reportText(at)) {
        if (word.group == ReportGroup::Pose)
            pose << QString::fromStdString(word.name + " " + word.text);
    }
    const QString joined = pose.join(QStringLiteral(", "));
    if (name.isEmpty())
        return joined;
    return joined.isEmpty() ? name : name + QStringLiteral(" — ") + joined;
}

QStringList captionLines(const QString &caption, const QFontMetricsF &metrics, double available)
{
    // A caption wider than its room (the five-bar's four variables in a video's half frame
    // ended "y = 1…", the O-X glide's five "… y = 73.74 mm, …") is broken after commas onto
    // up to three lines, each filled as far as it goes; only a last line still too long is
    // cut short. (Measured as plain text: lowered subscripts take less room.)
    constexpr int most = 3;
    const QStringList items = caption.split(QStringLiteral(", "));
    QStringList lines;
    for (qsizetype i = 0; i < items.size(); ++i) {
        const bool last = i + 1 == items.size();
        const QString item = items[i] + (last ? QString() : QStringLiteral(","));
        if (!lines.isEmpty() && lines.size() <= most
            && (lines.size() == most || metrics.horizontalAdvance(lines.back() + QLatin1Char(' ') + item) <= available))
            lines.back() += QLatin1Char(' ') + item;
        else
            lines << item;
    }
    for (QString &line : lines)
        line = metrics.elidedText(line, Qt::ElideRight, available);
    return lines;
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
    const QStringList lines = captionLines(caption, metrics, available);
    double width = 0.0;
    for (const QString &line : lines)
        width = std::max(width, metrics.horizontalAdvance(line));
    const double height = metrics.height() * double(lines.size());
    const QRectF text(area.left() + margin + pad, area.bottom() - margin - height, width, height);

    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    ScenePainter::paintKnockout(painter, text.adjusted(-pad, -pad, pad, pad), style);
    // the symbols as the window shows them: "x_AB" with AB lowered
    for (qsizetype i = 0; i < lines.size(); ++i)
        drawSymbolText(&painter, QRectF(text.left(), text.top() + double(i) * metrics.height(), text.width() + pad,
                                        metrics.height()).toAlignedRect(),
                       lines[i], font, style.ink);
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
    const QString &caption, PictureFit fit, std::vector<std::pair<QString, QPointF>> *labelPlaces)
{
    SceneStyle style = sceneStyle;
    style.showHandles = false; // rings are an affordance of the screen, not of a picture
    const double px = style.pixelSize;
    const ViewMapping mapping = pictureMapping(area, scene, style, fit, painter.device());

    ScenePainter::paintPicture(painter, area, scene, mapping, style, labelPlaces);
    painter.save();
    painter.setClipRect(area, Qt::IntersectClip);
    // the scale bar: at most 2.5 × its minimum length (1-2-5 steps), its knock-out and a gap
    const double bar = ScenePainter::niceStep(90.0 * px, mapping.scale) * mapping.scale;
    paintCaption(painter, area, caption, style, bar + (6.0 + 24.0) * px);
    painter.restore();
}

} // namespace pkm::pictures
