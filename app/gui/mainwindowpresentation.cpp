// The main window in front of a class: View ▸ Text Size (100 % to 250 %, remembered) and
// View ▸ Presentation Mode — full screen, high contrast, the panels reduced to the linkage, its
// plot or map, large sliders and the Play bar, at a text size of its own — and View ▸
// Presentation Plot, which of a page's plots presentation mode shows alone.

#include "gui/mainwindow.h"

#include "kinds/kindpanel.h"
#include "linkageview.h"
#include "playbar.h"
#include "plotfocus.h"

#include <qcustomplot.h>
#include "textscale.h"
#include "variablepanel.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QSettings>
#include <QScreen>
#include <QShortcut>
#include <QSlider>
#include <QSplitter>
#include <QStackedWidget>
#include <QTimer>
#include <QToolBar>

#include <cmath>

namespace pkm {

namespace {
constexpr int textSizes[] = {100, 125, 150, 175, 200, 250};
/// From this text size on, a page shows one plot at a time (applyPresentationPlots).
constexpr double onePlotTextScale = 1.75;
/// Settings keys: the normal window's text size and presentation mode's.
QString textSizeKey(bool presentation)
{
    return presentation ? QStringLiteral("presentation/textSize") : QStringLiteral("view/textSize");
}
/// Presentation mode starts at 150 %: read from the back of a classroom at 1280×720.
constexpr int defaultPresentationSize = 150;
QString presentationSliderStyle()
{
    return QStringLiteral(
        "QSlider::groove:horizontal { height: 10px; background: #c8c8c8; border-radius: 5px; }"
        "QSlider::handle:horizontal { width: 30px; margin: -10px 0; background: #1f5fbf; border-radius: 8px; }");
}
} // namespace

void MainWindow::createPresentationActions(QMenu *viewMenu)
{
    m_baseFont = QApplication::font();
    m_baseStyle = m_view->sceneStyle();
    viewMenu->addSeparator();
    m_presentationAction = translated(new QAction(this), QT_TR_NOOP("&Presentation Mode"),
                                      QT_TR_NOOP("Full screen, large text, high contrast: the linkage, its plot and the sliders (F5; Esc leaves)"));
    m_presentationAction->setObjectName(QStringLiteral("presentationAction"));
    m_presentationAction->setCheckable(true);
    m_presentationAction->setShortcut(QKeySequence(Qt::Key_F5));
    connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);
    viewMenu->addAction(m_presentationAction);
    // Esc leaves presentation mode, and only then is it taken from the fields and dialogs.
    m_leavePresentation = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    m_leavePresentation->setEnabled(false);
    connect(m_leavePresentation, &QShortcut::activated, this, [this] { setPresentationMode(false); });

    m_textSizeMenu = viewMenu->addMenu(QString());
    m_textSizeMenu->setObjectName(QStringLiteral("textSizeMenu"));
    translated(m_textSizeMenu->menuAction(), QT_TR_NOOP("&Text Size"));
    auto *sizes = new QActionGroup(this);
    for (int percent : textSizes) {
        QAction *action = m_textSizeMenu->addAction(QStringLiteral("%1 %").arg(percent));
        action->setObjectName(QStringLiteral("textSize_%1").arg(percent));
        action->setCheckable(true);
        action->setData(percent);
        sizes->addAction(action);
        connect(action, &QAction::triggered, this, [this, percent] {
            QSettings().setValue(textSizeKey(m_presenting), percent);
            setTextScale(percent / 100.0);
        });
    }
    const int remembered = QSettings().value(textSizeKey(false), 100).toInt();
    setTextScale(remembered / 100.0);

    m_presentationPlotMenu = viewMenu->addMenu(QString());
    m_presentationPlotMenu->setObjectName(QStringLiteral("presentationPlotMenu"));
    translated(m_presentationPlotMenu->menuAction(), QT_TR_NOOP("Presentation P&lot"));
    // Filled as it opens: the plots and their titles follow the design and the language.
    connect(m_presentationPlotMenu, &QMenu::aboutToShow, this, [this] { fillPresentationPlotMenu(true); });
    fillPresentationPlotMenu(false);
}

