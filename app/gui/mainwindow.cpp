#include "gui/mainwindow.h"

#include "gui/animationdialog.h"
#include "gui/backgroundtask.h"
#include "designpanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "export/dxfwriter.h"
#include "document/language.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "pictureexport.h"
#include "quantityformat.h"
#include "export/sheet.h"
#include "valuestable.h"
#include "variablepanel.h"
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
QString failureText(const Failure &failure)
{
    return QString::fromStdString(failure.message);
}

constexpr int settingsVersion = 1;
} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_document(new Document(this))
    , m_session(new DesignSession(m_document, this))
    , m_question([this](const QString &title, const QString &text, QMessageBox::StandardButtons buttons) {
        return QMessageBox::question(this, title, text, buttons);
    })
{
    setWindowIcon(QIcon(QStringLiteral(":/icons/pkm-studio.svg")));
    // Widgets keep the locale they were made with: a language switch gives the windows open
    // then the new one (their children inherit it), so spin boxes read numbers the new way.
    language::setLocaleHook([](const QLocale &locale) {
        for (QWidget *window : QApplication::topLevelWidgets())
            window->setLocale(locale);
    });

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

    // The panels beside the linkage: one per kind whose module has one, and the generic
    // workspace map for the other planar kinds. All are made here, once.
    m_plots = new QStackedWidget(this);
    for (const KindModule &module : kinds::modules()) {
        if (!module.createPanel)
            continue;
        KindPanel *panel = module.createPanel(m_document, this);
        m_kindPanels.emplace_back(std::string(module.kind), panel);
        m_plots->addWidget(panel);
    }
    m_workspacePanel = new WorkspacePanel(this);
    m_plots->addWidget(m_workspacePanel);
    m_sweepPanel = new SweepPlotsPanel(this);
    m_plots->addWidget(m_sweepPanel);

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
    connect(m_session, &DesignSession::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_session, &DesignSession::filePathChanged, this, &MainWindow::updateTitle);
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
    std::vector<KindPanel *> panels {m_workspacePanel, m_sweepPanel};
    for (const auto &[kind, panel] : m_kindPanels)
        panels.push_back(panel);
    for (KindPanel *panel : panels) {
        connect(panel, &KindPanel::pointClicked, this, moveTo);
        connect(panel, &KindPanel::statusMessage, this, &MainWindow::showStatus);
    }
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
    // Every plot and map (all made above, none later): a right click offers Save picture…,
    // named after the plot's title when saved.
    for (QCustomPlot *plot : findChildren<QCustomPlot *>())
        enablePictureExport(plot);
}

MainWindow::~MainWindow()
{
    // Closing the window moves the focus out of a design field, which commits what it holds
    // (an edit in progress, or a rejected value). By then this window is half destroyed: the
    // panels must not call back into it.
    disconnect(m_designPanel, nullptr, this, nullptr);
    disconnect(m_variables, nullptr, this, nullptr);
    disconnect(m_modeBar, nullptr, this, nullptr);
    for (const auto &[kind, panel] : m_kindPanels)
        disconnect(panel, nullptr, this, nullptr);
    disconnect(m_workspacePanel, nullptr, this, nullptr);
    disconnect(m_sweepPanel, nullptr, this, nullptr);
    disconnect(m_view, nullptr, this, nullptr);
    disconnect(m_document, nullptr, this, nullptr);
    disconnect(m_session, nullptr, this, nullptr); // the undo stack's end is no change of title
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
    auto *designDock = m_designDock = new QDockWidget(tr("Design"), this);
    designDock->setObjectName(QStringLiteral("designDock"));
    designDock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, designDock);

    m_values = new ValuesTable(this);
    m_values->setMinimumWidth(330);
    auto *valuesDock = m_valuesDock = new QDockWidget(tr("Values at this pose"), this);
    valuesDock->setObjectName(QStringLiteral("valuesDock"));
    valuesDock->setWidget(m_values);
    addDockWidget(Qt::LeftDockWidgetArea, valuesDock);
    splitDockWidget(designDock, valuesDock, Qt::Vertical);
    // Mobility (issue 6): a tab behind the values, so it takes no room until asked for.
    m_mobility = new MobilityPanel(this);
    m_mobility->setMinimumWidth(330);
    auto *mobilityDock = m_mobilityDock = new QDockWidget(tr("Mobility"), this);
    mobilityDock->setObjectName(QStringLiteral("mobilityDock"));
    mobilityDock->setWidget(m_mobility);
    addDockWidget(Qt::LeftDockWidgetArea, mobilityDock);
    tabifyDockWidget(valuesDock, mobilityDock);
    // The values in front; a tab raised before the window is shown does not stick. A restored
    // layout keeps the tab it had.
    QTimer::singleShot(0, this, [this, valuesDock] {
        if (!m_restoredGeometry)
            valuesDock->raise();
    });
    // Small minimum sizes keep the window usable on a 1366×768 laptop; on a larger screen the
    // docks start wider (once the window has its size, unless a saved layout is restored).
    QTimer::singleShot(0, this, [this, designDock, valuesDock] {
        if (m_restoredGeometry)
            return;
        resizeDocks({designDock}, {width() >= 1600 ? 420 : 340}, Qt::Horizontal);
        resizeDocks({designDock, valuesDock}, {height() * 55 / 100, height() * 45 / 100}, Qt::Vertical);
    });
}

