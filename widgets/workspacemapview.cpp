// The workspace and singularity map view (docs/mathematics.md, section 6): its construction —
// the plot, its layers and controls — and the requests that change what it shows; the maps are
// computed in workspacemapcompute.cpp and shown in workspacemapresults.cpp.

#include "workspacemapview.h"
#include "workspacemapviewinternal.h"

#include "plotfont.h"
#include "plotfit.h"
#include "plotstyle.h"
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

namespace workspacemap {

QCPColorGradient determinantGradient()
{
    QCPColorGradient gradient;
    gradient.setColorInterpolation(QCPColorGradient::ciRGB);
    gradient.setColorStopAt(0.0, QColor(0x053061));
    gradient.setColorStopAt(0.15, QColor(0x2166ac));
    gradient.setColorStopAt(0.32, QColor(0x67a9cf));
    gradient.setColorStopAt(0.45, QColor(0xd1e5f0));
    gradient.setColorStopAt(0.5, QColor(0xf7f7f7));
    gradient.setColorStopAt(0.55, QColor(0xfee0b6));
    gradient.setColorStopAt(0.68, QColor(0xfdb863));
    gradient.setColorStopAt(0.85, QColor(0xe08214));
    gradient.setColorStopAt(1.0, QColor(0x7f3b08));
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    return gradient;
}

} // namespace workspacemap

