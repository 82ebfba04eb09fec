// The workspace map's words: the title, the legend, the colour scale's label and the tooltip,
// in full beside a wide map and brief in presentation mode, and again on a change of language.

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

#include "plotstyle.h"
#include "quantityformat.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QEvent>
#include <QFontMetrics>
#include <QLabel>
#include <QLocale>
#include <QStackedWidget>

#include <algorithm>
#include <cmath>
#include <numbers>

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

using workspacemap::significant;

// -- texts -------------------------------------------------------------------------------------

bool WorkspaceMapView::plotIsShort() const
{
    return m_plot->height() < 22 * QFontMetrics(m_title->font()).height();
}

std::optional<double> WorkspaceMapView::exactArea() const
{
    if (const PlanarWorkspace *planar = m_mechanism ? m_mechanism->planarWorkspace() : nullptr)
        for (const ExactArea &known : planar->exactAreas())
            if (known.key == "area")
                return known.area;
    return std::nullopt;
}

double WorkspaceMapView::shownArea() const
{
    // Where the area of the design's own modes is known in closed form (the O-X glide's), the
    // title gives it, as the sheet and `pkm workspace` do; elsewhere the map's count.
    return exactArea().value_or(m_summary.area);
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

QStringList WorkspaceMapView::titleLines() const
{
    return m_title->text().remove(QChar(0x2060)).split(QLatin1Char('\n'));
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
    // The number and its unit kept on one line (U+00A0), and a grid's count marked as an
    // estimate: the five-bar's 71470 mm² and the same five-bar built from legs, 71451 mm² on
    // other grid bounds, were both read as exact.
    QString area = formatQuantity(shownArea(), units::squareMillimetre, 0).replace(QLatin1Char(' '), QChar(0x00A0));
    if (!exactArea())
        area = QStringLiteral("≈\u00A0") + area;
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
        setTitle(tr("Workspace map"));
        setScaleLabel(QString());
        return;
    }
    if (m_summary.reachableCells == 0) {
        setTitle(tr("Workspace empty in the design's working and assembly modes"));
    } else if (m_shownQuantity == MapQuantity::OrientationRange) {
        const double degree = std::numbers::pi / 180.0;
        setTitle(tr("Workspace %1 · orientation range of φ from %2° to %3°")
                     .arg(areaText(), significant(m_summary.min / degree), significant(m_summary.max / degree)),
                 tr("Workspace %1").arg(areaText()));
        setScaleLabel(tr("orientation range of φ (°): the angles that hold the platform"), tr("range of φ (°)"));
        setMapToolTip(tr("At each point, the total width of the platform angles φ at which the legs can hold it "
                         "there; the map's outline is the workspace at φ_map."));
        return;
    } else {
        // Broken into lines where the map is narrow (between words, never cut off). The range
        // is the grid points': the pose's own value can lie outside it, nearer a singularity.
        setTitle(tr("Workspace %1 · %2 from %3 to %4 at the grid points")
                     .arg(areaText(), symbol, significant(m_summary.min),
                          significant(m_summary.max) + (condition ? QString() : determinantUnit())),
                 tr("Workspace %1").arg(areaText()));
    }
    // Along the scale, broken into lines where the map is short (a projector at 1280×720).
    const QString scaleLabel = condition ? tr("κ(J), log scale (colours end at %1)").arg(significant(m_colourLimit))
                                         : tr("det J (colours clipped at ±%1)").arg(significant(m_colourLimit) + determinantUnit());
    const QString unit = determinantUnit().trimmed();
    setScaleLabel(scaleLabel, condition ? tr("κ(J), log scale") : unit.isEmpty() ? symbol : QStringLiteral("%1 (%2)").arg(symbol, unit));
    setMapToolTip(condition
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
    const auto name = [this](const QString &kind, const QString &meaning) {
        return meaning.isEmpty() || m_brief ? kind : tr("%1 (%2)").arg(kind, meaning);
    };
    // Brief mode names the curves alone; the tooltip says what each is.
    QStringList notes;
    for (int type = 0; type < 2 && m_brief; ++type)
        if (!m_singularityMeanings[type].empty())
            notes << tr("%1: %2").arg(type == 0 ? tr("inverse singularity") : tr("direct singularity"),
                                      coreLabel(m_singularityMeanings[type]));
    m_curveNotes = notes.join(QLatin1Char('\n'));
    refreshToolTip();
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

void WorkspaceMapView::setBrief(bool on)
{
    m_briefRequested = on;
    on = on || plotIsShort();
    if (on == m_brief)
        return;
    m_brief = on;
    updateTitle();
    updateLegend();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void WorkspaceMapView::setTitle(const QString &full, const QString &brief)
{
    m_titleShortened = m_brief && !brief.isEmpty() && brief != full;
    m_fullTitle = full;
    plotstyle::setFittedText(m_title, m_titleShortened ? brief : full);
    refreshToolTip();
}

void WorkspaceMapView::setMapToolTip(const QString &text)
{
    m_toolTip = text;
    refreshToolTip();
}

void WorkspaceMapView::refreshToolTip()
{
    QStringList parts;
    if (m_titleShortened)
        parts << m_fullTitle;
    if (!m_curveNotes.isEmpty())
        parts << m_curveNotes;
    if (!m_toolTip.isEmpty())
        parts << m_toolTip;
    m_plot->setToolTip(parts.join(QStringLiteral("\n\n")));
}

void WorkspaceMapView::setScaleLabel(const QString &text, const QString &brief)
{
    m_scaleLabel = text;
    m_briefScaleLabel = brief;
    m_colorScale->setLabel(scaleLabelFor(m_plot->axisRect()->height()));
}

QString WorkspaceMapView::scaleLabelFor(int height) const
{
    const QFont font = m_colorScale->axis()->labelFont();
    if (m_brief && !m_briefScaleLabel.isEmpty())
        return plotstyle::wrapped(m_briefScaleLabel, font, height);
    const QString full = plotstyle::wrapped(m_scaleLabel, font, height);
    return full.count(QLatin1Char('\n')) < 2 || m_briefScaleLabel.isEmpty() ? full
                                                                            : plotstyle::wrapped(m_briefScaleLabel, font, height);
}

} // namespace pkm