QAction *MainWindow::translated(QAction *action, const char *source, const char *toolTip)
{
    m_translatedActions.append({action, source, toolTip});
    action->setText(tr(source));
    if (toolTip)
        action->setToolTip(tr(toolTip));
    return action;
}

void MainWindow::createActions()
{
    QMenu *file = menuBar()->addMenu(QString());
    translated(file->menuAction(), QT_TR_NOOP("&File"));
    QAction *open = translated(file->addAction(QString(), this, &MainWindow::openFile), QT_TR_NOOP("&Open Design…"));
    open->setShortcut(QKeySequence::Open);
    m_recentMenu = file->addMenu(QString());
    translated(m_recentMenu->menuAction(), QT_TR_NOOP("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    updateRecentMenu();
    connect(m_session, &DesignSession::recentFilesChanged, this, &MainWindow::updateRecentMenu);
    QAction *save = translated(file->addAction(QString(), this, &MainWindow::saveFile), QT_TR_NOOP("&Save Design"));
    save->setShortcut(QKeySequence::Save);
    save->setObjectName(QStringLiteral("saveAction"));
    QAction *saveAs = translated(file->addAction(QString(), this, &MainWindow::saveFileAs), QT_TR_NOOP("Save Design &As…"));
    saveAs->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    translated(file->addAction(QString(), this, &MainWindow::exportAnimationDialog), QT_TR_NOOP("Export &Animation (GIF)…"))
        ->setObjectName(QStringLiteral("exportAnimationAction"));
    translated(file->addAction(QString(), this, &MainWindow::exportDrawing), QT_TR_NOOP("Export &Drawing (DXF)…"))
        ->setObjectName(QStringLiteral("exportDxfAction"));
    translated(file->addAction(QString(), this, &MainWindow::exportParameterSheet), QT_TR_NOOP("Export &Parameter Sheet…"))
        ->setObjectName(QStringLiteral("exportSheetAction"));
    translated(file->addAction(QString(), this, &MainWindow::saveViewPicture), QT_TR_NOOP("Save 2D &View Picture…"))
        ->setObjectName(QStringLiteral("saveViewPictureAction"));
    file->addSeparator();
    QAction *quit = translated(file->addAction(QString(), this, &QWidget::close), QT_TR_NOOP("&Quit"));
    quit->setShortcut(QKeySequence::Quit);

    m_editMenu = menuBar()->addMenu(QString());
    translated(m_editMenu->menuAction(), QT_TR_NOOP("&Edit"));
    // The menu names the step ("Undo Change a"); the toolbar keeps a short, steady label and
    // names the step in its tooltip, so a long design title does not widen it.
    m_undoButton = translated(new QAction(this), QT_TR_NOOP("Undo"));
    m_redoButton = translated(new QAction(this), QT_TR_NOOP("Redo"));
    createUndoActions();

    m_presetsMenu = menuBar()->addMenu(QString());
    translated(m_presetsMenu->menuAction(), QT_TR_NOOP("&Presets"));
    m_presetsMenu->setToolTipsVisible(true); // the description says where a preset comes from
    fillPresetsMenu();

    QMenu *view = menuBar()->addMenu(QString());
    translated(view->menuAction(), QT_TR_NOOP("&View"));
    QAction *fit = translated(view->addAction(QString(), m_view, &LinkageView::fitToView), QT_TR_NOOP("&Fit Mechanism"));
    fit->setShortcut(Qt::Key_F);
    QAction *zoomIn = translated(view->addAction(QString(), m_view, &LinkageView::zoomIn), QT_TR_NOOP("Zoom &In"));
    zoomIn->setShortcut(QKeySequence::ZoomIn);
    QAction *zoomOut = translated(view->addAction(QString(), m_view, &LinkageView::zoomOut), QT_TR_NOOP("Zoom &Out"));
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());

    // Each language by its own name, so that anyone finds theirs whatever is shown now.
    m_languageMenu = menuBar()->addMenu(QString());
    m_languageMenu->setObjectName(QStringLiteral("languageMenu"));
    translated(m_languageMenu->menuAction(), QT_TR_NOOP("&Language"));
    auto *languages = new QActionGroup(this);
    for (const language::Language &language : language::all()) {
        QAction *action = m_languageMenu->addAction(language.nativeName);
        action->setObjectName(QStringLiteral("language_") + language.code);
        action->setData(language.code);
        action->setCheckable(true);
        action->setChecked(language.code == language::current());
        languages->addAction(action);
        connect(action, &QAction::triggered, this, [this, code = language.code] { setLanguage(code); });
    }

    QMenu *help = menuBar()->addMenu(QString());
    translated(help->menuAction(), QT_TR_NOOP("&Help"));
    translated(help->addAction(QString(), this, &MainWindow::about), QT_TR_NOOP("&About PKM Studio"));

    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_toolBar->addAction(open);
    m_toolBar->addAction(save);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_undoButton);
    m_toolBar->addAction(m_redoButton);
    m_toolBar->addSeparator();
    m_toolBar->addAction(fit);
    m_toolBar->addAction(zoomIn);
    m_toolBar->addAction(zoomOut);
    translated(m_toolBar->toggleViewAction(), QT_TR_NOOP("Main Toolbar"));
}

