#pragma once
/// The singularity map of a planar mechanism over its workspace (the MOMA document's fig. 7):
/// det J or the condition number κ(J) as a colour map, the workspace boundary, the inverse and
/// direct singular curves, the current pose as a marker, and optionally a second design's
/// boundary to compare workspaces. Laid out for a classroom projector: large fonts, thick
/// lines, the legend and the colour scale outside the map.
///
/// The map is computed off the GUI thread (QtConcurrent): a design change is debounced, cancels
/// the running computation, and results of older requests are dropped by a generation counter;
/// the GUI thread only hands the finished colour data to the plot. A pose change only moves the
/// marker on its own buffered layer.
///
/// Units: mm on both axes (drawn at the same scale), mm² for areas; map values are
/// dimensionless.

#include "capabilitymap.h"
#include "linkageview.h" // Q_DECLARE_METATYPE(Eigen::Vector2d)
#include "mechanism.h"
#include "planarworkspace.h"

#include <Eigen/Core>

#include <QString>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QCPColorMap;
class QCPColorScale;
class QCPCurve;
class QCPItemTracer;
class QCPLayer;
class QCPTextElement;
class QComboBox;
class QCustomPlot;
class QLabel;
class QMouseEvent;
class QStackedWidget;
class QTimer;

namespace pkm {

struct WorkspaceMapResult; ///< what a worker hands to the GUI thread (workspacemapviewinternal.h)

class WorkspaceMapView : public QWidget
{
    Q_OBJECT

public:
    explicit WorkspaceMapView(QWidget *parent = nullptr);
    /// Cancels a running computation and waits for it (it stops within one block of rows).
    ~WorkspaceMapView() override;

    /// A new design: recomputes the map off the GUI thread, ~30 ms after the last of a burst
    /// of calls. A mechanism without a planar workspace (or null) shows a message instead.
    void setMechanism(MechanismPtr mechanism);
    MechanismPtr mechanism() const { return m_mechanism; }

    /// Cheap (no computation): moves the current-pose marker to the pose's two outputs (mm)
    /// and redraws only the marker's layer.
    void setPose(const Pose &pose);

    /// det J (diverging colours, symmetric limits) or κ(J) (logarithmic), the orientation
    /// range, what the actuators deliver or the specification region; also the combo box.
    void setQuantity(MapQuantity quantity);
    MapQuantity quantity() const { return m_quantity; }

    /// What the specification map checks (core units); recomputes it when it is shown.
    void setRequirements(std::vector<capability::Requirement> requirements);
    /// The design's tolerances (core units): with any, the Map list offers the worst-case error
    /// from them (tolerancemap.h); recomputes it when it is shown.
    void setTolerances(ParameterSet tolerances);
    /// The shown specification map's area where every requirement holds, mm² (0 otherwise).
    double specificationArea() const { return m_specificationArea; }

    /// Brief words for a small map (presentation mode): the title gives the workspace alone and
    /// the legend the curves' kinds; the rest (the value range, what a singularity means) goes
    /// to the tooltip. At 1280×720 the full title and legend took 320 px and left the map
    /// 185×145 px. A plot too short for the full words is brief without being asked.
    void setBrief(bool on);
    bool brief() const { return m_brief; }

    /// Cells along the longer side of the workspace bounds (default 500); recomputes.
    void setResolution(int cells);
    int resolution() const { return m_resolution; }

    /// Draws another design's workspace boundary (computed off-thread as well), dashed, with
    /// its area in the legend under `label` ("3d").
    void setComparison(MechanismPtr other, const QString &label);
    void clearComparison();

