// View ▸ Velocity and Force Shapes: what the actuators deliver at the platform point, drawn in
// the 2D view at every pose — during a drag, a slider move and Play alike, since every pose
// change redraws the view's scene (onPoseChanged()).
#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "document/document.h"
#include "gui/requirementsdialog.h"
#include "linkageview.h"
#include "quantityformat.h"
#include "workspacemapview.h"

#include <QAction>
#include <QComboBox>
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
        return tr("The output of this mechanism is one angle: its speed, torque and stiffness are in “Values”; "
                  "there is no platform point to draw shapes at.");
    return tr("The velocity and force shapes cannot be scaled for this design: its home pose is singular.");
}

void MainWindow::updateCapabilityDesign()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    m_actuators = capability::actuatorsOf(*mechanism);
    m_shapeScales = capability::scalesFor(*mechanism, m_actuators);
}

void MainWindow::createRequirementsAction(QMenu *editMenu)
{
    editMenu->addSeparator();
    m_requirementsAction = translated(new QAction(this), QT_TR_NOOP("Re&quirements…"),
        QT_TR_NOOP("What the actuators must deliver at the platform; the workspace map shows where it holds"));
    m_requirementsAction->setObjectName(QStringLiteral("requirementsAction"));
    connect(m_requirementsAction, &QAction::triggered, this, &MainWindow::editRequirements);
    editMenu->addAction(m_requirementsAction);
    connect(m_document, &Document::requirementsChanged, this, &MainWindow::showRequirements);
    connect(m_document, &Document::designChanged, this, &MainWindow::showRequirements);
    // the tolerances of the Tolerances panel: the workspace map offers their worst-case error
    const auto showTolerances = [this] {
        for (WorkspaceMapView *map : findChildren<WorkspaceMapView *>())
            map->setTolerances(m_document->tolerances());
    };
    connect(m_document, &Document::tolerancesChanged, this, showTolerances);
    connect(m_document, &Document::designChanged, this, showTolerances);
}

void MainWindow::editRequirements()
{
    RequirementsDialog dialog(*m_document->mechanism(), m_document->pose(), m_document->requirements(), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_document->setRequirements(dialog.requirements());
    const QList<WorkspaceMapView *> maps = findChildren<WorkspaceMapView *>();
    if (maps.isEmpty()) {
        showStatus(tr("The requirements are kept with the design; this mechanism has no workspace map to show "
                      "where they hold."));
        return;
    }
    // show what was just stated: the region where it holds
    for (WorkspaceMapView *map : maps)
        if (map->quantityBox()->findData(int(MapQuantity::Specification)) >= 0)
            map->setQuantity(MapQuantity::Specification);
}

void MainWindow::showRequirements()
{
    for (WorkspaceMapView *map : findChildren<WorkspaceMapView *>())
        map->setRequirements(m_document->requirements());
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