void MainWindow::createUndoActions()
{
    // QUndoStack's actions keep the prefix they were made with: a new language makes new ones.
    delete m_undoAction;
    delete m_redoAction;
    m_undoAction = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_redoAction = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    for (auto [button, full] : {std::pair{m_undoButton, m_undoAction}, std::pair{m_redoButton, m_redoAction}}) {
        disconnect(button, &QAction::triggered, nullptr, nullptr);
        connect(button, &QAction::triggered, full, &QAction::trigger);
        const auto follow = [button, full] {
            button->setEnabled(full->isEnabled());
            button->setToolTip(full->text().remove(QLatin1Char('&')));
        };
        connect(full, &QAction::changed, button, follow);
        follow();
    }
    m_editMenu->addAction(m_undoAction);
    m_editMenu->addAction(m_redoAction);
}

void MainWindow::fillPresetsMenu()
{
    m_presetsMenu->clear();
    QString lastKind;
    for (const PresetInfo &preset : designfile::presets()) {
        if (!lastKind.isEmpty() && preset.kind != lastKind)
            m_presetsMenu->addSeparator();
        lastKind = preset.kind;
        QAction *action = m_presetsMenu->addAction(designfile::presetText(preset.title), this,
                                                   [this, id = preset.id] { openFromMenu(id); });
        action->setData(preset.id);
        action->setObjectName(QStringLiteral("preset_") + preset.id);
        if (auto design = designfile::load(preset.id))
            action->setToolTip(designfile::presetText(design->description));
    }
}

void MainWindow::setLanguage(const QString &code)
{
    if (code == language::current())
        return;
    if (!language::apply(code)) {
        showStatus(tr("The language “%1” is not available.").arg(code), true);
        return;
    }
    language::remember(code);
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate()
{
    for (const TranslatedAction &entry : std::as_const(m_translatedActions)) {
        if (!entry.action)
            continue;
        entry.action->setText(tr(entry.source));
        if (entry.toolTip)
            entry.action->setToolTip(tr(entry.toolTip));
    }
    if (m_editMenu)
        createUndoActions();
    if (m_presetsMenu)
        fillPresetsMenu();
    if (m_languageMenu) {
        for (QAction *action : m_languageMenu->actions())
            action->setChecked(action->data().toString() == language::current());
    }
    if (m_toolBar)
        m_toolBar->setWindowTitle(tr("Main Toolbar"));
    m_designDock->setWindowTitle(tr("Design"));
    m_valuesDock->setWindowTitle(tr("Values at this pose"));
    m_mobilityDock->setWindowTitle(tr("Mobility"));
    m_viewTabs->setTabText(0, tr("2D"));
    m_viewTabs->setTabText(1, tr("3D"));
    m_viewTabs->setTabToolTip(1, tr("The mechanism in 3D: drag to turn it, right-drag to pan, wheel to zoom"));
    // What the main window shows of the design and the pose: the preset's title and note, the
    // pose in the status bar (numbers by the new locale), the modes, the limit note, the labels
    // of the drawing. A status message of the old language goes.
    const Design &design = m_document->design();
    m_designPanel->setNote(designfile::presetText(design.title), designfile::presetText(design.description));
    updateTitle();
    onPoseChanged();
    if (!m_statusIsError)
        statusBar()->clearMessage();
}

bool MainWindow::openDesign(const QString &presetOrPath)
{
    auto opened = m_session->open(presetOrPath);
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
    updateTitle();
    m_designPanel->setMechanism(mechanism);
    m_designPanel->setNote(designfile::presetText(design.title), designfile::presetText(design.description));
    m_variables->setMechanism(mechanism);
    m_values->setMechanism(mechanism);
    m_mobility->setMechanism(mechanism);
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
    m_plots->setVisible(m_currentPanel != nullptr);
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
    m_mobility->setPose(pose);
    m_view->setScene(mechanism->scene(pose));
    update3d(false);
    if (m_currentPanel)
        m_currentPanel->setPose(pose);

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
    statusBar()->setStyleSheet(error ? QStringLiteral("QStatusBar { color: #b3261e; font-weight: bold; }")
                                     : QString());
    statusBar()->showMessage(message); // an error stays until the next change succeeds
}

void MainWindow::openFile()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Design"), QFileInfo(m_session->filePath()).path(),
                                                      tr("PKM Studio designs (*.pkm.json);;All files (*)"));
    if (!path.isEmpty())
        openDesign(path);
}