namespace {
using workspacemap::determinantGradient;

constexpr QRgb inverseRgb = 0xa50f15;    // dark red
constexpr QRgb directRgb = 0x111111;     // black, dashed
constexpr QRgb outlineRgb = 0x404040;    // dark grey
constexpr QRgb comparisonRgb = 0xc51b7d; // magenta, dashed: apart from both gradients
constexpr QRgb axisRgb = 0x303030;
constexpr QRgb markerRgb = 0x202020;

constexpr double tickPoints = 11, labelPoints = 12, titlePoints = 13, legendPoints = 11, controlPoints = 11,
                 messagePoints = 14;

QCPCurve *addCurve(QCustomPlot *plot, const QPen &pen)
{
    auto *curve = new QCPCurve(plot->xAxis, plot->yAxis);
    curve->setPen(pen);
    curve->setSelectable(QCP::stNone);
    curve->removeFromLegend();
    return curve;
}

QPen dashedPen(QRgb rgb, double width, const QVector<qreal> &pattern)
{
    QPen pen(QColor(rgb), width);
    pen.setDashPattern(pattern);
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

} // namespace

WorkspaceMapView::WorkspaceMapView(QWidget *parent)
    : QWidget(parent)
    , m_debounce(new QTimer(this))
    , m_quantityBox(new QComboBox(this))
    , m_quantityLabel(new QLabel(this))
    , m_stack(new QStackedWidget(this))
    , m_messageLabel(new QLabel)
    , m_plot(new QCustomPlot)
{
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(debounceMilliseconds);
    connect(m_debounce, &QTimer::timeout, this, &WorkspaceMapView::startMap);

    // -- controls above the plot -------------------------------------------------------------
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    auto *controls = new QHBoxLayout;
    controls->setContentsMargins(4, 0, 4, 0);
    m_quantityLabel->setFont(fontOf(font(), controlPoints));
    m_quantityBox->setFont(fontOf(font(), controlPoints));
    m_quantityBox->addItem(QString(), int(MapQuantity::Determinant));
    m_quantityBox->addItem(QString(), int(MapQuantity::Condition));
    m_quantityLabel->setBuddy(m_quantityBox);
    controls->addWidget(m_quantityLabel);
    // The longest quantity's name must not make the map panel too wide for a 1024-pixel
    // screen: the box takes the row's width, and wider screens show every name whole.
    m_quantityBox->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_quantityBox->setMinimumContentsLength(14);
    m_quantityBox->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    controls->addWidget(m_quantityBox, 1);
    layout->addLayout(controls);
    layout->addWidget(m_stack, 1);
    connect(m_quantityBox, &QComboBox::activated, this,
        [this](int index) { setQuantity(MapQuantity(m_quantityBox->itemData(index).toInt())); });

    m_stack->addWidget(m_plot);
    m_messageLabel->setAlignment(Qt::AlignCenter);
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setFont(fontOf(font(), messagePoints));
    m_messageLabel->setStyleSheet(QStringLiteral("color: #505050; background: white;"));
    m_stack->addWidget(m_messageLabel);

    // -- the plot ------------------------------------------------------------------------------
    QCustomPlot *plot = m_plot;
    plot->setBackground(Qt::white);
    plot->setMinimumSize(320, 260);
    plot->installEventFilter(this);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot->setNoAntialiasingOnDrag(false);

    // Layers, bottom to top: background, map (the colours), grid, main (boundaries, singular
    // curves), axes, legend, overlay, pose. The pose has its own buffer, so setPose() redraws
    // it alone; the overlay (QCP's selection rect, unused here) shares the buffer below.
    plot->addLayer(QStringLiteral("map"), plot->layer(QStringLiteral("grid")), QCustomPlot::limBelow);
    plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    plot->addLayer(QStringLiteral("pose"), plot->layer(QStringLiteral("overlay")), QCustomPlot::limAbove);
    m_poseLayer = plot->layer(QStringLiteral("pose"));
    m_poseLayer->setMode(QCPLayer::lmBuffered);

    // Title and legend across the top; below them the axis rect with the colour scale at its
    // right, in a grid of their own so that the title may use the whole width.
    QCPLayoutGrid *grid = plot->plotLayout();
    QCPAxisRect *axisRect = plot->axisRect();
    grid->take(axisRect);
    grid->simplify();
    m_title = plotstyle::newTextElement(plot, fontOf(font(), titlePoints, true));
    grid->addElement(0, 0, m_title);
    axisRect->insetLayout()->take(plot->legend);
    grid->addElement(1, 0, plot->legend);
    auto *mapRow = new QCPLayoutGrid;
    grid->addElement(2, 0, mapRow);
    mapRow->addElement(0, 0, axisRect);
    m_colorScale = new QCPColorScale(plot);
    mapRow->addElement(0, 1, m_colorScale);
    mapRow->setColumnStretchFactor(1, 0.001);
    mapRow->setColumnSpacing(4);
    for (int row = 0; row < 2; ++row)
        grid->setRowStretchFactor(row, 0.001);
    grid->setRowSpacing(2);
    auto *margins = new QCPMarginGroup(plot);
    axisRect->setMarginGroup(QCP::msTop | QCP::msBottom, margins);
    m_colorScale->setMarginGroup(QCP::msTop | QCP::msBottom, margins);

    plot->legend->setVisible(true);
    plot->legend->setFont(fontOf(font(), legendPoints));
    plot->legend->setBorderPen(Qt::NoPen);
    plot->legend->setIconSize(34, 14);
    plot->legend->setColumnSpacing(18);
    plot->legend->setRowSpacing(1);
    plot->legend->setMargins(QMargins(8, 2, 8, 2));
    plot->legend->setSelectableParts(QCPLegend::spNone);

    for (QCPAxis *axis : {plot->xAxis, plot->yAxis, plot->xAxis2, plot->yAxis2, m_colorScale->axis()}) {
        const QPen pen(QColor(axisRgb), 1.2);
        axis->setBasePen(pen);
        axis->setTickPen(pen);
        axis->setSubTickPen(QPen(QColor(axisRgb), 1.0));
        axis->setTickLabelFont(fontOf(font(), tickPoints));
        axis->setLabelFont(fontOf(font(), labelPoints));
        axis->grid()->setPen(QPen(QColor(0, 0, 0, 30), 1.0));
        axis->grid()->setZeroLinePen(QPen(QColor(0, 0, 0, 60), 1.0));
    }
    for (QCPAxis *axis : {plot->xAxis2, plot->yAxis2}) { // a closed frame, no second scale
        axis->setVisible(true);
        axis->setTicks(false);
        axis->setTickLabels(false);
        axis->grid()->setVisible(false);
    }
    for (QCPAxis *axis : {plot->xAxis, plot->yAxis})
        axis->setTicker(QSharedPointer<MinusTicker>::create(axis));
    m_colorScale->setBarWidth(16);
    m_colorScale->setRangeDrag(false);
    m_colorScale->setRangeZoom(false);
    m_colorScale->axis()->grid()->setVisible(false);

    m_colorMap = new QCPColorMap(plot->xAxis, plot->yAxis);
    m_colorMap->setLayer(QStringLiteral("map"));
    m_colorMap->setSelectable(QCP::stNone);
    m_colorMap->removeFromLegend();
    m_colorMap->setColorScale(m_colorScale);
    m_colorMap->setGradient(determinantGradient());
    m_colorMap->data()->setSize(0, 0);

    // Boundaries and singular curves; each singular curve over a white halo of the same data,
    // so it shows on the darkest colours too.
    m_comparisonOutline = addCurve(plot, dashedPen(comparisonRgb, 2.5, {4.0, 2.5}));
    m_outline = addCurve(plot, QPen(QColor(outlineRgb), 1.5));
    m_inverseHalo = addCurve(plot, QPen(QColor(255, 255, 255, 200), 5.0));
    m_directHalo = addCurve(plot, QPen(QColor(255, 255, 255, 200), 5.0));
    m_inverse = addCurve(plot, QPen(QColor(inverseRgb), 2.5));
    m_direct = addCurve(plot, dashedPen(directRgb, 2.2, {4.0, 2.5}));
    m_inverseHalo->setData(m_inverse->data());
    m_directHalo->setData(m_direct->data());
    for (QCPCurve *curve : {m_outline, m_inverse, m_direct})
        curve->addToLegend();
    m_comparisonOutline->setVisible(false);

    // The current pose: a white disc with a dark rim and a cross.
    m_poseCircle = new QCPItemTracer(plot);
    m_poseCircle->setStyle(QCPItemTracer::tsCircle);
    m_poseCircle->setSize(17);
    m_poseCircle->setPen(QPen(QColor(markerRgb), 2.0));
    m_poseCircle->setBrush(Qt::white);
    m_poseCross = new QCPItemTracer(plot);
    m_poseCross->setStyle(QCPItemTracer::tsPlus);
    m_poseCross->setSize(11);
    m_poseCross->setPen(QPen(QColor(markerRgb), 1.6));
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross}) {
        item->setLayer(m_poseLayer);
        item->setSelectable(false);
        item->setVisible(false);
    }

    // "computing…", over the plot's top-right corner: a child widget, so showing it costs no replot.
    m_busyLabel = new QLabel(plot);
    m_busyLabel->setFont(fontOf(font(), controlPoints));
    m_busyLabel->setStyleSheet(QStringLiteral(
        "color: #303030; background: rgba(255, 255, 255, 225); border: 1px solid #a0a0a0; padding: 2px 8px;"));
    m_busyLabel->hide();

    connect(plot, &QCustomPlot::afterLayout, this, &WorkspaceMapView::fitView);
    connect(plot, &QCustomPlot::mousePress, this, &WorkspaceMapView::mousePressed);
    connect(plot, &QCustomPlot::mouseRelease, this, &WorkspaceMapView::mouseReleased);
    connect(plot, &QCustomPlot::mouseMove, this, &WorkspaceMapView::mouseMoved);
    connect(plot, &QCustomPlot::mouseWheel, this, [this] { m_userView = true; });
    connect(plot, &QCustomPlot::mouseDoubleClick, this, [this] { resetView(); });

    retranslate();
    showMessage(messageText());
}

