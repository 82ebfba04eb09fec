// The main window following its design: a design opened, changed or moved to a new pose
// updates the panels, the 2D and 3D views and the mode bar, and the status bar says why a
// change was refused.

#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "gui/animationdialog.h"
#include "gui/backgroundtask.h"
#include "gui/player.h"
#include "designpanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "document/language.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "equationspanel.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "pictureexport.h"
#include "quantityformat.h"
#include "export/sheet.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "playbar.h"
#include "gui/viewpicture.h"
#include "workspacemapview.h"
#include "kinds/kindmodule.h"
#include "kinds/kindpanel.h"
#include "kinds/sweepplotspanel.h"
#include "kinds/workspacepanel.h"

#include <qcustomplot.h>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSaveFile>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <utility>

namespace pkm {

namespace {
using mainwindow::failureText;
} // namespace

bool MainWindow::openDesign(const QString &presetOrPath)
{
    auto opened = m_session->open(presetOrPath);
    if (!opened) {
        showStatus(failureText(opened.failure()), true);
        return false;
    }
    m_currentBookmark = -1; // Page Down starts at the new design's first bookmark
    updateBookmarksMenu();
    m_view->fitToView();
    return true;
}

void MainWindow::onDesignChanged()
{
    m_statusIsError = false; // a design change that arrives is a success: the error is over
    const Design &design = m_document->design();
    const MechanismPtr &mechanism = design.mechanism;
    updateTitle();
    updateCapabilityDesign();
    m_designPanel->setMechanism(mechanism);
    m_designPanel->setNote(designfile::presetText(design.title), designfile::presetText(design.description));
    m_variables->setMechanism(mechanism);
    styleSliders(); // a new kind's sliders, large when presenting
    setPlaying(false); // a new design is a new lesson: Play does not carry on in it
    m_playBar->setMechanism(mechanism);
    updateBookmarksMenu();
    m_values->setMechanism(mechanism);
    m_mobility->setMechanism(mechanism);
    m_equations->setMechanism(mechanism);
    // The kind's own panel, else the generic one its outputs allow, else none: a mechanism
    // without plots gives the linkage the room rather than showing another mechanism's plots.
    m_currentPanel = mechanism->planarWorkspace() ? static_cast<KindPanel *>(m_workspacePanel)
        : SweepPlotsPanel::canShow(*mechanism)    ? static_cast<KindPanel *>(m_sweepPanel)
                                                  : nullptr;
    for (const auto &[kind, panel] : m_kindPanels) {
        if (kind == mechanism->kind())
            m_currentPanel = panel;
    }
    if (m_currentPanel) {
        m_currentPanel->setDesign(mechanism, design.title);
        m_plots->setCurrentWidget(m_currentPanel);
    }
    // The stack asks for the room of its largest page; only the one shown should count, or
    // the four-bar's panel keeps the window from fitting a projector while MOMA is open.
    for (int i = 0; i < m_plots->count(); ++i) {
        QWidget *page = m_plots->widget(i);
        page->setSizePolicy(page == m_currentPanel ? QSizePolicy::Preferred : QSizePolicy::Ignored,
                            page == m_currentPanel ? QSizePolicy::Preferred : QSizePolicy::Ignored);
    }
    m_plots->setVisible(m_currentPanel != nullptr);
    applyPresentationPlots(); // one plot per page of the new panel while presenting
    onPoseChanged();
    m_view->keepInSight();
    update3d(true);
}

void MainWindow::update3d(bool designChanged)
{
    if (m_viewTabs->currentWidget() != m_view3d) {
        if (designChanged)
            m_view3dExtent.setEmpty(); // refit when the 3D view is shown next
        return;
    }
    const Scene3D model = m_document->mechanism()->scene3d(m_document->pose());
    m_view3d->setScene(model);
    // Refit for a new mechanism or one that grew out of view or shrank a lot; a pose change
    // keeps the camera, so the model moves in a still view.
    const bool refit = m_view3dExtent.isEmpty() || !m_view3dExtent.contains(model.extent)
        || model.extent.diagonal().norm() < 0.5 * m_view3dExtent.diagonal().norm();
    if (refit) {
        if (m_view3dExtent.isEmpty())
            m_view3d->view()->setStandardView(Camera3D::StandardView::Isometric); // a new mechanism: the view that shows depth
        m_view3d->view()->fit();
        m_view3dExtent = model.extent;
    }
}

void MainWindow::onPoseChanged()
{
    const Pose &pose = m_document->pose();
    m_variables->setPose(pose);
    m_values->setPose(pose);
    m_mobility->setPose(pose);
    m_equations->setPose(pose);
    m_view->setScene(viewScene(pose));
    update3d(false);
    if (m_currentPanel)
        m_currentPanel->setPose(pose);

    // the symbols lowered, as the sliders write them; the read-out's wide gaps kept
    m_poseLabel->setText(symbolHtmlKnown(poseSummary(), shownSymbols())
                             .replace(QStringLiteral("   "), QStringLiteral("&nbsp;&nbsp; ")));

    updateModes();
    // A pose that arrives is a success: an error about an earlier move (a drag, a map click or a
    // value beyond reach) is no longer true, whatever the next note says.
    const QString note = m_document->limitNote();
    // While Play runs, a limit it turns at is said in the status bar only (Play says why it
    // turned or stopped): the note over the drawing covered part of what the class watches.
    m_view->setMessage(m_player && m_player->isPlaying() ? QString() : note);
    if (!note.isEmpty()) {
        showStatus(note);
    } else if (m_statusHeldUntil.hasExpired()) {
        if (m_statusIsError)
            showStatus(QString());
        statusBar()->clearMessage();
    }
}

void MainWindow::updateModes()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    m_alternatives = m_document->modeAlternatives();
    QStringList current;
    const ParameterSet values = mechanism->parameters();
    for (const ParameterInfo &info : mechanism->parameterInfo()) {
        if (info.group == ParameterGroup::Mode && info.domain.min == -1.0 && info.domain.max == 1.0
            && mechanism->parameterApplies(info.name)) {
            const double v = values.at(info.name);
            QString text = v > 0 ? QStringLiteral("+1") : QStringLiteral("−1");
            for (const auto &[name, choice] : info.choices) {
                if (choice == v)
                    text = coreLabel(name); // a key in files ("open"), a word on screen
            }
            current << QStringLiteral("%1 = %2").arg(coreLabel(info.symbol), text);
        }
    }
    QStringList labels;
    for (const ModeAlternative &alternative : m_alternatives)
        labels << coreLabel(alternative.label);
    m_modeBar->setModes(current.join(QStringLiteral(", ")), labels);
    QList<Scene> ghosts;
    for (const ModeAlternative &alternative : m_alternatives)
        ghosts << alternative.mechanism->scene(alternative.pose);
    m_view->setGhostScenes(ghosts, labels);
}

void MainWindow::switchMode(int index)
{
    if (index < 0 || index >= static_cast<int>(m_alternatives.size()))
        return;
    // a copy: the switch replaces m_alternatives with the new pose's
    const ModeAlternative alternative = m_alternatives[static_cast<std::size_t>(index)];
    auto switched = m_document->switchMode(alternative);
    if (!switched)
        showStatus(failureText(switched.failure()), true);
    else
        showStatus(tr("Switched to %1.").arg(coreLabel(alternative.label)));
}

void MainWindow::showStatus(const QString &message, bool error)
{
    m_lastStatus = message;
    m_statusIsError = error;
    statusBar()->setStyleSheet(error ? QStringLiteral("QStatusBar, QLabel#statusText { color: #b3261e; font-weight: bold; }")
                                     : QString());
    statusBar()->showMessage(message); // an error stays until the next change succeeds
    fitStatusMessage(); // also when only its weight changed
}

} // namespace pkm