void MainWindow::openFromMenu(const QString &presetOrPath)
{
    if (maybeSave())
        openDesign(presetOrPath);
}

bool MainWindow::saveFile()
{
    if (m_session->filePath().isEmpty())
        return saveFileAs();
    auto saved = m_session->save();
    if (!saved) {
        QMessageBox::warning(this, tr("Save Design"), failureText(saved.failure()));
        return false;
    }
    showStatus(tr("Saved %1").arg(m_session->filePath()));
    return true;
}

bool MainWindow::saveFileAs()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Design As"), m_session->filePath(),
                                                tr("PKM Studio designs (*.pkm.json)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QLatin1String(".json")))
        path += QStringLiteral(".pkm.json");
    auto saved = m_session->saveAs(path);
    if (!saved) {
        QMessageBox::warning(this, tr("Save Design"), failureText(saved.failure()));
        return false;
    }
    showStatus(tr("Saved %1").arg(path));
    return true;
}

void MainWindow::exportAnimationDialog()
{
    AnimationDialog dialog(*m_document->mechanism(), 0, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const QString base = m_session->filePath().isEmpty() ? QFileInfo(m_document->design().id).fileName()
                                                         : QFileInfo(m_session->filePath()).completeBaseName();
    QString path = QFileDialog::getSaveFileName(this, tr("Export Animation"),
                                                base.isEmpty() ? QString() : base + QStringLiteral(".gif"),
                                                tr("Animated GIF (*.gif)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".gif"), Qt::CaseInsensitive))
        path += QStringLiteral(".gif");
    exportAnimationTo(path, dialog.settings());
}

void MainWindow::exportAnimationTo(const QString &path, AnimationSettings settings)
{
    settings.name = m_session->displayName();
    exportAnimation(this, m_document->mechanism(), m_document->pose(), settings, path,
                    [this](const QString &message, bool error) { showStatus(message, error); });
}

bool MainWindow::maybeSave()
{
    if (!m_session->isModified())
        return true;
    const auto answer = m_question(tr("Unsaved Changes"),
                                   tr("The design “%1” has changes that are not saved. Save them?")
                                       .arg(m_session->displayName()),
                                   QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveFile();
    return answer == QMessageBox::Discard;
}

void MainWindow::offerRecovery()
{
    for (const DesignSession::Recovery &recovery : DesignSession::pendingRecoveries()) {
        const QString name = recovery.originalPath.isEmpty() ? recovery.title : recovery.originalPath;
        const auto answer =
            m_question(tr("Recover Design"),
                       tr("PKM Studio closed unexpectedly while “%1” had unsaved changes (autosaved %2). "
                          "Recover them?")
                           .arg(name, QLocale().toString(recovery.saved, QLocale::ShortFormat)),
                       QMessageBox::Yes | QMessageBox::No);
        if (answer != QMessageBox::Yes) {
            DesignSession::discardRecovery(recovery);
            continue;
        }
        auto recovered = m_session->recover(recovery);
        if (!recovered) {
            showStatus(failureText(recovered.failure()), true);
            continue;
        }
        m_view->fitToView();
        showStatus(tr("Recovered “%1”: save it to keep the changes.").arg(name));
        return; // one document at a time; older autosaves stay for the next start
    }
}

void MainWindow::updateTitle()
{
    // "[*]" is where Qt shows the unsaved-changes mark.
    setWindowTitle(tr("%1[*] — PKM Studio").arg(m_session->displayName()));
    setWindowModified(m_session->isModified());
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = m_session->recentFiles();
    for (const QString &path : files) {
        QAction *action = m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (!QFileInfo::exists(path)) {
                showStatus(tr("%1 no longer exists; removed from the recent files.").arg(path), true);
                m_session->removeRecentFile(path);
                return;
            }
            openFromMenu(path);
        });
        action->setToolTip(path);
        action->setData(path);
    }
    m_recentMenu->setToolTipsVisible(true);
    m_recentMenu->setEnabled(!files.isEmpty());
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
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("layout/version"), settingsVersion);
    settings.setValue(QStringLiteral("layout/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("layout/state"), saveState(settingsVersion));
    settings.setValue(QStringLiteral("layout/splitter"), m_splitter->saveState());
    event->accept();
}

void MainWindow::exportDrawing()
{
    // The linkage drawing of the current design and pose, the same file as `pkm dxf`.
    QString path = QFileDialog::getSaveFileName(this, tr("Export Drawing (DXF)"), QString(),
                                                tr("DXF drawings (*.dxf);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".dxf");
    const Design &design = m_document->design();
    const QString title = design.title.isEmpty() ? toQString(m_document->mechanism()->kind()) : design.title;
    dxf::DrawingOptions options;
    options.caption = (title + QStringLiteral(" — ") + m_poseLabel->text().simplified()).toStdString();
    const dxf::Drawing drawing = dxf::sceneDrawing(m_document->mechanism()->scene(m_document->pose()), options);
    QSaveFile file(path); // the file is replaced only once it is complete
    const auto size = static_cast<qint64>(drawing.dxf.size());
    if (!file.open(QIODevice::WriteOnly) || file.write(drawing.dxf.data(), size) != size || !file.commit()) {
        const QString message = tr("Cannot write the drawing to %1: %2.").arg(QDir::toNativeSeparators(path), file.errorString());
        showStatus(message, true);
        QMessageBox::warning(this, tr("Export Drawing (DXF)"), message);
        return;
    }
    showStatus(tr("Wrote the drawing to %1 (DXF R12, mm).").arg(QDir::toNativeSeparators(path)));
}

void MainWindow::exportParameterSheet()
{
    // The parameter sheet of the current design and pose, the same file as `pkm sheet`.
    QString filter;
    QString path = QFileDialog::getSaveFileName(this, tr("Export Parameter Sheet"), QString(),
        tr("PDF parameter sheets (*.pdf);;JSON (*.json);;CSV (*.csv)"), &filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += filter.contains(QLatin1String("*.json")) ? QStringLiteral(".json")
            : filter.contains(QLatin1String("*.csv"))    ? QStringLiteral(".csv")
                                                         : QStringLiteral(".pdf");
    const Design &design = m_document->design();
    sheet::Source source;
    source.design = !design.id.isEmpty() ? design.id.toStdString()
        : !m_session->filePath().isEmpty() ? QFileInfo(m_session->filePath()).fileName().toStdString()
                                           : design.title.toStdString();
    source.title = design.title;
    source.description = design.description;
    // A planar workspace and its maps take a second or two: off the GUI thread.
    runInBackground(
        this, tr("Export Parameter Sheet"), tr("Computing the parameter sheet…"),
        [mechanism = m_document->mechanism(), pose = m_document->pose(), source,
         path](const std::atomic<bool> &) -> TaskFailure {
            const sheet::Sheet built = kinds::buildSheet(*mechanism, pose, source);
            if (const std::optional<std::string> failure = sheet::save(built, path.toStdString()))
                return QString::fromStdString(*failure);
            return std::nullopt;
        },
        [this, path](const TaskFailure &failure, bool) {
            if (failure) {
                showStatus(*failure, true);
                QMessageBox::warning(this, tr("Export Parameter Sheet"), *failure);
                return;
            }
            showStatus(tr("Wrote the parameter sheet to %1.").arg(QDir::toNativeSeparators(path)));
        });
}

void MainWindow::saveViewPicture()
{
    // The 2D picture of the current design and pose, the same drawing as `pkm render`.
    const QString path = viewpicture::savePictureAs(this, *m_document->mechanism(), m_document->pose(),
        m_session->displayName(), viewpicture::suggestedName(m_session->filePath(), m_document->design().id),
        m_view->size(), m_view->sceneStyle());
    if (!path.isEmpty())
        showStatus(tr("Wrote the 2D view to %1.").arg(QDir::toNativeSeparators(path)));
}

} // namespace pkm
