#pragma once
/// Live plots of the active П-joint (docs/mathematics.md): the document's figures 8–17 for the
/// current design, with a cursor at the current pose. Laid out for a classroom projector
/// (1920×1080): large fonts, thick lines, legends outside the curves.
///
/// Three tabs: "Geometry" (figs. 8–10: d, φ, μ), "Jacobian" (figs. 11–12: J, J⁻¹) and
/// "Actuator" (figs. 15–17: Δθ, θ̇, T). The θ axis is in degrees; every other axis is in the
/// display unit of units.h (mm, °, mm/rad, rad/mm, °/step, rad/s, N·m).
///
/// graph(0) of every plot is the current design's curve over its θ range [θ_min, θ_max]; the
/// other graphs are the same design beyond that range and, on the Geometry tab, the k-family.

#include "kinds/kindpanel.h"
#include "kinds/pjoint/pjoint.h"

#include <QString>

#include <array>

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

class PJointPlots : public KindPanel
{
    Q_OBJECT

public:
    /// Plot indices for plot(), plotName() and cursorValue().
    enum PlotIndex {
        DiagonalPlot, ///< "d": fig. 8, mm
        PassiveAnglePlot, ///< "phi": fig. 9, °
        TransmissionAnglePlot, ///< "mu": fig. 10, °
        JacobianPlot, ///< "J": fig. 11, mm/rad
        InverseJacobianPlot, ///< "J_inv": fig. 12, rad/mm
        ResolutionPlot, ///< "resolution": fig. 15, °/step
        SpeedPlot, ///< "speed": fig. 16, rad/s
        TorquePlot, ///< "torque": fig. 17, N·m
        PlotCount
    };

    explicit PJointPlots(QWidget *parent = nullptr);
    ~PJointPlots() override;

    /// Recomputes every curve and axis range (~400 samples per curve: microseconds, so on the
    /// GUI thread) and replots the visible plots in full. The cursor stays at its θ.
    void setDesign(const pkm::PJointDesign &design);
    const pkm::PJointDesign &design() const { return m_design; }
    /// The main window's calls (KindPanel): a П-joint's design, and θ from the pose.
    void setDesign(const MechanismPtr &mechanism, const QString &title) override;
    void setPose(const Pose &pose) override;

    /// Moves the cursor on every plot. Cheap, for every slider move: only the buffered cursor
    /// layer of the visible plots is redrawn; hidden plots catch up when their tab is shown.
    void setTheta(double thetaRadians);
    double theta() const { return m_theta; } ///< rad

    // -- for tests and benchmarks --------------------------------------------------------
    int plotCount() const { return PlotCount; }
    QCustomPlot *plot(int i) const;
    QString plotName(int i) const; ///< "d", "phi", "mu", "J", "J_inv", "resolution", "speed", "torque"
    int plotIndex(const QString &name) const; ///< inverse of plotName(), −1 if unknown
    double cursorTheta() const; ///< °, where the cursor lines are
    double cursorValue(int i) const; ///< the value on plot i's marker, display unit
    QTabWidget *tabs() const { return m_tabs; }

    QSize sizeHint() const override { return {1400, 900}; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    /// One plot and its cursor items; the QCustomPlot owns them all.
    struct Panel {
        QCustomPlot *plot = nullptr;
        QCPTextElement *title = nullptr;
        QCPTextElement *subtitle = nullptr;
        QCPGraph *design = nullptr; ///< graph(0): the current design over [θ_min, θ_max]
        QCPGraph *extension = nullptr; ///< the current design beyond its range, or null
        std::array<QCPGraph *, 5> family {}; ///< the k-family (Geometry tab), or null
        QCPItemRect *recommendedBand = nullptr; ///< figs 11–17: the recommended range, or null
        std::array<QCPItemRect *, 2> steepBands {}; ///< below and above it
        QCPBars *steepSwatch = nullptr; ///< legend entries of the bands, or null
        QCPBars *recommendedSwatch = nullptr;
        QCPBars *weakTransmissionSwatch = nullptr; ///< fig. 10's μ < 5° band
        QCPLayer *cursorLayer = nullptr;
        QCPItemStraightLine *cursorLine = nullptr;
        QCPItemTracer *cursorMarker = nullptr;
        QCPItemText *cursorLabel = nullptr;
        double cursorValue = 0.0;
        bool needsReplot = true; ///< curves changed while the plot was hidden
        bool needsCursorReplot = true; ///< the cursor moved while the plot was hidden
    };

    void createPanel(int index);
    void retranslate();
    void recompute(int index);
    void placeCursor(int index);
    void refresh(int index, bool queued = false);
    void fitToWidth(int index); ///< legend columns and θ tick step for the plot's width

    pkm::PJointDesign m_design;
    double m_theta = 0.0; ///< rad
    QTabWidget *m_tabs = nullptr;
    std::array<Panel, PlotCount> m_panels;
};

} // namespace pkm
