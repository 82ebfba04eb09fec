// The main window (docs/architecture.md, the layers): its construction — the views, docks,
// actions, menus and the document's signals — and its languages; the design's changes are
// followed in mainwindowdesign.cpp, the files and exports in mainwindowfiles.cpp.

#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "gui/animationdialog.h"
#include "gui/backgroundtask.h"
#include "designpanel.h"
#include "equationspanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "document/language.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "pagestack.h"
#include "pictureexport.h"
#include "quantityformat.h"
#include "export/sheet.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "gui/tolerancepanel.h"
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
    m_view->setMinimumSize(300, 220); // small enough for 1024×768 beside the docks and a plot
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
    m_plots = new PageStack(this); // as large as the page in sight, not the largest
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
    m_poseLabel->setTextFormat(Qt::RichText); // for the lowered symbols (onPoseChanged)
    m_singularityLabel = new QLabel(this);
    // The read-outs step aside for a message that needs the room (fitStatusMessage()) and
    // never set the window's least width: in presentation mode the O-X glide's five values
    // at 150 % asked for 885 px, and with a message beside them more than the projector has.
    for (QLabel *readOut : {m_poseLabel, m_singularityLabel})
        readOut->setMinimumWidth(1);
    statusBar()->addPermanentWidget(m_poseLabel);
    statusBar()->addPermanentWidget(m_singularityLabel);
    watchStatusBar();

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
    connect(m_view, &LinkageView::dragStarted, m_document, &Document::beginDrag); // one undo step per drag
    connect(m_view, &LinkageView::handleDragged, this, [this](int handle, const Eigen::Vector2d &target) {
        auto solved = m_document->dragHandle(handle, target);
        if (!solved)
            showStatus(failureText(solved.failure()), true);
    });
    connect(m_modeBar, &ModeBar::switchRequested, this, &MainWindow::switchMode);
    connect(m_modeBar, &ModeBar::hovered, m_view, &LinkageView::highlightGhost);
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
    updateWhatsThis();
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
    disconnect(m_modeBar, nullptr, m_view, nullptr);
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
    scroll->setMinimumWidth(270);
    auto *designDock = m_designDock = new QDockWidget(tr("Design"), this);
    designDock->setObjectName(QStringLiteral("designDock"));
    designDock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, designDock);

    m_values = new ValuesTable(this);
    m_values->setMinimumWidth(270);
    auto *valuesBox = new QWidget(this); // the table, and below it a meaning its column cuts
    auto *valuesLayout = new QVBoxLayout(valuesBox);
    valuesLayout->setContentsMargins(0, 0, 0, 0);
    valuesLayout->setSpacing(0);
    valuesLayout->addWidget(m_values, 1);
    valuesLayout->addWidget(m_values->meaningStrip());
    auto *valuesDock = m_valuesDock = new QDockWidget(tr("Values"), this);
    valuesDock->setObjectName(QStringLiteral("valuesDock"));
    valuesDock->setWidget(valuesBox);
    addDockWidget(Qt::LeftDockWidgetArea, valuesDock);
    splitDockWidget(designDock, valuesDock, Qt::Vertical);
    // Mobility, the equations and the tolerances are tabs behind the Design and the values,
    // so they take no room until asked for; split between the two groups, their names fit the
    // 340 px the docks have on a 1280×720 projector in every language (four in one were cut).
    m_mobility = new MobilityPanel(this);
    m_mobility->setMinimumWidth(270);
    auto *mobilityDock = m_mobilityDock = new QDockWidget(tr("Mobility"), this);
    mobilityDock->setObjectName(QStringLiteral("mobilityDock"));
    mobilityDock->setWidget(m_mobility);
    addDockWidget(Qt::LeftDockWidgetArea, mobilityDock);
    tabifyDockWidget(designDock, mobilityDock);
    // The equations: the same numbers as the values, in formulas.
    m_equations = new EquationsPanel(this);
    m_equations->setMinimumWidth(270);
    auto *equationsDock = m_equationsDock = new QDockWidget(tr("Equations"), this);
    equationsDock->setObjectName(QStringLiteral("equationsDock"));
    equationsDock->setWidget(m_equations);
    addDockWidget(Qt::LeftDockWidgetArea, equationsDock);
    tabifyDockWidget(valuesDock, equationsDock);
    auto *toleranceDock = m_toleranceDock = new QDockWidget(tr("Tolerances"), this);
    toleranceDock->setObjectName(QStringLiteral("toleranceDock"));
    toleranceDock->setWidget(new TolerancePanel(m_document, toleranceDock));
    addDockWidget(Qt::LeftDockWidgetArea, toleranceDock);
    tabifyDockWidget(equationsDock, toleranceDock);
    // The Design and the values in front; a tab raised before the window is shown does not
    // stick. A restored layout keeps the tabs it had.
    QTimer::singleShot(0, this, [this, designDock, valuesDock] {
        if (m_restoredGeometry)
            return;
        designDock->raise();
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
    // New from Template: each kind module's designs to start from, opened as new, unsaved designs
    QMenu *templates = file->addMenu(QString());
    translated(templates->menuAction(), QT_TR_NOOP("New from &Template"));
    templates->setObjectName(QStringLiteral("templateMenu"));
    for (const KindModule &module : kinds::modules()) {
        for (const DesignTemplate &start : module.templates) {
            const QString id = QString::fromUtf8(start.preset);
            QAction *action = translated(templates->addAction(QString(), this, [this, id] {
                if (!maybeSave())
                    return;
                if (auto opened = m_session->openTemplate(id); !opened)
                    showStatus(failureText(opened.failure()), true);
                else
                    m_view->fitToView();
            }), start.title);
            action->setObjectName(QStringLiteral("template_") + id);
        }
    }
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
    translated(file->addAction(QString(), this, &MainWindow::exportAnimationDialog), QT_TR_NOOP("Export &Animation (GIF, MP4, WebM)…"))
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
    createRequirementsAction(m_editMenu);

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

    createPlayControls(view);
    createPresentationActions(view);
    createCapabilityActions(view);

    QMenu *help = menuBar()->addMenu(QString());
    translated(help->menuAction(), QT_TR_NOOP("&Help"));
    createHelpActions(help);
    translated(help->addAction(QString(), this, &MainWindow::sourceDocuments), QT_TR_NOOP("&Source Documents…"))
        ->setObjectName(QStringLiteral("sourceDocumentsAction"));
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
    m_toolBar->addSeparator();
    // the toolbar's own short label; the menu names the shapes in full
    QAction *shapesButton = translated(new QAction(this), QT_TR_NOOP("Ellipses"),
        QT_TR_NOOP("Velocity and force polygons and ellipses at the platform point (V)"));
    shapesButton->setObjectName(QStringLiteral("capabilityShapesButton"));
    shapesButton->setCheckable(true);
    shapesButton->setChecked(m_capabilityAction->isChecked());
    connect(shapesButton, &QAction::toggled, m_capabilityAction, &QAction::setChecked);
    connect(m_capabilityAction, &QAction::toggled, shapesButton, &QAction::setChecked);
    m_toolBar->addAction(shapesButton);
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
    // first in the menu, also when a new language makes them again after the others
    m_editMenu->insertActions(m_editMenu->actions().value(0, nullptr), {m_undoAction, m_redoAction});
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
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        fillPresentationPlotMenu(false); // the plots' titles are listed again as it opens
    }
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
    m_valuesDock->setWindowTitle(tr("Values"));
    m_mobilityDock->setWindowTitle(tr("Mobility"));
    m_equationsDock->setWindowTitle(tr("Equations"));
    m_toleranceDock->setWindowTitle(tr("Tolerances"));
    m_viewTabs->setTabText(0, tr("2D"));
    m_viewTabs->setTabText(1, tr("3D"));
    m_viewTabs->setTabToolTip(1, tr("The mechanism in 3D: drag to turn it, right-drag to pan, wheel to zoom"));
    // What the main window shows of the design and the pose: the preset's title and note, the
    // pose in the status bar (numbers by the new locale), the modes, the limit note, the labels
    // of the drawing. A status message of the old language goes.
    const Design &design = m_document->design();
    m_designPanel->setNote(designfile::presetText(design.title), designfile::presetText(design.description));
    updateTitle();
    updateWhatsThis();
    onPoseChanged();
    if (!m_statusIsError)
        statusBar()->clearMessage();
}

} // namespace pkm
