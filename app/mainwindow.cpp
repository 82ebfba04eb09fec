#include "mainwindow.h"

#include "designpanel.h"
#include "document.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "modebar.h"
#include "oxglide.h"
#include "oxglidepanel.h"
#include "pjoint.h"
#include "pjointplots.h"
#include "quantityformat.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "workspacemapview.h"
#include "workspacepanel.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
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

namespace pkm {

namespace {
QString failureText(const Failure &failure)
{
    return QString::fromStdString(failure.message);
}

constexpr int settingsVersion = 1;
} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_document(new Document(this))
{
    setWindowIcon(QIcon(QStringLiteral(":/icons/pkm-studio.svg")));

    m_view = new LinkageView(this);
    m_view->setMinimumSize(340, 300);
    m_variables = new VariablePanel(this);
    m_modeBar = new ModeBar(this);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    // the linkage in 2D and 3D, one tab each; the sliders below drive both
    m_viewTabs = new QTabWidget(left);
    m_viewTabs->setObjectName(QStringLiteral("viewTabs"));
    m_viewTabs->setDocumentMode(true);
    m_view3d = new View3DPanel(m_viewTabs);
    m_viewTabs->addTab(m_view, tr("2D"));
    m_viewTabs->addTab(m_view3d, tr("3D"));
    m_viewTabs->setTabToolTip(1, tr("The mechanism in 3D: drag to turn it, right-drag to pan, wheel to zoom"));
    connect(m_viewTabs, &QTabWidget::currentChanged, this, [this] { update3d(false); });
    leftLayout->addWidget(m_viewTabs, 1);
    leftLayout->addWidget(m_variables);
    leftLayout->addWidget(m_modeBar);

    m_plots = new QStackedWidget(this);
    m_pjointPlots = new PJointPlots(this);
    m_plots->addWidget(m_pjointPlots);
    m_workspacePanel = new WorkspacePanel(this);
    m_plots->addWidget(m_workspacePanel);
    m_oxglidePanel = new OxGlidePanel(m_document, this);
    m_plots->addWidget(m_oxglidePanel);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("mainSplitter"));
    m_splitter->addWidget(left);
    m_splitter->addWidget(m_plots);
    // The plots carry more text than the linkage: give them the larger share.
    m_splitter->setStretchFactor(0, 2);
    m_splitter->setStretchFactor(1, 3);
    m_splitter->setSizes({560, 840});
    m_splitter->setChildrenCollapsible(false);
    setCentralWidget(m_splitter);

    createDocks();
    createActions();

    m_poseLabel = new QLabel(this);
    m_singularityLabel = new QLabel(this);
    statusBar()->addPermanentWidget(m_poseLabel);
    statusBar()->addPermanentWidget(m_singularityLabel);

    connect(m_document, &Document::designChanged, this, &MainWindow::onDesignChanged);
    connect(m_document, &Document::poseChanged, this, &MainWindow::onPoseChanged);

    connect(m_variables, &VariablePanel::variableEdited, this, [this](int variable, double value) {
        auto solved = m_document->setVariable(variable, value);
        if (!solved) {
            showStatus(failureText(solved.failure()), true);
            m_variables->setPose(m_document->pose()); // the slider goes back to where the pose is
        }
    });
    connect(m_view, &LinkageView::handleDragged, this, [this](int handle, const Eigen::Vector2d &target) {
        auto solved = m_document->dragHandle(handle, target);
        if (!solved)
            showStatus(failureText(solved.failure()), true);
    });
    connect(m_modeBar, &ModeBar::switchRequested, this, &MainWindow::switchMode);
    connect(m_view, &LinkageView::ghostClicked, this, &MainWindow::switchMode);
    // A click on the map moves the platform there, through the same document call as a drag.
    const auto moveTo = [this](const Eigen::Vector2d &point) {
        Coordinates outputs(2);
        outputs << point.x(), point.y();
        auto moved = m_document->moveOutputsTo(outputs);
        if (!moved)
            showStatus(failureText(moved.failure()), true);
    };
    connect(m_workspacePanel->mapView(), &WorkspaceMapView::pointClicked, this, moveTo);
    connect(m_oxglidePanel->mapPanel()->mapView(), &WorkspaceMapView::pointClicked, this, moveTo);
    connect(m_oxglidePanel, &OxGlidePanel::pointClicked, this, moveTo);
    connect(m_oxglidePanel, &OxGlidePanel::statusMessage, this, &MainWindow::showStatus);
    connect(m_designPanel, &DesignPanel::parameterEdited, this,
            [this](const QString &name, double value, bool continuous) {
                auto changed = m_document->setParameter(name, value, continuous);
                if (!changed) {
                    m_designPanel->markInvalid(name, failureText(changed.failure()));
                    showStatus(failureText(changed.failure()), true);
                }
            });

    onDesignChanged();
    restoreLayout();
}

