// View ▸ Velocity and Force Shapes: what the actuators deliver at the platform point, drawn in
// the 2D view at every pose — during a drag, a slider move and Play alike, since every pose
// change redraws the view's scene (onPoseChanged()).
#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "document/document.h"
#include "linkageview.h"
#include "quantityformat.h"

#include <QAction>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

#include <vector>

namespace pkm {

namespace {
const QString shapesKey = QStringLiteral("view/capabilityShapes");
}

void MainWindow::createCapabilityActions(QMenu *viewMenu)
{
    viewMenu->addSeparator();
    m_capabilityAction = translated(new QAction(this), QT_TR_NOOP("&Velocity and Force Shapes"),
        QT_TR_NOOP("The velocity and force polygons (solid) and ellipses (dashed) the actuators give at the platform point, "
                   "to the scale of the legend (V)"));
    m_capabilityAction->setObjectName(QStringLiteral("capabilityShapesAction"));
    m_capabilityAction->setCheckable(true);
    m_capabilityAction->setShortcut(QKeySequence(Qt::Key_V));
    m_capabilityAction->setChecked(QSettings().value(shapesKey, false).toBool());
    connect(m_capabilityAction, &QAction::toggled, this, &MainWindow::setCapabilityShapes);
    viewMenu->addAction(m_capabilityAction);
}

void MainWindow::setCapabilityShapes(bool on)
{
    if (m_capabilityAction->isChecked() != on)
        m_capabilityAction->setChecked(on); // comes back here through toggled()
    QSettings().setValue(shapesKey, on);
    m_view->setScene(viewScene(m_document->pose()));
    if (!m_view->userMoved())
        m_view->fitToView(); // the legend's room at the top, or the room back
    const QString why = capabilityShapesUnavailable();
    if (on && !why.isEmpty())
        showStatus(why);
}

bool MainWindow::showsCapabilityShapes() const
{
    return m_capabilityAction && m_capabilityAction->isChecked();
}

QString MainWindow::capabilityShapesUnavailable() const
{
    if (m_shapeScales.valid())
        return QString();
    if (m_actuators.count == 0)
        return tr("This design states no actuator limits, so there are no velocity and force shapes to draw.");
    if (m_actuators.rotaryOutput || m_actuators.outputs < 2)
        return tr("The output of this mechanism is one angle: its speed, torque and stiffness are in “Values at this "
                  "pose”; there is no platform point to draw shapes at.");
    return tr("The velocity and force shapes cannot be scaled for this design: its home pose is singular.");
}

void MainWindow::updateCapabilityDesign()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    m_actuators = capability::actuatorsOf(*mechanism);
    m_shapeScales = capability::scalesFor(*mechanism, m_actuators);
}

Scene MainWindow::viewScene(const Pose &pose) const
{
    const MechanismPtr &mechanism = m_document->mechanism();
    Scene scene = mechanism->scene(pose);
    if (showsCapabilityShapes() && m_shapeScales.valid()) {
        // the pose's singularity class tells which shapes are unbounded and which collapse
        std::vector<double> values(static_cast<std::size_t>(mechanism->reportLayout().size));
        const Singularity singularity = mechanism->evaluate(pose, values);
        capability::addShapes(scene, *mechanism, m_actuators, m_shapeScales, pose, singularity.type);
    }
    return scene;
}

} // namespace pkm
