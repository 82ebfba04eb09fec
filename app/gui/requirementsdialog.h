#pragma once
/// Edit ▸ Requirements…: what the actuators must deliver at the platform — the least force and
/// speed in the weakest direction, the largest error from the actuators' steps, the least
/// stiffness — as checked rows in display units. The workspace map's specification region
/// shows where all of them hold (core/capabilitymap.h). Requirements the dialog has no row for
/// (from a file or `--require`) are kept as they are and listed.

#include "capabilitymap.h"
#include "mechanism.h"

#include <QDialog>

#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;

namespace pkm {

class RequirementsDialog : public QDialog
{
    Q_OBJECT

public:
    /// `pose` gives an unchecked row its starting value: what the actuators deliver there,
    /// rounded to two significant digits towards the safe side.
    RequirementsDialog(const Mechanism &mechanism, const Pose &pose,
                       const std::vector<capability::Requirement> &requirements, QWidget *parent = nullptr);

    /// The requirements as edited (core units), the kept ones after the rows'.
    std::vector<capability::Requirement> requirements() const;

    /// The row of entry `name` ("force_worst"), for tests: its check box and value (display units).
    QCheckBox *checkBox(const char *name) const;
    QDoubleSpinBox *valueBox(const char *name) const;

private:
    struct Row {
        const char *name = nullptr;
        bool atLeast = true;
        Unit unit;
        QCheckBox *check = nullptr;
        QDoubleSpinBox *value = nullptr;
    };
    std::vector<Row> m_rows;
    std::vector<capability::Requirement> m_kept;
};

} // namespace pkm
