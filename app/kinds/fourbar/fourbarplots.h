#pragma once
/// Live plots of the planar four-bar (the four-bar and mobility document; docs/mathematics.md) for the current design, with a
/// cursor at the current pose. Laid out for a classroom projector, like PJointPlots.
///
/// Four tabs: "δ(α)" (fig. 4), "ω₃, ε₃" (fig. 6: the rocker's angular velocity dδ/dt and
/// acceleration d²δ/dt² at the design's constant ω₁, exact), "γ(α)" (the transmission angle with
/// the poor band |γ| < 40° or > 140° shaded) and "δ vs AB" (fig. 5: δ at the current α as the
/// crank length sweeps, the other links fixed, with the largest crank that still assembles).
///
/// The α axis spans the design's input range in degrees. Samples where the pose does not exist
/// (or a rate is infinite, at a dead point) are NaN: QCustomPlot leaves a gap there. Near a
/// dead point (α at an assembly limit) ω₃ and ε₃ grow without bound: their axes fit the bulk of
/// the curve and the samples are clipped to four axis heights beyond it.
/// Every curve is a few hundred closed-form samples: recomputed on the GUI thread.

#include "kinds/fourbar/fourbar.h"

#include <QWidget>

#include <array>
#include <limits>

class QCustomPlot;
class QCPBars;
class QCPGraph;
class QCPItemRect;
class QCPItemStraightLine;
class QCPItemText;
class QCPItemTracer;
class QCPLayer;
class QCPTextElement;
class QTabWidget;

namespace pkm {

class FourBarPlots : public QWidget
{
    Q_OBJECT

public:
    enum PlotIndex {
        DeltaPlot, ///< δ(α), °: fig. 4
        Omega3Plot, ///< ω₃(α) = dδ/dt, rad/s: fig. 6
        Epsilon3Plot, ///< ε₃(α) = d²δ/dt², rad/s²: fig. 6
        GammaPlot, ///< γ(α), °, with the poor-transmission bands
        SweepPlot, ///< δ against AB (mm) at the current α: fig. 5
        PlotCount
    };

    explicit FourBarPlots(QWidget *parent = nullptr);
    ~FourBarPlots() override;

    /// Recomputes every curve for a four-bar (anything else is ignored), cursors at `pose`.
    void setDesign(const MechanismPtr &mechanism, const Pose &pose);
    /// Moves the cursors; recomputes the AB sweep when α moved.
    void setPose(const Pose &pose);

    /// The largest crank AB (mm) with which the loop ABCD closes at input α, the other links
    /// as in `design`: |BD| reaches BC + CD, AB = AD·cos α + √((BC + CD)² − AD²·sin²α). NaN when
    /// no crank length assembles at this α.
    static double largestCrank(const FourBarDesign &design, double alpha);

    // -- for tests ---------------------------------------------------------------------------
    QTabWidget *tabs() const { return m_tabs; }
    QCustomPlot *plot(int index) const;
    /// graph(0) of the plot: the design's curve (x: α in ° or AB in mm).
    QCPGraph *curve(int index) const;
    /// The value on the plot's cursor marker (display units), NaN if none.
    double cursorValue(int index) const;
    /// Where the α cursor stands, °.
    double cursorAlpha() const;
    /// The marker of the sweep: the largest crank at the current α, mm.
    double largestCrankMarker() const { return m_largestCrank; }

    QSize sizeHint() const override { return {900, 640}; }

signals:
    /// A click (or drag) on an α plot asks for this crank angle (rad).
    void alphaRequested(double alpha);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Panel {
        QCustomPlot *plot = nullptr;
        QCPTextElement *title = nullptr;
        QCPTextElement *subtitle = nullptr;
        QCPGraph *curve = nullptr;
        QCPLayer *cursorLayer = nullptr;
        QCPItemStraightLine *cursorLine = nullptr;
        QCPItemTracer *cursorMarker = nullptr;
        QCPItemText *cursorLabel = nullptr;
        double cursorValue = 0.0;
        bool needsReplot = true;
        bool needsCursorReplot = true;
    };

    void createPanel(int index);
    void recomputeCurves();
    void recomputeSweep();
    void retitle();
    /// Sets every text again in the current language (tabs, tooltips, titles, axes, legends,
    /// cursor labels).
    void retranslate();
    void placeCursor(int index);
    void refresh(int index);
    /// The value of plot `index` at α (display units) for the current design.
    double valueAt(int index, double alpha, double delta) const;

    MechanismPtr m_mechanism;
    FourBarDesign m_design;
    Pose m_pose;
    double m_sweepAlpha = std::numeric_limits<double>::quiet_NaN(); ///< α of the current sweep
    double m_largestCrank = std::numeric_limits<double>::quiet_NaN();
    QTabWidget *m_tabs = nullptr;
    std::array<Panel, PlotCount> m_panels;
    QCPGraph *m_largestCrankLine = nullptr; ///< the sweep's vertical line at the largest AB
    QCPBars *m_poorSwatch = nullptr; ///< the legend entry of the γ plot's bands
    std::array<QCPItemRect *, 2> m_poorBands {};
    bool m_pressed = false; ///< a mouse button is down on an α plot
};

} // namespace pkm