WorkspaceMapView::~WorkspaceMapView()
{
    m_debounce->stop();
    for (const auto &job : m_jobs)
        job->cancel->store(true);
    // Each worker stops within one block of rows; wait so none outlives the widget's thread
    // objects (they hold nothing of the widget, but the pool and the process may be going away).
    for (const auto &job : m_jobs)
        job->watcher->waitForFinished();
}

// -- requests ----------------------------------------------------------------------------------

void WorkspaceMapView::setMechanism(MechanismPtr mechanism)
{
    m_mechanism = std::move(mechanism);
    if (!m_mechanism || !m_mechanism->planarWorkspace()) {
        ++m_generation;
        cancel(JobKind::Map);
        m_debounce->stop();
        m_mapPending = false;
        clearMap();
        showMessage(messageText());
        updateBusy();
        return;
    }
    m_stack->setCurrentWidget(m_plot);
    m_quantityBox->setEnabled(true);
    // The orientation range only where the platform turns (a leg design with three legs).
    const bool turns = m_mechanism->planarWorkspace()->offers(MapQuantity::OrientationRange);
    const int rangeItem = m_quantityBox->findData(int(MapQuantity::OrientationRange));
    if (turns && rangeItem < 0) {
        m_quantityBox->addItem(tr("orientation range of φ"), int(MapQuantity::OrientationRange));
    } else if (!turns && rangeItem >= 0) {
        const QSignalBlocker blocker(m_quantityBox);
        m_quantityBox->removeItem(rangeItem);
        if (m_quantity == MapQuantity::OrientationRange)
            m_quantity = MapQuantity::Determinant;
        m_quantityBox->setCurrentIndex(m_quantityBox->findData(int(m_quantity)));
    }
    syncCapabilityItems();
    syncToleranceItem();
    if (m_hasPose)
        setPose(m_fullPose); // the slice may have moved to the pose's φ or away from it
    requestMap();
}

