#include "formworkspaceview.h"

#include "plotfont.h"
#include "plotfit.h"
#include "plotstyle.h"
#include "plotticker.h"
#include "quantityformat.h"

#include <QEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
constexpr int resolution = 700; ///< cells along the longer side of the common grid
constexpr QRgb singularRgb = 0xc62828;
constexpr QRgb outlineRgb = 0x202020;
constexpr double tickPoints = 11, labelPoints = 12, titlePoints = 13, legendPoints = 11;

QString areaText(double area)
{
    return QLocale().toString(area, 'f', 1) + QLatin1Char(' ') + unitText(units::squareMillimetre);
}

QCPCurve *addCurve(QCustomPlot *plot, const QPen &pen)
{
    auto *curve = new QCPCurve(plot->xAxis, plot->yAxis);
    curve->setPen(pen);
    curve->setSelectable(QCP::stNone);
    curve->removeFromLegend();
    return curve;
}

/// A legend entry with a filled swatch and no data.
QCPGraph *addSwatch(QCustomPlot *plot, const QColor &fill)
{
    QCPGraph *graph = plot->addGraph();
    graph->setPen(QPen(fill.darker(130), 1.0));
    graph->setBrush(fill);
    graph->setSelectable(QCP::stNone);
    graph->setProperty("swatch", true);
    return graph;
}
} // namespace

