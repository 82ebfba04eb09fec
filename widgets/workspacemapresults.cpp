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

QString workspacemap::significant(double value)
{
    const QLocale locale;
    auto minus = [](QString text) { return text.replace(QLatin1Char('-'), QChar(0x2212)); };
    const double magnitude = std::abs(value);
    if (!std::isfinite(value) || magnitude == 0.0 || (magnitude >= 1e-3 && magnitude < 1e4))
        return minus(locale.toString(value, 'g', 3));
    int exponent = int(std::floor(std::log10(magnitude)));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(mantissa) >= 9.995) { // rounds up to 10
        mantissa /= 10.0;
        ++exponent;
    }
    static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString power;
    for (const QChar digit : QString::number(std::abs(exponent)))
        power += superscripts[digit.digitValue()];
    return minus(locale.toString(mantissa, 'g', 3)) + QStringLiteral("·10") + (exponent < 0 ? QStringLiteral("⁻") : QString())
        + power;
}

namespace {
using workspacemap::determinantGradient;
using workspacemap::nan;
using workspacemap::significant;

/// Ticks for κ on a logarithmic colour scale: powers of ten over many decades, 1-2-5 over a
/// few, 1-1.5-2-3-4-5-6-8 over less than one (QCPAxisTickerLog falls back to linear steps there).
class ConditionTicker : public MinusTicker
{
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
        m_colorScale->axis()->setTicker(QSharedPointer<MinusTicker>::create());
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

// -- texts -------------------------------------------------------------------------------------

double WorkspaceMapView::shownArea() const
{
    // Where the area of the design's own modes is known in closed form (the O-X glide's), the
    // title gives it, as the sheet and `pkm workspace` do; elsewhere the map's count.
    if (const PlanarWorkspace *planar = m_mechanism ? m_mechanism->planarWorkspace() : nullptr)
        for (const ExactArea &known : planar->exactAreas())
            if (known.key == "area")
                return known.area;
    return m_summary.area;
}

QString WorkspaceMapView::determinantUnit() const
{
    // det J's unit follows the kind (and a leg-built mechanism's legs): rad²/mm² for a five-bar
    const ReportEntry *entry = m_mechanism ? m_mechanism->reportLayout().find("det_J") : nullptr;
    return entry && !entry->unit.symbol.empty() ? QLatin1Char(' ') + coreLabel(entry->unit.symbol) : QString();
}

QString WorkspaceMapView::titleText() const
{
    return m_title->text().remove(QChar(0x2060)).simplified(); // without the word joiners of unbreakable()
}

std::optional<double> WorkspaceMapView::sliceAngle() const
{
    if (!m_mechanism || m_mechanism->outputCount() != 3 || !m_mechanism->parameterApplies("phi_map"))
        return std::nullopt;
    const ParameterSet parameters = m_mechanism->parameters();
    const auto phi = parameters.find("phi_map");
    return phi == parameters.end() ? std::nullopt : std::optional<double>(phi->second);
}

QString WorkspaceMapView::areaText() const
{
    const QString area = formatQuantity(shownArea(), units::squareMillimetre, 0);
    const std::optional<double> slice = sliceAngle();
    if (!slice)
        return area;
    const QString angle = formatQuantity(*slice, units::angle, 1);
    return m_poseOffSlice ? tr("%1 at φ = %2, not the pose's φ").arg(area, angle) : tr("%1 at φ = %2").arg(area, angle);
}

void WorkspaceMapView::updateTitle()
{
    const bool condition = m_shownQuantity == MapQuantity::Condition;
    const QString symbol = condition ? QStringLiteral("κ(J)") : QStringLiteral("det J"); // symbols
    if (isPoseValue(m_shownQuantity) && !m_mapBounds.isEmpty() && m_summary.reachableCells > 0) {
        updateCapabilityTitle();
        return;
    }
    if (m_mapBounds.isEmpty()) {
        plotstyle::setFittedText(m_title, tr("Workspace map"));
        setScaleLabel(QString());
        return;
    }
    if (m_summary.reachableCells == 0) {
        plotstyle::setFittedText(m_title, tr("Workspace empty in the design's working and assembly modes"));
    } else if (m_shownQuantity == MapQuantity::OrientationRange) {
        const double degree = std::numbers::pi / 180.0;
        plotstyle::setFittedText(m_title, tr("Workspace %1 · orientation range of φ from %2° to %3°")
                                              .arg(areaText(), significant(m_summary.min / degree), significant(m_summary.max / degree)));
        setScaleLabel(tr("orientation range of φ (°): the angles that hold the platform"), tr("range of φ (°)"));
        m_plot->setToolTip(tr("At each point, the total width of the platform angles φ at which the legs can hold it "
                              "there; the map's outline is the workspace at φ_map."));
        return;
    } else {
        // Broken into lines where the map is narrow (between words, never cut off). The range
        // is the grid points': the pose's own value can lie outside it, nearer a singularity.
        plotstyle::setFittedText(m_title, tr("Workspace %1 · %2 from %3 to %4 at the grid points")
                                              .arg(areaText(), symbol, significant(m_summary.min),
                                                   significant(m_summary.max) + (condition ? QString() : determinantUnit())));
    }
    // Along the scale, broken into lines where the map is short (a projector at 1280×720).
    const QString scaleLabel = condition ? tr("κ(J), log scale (colours end at %1)").arg(significant(m_colourLimit))
                                         : tr("det J (colours clipped at ±%1)").arg(significant(m_colourLimit) + determinantUnit());
    const QString unit = determinantUnit().trimmed();
    setScaleLabel(scaleLabel, condition ? tr("κ(J), log scale") : unit.isEmpty() ? symbol : QStringLiteral("%1 (%2)").arg(symbol, unit));
    m_plot->setToolTip(condition
            ? tr("The colours end at the 98th percentile of κ(J) over the workspace, %1; κ → ∞ at the "
                 "singularities.")
                  .arg(significant(m_colourLimit))
            : tr("The colours are clipped at ±%1, the larger of the 5th and 95th percentiles of |det J| "
                 "over the workspace: det J → ±∞ at inverse singularities, 0 at direct ones.")
                  .arg(significant(m_colourLimit)));
}

void WorkspaceMapView::updateLegend()
{
    m_outline->setName(tr("workspace boundary"));
    const QString none = tr(": none");
    const auto name = [](const QString &kind, const QString &meaning) {
        return meaning.isEmpty() ? kind : tr("%1 (%2)").arg(kind, meaning);
    };
    m_inverse->setName(name(tr("inverse singularity"), coreLabel(m_singularityMeanings[0]))
                       + (m_curveCounts[0] || m_mapBounds.isEmpty() ? QString() : none));
    m_direct->setName(name(tr("direct singularity"), coreLabel(m_singularityMeanings[1]))
                      + (m_curveCounts[1] || m_mapBounds.isEmpty() ? QString() : none));
    if (m_comparisonArea > 0.0) {
        QString text = tr("%1: boundary, %2").arg(m_comparisonLabel, formatQuantity(m_comparisonArea, units::squareMillimetre, 0));
        if (m_summary.area > 0.0) {
            const double change = 100.0 * (m_comparisonArea / m_summary.area - 1.0);
            text += tr(" (%1%2 %)").arg(change >= 0.0 ? QStringLiteral("+") : QString(QChar(0x2212)),
                QLocale().toString(std::abs(change), 'f', 1));
        }
        m_comparisonOutline->setName(text);
    }

    // A long name (a singular curve's meaning in Russian) wraps rather than run off the plot.
    QCPLegend *legend = m_plot->legend;
    const int textRoom = m_plot->width() - legend->margins().left() - legend->margins().right()
        - legend->iconSize().width() - legend->iconTextPadding() - 12;
    for (QCPAbstractPlottable *plottable : {static_cast<QCPAbstractPlottable *>(m_outline),
                                            static_cast<QCPAbstractPlottable *>(m_inverse),
                                            static_cast<QCPAbstractPlottable *>(m_direct)})
        plottable->setName(plotstyle::wrapped(plottable->name(), legend->font(), textRoom));
    // Two columns when they fit beside the colour scale, else one; filled row by row.
    int widest = 0, count = 0;
    for (int j = 0; j < legend->itemCount(); ++j)
        if (const QCPAbstractLegendItem *item = legend->item(j)) {
            ++count;
            widest = std::max(widest, item->minimumOuterSizeHint().width());
        }
    const int available = m_plot->width() - m_colorScale->outerRect().width() - legend->margins().left()
        - legend->margins().right();
    const int columns = count > 1 && 2 * widest + legend->columnSpacing() <= available ? 2 : 1;
    legend->setWrap(columns);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true); // also re-flows after items came or went
    // The columns follow the plot's width (on every resize): the two of a wide screen must not
    // keep the plot from narrowing on a 1024-pixel one.
    legend->setMinimumSize(QSize(40, 0));
}

void WorkspaceMapView::retranslate()
{
    m_quantityLabel->setText(tr("&Map:"));
    m_quantityBox->setItemText(0, QStringLiteral("det J")); // a symbol
    m_quantityBox->setItemText(1, tr("condition number κ(J)"));
    if (const int range = m_quantityBox->findData(int(MapQuantity::OrientationRange)); range >= 0)
        m_quantityBox->setItemText(range, tr("orientation range of φ"));
    retranslateCapabilityItems();
    retranslateToleranceItem();
    m_busyLabel->setText(tr("computing…"));
    m_plot->xAxis->setLabel(tr("x (mm)"));
    m_plot->yAxis->setLabel(tr("y (mm)"));
    if (m_stack->currentWidget() == m_messageLabel)
        m_messageLabel->setText(messageText());
    updateTitle();
    updateLegend();
}

void WorkspaceMapView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        updateBusy(); // "computing…" changed its width
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    QWidget::changeEvent(event);
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
void WorkspaceMapView::setScaleLabel(const QString &text, const QString &brief)
{
    m_scaleLabel = text;
    m_briefScaleLabel = brief;
    m_colorScale->setLabel(scaleLabelFor(m_plot->axisRect()->height()));
}

QString WorkspaceMapView::scaleLabelFor(int height) const
{
    const QFont font = m_colorScale->axis()->labelFont();
    const QString full = plotstyle::wrapped(m_scaleLabel, font, height);
    return full.count(QLatin1Char('\n')) < 2 || m_briefScaleLabel.isEmpty() ? full
                                                                            : plotstyle::wrapped(m_briefScaleLabel, font, height);
}

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
        updateTitle();
        updateLegend();
        updateBusy();
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace pkm
