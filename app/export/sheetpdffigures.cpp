// The sheet PDF's figures: their placement with titles and captions, the workspace pictures
// and the dimensioned drawing to a standard scale with its own title block; the plots are drawn
// in sheetpdfplots.cpp.

#include "export/sheetpdfinternal.h"

#include "scenepainter.h"
#include "export/sheet.h"
#include "export/sheetparts.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QMarginsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QPicture>

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm::sheet {

namespace detail {

void PdfSheet::figures(const std::vector<Figure> &list)
{
    std::vector<const Figure *> pair;
    const auto flush = [&] {
        if (pair.empty())
            return;
        const double gap = mm(6.0);
        const double width = pair.size() == 1 && pair.front()->kind == FigureKind::Drawing
            ? m_body.width()
            : (m_body.width() - gap) / 2.0;
        double height = 0.0;
        for (const Figure *figure : pair)
            height = std::max(height, figureHeight(*figure, width));
        need(height);
        for (std::size_t i = 0; i < pair.size(); ++i)
            paintFigure(*pair[i], QRectF(m_body.left() + double(i) * (width + gap), m_y, width, height));
        m_y += height + mm(4.0);
        pair.clear();
    };
    for (const Figure &figure : list) {
        if (figure.kind == FigureKind::Drawing) {
            flush();
            pair.push_back(&figure);
            flush();
            continue;
        }
        pair.push_back(&figure);
        if (pair.size() == 2)
            flush();
    }
    flush();
}

double PdfSheet::captionHeight(const Figure &figure, double width) const
{
    return figure.caption.isEmpty() ? 0.0 : wrappedHeight(font(6.8, false, true), figure.caption, width) + mm(1.0);
}

double PdfSheet::figureHeight(const Figure &figure, double width)
{
    const double title = metrics(font(8.5, true)).height() + mm(1.0);
    switch (figure.kind) {
    case FigureKind::Plot:
        return title + mm(58.0) + legendHeight(figure.plot, width - mm(2.0)) + captionHeight(figure, width);
    case FigureKind::Image: {
        double aspect = figure.image.isNull() ? 1.0 : double(figure.image.height()) / figure.image.width();
        const double plotWidth = width - mm(14.0);
        const double imageHeight = std::min(mm(85.0), plotWidth * aspect);
        return title + imageHeight + mm(10.0) + captionHeight(figure, width);
    }
    case FigureKind::Drawing:
        return title + mm(drawingHeight) + mm(16.0) + captionHeight(figure, width);
    }
    return 0.0;
}

void PdfSheet::paintFigure(const Figure &figure, const QRectF &area)
{
    const QFont titleFont = font(8.5, true);
    const double titleHeight = metrics(titleFont).height();
    text(QRectF(area.left(), area.top(), area.width(), titleHeight), titleFont, ink,
        Qt::AlignLeft | Qt::AlignVCenter, metrics(titleFont).elidedText(figure.title, Qt::ElideRight, area.width()));
    QRectF content(area.left(), area.top() + titleHeight + mm(1.0), area.width(),
        area.height() - titleHeight - mm(1.0) - captionHeight(figure, area.width()));
    switch (figure.kind) {
    case FigureKind::Plot:
        paintPlot(figure.plot, content);
        break;
    case FigureKind::Image:
        paintImage(figure, content);
        break;
    case FigureKind::Drawing:
        paintDrawing(figure, content);
        break;
    }
    if (!figure.caption.isEmpty()) {
        const QFont f = font(6.8, false, true);
        text(QRectF(area.left(), content.bottom() + mm(1.0), area.width(), captionHeight(figure, area.width())), f,
            grey, Qt::TextWordWrap, figure.caption);
    }
}

void PdfSheet::paintImage(const Figure &figure, const QRectF &area)
{
    if (figure.image.isNull())
        return;
    const double aspect = double(figure.image.height()) / figure.image.width();
    double width = area.width() - mm(14.0);
    double height = width * aspect;
    const double available = area.height() - mm(10.0);
    if (height > available) {
        height = available;
        width = height / aspect;
    }
    const QRectF target(area.left() + mm(13.0) + (area.width() - mm(14.0) - width) / 2.0, area.top() + mm(1.0), width,
        height);
    if (m_painter) {
        m_painter->save();
        m_painter->setRenderHint(QPainter::LosslessImageRendering, true);
        m_painter->setRenderHint(QPainter::SmoothPixmapTransform, false);
        m_painter->drawImage(target, figure.image);
        m_painter->restore();
    }
    if (!figure.imageBounds.isEmpty()) {
        paintAxes(target, figure.imageBounds.min().x(), figure.imageBounds.max().x(), figure.imageBounds.min().y(),
            figure.imageBounds.max().y(), false, false, false);
        const QFont labelFont = font(6.5);
        const double labelHeight = metrics(labelFont).height();
        text(QRectF(target.left(), target.bottom() + mm(4.2), target.width(), labelHeight), labelFont, ink,
            Qt::AlignHCenter | Qt::AlignTop, QCoreApplication::translate("Sheet", "x (mm)"));
        text(QRectF(area.left(), target.bottom() + mm(4.2), mm(12.0), labelHeight), labelFont, ink,
            Qt::AlignRight | Qt::AlignTop, QCoreApplication::translate("Sheet", "y (mm)"));
    }
}

void PdfSheet::paintDrawing(const Figure &figure, const QRectF &area)
{
    const Scene &scene = figure.scene;
    const QRectF frame(area.left(), area.top(), area.width(), mm(drawingHeight));
    const double ratio = double(figure.scale.first) / figure.scale.second; // paper mm per mm
    ViewMapping mapping;
    mapping.scale = mm(1.0) * ratio;
    const Eigen::Vector2d centre = !figure.imageBounds.isEmpty() ? Eigen::Vector2d(figure.imageBounds.center())
        : scene.extent.isEmpty()                                  ? Eigen::Vector2d(Eigen::Vector2d::Zero())
                                                                  : Eigen::Vector2d(scene.extent.center().head<2>());
    mapping.origin = QPointF(frame.center().x() - mapping.scale * centre.x(), frame.center().y() + mapping.scale * centre.y());
    SceneStyle style = detail::drawingStyle(m_unit);
    if (m_painter) {
        m_painter->save();
        m_painter->setClipRect(frame);
        m_painter->setRenderHint(QPainter::Antialiasing, true);
        m_painter->setRenderHint(QPainter::TextAntialiasing, true);
        ScenePainter::paint(*m_painter, scene, mapping, style);
        m_painter->restore();
        m_painter->setPen(QPen(ink, mm(0.35)));
        m_painter->setBrush(Qt::NoBrush);
        m_painter->drawRect(frame);
    }
    // the drawing's title block, under the frame
    const double top = frame.bottom() + mm(2.0);
    const QFont field = font(6.5), value = font(8.0, true);
    // the scale bar has a cell of its own, so that it never covers the drawing
    const std::array<std::pair<QString, QString>, 5> cells {{
        {QCoreApplication::translate("Sheet", "scale (A4)"), scaleText(figure.scale)},
        {QCoreApplication::translate("Sheet", "scale bar"), QString()},
        {QCoreApplication::translate("Sheet", "units"), QCoreApplication::translate("Sheet", "mm, degrees")},
        {QCoreApplication::translate("Sheet", "design"), QString::fromStdString(m_sheet.design)},
        {QCoreApplication::translate("Sheet", "date"), m_sheet.date},
    }};
    const std::array<double, 5> shares {0.12, 0.27, 0.16, 0.28, 0.17};
    double x = frame.left();
    const double height = mm(11.0);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const double w = frame.width() * shares[i];
        const QRectF box(x, top, w, height);
        if (m_painter) {
            m_painter->setPen(QPen(ink, mm(0.25)));
            m_painter->setBrush(Qt::NoBrush);
            m_painter->drawRect(box);
        }
        text(box.adjusted(mm(1.5), mm(0.8), -mm(1.5), 0.0), field, grey, Qt::AlignLeft | Qt::AlignTop, cells[i].first);
        text(box.adjusted(mm(1.5), 0.0, -mm(1.5), -mm(1.2)), value, ink, Qt::AlignLeft | Qt::AlignBottom,
            metrics(value).elidedText(cells[i].second, Qt::ElideRight, w - mm(3.0)));
        if (i == 1 && m_painter) {
            m_painter->save();
            ScenePainter::paintScaleBar(*m_painter, box.adjusted(0.0, 0.0, 0.0, mm(1.2)), mapping, style);
            m_painter->restore();
        }
        x += w;
    }
}

} // namespace detail

} // namespace pkm::sheet