void MainWindow::fillPresentationPlotMenu(bool entries)
{
    m_presentationPlotMenu->clear();
    const QList<QCustomPlot *> plots = m_currentPanel ? plotfocus::plots(m_currentPanel) : QList<QCustomPlot *>();
    // Only where a page holds more than one plot is there a choice to make.
    m_presentationPlotMenu->menuAction()->setEnabled(plots.size() > 1);
    if (!entries || plots.size() < 2)
        return; // the titles as the menu opens, in the language of that moment
    QCustomPlot *shown = m_presenting || textscale::factor() >= onePlotTextScale ? plotfocus::shownAlone(m_currentPanel)
                                                                                 : m_presentationPlot.data();
    auto *group = new QActionGroup(m_presentationPlotMenu);
    for (int i = 0; i < plots.size(); ++i) {
        QCustomPlot *plot = plots[i];
        QAction *action = m_presentationPlotMenu->addAction(plotfocus::title(plot));
        action->setObjectName(QStringLiteral("presentationPlot_%1").arg(i));
        action->setCheckable(true);
        action->setChecked(plot == shown);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, plot = QPointer<QCustomPlot>(plot)] {
            m_presentationPlot = plot;
            applyPresentationPlots();
        });
    }
}

void MainWindow::applyPresentationPlots()
{
    // From 175 % text, plots that share a page squeeze their axes to nothing (three side by
    // side at 250 % on a 1280×720 screen): one plot a page then, as in presentation mode, and
    // View ▸ Presentation Plot chooses which.
    const bool alone = m_presenting || textscale::factor() >= onePlotTextScale;
    for (int i = 0; i < m_plots->count(); ++i) {
        QWidget *panel = m_plots->widget(i);
        if (auto *kindPanel = qobject_cast<KindPanel *>(panel))
            kindPanel->setPresenting(m_presenting && panel == m_currentPanel);
        if (alone && panel == m_currentPanel)
            plotfocus::showOnePerPage(panel, m_presentationPlot);
        else
            plotfocus::showAll(panel);
    }
    // Chosen outside presentation mode: its tab comes to the front now, and it is alone later.
    if (!m_presenting && m_presentationPlot && m_currentPanel && m_currentPanel->isAncestorOf(m_presentationPlot))
        plotfocus::bringToFront(m_presentationPlot);
    fillPresentationPlotMenu(false);
}

void MainWindow::setTextScale(double factor)
{
    const double old = textscale::factor();
    const double now = textscale::setFactor(factor);
    // What has a font of its own is scaled; what inherits follows the application's font.
    textscale::rescale(this, now / old);
    QFont font = m_baseFont;
    font.setPointSizeF(m_baseFont.pointSizeF() * now);
    QApplication::setFont(font);
    applySceneStyle();
    for (QAction *action : m_textSizeMenu->actions())
        action->setChecked(action->data().toInt() == qRound(now * 100));
    if (m_presentationPlotMenu && (old >= onePlotTextScale) != (now >= onePlotTextScale))
        applyPresentationPlots(); // (not yet while the menus are made: the first design does it)
}

void MainWindow::applySceneStyle()
{
    // Lines grow more slowly than text: at 250 % the bars would otherwise hide the joints.
    const double text = textscale::factor();
    const double line = 1.0 + 0.5 * (text - 1.0);
    SceneStyle style = m_baseStyle;
    style.fontPixels *= text;
    style.jointFontPixels *= text;
    style.groundWidth *= line;
    style.barWidth *= line;
    style.pivotRadius *= line;
    style.arrowLength *= line;
    style.arrowWidth *= line;
    if (m_presenting) {
        // High contrast for a washed-out projector: white ground, black ink, no faint grid.
        style.background = Qt::white;
        style.ink = Qt::black;
        style.dimension = Qt::black;
        style.gridMinor = QColor(0xf4, 0xf4, 0xf4);
        style.gridMajor = QColor(0xc8, 0xc8, 0xc8);
        style.ghostOpacity = 0.5;
    }
    m_view->setSceneStyle(style);
}

void MainWindow::styleSliders()
{
    for (QSlider *slider : m_variables->findChildren<QSlider *>())
        slider->setStyleSheet(m_presenting ? presentationSliderStyle() : QString());
}