MainWindow::~MainWindow()
{
    // Closing the window moves the focus out of a design field, which commits what it holds
    // (an edit in progress, or a rejected value). By then this window is half destroyed: the
    // panels must not call back into it.
    disconnect(m_designPanel, nullptr, this, nullptr);
    disconnect(m_variables, nullptr, this, nullptr);
    disconnect(m_modeBar, nullptr, this, nullptr);
    disconnect(m_workspacePanel->mapView(), nullptr, this, nullptr);
    disconnect(m_view, nullptr, this, nullptr);
    disconnect(m_document, nullptr, this, nullptr);
}

void MainWindow::createDocks()
{
    m_designPanel = new DesignPanel(this);
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(m_designPanel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(330);
    auto *designDock = new QDockWidget(tr("Design"), this);
    designDock->setObjectName(QStringLiteral("designDock"));
    designDock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, designDock);

    m_values = new ValuesTable(this);
    m_values->setMinimumWidth(330);
    auto *valuesDock = new QDockWidget(tr("Values at this pose"), this);
    valuesDock->setObjectName(QStringLiteral("valuesDock"));
    valuesDock->setWidget(m_values);
    addDockWidget(Qt::LeftDockWidgetArea, valuesDock);
    splitDockWidget(designDock, valuesDock, Qt::Vertical);
    // Small minimum sizes keep the window usable on a 1366×768 laptop; on a larger screen the
    // docks start wider (once the window has its size, unless a saved layout is restored).
    QTimer::singleShot(0, this, [this, designDock, valuesDock] {
        if (m_restoredGeometry)
            return;
        resizeDocks({designDock}, {width() >= 1600 ? 420 : 340}, Qt::Horizontal);
        resizeDocks({designDock, valuesDock}, {height() * 55 / 100, height() * 45 / 100}, Qt::Vertical);
    });
}

void MainWindow::createActions()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *open = file->addAction(tr("&Open Design…"), this, &MainWindow::openFile);
    open->setShortcut(QKeySequence::Open);
    QAction *saveAs = file->addAction(tr("Save Design &As…"), this, &MainWindow::saveFileAs);
    saveAs->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu *presets = menuBar()->addMenu(tr("&Presets"));
    presets->setToolTipsVisible(true); // the description says where a preset comes from
    QString lastKind;
    for (const PresetInfo &preset : designfile::presets()) {
        if (!lastKind.isEmpty() && preset.kind != lastKind)
            presets->addSeparator();
        lastKind = preset.kind;
        QAction *action = presets->addAction(preset.title, this, [this, id = preset.id] { openDesign(id); });
        action->setData(preset.id);
        action->setObjectName(QStringLiteral("preset_") + preset.id);
        if (auto design = designfile::load(preset.id))
            action->setToolTip(design->description);
    }

    QMenu *view = menuBar()->addMenu(tr("&View"));
    QAction *fit = view->addAction(tr("&Fit Mechanism"), m_view, &LinkageView::fitToView);
    fit->setShortcut(Qt::Key_F);
    QAction *zoomIn = view->addAction(tr("Zoom &In"), m_view, &LinkageView::zoomIn);
    zoomIn->setShortcut(QKeySequence::ZoomIn);
    QAction *zoomOut = view->addAction(tr("Zoom &Out"), m_view, &LinkageView::zoomOut);
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About PKM Studio"), this, &MainWindow::about);

    QToolBar *toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("mainToolBar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolbar->addAction(open);
    toolbar->addSeparator();
    toolbar->addAction(undo);
    toolbar->addAction(redo);
    toolbar->addSeparator();
    toolbar->addAction(fit);
    toolbar->addAction(zoomIn);
    toolbar->addAction(zoomOut);
}

bool MainWindow::openDesign(const QString &presetOrPath)
{
    auto opened = m_document->open(presetOrPath);
    if (!opened) {
        showStatus(failureText(opened.failure()), true);
        return false;
    }
    m_view->fitToView();
    return true;
}

