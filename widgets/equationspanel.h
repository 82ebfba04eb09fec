#pragma once
/// The governing equations of the current mechanism beside its values, for the classroom:
/// each equation as its source document prints it (with the document's equation number), under
/// it the same equation with the numbers of the pose put in and its result, and where the
/// program departs from the printed formula a line saying why (core/equations.h). The numbers
/// are written as the values panel writes them (formatQuantity: the locale, ∞ and — at
/// singular poses), so the two panels always agree.
///
/// The text follows every pose while the panel is seen; a hidden panel (a tab behind another)
/// catches up when it is shown.

#include "equations.h"
#include "mechanism.h"

#include <QTextBrowser>

#include <optional>
#include <vector>

namespace pkm {

class EquationsPanel : public QTextBrowser
{
    Q_OBJECT

public:
    explicit EquationsPanel(QWidget *parent = nullptr);

    void setMechanism(const MechanismPtr &mechanism);
    void setPose(const Pose &pose);

    /// The equations on display (for tests).
    const std::vector<Equation> &shownEquations() const { return m_equations; }
    /// The result of equation `index` as shown ("183.12 mm"), for tests.
    QString resultText(int index) const;
    /// The substituted line of equation `index` as shown ("= 170.00·√(…) = 183.12 mm").
    QString substitutedText(int index) const;

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void refresh();
    /// Rewrites only the lines with the pose's numbers, in place; false when the page must be
    /// built again (another mechanism, a note that changed, a language).
    bool updateNumbers(const QString &structure);

    MechanismPtr m_mechanism;
    std::optional<Pose> m_pose;
    std::vector<Equation> m_equations;
    QStringList m_results;
    QStringList m_substituted;
    bool m_stale = false; ///< a pose arrived while the panel was hidden
    /// What a pose does not change (titles, sources, formulas, notes) as the page shows it,
    /// and the block of each equation's line of numbers. While it stays, a new pose rewrites
    /// only those lines: rebuilding the page by setHtml() was a third of the main window's
    /// repaint on every slider step.
    QString m_structure;
    std::vector<int> m_lineBlocks;
};

} // namespace pkm
