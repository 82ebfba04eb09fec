#pragma once
/// The generic panel of a kind with one actuated input and no panel of its own: any scalar
/// quantity of its report (Mechanism::reportLayout) plotted over the input's range, with a
/// cursor at the current pose. The curve is solved by direct kinematics from one end of the
/// range to the other, each step from the last, so it stays in the design's assembly mode;
/// steps that cannot be solved, and values that are not finite (at a singular pose), are gaps.

#include "kinds/kindpanel.h"

#include <vector>

class QComboBox;
class QCustomPlot;
class QCPGraph;
class QCPLayer;
class QCPTextElement;

namespace pkm {

class SweepPlotsPanel : public KindPanel
{
    Q_OBJECT

public:
    explicit SweepPlotsPanel(QWidget *parent = nullptr);

    /// Whether this panel can show `mechanism`: one actuated input and a scalar quantity.
    static bool canShow(const Mechanism &mechanism);

    void setDesign(const MechanismPtr &mechanism, const QString &title) override;
    void setPose(const Pose &pose) override;

    // -- for tests -----------------------------------------------------------------------
    QComboBox *quantityBox() const { return m_quantity; }
    QCustomPlot *plot() const { return m_plot; }
    /// The samples of the curve shown: input (display unit) and value (display unit).
    const std::vector<double> &inputs() const { return m_inputs; }
    const std::vector<double> &values() const { return m_values; }
    double cursorInput() const { return m_cursorInput; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fillQuantities();
    /// Solves the sweep and replots the chosen quantity.
    void recompute();
    void placeCursor();

    QComboBox *m_quantity = nullptr;
    QCustomPlot *m_plot = nullptr;
    QCPGraph *m_curve = nullptr;
    QCPGraph *m_cursor = nullptr;
    QCPTextElement *m_title = nullptr;
    QCPLayer *m_cursorLayer = nullptr;
    MechanismPtr m_mechanism;
    Pose m_pose;
    std::vector<double> m_inputs, m_values;
    double m_cursorInput = 0.0;
};

} // namespace pkm