    // -- state, for tests and benchmarks -----------------------------------------------------
    /// A map or comparison is waiting for the debounce or being computed.
    bool busy() const;
    /// Counts map requests; results of an older generation are dropped.
    int generation() const { return m_generation; }
    /// Map computations actually started (a burst of requests starts one).
    int computationsStarted() const { return m_computationsStarted; }
    /// The shown map's summary (empty before the first map and without a planar workspace).
    const MapSummary &summary() const { return m_summary; }
    /// The map's title as shown, lines joined by spaces (tests, the walk-through's checks).
    QString titleText() const;
    /// The title's lines as broken for the plot's width.
    QStringList titleLines() const;
    double area() const { return m_summary.area; } ///< mm²
    /// The comparison's workspace area, mm² (0 without a comparison result).
    double comparisonArea() const { return m_comparisonArea; }
    /// The shown map's value at a point (mm): NaN where unreachable or off the map.
    double valueAt(const Eigen::Vector2d &pointMm) const;
    /// Singular curves (polylines) drawn: all, or of one type.
    int curveCount() const { return m_curveCounts[0] + m_curveCounts[1]; }
    int curveCount(SingularCurve::Type type) const { return m_curveCounts[type == SingularCurve::Type::Direct]; }
    /// Where the pose marker is (mm), NaN when there is none.
    Eigen::Vector2d markerPosition() const;
    /// Whether the pose's φ is off the slice mapped (a dashed marker; the title says so).
    bool markerOffSlice() const { return m_poseOffSlice; }
    /// The message shown instead of the map ("no planar workspace"), or empty.
    QString message() const;
    QCustomPlot *plot() const { return m_plot; }
    QCPColorMap *colorMap() const { return m_colorMap; }
    QComboBox *quantityBox() const { return m_quantityBox; }
    double lastApplyMilliseconds() const { return m_lastApplyMilliseconds; }

    QSize sizeHint() const override { return {1000, 800}; }
    /// Narrow enough for a 1024-pixel screen beside the docks and the linkage (tst_classroom).
    QSize minimumSizeHint() const override { return {380, 360}; }

    static constexpr int debounceMilliseconds = 30;

signals:
    /// A left click (press and release without moving) inside the map, in mm.
    void pointClicked(const Eigen::Vector2d &pointMm);
    /// A new map was applied.
    void mapReady();
    /// A comparison boundary was applied.
    void comparisonReady();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    enum class JobKind { Map, Comparison };
    struct Job;

    void requestMap();
    void startMap();
    void startComparison();
    void start(JobKind kind, const MechanismPtr &mechanism);
    void cancel(JobKind kind);
    void finished(JobKind kind, int generation, std::shared_ptr<WorkspaceMapResult> result);
    void applyMap(WorkspaceMapResult &result);
    void applyComparison(WorkspaceMapResult &result);
    void clearMap();
    void showMessage(const QString &text);
    /// Why there is no map: no mechanism, or one without a planar workspace.
    QString messageText() const;
    void updateBusy();
    void updateTitle();
    /// The workspace area the title gives: exact where the kind knows it, else the map's count (mm²).
    double shownArea() const;
    /// The workspace area where the kind knows it in closed form (else the map's count), mm².
    std::optional<double> exactArea() const;
    /// The plot is short for the full title and legend: fewer than 22 title lines high.
    bool plotIsShort() const;
    /// shownArea() as the titles give it, with the slice φ = φ_map of a platform that turns:
    /// the map of a 3-DOF platform is that slice, whatever φ the pose has.
    QString areaText() const;
    /// " rad²/mm²": det J's unit after a number, empty where det J has none.
    QString determinantUnit() const;
    /// The title and scale of a capability or specification map (workspacemapcapability.cpp).
    void updateCapabilityTitle();
    /// Adds or removes the capability items of the combo box as the design declares actuators.
    void syncCapabilityItems();
    void retranslateCapabilityItems();
    void syncToleranceItem();
    void retranslateToleranceItem();
    void updateLegend();
    /// The title, or `brief` instead in brief mode where it is given (setBrief()).
    void setTitle(const QString &full, const QString &brief = {});
    /// The plot's tooltip: `text`, after what brief mode left out of the title and legend.
    void setMapToolTip(const QString &text);
    void refreshToolTip();
    void fitView();
    /// The colour scale's label, broken into lines for the scale's height now and again after
    /// every layout (fitView()); `brief` (the symbol and unit) where `text` would take more
    /// than two lines, whose width the map lacks (presentation mode: four lines of "det J
    /// (colours clipped at …)" left the map 75 px wide). The plot's tooltip says the rest.
    void setScaleLabel(const QString &text, const QString &brief = {});
    /// The scale's label broken for `height` pixels (setScaleLabel()).
    QString scaleLabelFor(int height) const;
    void resetView();
    void retranslate();

