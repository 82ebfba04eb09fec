#include "kinds/pjoint/pjointplots.h"

#include "plotfont.h"
#include "plotstyle.h"
#include "textscale.h"

#include "kinds/pjoint/pjointcurves.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QEvent>
#include <QGridLayout>
#include <QLocale>
#include <QTabWidget>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {

/// The θ tick step for the axis rect's width: the width the last layout gave it, or an
/// estimate before the first (the plot less its y tick labels, axis title and margins).
void fitThetaTicks(QCustomPlot *plot)
{
    const int laidOut = plot->axisRect()->width();
    const int axisPixels = laidOut > 0 ? laidOut : plot->width() - 110;
    const double label = QFontMetricsF(plot->xAxis->tickLabelFont()).horizontalAdvance(QStringLiteral("−60°"));
    qSharedPointerCast<QCPAxisTickerFixed>(plot->xAxis->ticker())
        ->setTickStep(pjointcurves::thetaStep(plot->xAxis->range().size(), axisPixels, label));
}

using pjointcurves::familyK;
using pjointcurves::quantities;
using pjointcurves::Quantity;
using pjointcurves::symbolOf;
using pjointcurves::Tab;
using pjointcurves::unitOf;
using pjointcurves::valueText;
static_assert(PJointPlots::PlotCount == pjointcurves::quantityCount, "one quantity per plot, in PlotIndex order");

using pjointcurves::weakTransmission;
constexpr std::array<QRgb, familyK.size()> familyRgb {0x5e9c76, 0x8e6fb0, 0xc08a3e, 0x8c8c8c, 0xb0b0b0};

constexpr QRgb steepFillRgb = 0xfcdcb4, steepEdgeRgb = 0xe8a04c;
constexpr QRgb recommendedFillRgb = 0xeaf5e7;
constexpr QRgb weakFillRgb = 0xf6e0e0, weakEdgeRgb = 0xd9a0a0;

using plotstyle::axisRgb, plotstyle::cursorRgb, plotstyle::designRgb, plotstyle::gridRgb;
using plotstyle::labelPoints, plotstyle::legendPoints, plotstyle::subtitlePoints, plotstyle::tickPoints,
    plotstyle::titlePoints;

/// Degree tick labels ("−45°") at a fixed step, for θ and for the φ, μ axes.
class DegreeTicker : public QCPAxisTickerFixed
{
protected:
    QString getTickLabel(double tick, const QLocale &locale, QChar, int) override
    {
        return locale.toString(qRound(tick)).replace(QLatin1Char('-'), QChar(0x2212)) + QChar(0x00B0);
    }
};

void setDegreeTicks(QCPAxis *axis, double step)
{
    auto ticker = QSharedPointer<DegreeTicker>::create();
    ticker->setTickStep(step);
    ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
    axis->setTicker(ticker);
}

QVector<QCPGraphData> toGraphData(const pjointcurves::Curve &curve)
{
    QVector<QCPGraphData> data;
    data.reserve(qsizetype(curve.size()));
    for (const pjointcurves::Point &point : curve)
        data.append(QCPGraphData(point.theta, point.value));
    return data;
}

/// Moves a vertical band to [from, to] in θ; a band narrower than 0.05° is hidden.
void setBand(QCPItemRect *band, double from, double to)
{
    band->topLeft->setCoords(from, 0.0);
    band->bottomRight->setCoords(to, 1.0);
    band->setVisible(to - from > 0.05);
}

/// A light band [from, to] in θ over the whole height of the axis rect (vertical) or in the
/// value over its whole width (horizontal).
QCPItemRect *addBand(QCustomPlot *plot, Qt::Orientation orientation, double from, double to, QRgb fill, QPen edge)
{
    const bool vertical = orientation == Qt::Vertical;
    auto *band = new QCPItemRect(plot);
    band->setLayer(QStringLiteral("bands"));
    for (QCPItemPosition *corner : {band->topLeft, band->bottomRight}) {
        corner->setTypeX(vertical ? QCPItemPosition::ptPlotCoords : QCPItemPosition::ptAxisRectRatio);
        corner->setTypeY(vertical ? QCPItemPosition::ptAxisRectRatio : QCPItemPosition::ptPlotCoords);
    }
    band->topLeft->setCoords(vertical ? from : 0.0, vertical ? 0.0 : to);
    band->bottomRight->setCoords(vertical ? to : 1.0, vertical ? 1.0 : from);
    band->setBrush(QColor(fill));
    band->setPen(edge);
    band->setSelectable(false);
    return band;
}

