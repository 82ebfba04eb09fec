// The four-bar's live plots (docs/mathematics.md, section 4): the four tabs with their axes,
// titles and cursors, built once and kept in step with the pose; the curves themselves are
// computed in fourbarcurves.cpp.

#include "kinds/fourbar/fourbarplots.h"
#include "kinds/fourbar/fourbarplotsinternal.h"

#include "plotfont.h"
#include "plotstyle.h"
#include "plotticker.h"
#include "textscale.h"

#include <qcustomplot.h>

#include <QEvent>
#include <QLocale>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm {

namespace {
using fourbarplots::angleStep;
using fourbarplots::nan;
using fourbarplots::setDegreeStep;

constexpr QRgb limitRgb = 0x2e7d32;
constexpr QRgb poorFillRgb = 0xf6dcdc, poorEdgeRgb = 0xd9a0a0;

using plotstyle::axisRgb, plotstyle::cursorRgb, plotstyle::designRgb, plotstyle::gridRgb;
using plotstyle::labelPoints, plotstyle::legendPoints, plotstyle::subtitlePoints, plotstyle::tickPoints,
    plotstyle::titlePoints;

QString minus(QString text)
{
    return text.replace(QLatin1Char('-'), QChar(0x2212));
}

QString number(double value, int decimals)
{
    return minus(QLocale().toString(value, 'f', decimals));
}

/// Degree tick labels ("−45°") at a fixed step.
class DegreeTicker : public QCPAxisTickerFixed
{
protected:
    QString getTickLabel(double tick, const QLocale &locale, QChar, int) override
    {
        return minus(locale.toString(qRound(tick))) + QChar(0x00B0);
    }
};

void setDegreeTicks(QCPAxis *axis)
{
    auto ticker = QSharedPointer<DegreeTicker>::create();
    ticker->setTickStep(30.0);
    ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
    axis->setTicker(ticker);
}

} // namespace

