#pragma once
/// Sliders and spin boxes for the joint variables (inputs and outputs), built from the
/// mechanism's VariableInfo. Moving one asks for a pose; the answer (setPose) moves all of
/// them, so θ and d stay linked both ways. Ranges come from the design.

#include "mechanism.h"

#include <QVector>
#include <QWidget>

class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QSlider;

namespace pkm {

class VariablePanel : public QWidget
{
    Q_OBJECT

public:
    explicit VariablePanel(QWidget *parent = nullptr);

    void setMechanism(const MechanismPtr &mechanism);
    void setPose(const Pose &pose);

    /// Short roles ("input" for "input, actuated"), one line a row, and from four rows on two
    /// blocks side by side: presentation mode, where a 3-DOF design's six rows at a large text
    /// size leave no room for a second line nor for the linkage above them.
    void setCompact(bool compact);
    bool isCompact() const { return m_compact; }
    /// Whether the compact rows stand in two blocks side by side.
    bool hasTwoBlocks() const { return m_twoBlocks; }

    QSlider *slider(int variable) const { return m_rows.value(variable).slider; }
    QDoubleSpinBox *spinBox(int variable) const { return m_rows.value(variable).spinBox; }
    static constexpr int sliderSteps = 10000;
    /// Narrower than with the limits beside the sliders: they hide (their values stay in the
    /// spin boxes' ranges and tooltips) rather than widen the window.
    QSize minimumSizeHint() const override;

signals:
    /// The user moved variable `variable` (index into variableInfo()) to `value` (core units).
    void variableEdited(int variable, double value);
    void sliderPressed();
    void sliderReleased();

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    struct Row {
        QLabel *name = nullptr;
        QLabel *minimum = nullptr;
        QSlider *slider = nullptr;
        QLabel *maximum = nullptr;
        QDoubleSpinBox *spinBox = nullptr;
    };
    void rebuild();
    /// Puts the rows in the grid: one under another, or compact in two blocks side by side.
    void placeRows();
    /// A block's columns: name, lower limit, slider, upper limit, spin box, and a gap.
    static constexpr int blockColumns = 6;
    static constexpr int blockGap = 16;
    /// A slider this short still moves by hand; at 60 px, names on two lines (WrapLabel) left a
    /// Serbian MOMA's window a pixel wider than a 1024×768 projector.
    static constexpr int minimumSliderWidth = 48;
    /// The least width of a block of rows, without the limits.
    int blockWidth() const;
    /// Compact, with four rows or more, and wide enough for two blocks side by side.
    bool wantsTwoBlocks() const;
    /// The texts of row i (its name, role, tooltips and unit) in the current language.
    void describe(int i);
    void updateRanges();
    /// The width of the limit labels' two columns with their spacing.
    int limitsWidth() const;
    /// Shows the limit labels where the panel is wide enough for them.
    void fitLimits();

    MechanismPtr m_mechanism;
    QGridLayout *m_grid = nullptr;
    QVector<Row> m_rows;
    bool m_compact = false;
    bool m_twoBlocks = false; ///< the rows in two blocks side by side (placeRows())
    bool m_updating = false;
};

} // namespace pkm
