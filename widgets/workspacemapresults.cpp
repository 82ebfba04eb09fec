// The workspace map's results on screen: the colour map, outline and singular curves applied
// to the plot, the title and legend in words, the view fitted to the workspace and the marker
// dragged with the mouse (docs/mathematics.md, section 6).

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

#include "plotfont.h"
#include "plotstyle.h"
#include "plotfit.h"
#include "plotticker.h"
#include "quantityformat.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QComboBox>
#include <QElapsedTimer>
#include <QEvent>
#include <QFutureWatcher>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QStackedWidget>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace pkm {

namespace {
using workspacemap::determinantGradient;
using workspacemap::nan;
using workspacemap::significant;

/// Ticks for κ on a logarithmic colour scale: powers of ten over many decades, 1-2-5 over a
/// few, 1-1.5-2-3-4-5-6-8 over less than one (QCPAxisTickerLog falls back to linear steps there).
class ConditionTicker : public MinusTicker
{
public:
    ConditionTicker() { m_sharePower = false; }

protected:
    int getSubTickCount(double) override { return 0; }
    QVector<double> createTickVector(double, const QCPRange &range) override
    {
        static const std::vector<std::vector<double>> sequences {{1.0}, {1.0, 2.0, 5.0}, {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0}};
        const double lower = std::max(range.lower, 1e-12), upper = std::max(range.upper, lower);
        const int first = int(std::floor(std::log10(lower))), last = int(std::ceil(std::log10(upper)));
        QVector<double> ticks;
        for (const std::vector<double> &steps : sequences) {
            ticks.clear();
            const int decadeStep = steps.size() == 1 ? std::max(1, (last - first + 7) / 8) : 1;
            for (int e = first; e <= last; e += decadeStep)
                for (const double step : steps) {
                    const double tick = step * std::pow(10.0, e);
                    if (tick >= lower * (1 - 1e-9) && tick <= upper * (1 + 1e-9))
                        ticks.append(tick);
                }
            if (ticks.size() >= 4)
                break;
        }
        return ticks;
    }
};

/// κ(J): light yellow (κ = 1, isotropic) to dark blue (near a singularity).
QCPColorGradient conditionGradient()
{
    QCPColorGradient gradient;
    gradient.setColorInterpolation(QCPColorGradient::ciRGB);
    gradient.setColorStopAt(0.0, QColor(0xffffd9));
    gradient.setColorStopAt(0.2, QColor(0xc7e9b4));
    gradient.setColorStopAt(0.45, QColor(0x41b6c4));
    gradient.setColorStopAt(0.7, QColor(0x225ea8));
    gradient.setColorStopAt(1.0, QColor(0x081d58));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}
} // namespace

// -- applying results (GUI thread) -------------------------------------------------------------

void WorkspaceMapView::applyMap(WorkspaceMapResult &result)
{
    QElapsedTimer timer;
    timer.start();
    const bool condition = result.quantity == MapQuantity::Condition;
    m_summary = result.summary;
    m_shownQuantity = result.quantity;
    m_values = std::move(result.values);
    m_colourLimit = result.colourLimit;
    m_mapBounds = result.summary.grid.bounds;

    m_colorMap->setData(result.colours.release()); // takes ownership, no copy
    const bool range = result.quantity == MapQuantity::OrientationRange;
    const bool delivered = isPoseValue(result.quantity);
    const bool specification = result.quantity == MapQuantity::Specification;
    m_shownSymbol = result.symbol;
    m_shownLabel = result.label;
    m_shownUnit = result.unit;
    m_specificationArea = specification ? result.specification.metArea : 0.0;
    m_colorMap->setGradient(condition       ? conditionGradient()
                            : range         ? QCPColorGradient(QCPColorGradient::gpThermal)
                            : specification ? workspacemap::specificationGradient()
                            : delivered     ? workspacemap::capabilityGradient()
                                            : determinantGradient());
    m_colorScale->setDataScaleType(condition ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (condition) {
        m_colorScale->axis()->setTicker(QSharedPointer<ConditionTicker>::create());
    } else if (specification) {
        auto ticker = QSharedPointer<QCPAxisTickerFixed>::create(); // met or not: 0 and 1 only
        ticker->setTickStep(1.0);
        ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
        m_colorScale->axis()->setTicker(ticker);
    } else {
        m_colorScale->axis()->setTicker(QSharedPointer<MinusTicker>::create(m_colorScale->axis())); // ticks kept apart
    }
    m_colorScale->axis()->setNumberFormat(QStringLiteral("gb"));
    m_colorScale->axis()->setNumberPrecision(3);
    m_colorScale->setDataRange(condition           ? QCPRange(1.0, m_colourLimit)
                               : range || delivered ? QCPRange(0.0, m_colourLimit)
                                                    : QCPRange(-m_colourLimit, m_colourLimit));

    m_outline->data()->set(result.outline, true);
    m_inverse->data()->set(result.inverse, true);
    m_direct->data()->set(result.direct, true);
    m_curveCounts = {result.inverseCount, result.directCount};
    m_singularityMeanings = {result.inverseMeaning, result.directMeaning};
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross})
        item->setVisible(m_hasPose);

    updateTitle();
    updateLegend();
    m_plot->replot();
    m_lastApplyMilliseconds = double(timer.nsecsElapsed()) * 1e-6;
}

void WorkspaceMapView::applyComparison(WorkspaceMapResult &result)
{
    m_comparisonArea = result.summary.area;
    m_comparisonBounds = result.summary.grid.bounds;
    m_comparisonOutline->data()->set(result.outline, true);
    m_comparisonOutline->setVisible(true);
    m_comparisonOutline->addToLegend();
    updateLegend();
    m_plot->replot();
}