FourBarPlots::FourBarPlots(QWidget *parent)
    : QWidget(parent)
    , m_tabs(new QTabWidget(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    m_tabs->setFont(fontOf(font(), labelPoints));
    // presentation mode's large text pushed the fourth tab behind scroll arrows
    textscale::keepTabsInSight(m_tabs);
    m_tabs->setObjectName(QStringLiteral("fourbarPlotTabs"));

    for (int i = 0; i < PlotCount; ++i)
        createPanel(i);
    auto page = [](std::initializer_list<QWidget *> plots) {
        auto *widget = new QWidget;
        auto *column = new QVBoxLayout(widget);
        column->setContentsMargins(4, 4, 4, 4);
        column->setSpacing(6);
        for (QWidget *plot : plots)
            column->addWidget(plot);
        return widget;
    };
    m_tabs->addTab(page({m_panels[DeltaPlot].plot}), QString());
    m_tabs->addTab(page({m_panels[Omega3Plot].plot, m_panels[Epsilon3Plot].plot}), QString());
    m_tabs->addTab(page({m_panels[GammaPlot].plot}), QString());
    m_tabs->addTab(page({m_panels[SweepPlot].plot}), QString());
    retranslate();
}

void FourBarPlots::retranslate()
{
    m_tabs->setTabText(0, tr("δ(α) — fig. 4"));
    m_tabs->setTabText(1, tr("ω₃, ε₃ — fig. 6"));
    m_tabs->setTabText(2, QStringLiteral("γ(α)")); // symbols only
    m_tabs->setTabText(3, tr("δ vs AB — fig. 5"));
    m_tabs->setTabToolTip(0, tr("The rocker angle δ over the crank's range (click to set α)"));
    m_tabs->setTabToolTip(1, tr("The rocker's angular velocity and acceleration at constant ω₁ (click to set α)"));
    m_tabs->setTabToolTip(2, tr("The transmission angle at C; shaded where the crank drives the rocker poorly"));
    m_tabs->setTabToolTip(3, tr("δ at the current α as the crank length AB changes, the other links fixed"));
    for (int i = 0; i < PlotCount; ++i) {
        if (i != SweepPlot)
            m_panels[i].plot->setToolTip(tr("Click or drag to set the crank angle α"));
    }
    if (!m_mechanism)
        return;
    retitle();
    for (int i = 0; i < PlotCount; ++i) {
        placeCursor(i);
        m_panels[i].needsReplot = true;
        refresh(i);
    }
}

void FourBarPlots::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

FourBarPlots::~FourBarPlots() = default;

void FourBarPlots::createPanel(int index)
{
    Panel &p = m_panels[index];
    auto *plot = new QCustomPlot;
    p.plot = plot;
    plot->setObjectName(QStringLiteral("fourbarPlot%1").arg(index));
    plot->installEventFilter(this);
    plot->setMinimumSize(260, 150);
    const plotstyle::Header header = plotstyle::apply(plot, font());
    p.title = header.title;
    p.subtitle = header.subtitle;
    p.cursorLayer = header.cursorLayer;
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot->legend->setWrap(2);
    const bool hasLegend = index == GammaPlot || index == SweepPlot;
    plot->legend->setVisible(hasLegend);
    if (!hasLegend) { // no empty row: the legend goes (its destructor tells the plot)
        QCPLayoutGrid *grid = plot->plotLayout();
        grid->remove(plot->legend);
        grid->simplify();
    }
    if (index == Omega3Plot || index == Epsilon3Plot)
        plot->yAxis->grid()->setZeroLinePen(QPen(QColor(0xb0b0b0), 1.0));
    // room for the last α label (QCustomPlot drops a tick label that would stick out)
    plot->axisRect()->setMinimumMargins(QMargins(0, 0, 22, 0));
    if (index == SweepPlot) {
        plot->xAxis->setTicker(QSharedPointer<MinusTicker>::create());
        plot->xAxis->ticker()->setTickCount(7);
    } else {
        setDegreeTicks(plot->xAxis);
    }
    if (index == Omega3Plot || index == Epsilon3Plot) {
        plot->yAxis->setTicker(QSharedPointer<MinusTicker>::create());
        plot->yAxis->ticker()->setTickCount(6);
    } else {
        setDegreeTicks(plot->yAxis);
    }

    p.curve = plot->addGraph();
    p.curve->setName(QString()); // not QCustomPlot's "Graph 1": retitle() names it
    p.curve->setPen(QPen(QColor(designRgb), 2.5));
    p.curve->setSelectable(QCP::stNone);

    if (index == GammaPlot) {
        for (QCPItemRect *&band : m_poorBands) {
            band = new QCPItemRect(plot);
            band->setLayer(QStringLiteral("bands"));
            for (QCPItemPosition *corner : {band->topLeft, band->bottomRight}) {
                corner->setTypeX(QCPItemPosition::ptAxisRectRatio);
                corner->setTypeY(QCPItemPosition::ptPlotCoords);
            }
            band->setBrush(QColor(poorFillRgb));
            band->setPen(Qt::NoPen);
            band->setSelectable(false);
        }
        m_poorSwatch = new QCPBars(plot->xAxis, plot->yAxis);
        m_poorSwatch->setBrush(QColor(poorFillRgb));
        m_poorSwatch->setPen(QPen(QColor(poorEdgeRgb), 1.0));
        m_poorSwatch->setSelectable(QCP::stNone);
    }
    if (index == SweepPlot) {
        m_largestCrankLine = plot->addGraph();
        m_largestCrankLine->setName(QString());
        m_largestCrankLine->setPen(QPen(QColor(limitRgb), 2.0, Qt::DashLine));
        m_largestCrankLine->setSelectable(QCP::stNone);
    }

    // Cursor: a vertical line at α (AB on the sweep), a marker on the curve, its value beside it.
    const plotstyle::Cursor cursor = plotstyle::addCursor(plot, font(), header.cursorLayer);
    p.cursorLine = cursor.line;
    p.cursorMarker = cursor.marker;
    p.cursorLabel = cursor.label;

    if (index != SweepPlot) { // a click or a drag on an α plot sets α
        auto request = [this, plot](QMouseEvent *event) {
            if (!m_mechanism || !plot->axisRect()->rect().contains(event->position().toPoint()))
                return;
            const QCPRange range = plot->xAxis->range();
            const double x = std::clamp(plot->xAxis->pixelToCoord(event->position().x()), range.lower, range.upper);
            emit alphaRequested(x * units::degree);
        };
        connect(plot, &QCustomPlot::mousePress, this, [this, request](QMouseEvent *event) {
            if (event->button() != Qt::LeftButton)
                return;
            m_pressed = true;
            request(event);
        });
        connect(plot, &QCustomPlot::mouseMove, this, [this, request](QMouseEvent *event) {
            if (m_pressed && (event->buttons() & Qt::LeftButton))
                request(event);
        });
        connect(plot, &QCustomPlot::mouseRelease, this, [this](QMouseEvent *) { m_pressed = false; });
        plot->setCursor(Qt::CrossCursor); // its tooltip: retranslate()
    }
}

void FourBarPlots::setDesign(const MechanismPtr &mechanism, const Pose &pose)
{
    const auto *fourbar = dynamic_cast<const FourBar *>(mechanism.get());
    if (!fourbar)
        return;
    m_mechanism = mechanism;
    m_design = fourbar->design();
    recomputeCurves();
    m_sweepAlpha = nan; // the links changed: the sweep too
    const bool fits = pose.inputs.size() == 1 && pose.outputs.size() == 1;
    setPose(fits ? pose : fourbar->homePose());
    retitle();
    for (int i = 0; i < PlotCount; ++i) {
        m_panels[i].needsReplot = true;
        refresh(i);
    }
}

void FourBarPlots::setPose(const Pose &pose)
{
    if (!m_mechanism || pose.inputs.size() != 1 || pose.outputs.size() != 1)
        return;
    m_pose = pose;
    const bool sweepMoved = !(std::abs(pose.inputs[0] - m_sweepAlpha) < 1e-12);
    if (sweepMoved) {
        recomputeSweep();
        retitle();
        m_panels[SweepPlot].needsReplot = true;
    }
    for (int i = 0; i < PlotCount; ++i) {
        placeCursor(i);
        m_panels[i].needsCursorReplot = true;
        refresh(i);
    }
}

void FourBarPlots::retitle()
{
    if (!m_mechanism)
        return;
    const FourBarDesign &d = m_design;
    const QLocale locale;
    const QString links = tr("AB/BC/CD/AD = %1/%2/%3/%4 mm, %5 branch")
                              .arg(locale.toString(d.crank, 'g', 6), locale.toString(d.coupler, 'g', 6),
                                  locale.toString(d.rocker, 'g', 6), locale.toString(d.ground, 'g', 6),
                                  d.branch == fourbar::crossed ? tr("crossed", "branch") : tr("open", "branch"));
    const QString omega = number(d.omega1, 2);
    const QString alpha = number(m_sweepAlpha / units::degree, 1);
    const std::array<QString, PlotCount> titles {
        tr("Fig. 4 — rocker angle δ(α)"),
        tr("Fig. 6 — rocker angular velocity ω₃ = dδ/dt"),
        tr("Fig. 6 — rocker angular acceleration ε₃ = d²δ/dt²"),
        tr("Transmission angle γ(α), (5)"),
        tr("Fig. 5 — rocker angle δ against the crank length AB"),
    };
    const std::array<QString, PlotCount> subtitles {
        links,
        tr("ω₁ = %1 rad/s constant; exact (the document's (8) has the opposite sign)").arg(omega),
        tr("ω₁ = %1 rad/s constant; exact (not the document's (14))").arg(omega),
        links,
        tr("at α = %1°; BC, CD, AD fixed").arg(alpha),
    };
    const std::array<QString, PlotCount> yLabels {
        QStringLiteral("δ (°)"), tr("ω₃ (rad/s)"), tr("ε₃ (rad/s²)"), QStringLiteral("γ (°)"), QStringLiteral("δ (°)")};
    for (int i = 0; i < PlotCount; ++i) {
        Panel &p = m_panels[i];
        plotstyle::setFittedText(p.title, titles[std::size_t(i)]); // broken into lines, as the subtitle
        plotstyle::setFittedText(p.subtitle, subtitles[std::size_t(i)]);
        p.plot->xAxis->setLabel(i == SweepPlot ? tr("crank length AB (mm)") : tr("crank angle α (°)"));
        p.plot->yAxis->setLabel(yLabels[std::size_t(i)]);
    }
    // symbols, the same in every language (only γ and δ are in a legend)
    m_panels[DeltaPlot].curve->setName(QStringLiteral("δ(α)"));
    m_panels[Omega3Plot].curve->setName(QStringLiteral("ω₃(α)"));
    m_panels[Epsilon3Plot].curve->setName(QStringLiteral("ε₃(α)"));
    m_panels[GammaPlot].curve->setName(QStringLiteral("γ(α)"));
    m_poorSwatch->setName(tr("poor transmission: |γ| < %1° or > %2°")
                              .arg(number(FourBar::poorTransmission, 0), number(180.0 - FourBar::poorTransmission, 0)));
    m_panels[SweepPlot].curve->setName(tr("δ at α = %1°").arg(alpha));
    if (std::isfinite(m_largestCrank)) {
        m_largestCrankLine->setName(
            tr("largest AB that assembles: %1 mm").arg(locale.toString(m_largestCrank, 'f', 1)));
        m_largestCrankLine->addToLegend();
    } else {
        m_largestCrankLine->setName(QString());
        m_largestCrankLine->removeFromLegend();
    }
}

void FourBarPlots::placeCursor(int index)
{
    Panel &p = m_panels[index];
    const double alpha = m_pose.inputs[0], delta = m_pose.outputs[0];
    const bool sweep = index == SweepPlot;
    const double x = sweep ? m_design.crank : alpha / units::degree;
    const double value = sweep ? delta / units::degree : valueAt(index, alpha, delta);
    p.cursorValue = value;
    p.cursorLine->point1->setCoords(x, 0.0);
    p.cursorLine->point2->setCoords(x, 1.0);

    // The marker sits on the curve; off the y range it waits at the edge with an arrow.
    const QCPRange yRange = p.plot->yAxis->range();
    const bool finite = std::isfinite(value);
    const double shown = finite ? std::clamp(value, yRange.lower, yRange.upper) : yRange.upper;
    p.cursorMarker->position->setCoords(x, shown);
    p.cursorMarker->setVisible(finite && yRange.contains(value));

    QString text;
    switch (index) {
    case DeltaPlot:
        text = QStringLiteral("δ = %1°").arg(number(value, 1));
        break;
    case Omega3Plot:
        text = tr("ω₃ = %1 rad/s").arg(number(value, 2));
        break;
    case Epsilon3Plot:
        text = tr("ε₃ = %1 rad/s²").arg(number(value, 1));
        break;
    case GammaPlot:
        text = QStringLiteral("γ = %1°").arg(number(value, 1));
        break;
    default:
        text = tr("AB = %1 mm, δ = %2°").arg(QLocale().toString(x, 'f', 1), number(value, 1));
        break;
    }
    const bool rate = index == Omega3Plot || index == Epsilon3Plot;
    const double gamma = fourbar::angles(m_design, alpha, delta).gamma;
    if (rate && (!finite || std::abs(std::sin(gamma)) < 1e-6)) {
        // at a dead point the crank cannot drive the rocker: the rate is unbounded
        const QString symbol = index == Omega3Plot ? QStringLiteral("ω₃") : QStringLiteral("ε₃");
        text = tr("%1 → %2∞: dead point").arg(symbol, value < 0 ? QString(QChar(0x2212)) : QString());
    } else if (!finite) {
        text = tr("no pose");
    } else if (value > yRange.upper) {
        text += QStringLiteral(" ↑");
    } else if (value < yRange.lower) {
        text += QStringLiteral(" ↓");
    }
    p.cursorLabel->setText(text);
    plotstyle::placeCursorLabel(p.plot, p.cursorLabel, x, shown);
}

void FourBarPlots::refresh(int index)
{
    Panel &p = m_panels[index];
    if (!p.plot->isVisible())
        return; // on a hidden tab: the Show event brings it up to date
    if (p.needsReplot)
        p.plot->replot(QCustomPlot::rpQueuedReplot);
    else if (p.needsCursorReplot)
        p.cursorLayer->replot();
    p.needsReplot = false;
    p.needsCursorReplot = false;
}

bool FourBarPlots::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show || event->type() == QEvent::Resize) {
        for (int i = 0; i < PlotCount; ++i) {
            Panel &p = m_panels[i];
            if (p.plot != watched)
                continue;
            if (event->type() == QEvent::Resize && i != SweepPlot) {
                const double span = p.plot->xAxis->range().size();
                const double width = std::max(200, p.plot->width() - 110);
                setDegreeStep(p.plot->xAxis, angleStep(span, std::max(3.0, width / 60.0)));
            }
            if (event->type() == QEvent::Resize) {
                plotstyle::fitText(p.title);
                plotstyle::fitText(p.subtitle);
            }
            p.needsReplot = true;
            refresh(i);
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

QCustomPlot *FourBarPlots::plot(int index) const
{
    return index >= 0 && index < PlotCount ? m_panels[std::size_t(index)].plot : nullptr;
}

QCPGraph *FourBarPlots::curve(int index) const
{
    return index >= 0 && index < PlotCount ? m_panels[std::size_t(index)].curve : nullptr;
}

double FourBarPlots::cursorValue(int index) const
{
    return index >= 0 && index < PlotCount ? m_panels[std::size_t(index)].cursorValue : nan;
}

double FourBarPlots::cursorAlpha() const
{
    return m_panels[DeltaPlot].cursorLine->point1->key();
}

} // namespace pkm