    void mousePressed(QMouseEvent *event);
    void mouseReleased(QMouseEvent *event);
    void mouseMoved(QMouseEvent *event);

    MechanismPtr m_mechanism;
    MechanismPtr m_comparison;
    QString m_comparisonLabel;
    MapQuantity m_quantity = MapQuantity::Determinant;
    int m_resolution = 500;
    /// φ_map of a platform that turns (the slice mapped), none for a 2-DOF mechanism.
    std::optional<double> sliceAngle() const;
    /// A pose's φ this far from the slice's (rad) is off it: the marker is dashed.
    static constexpr double offSliceTolerance = 1e-3;
    bool m_poseOffSlice = false;
    Pose m_fullPose; ///< the last pose given: a capability map's cells start from its modes
    std::vector<capability::Requirement> m_requirements;
    ParameterSet m_tolerances;
    double m_specificationArea = 0.0;
    std::string m_shownSymbol, m_shownLabel, m_shownUnit; ///< a capability map's entry

    int m_generation = 0;
    int m_comparisonGeneration = 0;
    int m_computationsStarted = 0;
    bool m_mapPending = false; ///< waiting for the debounce timer
    std::vector<std::unique_ptr<Job>> m_jobs; ///< running, the cancelled ones too

    // the shown map
    MapSummary m_summary;
    MapQuantity m_shownQuantity = MapQuantity::Determinant;
    std::vector<float> m_values; ///< as computed, row-major from the bottom row
    double m_colourLimit = 0.0;  ///< det J: ±limit; κ: 1…limit
    std::array<int, 2> m_curveCounts {}; ///< inverse, direct
    /// "link ⟂ guide", "links collinear": English sources from core, translated when shown
    std::array<std::string, 2> m_singularityMeanings;
    double m_comparisonArea = 0.0;
    Eigen::AlignedBox2d m_mapBounds;        ///< grid bounds of the map, mm (empty: none)
    Eigen::AlignedBox2d m_comparisonBounds; ///< of the comparison's grid, mm (empty: none)
    bool m_userView = false; ///< the user zoomed or dragged: keep the view on new maps
    QString m_scaleLabel; ///< the colour scale's label before it is broken into lines
    QString m_briefScaleLabel; ///< its short form, or empty
    bool m_brief = false;          ///< asked for, or the plot is short
    bool m_briefRequested = false; ///< setBrief()
    QString m_fullTitle;   ///< the title in full, whichever is shown
    bool m_titleShortened = false;
    QString m_toolTip;     ///< the tooltip before brief mode's additions
    QString m_curveNotes;  ///< what the singular curves are, when the legend leaves it out
    int m_refits = 0; ///< relayouts in a row asked by fitView(), to stop a ping-pong of margins
    bool m_hasPose = false;
    Eigen::Vector2d m_pose = Eigen::Vector2d::Zero();
    QPoint m_pressPosition;
    bool m_pressInside = false;
    double m_lastApplyMilliseconds = 0.0;

    QTimer *m_debounce = nullptr;
    QComboBox *m_quantityBox = nullptr;
    QLabel *m_quantityLabel = nullptr;
    QStackedWidget *m_stack = nullptr;
    QLabel *m_messageLabel = nullptr;
    QLabel *m_busyLabel = nullptr;
    QCustomPlot *m_plot = nullptr;
    QCPTextElement *m_title = nullptr;
    QCPColorMap *m_colorMap = nullptr;
    QCPColorScale *m_colorScale = nullptr;
    QCPCurve *m_outline = nullptr;
    QCPCurve *m_comparisonOutline = nullptr;
    QCPCurve *m_inverseHalo = nullptr; ///< a white line under m_inverse, so it shows on any colour
    QCPCurve *m_directHalo = nullptr;
    QCPCurve *m_inverse = nullptr;
    QCPCurve *m_direct = nullptr;
    QCPLayer *m_poseLayer = nullptr;
    QCPItemTracer *m_poseCircle = nullptr;
    QCPItemTracer *m_poseCross = nullptr;
};

} // namespace pkm