FormWorkspaceView::FormWorkspaceView(QWidget *parent)
    : QWidget(parent)
    , m_plot(new QCustomPlot(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    QCustomPlot *plot = m_plot;
    plot->setBackground(Qt::white);
    plot->setMinimumSize(320, 260);
    plot->installEventFilter(this);

    QCPLayoutGrid *grid = plot->plotLayout();
    QCPAxisRect *axisRect = plot->axisRect();
    grid->take(axisRect);
    grid->simplify();
    m_title = plotstyle::newTextElement(plot, fontOf(font(), titlePoints, true));
    grid->addElement(0, 0, m_title);
    axisRect->insetLayout()->take(plot->legend);
    grid->addElement(1, 0, plot->legend);
    grid->addElement(2, 0, axisRect);
    grid->setRowStretchFactor(0, 0.001);
    grid->setRowStretchFactor(1, 0.001);
    plot->legend->setVisible(true);
    plot->legend->setFont(fontOf(font(), legendPoints));
    plot->legend->setBorderPen(Qt::NoPen);
    plot->legend->setIconSize(30, 14);
    plot->legend->setWrap(2);
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot->legend->setColumnSpacing(18);
    plot->legend->setSelectableParts(QCPLegend::spNone);

    for (QCPAxis *axis : {plot->xAxis, plot->yAxis, plot->xAxis2, plot->yAxis2}) {
        const QPen pen(QColor(0x30, 0x30, 0x30), 1.2);
        axis->setBasePen(pen);
        axis->setTickPen(pen);
        axis->setSubTickPen(pen);
        axis->setTickLabelFont(fontOf(font(), tickPoints));
        axis->setLabelFont(fontOf(font(), labelPoints));
        axis->grid()->setPen(QPen(QColor(0, 0, 0, 30), 1.0));
        axis->setTicker(QSharedPointer<MinusTicker>::create(axis));
    }
    for (QCPAxis *axis : {plot->xAxis2, plot->yAxis2}) {
        axis->setVisible(true);
        axis->setTicks(false);
        axis->setTickLabels(false);
        axis->grid()->setVisible(false);
    }

    m_regions = new QCPItemPixmap(plot);
    m_regions->setScaled(true, Qt::IgnoreAspectRatio, Qt::FastTransformation);
    m_regions->setSelectable(false);
    m_regions->setLayer(QStringLiteral("background"));
    m_regions->setClipToAxisRect(true);
    m_outline = addCurve(plot, QPen(QColor(outlineRgb), 1.8));
    m_outline->setLineStyle(QCPCurve::lsLine);
    m_singularHalo = addCurve(plot, QPen(QColor(255, 255, 255, 210), 6.0));
    QPen dashed(QColor(singularRgb), 2.6);
    dashed.setDashPattern({4.0, 2.5});
    m_singular = addCurve(plot, dashed);
    m_pose = new QCPItemTracer(plot);
    m_pose->setStyle(QCPItemTracer::tsCircle);
    m_pose->setSize(15);
    m_pose->setPen(QPen(QColor(0x20, 0x20, 0x20), 2.0));
    m_pose->setBrush(Qt::white);
    m_pose->setSelectable(false);
    m_pose->setVisible(false);

    connect(plot, &QCustomPlot::afterLayout, this, &FormWorkspaceView::fitView);
    connect(plot, &QCustomPlot::mousePress, this, [this](QMouseEvent *event) { m_pressPosition = event->position().toPoint(); });
    connect(plot, &QCustomPlot::mouseRelease, this, &FormWorkspaceView::mouseReleased);
    retranslate();
}

void FormWorkspaceView::setForms(const QString &title, const std::vector<FormRegion> &forms,
                                 const std::vector<SingularCurve> &singular, const QString &singularLabel)
{
    plotstyle::setFittedText(m_title, title);
    m_bounds.setEmpty();
    for (const FormRegion &form : forms)
        m_bounds.extend(form.mechanism->planarWorkspace()->workspaceBounds());
    m_reached.clear();
    m_areas.clear();
    m_unionArea = 0.0;
    m_plot->clearGraphs();
    m_swatches.clear();
    m_formTitles.clear();
    m_shownAreas.clear();
    m_unionShown = 0.0;
    m_exactAreas = false;
    if (m_bounds.isEmpty()) {
        retranslate();
        m_plot->replot();
        return;
    }
    // One grid over every form: each cell reached by a form, and by any (the union).
    m_grid = squareGrid(m_bounds, resolution);
    std::vector<float> values(m_grid.cells());
    std::vector<char> any(m_grid.cells(), 0);
    QImage image(m_grid.columns, m_grid.rows, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    for (const FormRegion &form : forms) {
        computeMap(*form.mechanism->planarWorkspace(), MapQuantity::Determinant, m_grid, values);
        std::vector<char> reached(m_grid.cells(), 0);
        std::size_t count = 0;
        const QRgb fill = form.fill.rgba();
        for (int r = 0; r < m_grid.rows; ++r) {
            auto *line = reinterpret_cast<QRgb *>(image.scanLine(m_grid.rows - 1 - r)); // row 0 is the bottom
            for (int c = 0; c < m_grid.columns; ++c) {
                const std::size_t i = std::size_t(r) * std::size_t(m_grid.columns) + std::size_t(c);
                if (std::isnan(values[i]))
                    continue;
                reached[i] = 1;
                any[i] = 1;
                line[c] = fill;
                ++count;
            }
        }
        m_areas.push_back(double(count) * m_grid.cellArea());
        m_reached.push_back(std::move(reached));
    }
    m_unionArea = double(std::count(any.begin(), any.end(), 1)) * m_grid.cellArea();
    m_regions->setPixmap(QPixmap::fromImage(image));
    m_regions->topLeft->setCoords(m_grid.bounds.min().x(), m_grid.bounds.max().y());
    m_regions->bottomRight->setCoords(m_grid.bounds.max().x(), m_grid.bounds.min().y());

    // the union's boundary: the cell edges between reached and unreached cells
    std::vector<float> unionValues(any.size());
    for (std::size_t i = 0; i < any.size(); ++i)
        unionValues[i] = any[i] ? 1.0f : std::numeric_limits<float>::quiet_NaN();
    const std::vector<Eigen::Vector2d> segments = workspaceOutline(m_grid, unionValues);
    QVector<QCPCurveData> outline;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double t = 0;
    for (std::size_t i = 0; i + 1 < segments.size(); i += 2) {
        outline.append(QCPCurveData(t++, segments[i].x(), segments[i].y()));
        outline.append(QCPCurveData(t++, segments[i + 1].x(), segments[i + 1].y()));
        outline.append(QCPCurveData(t++, nan, nan));
    }
    m_outline->data()->set(outline, true);
    QVector<QCPCurveData> curves;
    t = 0;
    for (const SingularCurve &curve : singular) {
        for (const Eigen::Vector2d &p : curve.points)
            curves.append(QCPCurveData(t++, p.x(), p.y()));
        curves.append(QCPCurveData(t++, nan, nan));
    }
    m_singular->data()->set(curves, true);
    m_singularHalo->data()->set(curves, true);

    for (std::size_t i = 0; i < forms.size(); ++i) {
        m_swatches.push_back(addSwatch(m_plot, forms[i].fill));
        m_formTitles.push_back(forms[i].title);
        m_shownAreas.push_back(forms[i].exactArea > 0 ? forms[i].exactArea : m_areas[i]);
    }
    m_exactAreas = std::all_of(forms.begin(), forms.end(), [](const FormRegion &f) { return f.exactArea > 0; });
    // Nested forms (the O-X glide's O inside X): the union is the larger form, exactly.
    double unionShown = m_unionArea;
    for (std::size_t i = 0; i < forms.size(); ++i) {
        if (forms[i].exactArea > 0 && std::abs(m_areas[i] - m_unionArea) < 0.5 * m_grid.cellArea())
            unionShown = forms[i].exactArea;
    }
    m_unionShown = unionShown;
    m_outline->addToLegend();
    m_singular->setName(singularLabel);
    m_singular->setVisible(!curves.isEmpty());
    if (!curves.isEmpty())
        m_singular->addToLegend();
    else
        m_singular->removeFromLegend();
    retranslate();
    fitView();
    m_plot->replot();
}

void FormWorkspaceView::setPose(const Eigen::Vector2d &platform)
{
    const bool valid = platform.allFinite();
    m_pose->setVisible(valid);
    if (valid)
        m_pose->position->setCoords(platform.x(), platform.y());
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

double FormWorkspaceView::gridArea(int form) const
{
    return form >= 0 && form < int(m_areas.size()) ? m_areas[std::size_t(form)] : 0.0;
}

std::vector<int> FormWorkspaceView::formsAt(const Eigen::Vector2d &point) const
{
    std::vector<int> inside;
    if (m_grid.cells() == 0)
        return inside;
    const int c = int(std::floor((point.x() - m_grid.bounds.min().x()) / m_grid.dx()));
    const int r = int(std::floor((point.y() - m_grid.bounds.min().y()) / m_grid.dy()));
    if (c < 0 || r < 0 || c >= m_grid.columns || r >= m_grid.rows)
        return inside;
    const std::size_t i = std::size_t(r) * std::size_t(m_grid.columns) + std::size_t(c);
    for (std::size_t f = 0; f < m_reached.size(); ++f) {
        if (m_reached[f][i])
            inside.push_back(int(f));
    }
    return inside;
}

QString FormWorkspaceView::legendText() const
{
    QStringList items;
    for (int i = 0; i < m_plot->legend->itemCount(); ++i) {
        if (auto *item = qobject_cast<QCPPlottableLegendItem *>(m_plot->legend->item(i)))
            items << item->plottable()->name().replace(QLatin1Char('\n'), QLatin1Char(' ')); // as one line, however wrapped
    }
    return items.join(QLatin1Char('\n'));
}

void FormWorkspaceView::fitView()
{
    // a new width or a new text size (presentation mode scales the plot's fonts): the title
    // and the legend are broken again, and laid out on the next replot
    const QString fittedFor = QStringLiteral("%1 %2 %3").arg(m_plot->width()).arg(m_title->font().key(), m_plot->legend->font().key());
    if (fittedFor != m_fittedFor) {
        m_fittedFor = fittedFor;
        fitTexts();
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    if (m_bounds.isEmpty())
        return;
    // equal scales on both axes, the whole union in view with a margin
    const QRect rect = m_plot->axisRect()->rect();
    if (rect.width() <= 0 || rect.height() <= 0)
        return;
    const Eigen::Vector2d centre = m_bounds.center();
    Eigen::Vector2d size = 1.1 * m_bounds.sizes();
    const double perPixel = std::max(size.x() / rect.width(), size.y() / rect.height());
    size = perPixel * Eigen::Vector2d(rect.width(), rect.height());
    applyFittedRanges(m_plot, QCPRange(centre.x() - 0.5 * size.x(), centre.x() + 0.5 * size.x()),
                      QCPRange(centre.y() - 0.5 * size.y(), centre.y() + 0.5 * size.y()), m_refits);
}

void FormWorkspaceView::mouseReleased(QMouseEvent *event)
{
    const QPoint position = event->position().toPoint();
    if (event->button() != Qt::LeftButton || (position - m_pressPosition).manhattanLength() > 3
        || !m_plot->axisRect()->rect().contains(position))
        return;
    emit pointClicked(Eigen::Vector2d(m_plot->xAxis->pixelToCoord(position.x()), m_plot->yAxis->pixelToCoord(position.y())));
}

void FormWorkspaceView::retranslate()
{
    m_plot->xAxis->setLabel(tr("x (mm)"));
    m_plot->yAxis->setLabel(tr("y (mm)"));
    for (std::size_t i = 0; i < m_swatches.size(); ++i)
        m_swatches[i]->setName(tr("%1: %2").arg(m_formTitles[i], areaText(m_shownAreas[i])));
    if (m_swatches.empty())
        return;
    m_outline->setName(tr("union, outlined: %1").arg(areaText(m_unionShown)));
    plotstyle::forgetLegendNames(m_plot); // the names just given are the whole ones
    fitTexts();
    const QLocale locale;
    const QString columns = locale.toString(m_grid.columns), rows = locale.toString(m_grid.rows);
    m_plot->setToolTip(m_exactAreas
            ? tr("Areas of the forms: exact (closed form). Union: counted on a %1 × %2 grid.").arg(columns, rows)
            : tr("Areas counted on a %1 × %2 grid.").arg(columns, rows));
}

void FormWorkspaceView::fitTexts()
{
    // At a projector's 1280×720 and 150 % text the title and the legend are wider than the
    // plot: the title breaks into lines and the legend takes as many columns as fit, its
    // names broken too, so that no area or unit is cut off.
    plotstyle::fitText(m_title);
    plotstyle::wrapLegendNames(m_plot);
    plotstyle::layOutLegend(m_plot);
}

void FormWorkspaceView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    QWidget::changeEvent(event);
}

bool FormWorkspaceView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot && event->type() == QEvent::Resize)
        fitView();
    return QWidget::eventFilter(watched, event);
}

} // namespace pkm