void MainWindow::setPresentationMode(bool on)
{
    if (on == m_presenting) {
        m_presentationAction->setChecked(on);
        return;
    }
    m_presenting = on;
    m_presentationAction->setChecked(on);
    m_leavePresentation->setEnabled(on);
    if (on) {
        m_stateBeforePresentation = saveState();
        m_splitterBeforePresentation = m_splitter->saveState();
        m_maximizedBeforePresentation = isMaximized();
        m_geometryBeforePresentation = geometry();
        m_docksBeforePresentation.clear();
        for (QDockWidget *dock : findChildren<QDockWidget *>()) {
            if (dock->isVisible())
                m_docksBeforePresentation.append({dock, dock->size()});
            dock->hide();
        }
        m_toolBar->hide();
        m_playToolBar->show();
        QPalette palette = QApplication::palette();
        palette.setColor(QPalette::WindowText, Qt::black);
        palette.setColor(QPalette::Text, Qt::black);
        palette.setColor(QPalette::ButtonText, Qt::black);
        palette.setColor(QPalette::Base, Qt::white);
        palette.setColor(QPalette::Window, Qt::white);
        setPalette(palette);
        setTextScale(QSettings().value(textSizeKey(true), defaultPresentationSize).toInt() / 100.0);
        // Large sliders: a handle a hand finds on a touch screen or with a wireless mouse. Set
        // on the sliders themselves, after the text size: a style sheet on the panel would stop
        // the application's new font from reaching its labels.
        styleSliders();
        m_variables->setCompact(true);
        m_playBar->setCompact(true);
        showFullScreen();
        // The linkage is what the class looks at: three fifths, beside its plot or map (whose
        // title and legend take their height whatever its width).
        const int width = screen() ? screen()->geometry().width() : this->width();
        m_splitter->setSizes({width * 3 / 5, width * 2 / 5});
        applyPresentationPlots();
        showStatus(tr("Presentation mode: Esc or F5 leaves it; Page Up and Page Down step through the bookmarks."));
    } else {
        setPalette(QPalette());
        styleSliders();
        m_variables->setCompact(false);
        m_playBar->setCompact(false);
        setTextScale(QSettings().value(textSizeKey(false), 100).toInt() / 100.0);
        restoreState(m_stateBeforePresentation); // the docks and toolbars as they were
        m_splitter->restoreState(m_splitterBeforePresentation);
        applyPresentationPlots();
        if (m_maximizedBeforePresentation)
            showMaximized();
        else
            showNormal();
        showStatus(QString());
    }
    applySceneStyle();
    fitStatusMessage(); // the bar's height for the mode (two lines while presenting)
    // Once the window has its new size (full screen or back): the splitter shared out again
    // over the width the window really has (the screen's was a first guess), and the linkage
    // fills the view.
    QTimer::singleShot(100, this, [this] {
        if (m_presenting) {
            const int width = m_splitter->width();
            m_splitter->setSizes({width * 3 / 5, width * 2 / 5});
        } else {
            // and the window's own size: showNormal() or showMaximized() ran while the panels
            // still had the presentation's large text, and grew the window to what they asked
            // then (1552 px wide in Russian on a 1280×720 projector, the map off the screen,
            // where no window manager holds a maximised window to the screen)
            if (!m_maximizedBeforePresentation && m_geometryBeforePresentation.isValid()) {
                resize(m_geometryBeforePresentation.size());
                move(m_geometryBeforePresentation.topLeft());
            } else if (screen() && !screen()->availableGeometry().contains(frameGeometry())) {
                // a maximised window keeps its size: maximised again, now that the text is small
                showNormal();
                setGeometry(screen()->availableGeometry());
                showMaximized();
            }
            // the docks' sizes again at the window's own size: restored while the window was
            // still full screen, they were shared out anew as it shrank
            restoreState(m_stateBeforePresentation);
            m_splitter->restoreState(m_splitterBeforePresentation);
            // and each dock at the size it had: restored, the Russian five-bar's left docks came
            // back 50 px narrower, their titles and the values' columns cut
            QList<QDockWidget *> docks;
            QList<int> widths, heights;
            for (const auto &[dock, size] : std::as_const(m_docksBeforePresentation)) {
                if (dock && dock->isVisible() && !dock->isFloating()) {
                    docks << dock;
                    widths << size.width();
                    heights << size.height();
                }
            }
            resizeDocks(docks, widths, Qt::Horizontal);
            resizeDocks(docks, heights, Qt::Vertical);
        }
        m_view->fitToView();
        fitStatusMessage(); // the read-outs' width at the new text size
    });
}

} // namespace pkm
