#pragma once
/// The right-hand panel for mechanisms with a planar workspace: the det J / κ map over the
/// workspace, and a row to overlay another configuration's workspace for comparison — a
/// preset of the same mechanism or the current design pinned before it is changed.

#include "kinds/kindpanel.h"

class QComboBox;
class QLabel;
class QPushButton;

namespace pkm {

class WorkspaceMapView;

class WorkspacePanel : public KindPanel
{
    Q_OBJECT

public:
    explicit WorkspacePanel(QWidget *parent = nullptr);

    WorkspaceMapView *mapView() const { return m_map; }
    QComboBox *comparisonBox() const { return m_compare; }
    QPushButton *pinButton() const { return m_pin; }

    /// A new design (`title` names it in the comparison list).
    void setDesign(const MechanismPtr &mechanism, const QString &title) override;
    void setPose(const Pose &pose) override;
    /// Presenting: the map alone, without the comparison row.
    void setPresenting(bool on) override;

protected:
    /// A new language: the texts and the comparison list again, the choice kept.
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    /// Fills the comparison list; the item with data `keep` stays current if it is still there.
    void fillComparisons(const QString &keep = {});
    void compareWith(int index);
    void pinCurrent();

    WorkspaceMapView *m_map = nullptr;
    QLabel *m_label = nullptr;
    QComboBox *m_compare = nullptr;
    QPushButton *m_pin = nullptr;
    MechanismPtr m_mechanism;
    QString m_title; ///< as the design gives it (a preset's in English, translated when shown)
    QString m_kind; ///< the mechanism kind the comparison list was filled for
    MechanismPtr m_pinned;
    QString m_pinnedTitle;
};

} // namespace pkm