void MainWindow::onDesignChanged()
{
    m_statusIsError = false; // a design change that arrives is a success: the error is over
    const Design &design = m_document->design();
    const MechanismPtr &mechanism = design.mechanism;
    setWindowTitle(tr("%1 — PKM Studio").arg(design.title.isEmpty() ? toQString(mechanism->kind()) : design.title));
    m_designPanel->setMechanism(mechanism);
    m_designPanel->setNote(design.title, design.description);
    m_variables->setMechanism(mechanism);
    m_values->setMechanism(mechanism);
    if (const auto *joint = dynamic_cast<const PJoint *>(mechanism.get())) {
        m_pjointPlots->setDesign(joint->design());
        m_plots->setCurrentWidget(m_pjointPlots);
    } else if (dynamic_cast<const OxGlide *>(mechanism.get())) {
        m_oxglidePanel->setDesign(mechanism, design.title);
        m_plots->setCurrentWidget(m_oxglidePanel);
    } else if (mechanism->planarWorkspace()) {
        m_workspacePanel->setDesign(mechanism, design.title);
        m_plots->setCurrentWidget(m_workspacePanel);
    }
    // A mechanism without plots of its own (the four-bar, for now) gives the linkage the room
    // rather than showing another mechanism's plots.
    const bool hasPlots = dynamic_cast<const PJoint *>(mechanism.get()) || mechanism->planarWorkspace();
    m_plots->setVisible(hasPlots);
    onPoseChanged();
    keepMechanismInView();
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

void MainWindow::keepMechanismInView()
{
    // Refit only when the new design leaves the view or shrinks to a small part of it: a
    // fixed scale while stepping a dimension shows the mechanism growing or shrinking.
    const Eigen::AlignedBox3d &extent = m_view->scene().extent;
    if (extent.isEmpty())
        return;
    const ViewMapping mapping = m_view->mapping();
    const QRectF drawn = QRectF(mapping.toDevice(Eigen::Vector2d(extent.min().head<2>())),
                                mapping.toDevice(Eigen::Vector2d(extent.max().head<2>())))
                             .normalized();
    const QRectF area = QRectF(m_view->rect());
    const bool outside = !area.contains(drawn);
    const bool tiny = drawn.width() < 0.3 * area.width() && drawn.height() < 0.3 * area.height();
    if (outside || tiny)
        m_view->fitToView();
}

void MainWindow::onPoseChanged()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    const Pose &pose = m_document->pose();
    m_variables->setPose(pose);
    m_values->setPose(pose);
    m_view->setScene(mechanism->scene(pose));
    update3d(false);
    if (dynamic_cast<const PJoint *>(mechanism.get()))
        m_pjointPlots->setTheta(pose.outputs[0]);
    else if (dynamic_cast<const OxGlide *>(mechanism.get()))
        m_oxglidePanel->setPose(pose);
    else if (mechanism->planarWorkspace())
        m_workspacePanel->setPose(pose);

    QStringList summary;
    const auto &variables = mechanism->variableInfo();
    for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
        summary << QStringLiteral("%1 = %2").arg(toQString(variables[i].symbol),
                                                 formatQuantity(mechanism->variableValue(pose, i), variables[i].unit,
                                                                variables[i].decimals));
    }
    m_poseLabel->setText(summary.join(QStringLiteral("   ")));

    updateModes();
    const QString note = m_document->limitNote();
    m_view->setMessage(note);
    if (!note.isEmpty())
        showStatus(note);
    else if (!m_statusIsError)
        statusBar()->clearMessage();
}

void MainWindow::updateModes()
{
    const MechanismPtr &mechanism = m_document->mechanism();
    m_alternatives = m_document->modeAlternatives();
    QStringList current;
    const ParameterSet values = mechanism->parameters();
    for (const ParameterInfo &info : mechanism->parameterInfo()) {
        if (info.group == ParameterGroup::Mode && info.domain.min == -1.0 && info.domain.max == 1.0) {
            const double v = values.at(info.name);
            QString text = v > 0 ? QStringLiteral("+1") : QStringLiteral("−1");
            for (const auto &[name, choice] : info.choices) {
                if (choice == v)
                    text = toQString(name);
            }
            current << QStringLiteral("%1 = %2").arg(toQString(info.symbol), text);
        }
    }
    QStringList labels;
    for (const ModeAlternative &alternative : m_alternatives)
        labels << QString::fromStdString(alternative.label);
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
        showStatus(tr("Switched to %1.").arg(QString::fromStdString(alternative.label)));
}

void MainWindow::showStatus(const QString &message, bool error)
{
    m_lastStatus = message;
    m_statusIsError = error;
    statusBar()->setStyleSheet(error ? QStringLiteral("QStatusBar { color: #b3261e; font-weight: bold; }")
                                     : QString());
    statusBar()->showMessage(message); // an error stays until the next change succeeds
}

void MainWindow::openFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Design"), QString(),
                                                      tr("PKM Studio designs (*.pkm.json);;All files (*)"));
    if (!path.isEmpty())
        openDesign(path);
}

void MainWindow::saveFileAs()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Design As"), QString(),
                                                tr("PKM Studio designs (*.pkm.json)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".json")))
        path += QStringLiteral(".pkm.json");
    Design design = m_document->design();
    design.id.clear(); // a saved copy is the user's design, not the preset
    auto saved = designfile::save(design, path);
    if (!saved)
        QMessageBox::warning(this, tr("Save Design"), failureText(saved.failure()));
    else
        showStatus(tr("Saved %1").arg(path));
}

void MainWindow::about()
{
    QMessageBox::about(this, tr("About PKM Studio"),
                       tr("<h3>PKM Studio %1</h3><p>Design, analysis and teaching of parallel-kinematic "
                          "mechanisms.</p><p>Licensed under the GNU General Public License, version 3 or "
                          "later.</p>")
                           .arg(QStringLiteral(PKM_VERSION)));
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    if (settings.value(QStringLiteral("layout/version")).toInt() != settingsVersion)
        return;
    m_restoredGeometry = restoreGeometry(settings.value(QStringLiteral("layout/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("layout/state")).toByteArray(), settingsVersion);
    m_splitter->restoreState(settings.value(QStringLiteral("layout/splitter")).toByteArray());
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    QSettings settings;
    settings.setValue(QStringLiteral("layout/version"), settingsVersion);
    settings.setValue(QStringLiteral("layout/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("layout/state"), saveState(settingsVersion));
    settings.setValue(QStringLiteral("layout/splitter"), m_splitter->saveState());
    event->accept();
}

} // namespace pkm
