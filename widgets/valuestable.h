#pragma once
/// Live values of the current pose: every entry of the mechanism's report (pose, Jacobian,
/// derived), what its actuators deliver (core/capability.h) and the singularity class,
/// grouped, with units and meanings.

#include "capability.h"
#include "mechanism.h"

#include <QPointer>
#include <QTreeWidget>

#include <optional>
#include <vector>

class QLabel;

namespace pkm {

class ValuesTable : public QTreeWidget
{
    Q_OBJECT

public:
    explicit ValuesTable(QWidget *parent = nullptr);

    void setMechanism(const MechanismPtr &mechanism);
    void setPose(const Pose &pose);

    /// The text shown for a report entry ("J") or "singularity", or why the capability group
    /// is as at a singular pose ("capability"; empty where it is not); for tests.
    QString valueText(const QString &name) const;

    /// A line for below the table that shows the meaning of the row under the pointer in full,
    /// made on the first call, for the caller's layout. It shows only while the "Meaning"
    /// column is too narrow for its texts (a 340 px dock on a projector shows "crank angl…").
    QLabel *meaningStrip();

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    /// Sizes the quantity and value columns to their texts, the value column no wider than
    /// the view leaves: a long matrix is cut with "…" (its tooltip has it whole) rather than
    /// push the short values, aligned right, out of sight.
    void fitColumns();
    void rebuild();
    /// Shows the strip while a meaning is cut, with `item`'s meaning (or a prompt).
    void updateMeaningStrip(const QTreeWidgetItem *item = nullptr);
    /// The text of entry `entry` in `values`: a number, or a matrix row by row.
    QString entryText(const ReportEntry &entry, const std::vector<double> &values) const;

    MechanismPtr m_mechanism;
    std::vector<QTreeWidgetItem *> m_items; ///< one per report entry
    capability::Actuators m_actuators;     ///< of the design shown
    const ReportLayout *m_capabilityLayout = nullptr;
    std::vector<QTreeWidgetItem *> m_capabilityItems; ///< one per capability entry
    std::vector<double> m_capabilityValues;
    QTreeWidgetItem *m_capabilityGroup = nullptr; ///< its title says when it is near-singular
    QTreeWidgetItem *m_singularity = nullptr;
    std::vector<double> m_values;
    std::optional<Pose> m_pose; ///< the pose shown, to show it again in another language
    qsizetype m_widestValue = 0; ///< longest value text so far, in characters
    QPointer<QLabel> m_meaningStrip;
    const QTreeWidgetItem *m_meaningShown = nullptr; ///< the row whose meaning the strip shows
    int m_widestMeaning = 0;                         ///< pixels, of the meanings' texts
};

} // namespace pkm