void WorkspaceMapView::clearMap()
{
    m_summary = MapSummary();
    m_values.clear();
    m_colourLimit = 0.0;
    m_mapBounds.setEmpty();
    m_curveCounts = {};
    m_colorMap->data()->setSize(0, 0);
    for (QCPCurve *curve : {m_outline, m_inverse, m_direct})
        curve->data()->clear();
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross})
        item->setVisible(false);
    updateTitle();
    updateLegend();
}

void WorkspaceMapView::showMessage(const QString &text)
{
    m_messageLabel->setText(text);
    m_stack->setCurrentWidget(m_messageLabel);
    m_quantityBox->setEnabled(false);
}

QString WorkspaceMapView::messageText() const
{
    return m_mechanism ? tr("No planar workspace: the outputs of this mechanism are not a point of the plane, so "
                            "there is no workspace map to show.")
                       : tr("No mechanism.");
}

QString WorkspaceMapView::message() const
{
    return m_stack->currentWidget() == m_messageLabel ? m_messageLabel->text() : QString();
}

// -- view --------------------------------------------------------------------------------------

Eigen::Vector2d WorkspaceMapView::markerPosition() const
{
    if (!m_poseCircle->visible())
        return Eigen::Vector2d::Constant(nan);
    return {m_poseCircle->position->key(), m_poseCircle->position->value()};
}

double WorkspaceMapView::valueAt(const Eigen::Vector2d &pointMm) const
{
    const MapGrid &grid = m_summary.grid;
    if (m_values.size() < grid.cells() || grid.columns <= 0 || grid.rows <= 0)
        return nan;
    const double c = std::floor((pointMm.x() - grid.bounds.min().x()) / grid.dx());
    const double r = std::floor((pointMm.y() - grid.bounds.min().y()) / grid.dy());
    if (!(c >= 0 && c < grid.columns && r >= 0 && r < grid.rows))
        return nan;
    return m_values[std::size_t(r) * std::size_t(grid.columns) + std::size_t(c)];
}

/// Runs after every layout (so the axis rect's size is known) and gives both axes the same
/// mm per pixel: the whole map (and comparison) fitted, or the user's zoom kept.
void WorkspaceMapView::fitView()
{
    const QRect pixels = m_plot->axisRect()->rect();
    if (pixels.width() < 10 || pixels.height() < 10)
        return;
    // The scale's label broken for the height the layout gave it: broken for the height before
    // (a legend grown by a Russian line, presentation mode's text), "det J (цвета ограничены
    // на" ran past the scale's top and lost its "d".
    const QString label = scaleLabelFor(pixels.height());
    if (label != m_colorScale->label()) {
        m_colorScale->setLabel(label);
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    QCPAxis *x = m_plot->xAxis, *y = m_plot->yAxis;
    Eigen::Vector2d centre;
    double mmPerPixel = 0.0;
    if (m_userView) {
        centre = {x->range().center(), y->range().center()};
        mmPerPixel = x->range().size() / pixels.width();
    } else {
        Eigen::AlignedBox2d box = m_mapBounds;
        box.extend(m_comparisonBounds);
        if (box.isEmpty())
            return;
        const Eigen::Vector2d size = box.sizes() * 1.04; // a little air around the boundary
        centre = box.center();
        mmPerPixel = std::max(size.x() / pixels.width(), size.y() / pixels.height());
    }
    if (!(mmPerPixel > 0.0))
        return;
    const QCPRange xRange(centre.x() - 0.5 * mmPerPixel * pixels.width(), centre.x() + 0.5 * mmPerPixel * pixels.width());
    const QCPRange yRange(centre.y() - 0.5 * mmPerPixel * pixels.height(), centre.y() + 0.5 * mmPerPixel * pixels.height());
    applyFittedRanges(m_plot, xRange, yRange, m_refits);
}

void WorkspaceMapView::resetView()
{
    m_userView = false;
    m_plot->replot();
}

// -- mouse -------------------------------------------------------------------------------------

void WorkspaceMapView::mousePressed(QMouseEvent *event)
{
    m_pressPosition = event->position().toPoint();
    m_pressInside = event->button() == Qt::LeftButton && !m_mapBounds.isEmpty()
        && m_plot->axisRect()->rect().contains(m_pressPosition);
}

void WorkspaceMapView::mouseMoved(QMouseEvent *event)
{
    if ((event->buttons() & Qt::LeftButton) && (event->position().toPoint() - m_pressPosition).manhattanLength() > 3)
        m_userView = true; // a drag of the map
}

void WorkspaceMapView::mouseReleased(QMouseEvent *event)
{
    const QPoint position = event->position().toPoint();
    const bool click = m_pressInside && event->button() == Qt::LeftButton
        && (position - m_pressPosition).manhattanLength() <= 3 && m_plot->axisRect()->rect().contains(position);
    m_pressInside = false;
    if (click)
        emit pointClicked(
            Eigen::Vector2d(m_plot->xAxis->pixelToCoord(event->position().x()), m_plot->yAxis->pixelToCoord(event->position().y())));
}

bool WorkspaceMapView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot && event->type() == QEvent::Resize) {
        // Brief words also where the plot is short for the full ones (a 1280×720 screen beside
        // the Legs box left the 3-RP̲R's map 110 px high): plotIsShort().
        m_brief = m_briefRequested || plotIsShort();
        updateTitle();
        updateLegend();
        updateBusy();
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace pkm