/// Items have no legend entry: an empty bar plottable gives the band a filled swatch there.
QCPBars *addSwatch(QCustomPlot *plot, QRgb fill, QPen edge)
{
    auto *swatch = new QCPBars(plot->xAxis, plot->yAxis);
    swatch->setBrush(QColor(fill));
    swatch->setPen(edge);
    swatch->setSelectable(QCP::stNone);
    return swatch;
}

} // namespace

PJointPlots::PJointPlots(QWidget *parent)
    : KindPanel(parent)
    , m_tabs(new QTabWidget(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    m_tabs->setFont(fontOf(font(), labelPoints));
    // presentation mode's large text pushed the fourth tab behind scroll arrows
    textscale::keepTabsInSight(m_tabs);

    std::array<QWidget *, 3> pages {};
    for (QWidget *&page : pages) {
        page = new QWidget;
        m_tabs->addTab(page, QString());
    }
    for (int i = 0; i < PlotCount; ++i)
        createPanel(i);

    // Geometry: fig. 8 has the largest legend, so it takes the left half; φ and μ share the right.
    auto *geometry = new QGridLayout(pages[int(Tab::Geometry)]);
    geometry->addWidget(m_panels[DiagonalPlot].plot, 0, 0, 2, 1);
    geometry->addWidget(m_panels[PassiveAnglePlot].plot, 0, 1);
    geometry->addWidget(m_panels[TransmissionAnglePlot].plot, 1, 1);
    auto *jacobian = new QHBoxLayout(pages[int(Tab::Jacobian)]);
    jacobian->addWidget(m_panels[JacobianPlot].plot, 1);
    jacobian->addWidget(m_panels[InverseJacobianPlot].plot, 1);
    // Actuator: figs 15 and 16 side by side, fig. 17 below across the width, so that each keeps
    // a readable θ axis when the plot area is only about 800 px wide (1920 px screen).
    auto *actuator = new QGridLayout(pages[int(Tab::Actuator)]);
    actuator->addWidget(m_panels[ResolutionPlot].plot, 0, 0);
    actuator->addWidget(m_panels[SpeedPlot].plot, 0, 1);
    actuator->addWidget(m_panels[TorquePlot].plot, 1, 0, 1, 2);
    // Columns shared by stretch, not by the plots' size hints: those follow the legends'
    // wrapping, and after presentation mode's larger text fig. 9 was left a 70 px strip. Figs.
    // 9 and 10 stack, so their column is the wider; figs. 15 and 16 share theirs evenly.
    geometry->setColumnStretch(0, 2);
    geometry->setColumnStretch(1, 3);
    actuator->setColumnStretch(0, 1);
    actuator->setColumnStretch(1, 1);
    // And the rows: after leaving presentation mode in Russian, fig. 9 over fig. 10 was
    // squashed from 165 px to 85 px by fig. 10's hint.
    for (QGridLayout *grid : {geometry, actuator}) {
        grid->setRowStretch(0, 1);
        grid->setRowStretch(1, 1);
    }
    for (QLayout *l : std::initializer_list<QLayout *> {geometry, jacobian, actuator}) {
        l->setContentsMargins(4, 4, 4, 4);
        l->setSpacing(6);
    }

    setDesign(m_design);
}

PJointPlots::~PJointPlots() = default;

void PJointPlots::createPanel(int index)
{
    const Quantity &q = quantities[index];
    Panel &p = m_panels[index];
    auto *plot = new QCustomPlot;
    p.plot = plot;
    plot->installEventFilter(this);
    plot->setMinimumSize(180, 170);
    // Layers, bottom to top: background, bands, grid, family, main (this design), axes,
    // legend, overlay, cursor (plotstyle.h).
    const plotstyle::Header header = plotstyle::apply(plot, font());
    p.title = header.title;
    p.subtitle = header.subtitle;
    p.cursorLayer = header.cursorLayer;
    plot->addLayer(QStringLiteral("family"), plot->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    setDegreeTicks(plot->xAxis, 30.0); // steps set in recompute()
    if (q.unit.symbol == units::angle.symbol)
        setDegreeTicks(plot->yAxis, 30.0);
    else
        plot->yAxis->ticker()->setTickCount(6);

    // Curves. graph(0) is this design over its range; the rest are drawn underneath it.
    p.design = plot->addGraph();
    p.design->setPen(QPen(QColor(designRgb), 2.5));
    if (pjointcurves::hasExtension(q)) { // figs. 8–12 reach beyond the design's θ range
        p.extension = plot->addGraph();
        QColor light(designRgb);
        light.setAlpha(150);
        p.extension->setPen(QPen(light, 1.5, Qt::DashLine));
        p.extension->setLayer(QStringLiteral("family"));
    }
    for (int j = 0; j < q.familySize; ++j) {
        QCPGraph *graph = plot->addGraph();
        graph->setPen(
            QPen(QColor(familyRgb[size_t(j)]), 1.5, familyK[size_t(j)] >= 1.0 ? Qt::DashDotLine : Qt::SolidLine));
        graph->setLayer(QStringLiteral("family"));
        p.family[size_t(j)] = graph;
    }
    for (int g = 0; g < plot->graphCount(); ++g)
        plot->graph(g)->setSelectable(QCP::stNone);

    // Bands: the recommended range and the steep regions beyond it, computed for the design
    // (pjoint::recommendedRange; for the prototype the document's −60°…40° and 40°…60°).
    if (q.tab != Tab::Geometry) {
        p.recommendedBand = addBand(plot, Qt::Vertical, 0.0, 0.0, recommendedFillRgb, Qt::NoPen);
        for (QCPItemRect *&band : p.steepBands)
            band = addBand(plot, Qt::Vertical, 0.0, 0.0, steepFillRgb, QPen(QColor(steepEdgeRgb), 1.0));
        p.recommendedSwatch = addSwatch(plot, recommendedFillRgb, QPen(QColor(0xa8cfa0), 1.0));
        p.steepSwatch = addSwatch(plot, steepFillRgb, QPen(QColor(steepEdgeRgb), 1.0));
    }
    if (index == TransmissionAnglePlot) { // μ ≥ 0
        addBand(plot, Qt::Horizontal, 0.0, weakTransmission, weakFillRgb, Qt::NoPen);
        p.weakTransmissionSwatch = addSwatch(plot, weakFillRgb, QPen(QColor(weakEdgeRgb), 1.0));
    }

    // Cursor: a vertical line at θ, a marker on this design's curve, its value beside it.
    const plotstyle::Cursor cursor = plotstyle::addCursor(plot, font(), header.cursorLayer);
    // The tick step is for the width the layout gives the axis rect, known only after it: a
    // step that no longer fits is changed for the next frame.
    connect(plot, &QCustomPlot::afterLayout, this, [plot] {
        const auto ticker = qSharedPointerCast<QCPAxisTickerFixed>(plot->xAxis->ticker());
        const double before = ticker->tickStep();
        fitThetaTicks(plot);
        if (ticker->tickStep() != before)
            plot->replot(QCustomPlot::rpQueuedReplot);
    });
    p.cursorLine = cursor.line;
    p.cursorMarker = cursor.marker;
    p.cursorLabel = cursor.label;
}

void PJointPlots::setDesign(const PJointDesign &design)
{
    m_design = design;
    for (int i = 0; i < PlotCount; ++i)
        recompute(i);
    retranslate(); // the legend and the subtitles quote the design
    for (int i = 0; i < PlotCount; ++i) {
        placeCursor(i); // its value and its label's side depend on the new curve and y range
        m_panels[i].needsReplot = true;
        refresh(i);
    }
}

void PJointPlots::setDesign(const MechanismPtr &mechanism, const QString &)
{
    if (const auto *joint = dynamic_cast<const PJoint *>(mechanism.get()))
        setDesign(joint->design());
}

void PJointPlots::setPose(const Pose &pose)
{
    setTheta(pose.outputs[0]);
}

void PJointPlots::setTheta(double thetaRadians)
{
    m_theta = thetaRadians;
    for (int i = 0; i < PlotCount; ++i) {
        placeCursor(i);
        m_panels[i].needsCursorReplot = true;
        refresh(i);
    }
}

QCustomPlot *PJointPlots::plot(int i) const
{
    return i >= 0 && i < PlotCount ? m_panels[i].plot : nullptr;
}

QString PJointPlots::plotName(int i) const
{
    return i >= 0 && i < PlotCount ? QString::fromLatin1(quantities[i].name) : QString();
}

int PJointPlots::plotIndex(const QString &name) const
{
    for (int i = 0; i < PlotCount; ++i)
        if (name == QLatin1String(quantities[i].name))
            return i;
    return -1;
}

double PJointPlots::cursorTheta() const
{
    return m_panels[0].cursorLine->point1->key();
}

double PJointPlots::cursorValue(int i) const
{
    return i >= 0 && i < PlotCount ? m_panels[i].cursorValue : std::numeric_limits<double>::quiet_NaN();
}

bool PJointPlots::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show || event->type() == QEvent::Resize) {
        for (int i = 0; i < PlotCount; ++i) {
            if (m_panels[i].plot != watched)
                continue;
            if (event->type() == QEvent::Resize) {
                fitToWidth(i);
                plotstyle::fitText(m_panels[i].title);
                plotstyle::fitText(m_panels[i].subtitle);
            }
            else
                refresh(i, true); // its tab became visible: catch up with what it missed
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void PJointPlots::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        for (int i = 0; i < PlotCount; ++i) {
            placeCursor(i); // the value beside the marker, in the new locale
            m_panels[i].needsReplot = true;
            refresh(i, true);
        }
    }
    QWidget::changeEvent(event);
}

void PJointPlots::recompute(int index)
{
    Panel &p = m_panels[index];
    const pjointcurves::Plot curves = pjointcurves::compute(m_design, index);
    p.design->data()->set(toGraphData(curves.design), true);
    if (p.extension) {
        p.extension->data()->set(toGraphData(curves.extension), true);
        if (curves.extensionBeyond)
            p.extension->addToLegend();
        else
            p.extension->removeFromLegend();
    }
    for (size_t j = 0; j < curves.family.size(); ++j)
        p.family[j]->data()->set(toGraphData(curves.family[j]), true);

    if (p.recommendedBand) {
        const Interval recommended = pjoint::recommendedRange(m_design);
        const double from = recommended.min / units::degree, to = recommended.max / units::degree;
        const double bounds[] = {m_design.thetaMin / units::degree, from, to, m_design.thetaMax / units::degree};
        setBand(p.recommendedBand, from, to);
        setBand(p.steepBands[0], bounds[0], bounds[1]);
        setBand(p.steepBands[1], bounds[2], bounds[3]);
    }
    p.plot->xAxis->setRange(curves.theta.lower, curves.theta.upper);
    p.plot->yAxis->setRange(curves.value.lower, curves.value.upper);
    if (quantities[index].unit.symbol == units::angle.symbol)
        qSharedPointerCast<QCPAxisTickerFixed>(p.plot->yAxis->ticker())
            ->setTickStep(pjointcurves::angleStep(curves.value.upper - curves.value.lower));
}

void PJointPlots::placeCursor(int index)
{
    Panel &p = m_panels[index];
    const double x = m_theta / units::degree;
    const double value = quantities[index].value(m_design, m_theta);
    p.cursorValue = value;

    p.cursorLine->point1->setCoords(x, 0.0);
    p.cursorLine->point2->setCoords(x, 1.0);

    // The marker sits on the curve; off the y range it is hidden and the label waits at the
    // edge with an arrow, so a near-singular value never moves the axes.
    const QCPRange yRange = p.plot->yAxis->range();
    const bool finite = std::isfinite(value);
    const double shown = finite ? std::clamp(value, yRange.lower, yRange.upper) : yRange.upper;
    p.cursorMarker->position->setCoords(x, shown);
    p.cursorMarker->setVisible(finite && yRange.contains(value));

    QString text = valueText(index, value);
    if (!finite || value > yRange.upper)
        text += QStringLiteral(" ↑");
    else if (value < yRange.lower)
        text += QStringLiteral(" ↓");
    p.cursorLabel->setText(text);
    plotstyle::placeCursorLabel(p.plot, p.cursorLabel, x, shown);
}

void PJointPlots::refresh(int index, bool queued)
{
    Panel &p = m_panels[index];
    if (!p.plot->isVisible())
        return; // on a hidden tab: the Show event brings it up to date
    if (p.needsReplot)
        p.plot->replot(queued ? QCustomPlot::rpQueuedReplot : QCustomPlot::rpRefreshHint);
    else if (p.needsCursorReplot)
        p.cursorLayer->replot(); // the cursor alone: the curves' buffer is reused
    p.needsReplot = false;
    p.needsCursorReplot = false;
}

void PJointPlots::fitToWidth(int index)
{
    QCustomPlot *plot = m_panels[index].plot;
    fitThetaTicks(plot);

    // A name longer than the plot is wide wraps rather than run off its edge (a narrow
    // projector screen, a longer language); then as many legend columns as the width allows,
    // balanced over the rows.
    plotstyle::wrapLegendNames(plot);
    // Fig. 9 and fig. 10 share a column on a short screen (a projector at 1280×720): there the
    // k-family, in fig. 8's colours whose legend stands beside them, leaves their legends so
    // that the curves keep a readable plot (at least 150 px besides titles and axes).
    Panel &p = m_panels[index];
    const auto setFamilyShown = [&](bool shown) {
        for (QCPGraph *graph : p.family)
            if (graph && !graph->name().isEmpty())
                shown ? graph->addToLegend() : graph->removeFromLegend();
        if (shown && p.weakTransmissionSwatch && p.weakTransmissionSwatch->removeFromLegend())
            p.weakTransmissionSwatch->addToLegend(); // the band's entry stays last
    };
    // Still too tall (a longer language wraps every name in two lines): the design's own
    // two entries go too, since fig. 8 beside them names the same line styles; a band's
    // entry, which only this plot has, stays.
    const auto setDesignShown = [&](bool shown) {
        for (QCPAbstractPlottable *graph : {static_cast<QCPAbstractPlottable *>(p.design),
                                            static_cast<QCPAbstractPlottable *>(p.extension)})
            if (graph && !graph->name().isEmpty())
                shown ? graph->addToLegend() : graph->removeFromLegend();
    };
    const bool shortened = index != DiagonalPlot && p.family[0];
    if (shortened && !plot->legend->hasItemWithPlottable(p.design)) {
        setDesignShown(true);
        if (p.weakTransmissionSwatch && p.weakTransmissionSwatch->removeFromLegend())
            p.weakTransmissionSwatch->addToLegend(); // the band's entry stays last
    }
    if (shortened && !plot->legend->hasItemWithPlottable(p.family[0]))
        setFamilyShown(true);
    const auto tooTall = [&] { return plotstyle::layOutLegend(plot) + 120 + 150 > plot->height(); };
    if (shortened && tooTall()) {
        setFamilyShown(false);
        if (tooTall()) {
            setDesignShown(false);
            plotstyle::layOutLegend(plot);
        }
    } else {
        plotstyle::layOutLegend(plot); // fig. 8's seven entries in columns where they fit
    }
    // Figs. 15 and 16 share a row above fig. 17 (1280×720): where their legends leave the axes
    // a strip, they show none, since fig. 17 below, as wide as both, names the same curve and
    // bands. Its row then takes no room.
    if (index == ResolutionPlot || index == SpeedPlot)
        plotstyle::setLegendShown(plot, !tooTall());
}

} // namespace pkm
