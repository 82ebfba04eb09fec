#pragma once
/// The panel beside the linkage in the main window: the plots, maps and controls of the current
/// design. A kind with a GUI of its own makes one (kindmodule.h); a kind without gets a generic
/// one (the workspace map for a planar workspace, WorkspacePanel). The main window gives it
/// every new design and pose and listens to the two signals; it knows no kind's panel by name.

#include "mechanism.h"

#include <Eigen/Core>

#include <QString>
#include <QWidget>

namespace pkm {

class KindPanel : public QWidget
{
    Q_OBJECT

public:
    using QWidget::QWidget;

    /// A new design (`title` names it, e.g. in a comparison list).
    virtual void setDesign(const MechanismPtr &mechanism, const QString &title) = 0;
    /// A new pose of the current design: cursors and markers follow.
    virtual void setPose(const Pose &pose) = 0;
    /// Presentation mode on or off: a panel with controls and texts beside its plots keeps only
    /// the plots or map while presenting, which is what a class looks at (the main window shows
    /// one plot per tab, plotfocus.h). Nothing changes by default.
    virtual void setPresenting(bool on) { Q_UNUSED(on) }

signals:
    /// A message for the status bar (an error in red).
    void statusMessage(const QString &message, bool error);
    /// A click on a map or plot at a point of the outputs' plane: the platform goes there.
    void pointClicked(const Eigen::Vector2d &point);
};

} // namespace pkm
