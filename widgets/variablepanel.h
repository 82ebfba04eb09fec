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

    QSlider *slider(int variable) const { return m_rows.value(variable).slider; }
    QDoubleSpinBox *spinBox(int variable) const { return m_rows.value(variable).spinBox; }
    static constexpr int sliderSteps = 10000;

signals:
    /// The user moved variable `variable` (index into variableInfo()) to `value` (core units).
    void variableEdited(int variable, double value);
    void sliderPressed();
    void sliderReleased();

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Row {
        QLabel *name = nullptr;
        QLabel *minimum = nullptr;
        QSlider *slider = nullptr;
        QLabel *maximum = nullptr;
        QDoubleSpinBox *spinBox = nullptr;
    };
    void rebuild();
    /// The texts of row i (its name, role, tooltips and unit) in the current language.
    void describe(int i);
    void updateRanges();

    MechanismPtr m_mechanism;
    QGridLayout *m_grid = nullptr;
    QVector<Row> m_rows;
    bool m_updating = false;
};

} // namespace pkm