void WorkspaceMapView::setRequirements(std::vector<capability::Requirement> requirements)
{
    if (requirements == m_requirements)
        return;
    m_requirements = std::move(requirements);
    if (m_quantity == MapQuantity::Specification && m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
}

void WorkspaceMapView::setTolerances(ParameterSet tolerances)
{
    if (tolerances == m_tolerances)
        return;
    m_tolerances = std::move(tolerances);
    syncToleranceItem();
    if (m_quantity == MapQuantity::ToleranceWorst && m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
}

void WorkspaceMapView::setPose(const Pose &pose)
{
    const bool valid = pose.outputs.size() >= 2 && std::isfinite(pose.outputs[0]) && std::isfinite(pose.outputs[1]);
    m_hasPose = valid;
    if (valid)
        m_fullPose = pose; // no recomputation: a capability map follows the design, not the drag
    if (valid)
        m_pose = Eigen::Vector2d(pose.outputs[0], pose.outputs[1]);
    // A platform that turns is mapped on its slice φ = φ_map: a pose at another φ is drawn as
    // a dashed ring without its white disc, where it would stand on the slice, and the title
    // says that the pose is not on it (the marker stood on white, outside the slice's
    // workspace, with nothing to tell why).
    const std::optional<double> slice = sliceAngle();
    const bool offSlice = valid && slice && pose.outputs.size() >= 3
        && std::abs(std::remainder(pose.outputs[2] - *slice, 2.0 * std::numbers::pi)) > offSliceTolerance;
    const bool titleChanged = offSlice != m_poseOffSlice;
    if (titleChanged) {
        m_poseOffSlice = offSlice;
        QPen rim(QColor(markerRgb), 2.0);
        rim.setStyle(offSlice ? Qt::DashLine : Qt::SolidLine);
        m_poseCircle->setPen(rim);
        m_poseCircle->setBrush(offSlice ? QBrush(Qt::NoBrush) : QBrush(Qt::white));
        updateTitle();
    }
    for (QCPItemTracer *item : {m_poseCircle, m_poseCross}) {
        item->position->setCoords(m_pose.x(), m_pose.y());
        item->setVisible(valid && !m_mapBounds.isEmpty());
    }
    // The marker alone, a full replot only if the buffers are stale; the title too where it
    // changed (the marker's layer alone left a playing 3-R̲RR's title saying nothing of the
    // pose's φ leaving the slice).
    if (m_plot->isVisible() && titleChanged)
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    else if (m_plot->isVisible())
        m_poseLayer->replot();
}

void WorkspaceMapView::setQuantity(MapQuantity quantity)
{
    const int index = m_quantityBox->findData(int(quantity));
    if (index != m_quantityBox->currentIndex()) {
        const QSignalBlocker blocker(m_quantityBox);
        m_quantityBox->setCurrentIndex(index);
    }
    if (quantity == m_quantity)
        return;
    m_quantity = quantity;
    if (m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
}

void WorkspaceMapView::setResolution(int cells)
{
    cells = std::max(2, cells);
    if (cells == m_resolution)
        return;
    m_resolution = cells;
    if (m_mechanism && m_mechanism->planarWorkspace())
        requestMap();
    if (m_comparison)
        startComparison();
}

void WorkspaceMapView::setComparison(MechanismPtr other, const QString &label)
{
    if (!other || !other->planarWorkspace()) {
        clearComparison();
        return;
    }
    m_comparison = std::move(other);
    m_comparisonLabel = label;
    startComparison();
}

void WorkspaceMapView::clearComparison()
{
    m_comparison.reset();
    m_comparisonLabel.clear();
    ++m_comparisonGeneration;
    cancel(JobKind::Comparison);
    m_comparisonArea = 0.0;
    m_comparisonBounds.setEmpty();
    m_comparisonOutline->data()->clear();
    m_comparisonOutline->setVisible(false);
    m_comparisonOutline->removeFromLegend();
    updateLegend();
    updateBusy();
    m_plot->replot();
}

} // namespace pkm
