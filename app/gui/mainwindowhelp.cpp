// The main window's help (issue 18): Help ▸ User Guide (F1) and What's This (Shift+F1) with a
// text on every panel, and a status bar whose message is never cut by the pose read-out.

#include "gui/mainwindow.h"

#include "designpanel.h"
#include "document/document.h"
#include "equationspanel.h"
#include "gui/guidewindow.h"
#include "kinds/kindpanel.h"
#include "kinds/sweepplotspanel.h"
#include "kinds/workspacepanel.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "playbar.h"
#include "quantityformat.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "workspacemapview.h"

#include <QAction>
#include <QEvent>
#include <QLabel>
#include <QLayout>
#include <QMenu>
#include <QSizeGrip>
#include <QStatusBar>
#include <QTextDocument>
#include <QWhatsThis>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {

/// Calls `react` whenever the watched widget changes size or font.
class ResizeWatcher : public QObject
{
public:
    ResizeWatcher(QObject *parent, std::function<void()> react)
        : QObject(parent)
        , m_react(std::move(react))
    {
    }
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        // a new text size reaches the bar after the message was fitted with the old one
        if (event->type() == QEvent::Resize || event->type() == QEvent::FontChange)
            m_react();
        return QObject::eventFilter(watched, event);
    }

private:
    std::function<void()> m_react;
};

/// The room QStatusBar leaves around its items: its margins and the layout's spacing.
constexpr int statusMessageMargins = 6 + 12 + 2;
/// A message longer than this many lines of the bar is cut with an ellipsis; the tooltip
/// keeps the whole of it.
constexpr int statusMessageLines = 3;
/// Where the message starts, from the bar's left edge.
constexpr int statusTextIndent = 4;

} // namespace

void MainWindow::createHelpActions(QMenu *help)
{
    QAction *guide = translated(help->addAction(QString(), this, &MainWindow::showGuide), QT_TR_NOOP("&User Guide"));
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents); // F1
    // QWhatsThis's own action (Shift+F1): the pointer turns into a question mark, and a click on a
    // panel shows what it is for.
    QAction *whatsThis = translated(QWhatsThis::createAction(this), QT_TR_NOOP("What's &This?"));
    whatsThis->setObjectName(QStringLiteral("whatsThisAction"));
    whatsThis->setShortcut(QKeySequence::WhatsThis);
    addAction(whatsThis); // Shift+F1 wherever the focus is
    help->addAction(whatsThis);
    help->addSeparator();
}

void MainWindow::showGuide()
{
    if (!m_guide)
        m_guide = new GuideWindow(this);
    m_guide->followLanguage(); // the language may have changed since it was last shown
    m_guide->show();
    m_guide->raise();
    m_guide->activateWindow();
}

GuideWindow *MainWindow::guideWindow() const
{
    return m_guide;
}

void MainWindow::updateWhatsThis()
{
    const QString plots = tr("The plots of this mechanism over the range of its input; the cursor marks the current pose. "
                             "A right click saves a plot as a picture.");
    const QString map = tr("The workspace map: where the platform can go, coloured by the quantity chosen above it, with "
                           "the singular curves. Click a point to move the platform there; the marker shows the current pose.");
    // the plots' panels first, so that the maps inside them get the map's text
    m_workspacePanel->setWhatsThis(map);
    m_sweepPanel->setWhatsThis(plots);
    for (const auto &[kind, panel] : m_kindPanels)
        panel->setWhatsThis(plots);
    for (WorkspaceMapView *view : findChildren<WorkspaceMapView *>())
        view->setWhatsThis(map);

    m_view->setWhatsThis(tr("The linkage at its current pose. Drag a round handle to move a joint or the platform; the "
                            "wheel zooms, the right button pans and F fits the mechanism. Faint ghosts are the other "
                            "assembly modes: click one to switch to it. Limits and singular poses are told at the bottom."));
    m_variables->setWhatsThis(tr("The joint variables: each slider and its number set one variable of the mechanism, and the "
                                 "pose follows at once. A value the mechanism cannot reach is refused with a message."));
    m_playBar->setWhatsThis(tr("Play moves the chosen joint variable by itself over the range set here, at this speed, in a "
                               "loop, forth and back or once. It stops at a limit or before a singular pose and says why."));
    m_designPanel->setWhatsThis(tr("The design: every dimension and mode of the mechanism. Change a value and the linkage, the "
                                   "values, the plots and the maps follow; every change can be undone (Ctrl+Z)."));
    m_values->setWhatsThis(tr("The values at this pose: joint variables, the Jacobian, its determinant and condition number "
                              "and what the actuators deliver, each with its unit and meaning. At a singular pose a value "
                              "that is infinite reads ∞ and one that is undefined reads —."));
    m_mobility->setWhatsThis(tr("The mobility of the mechanism: its degrees of freedom counted by the structural formulas "
                                "and by the rank of its loop equations at this pose, and where the formulas are wrong."));
    m_equations->setWhatsThis(tr("The governing equations of this mechanism with the source document's equation numbers, each "
                                 "followed by the same equation with the current numbers put in; they follow the pose."));
    m_view3d->setWhatsThis(tr("The mechanism in 3D at the current pose: drag to turn it, right-drag to pan, the wheel "
                              "zooms and a double-click fits it. The sliders drive it as they drive the 2D view."));
    m_modeBar->setWhatsThis(tr("The assembly and working modes: the mode of the current pose, and a button for each other "
                               "mode the mechanism can take here, which switches to it."));
}

void MainWindow::watchStatusBar()
{
    // QStatusBar draws a message on one line, cut at the bar's edge. The message is shown by a
    // word-wrapped label instead, the first permanent widget, which also leaves the bar's own
    // drawing no room (it ends 2 px before the first permanent widget shown). The bar's
    // message stays the one state: the label only follows it.
    m_statusText = new QLabel(this);
    m_statusText->setObjectName(QStringLiteral("statusText"));
    m_statusText->setWordWrap(true);
    // rich text only to lower the mechanism's symbols (symbolHtmlKnown); the rest is escaped
    m_statusText->setTextFormat(Qt::RichText);
    m_statusText->setContentsMargins(statusTextIndent, 0, 0, 0);
    // its size is set from the message (fitStatusMessage): a word-wrapped label's own minimum
    // is its text at the narrowest width, as tall as the screen
    m_statusText->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    statusBar()->insertPermanentWidget(0, m_statusText, 1);
    connect(statusBar(), &QStatusBar::messageChanged, this, &MainWindow::fitStatusMessage);
    statusBar()->installEventFilter(new ResizeWatcher(this, [this] { fitStatusMessage(); }));
}

void MainWindow::fitStatusMessage()
{
    // A message is worth more than the pose read-out beside it (the sliders show the pose too):
    // when both do not fit, the read-out steps aside while the message is shown. A message
    // wider than the whole bar wraps onto up to three lines, and the bar grows while it shows.
    if (!m_poseLabel || !m_statusText)
        return; // a message before the read-outs exist
    QStatusBar *bar = statusBar();
    const QString message = bar->currentMessage();
    bar->setToolTip(message);
    QFont font = bar->font();
    font.setBold(m_statusIsError && !message.isEmpty()); // errors are bold (showStatus)
    const QFontMetrics metrics(font);
    // Presenting, the large sliders show the pose: the read-outs would only crowd the bar.
    bool readOuts = !m_presenting;
    if (readOuts && !message.isEmpty()) {
        const int needed = metrics.horizontalAdvance(message) + statusMessageMargins;
        int beside = 0;
        for (QLabel *label : {m_poseLabel, m_singularityLabel}) {
            if (!label->text().isEmpty())
                beside += label->sizeHint().width() + 2 * bar->layout()->spacing() + 8;
        }
        readOuts = needed + beside <= bar->width();
    }
    m_poseLabel->setVisible(readOuts);
    m_singularityLabel->setVisible(readOuts);

    // The size grip (a window that is neither maximized nor full screen) takes its part too.
    const QSizeGrip *grip = bar->findChild<QSizeGrip *>();
    const int gripWidth = grip && grip->isVisible() ? grip->width() + bar->layout()->spacing() : 0;
    const int room = std::max(1, bar->width() - statusMessageMargins - statusTextIndent - gripWidth);
    const int maxHeight = statusMessageLines * metrics.lineSpacing();
    QString shown = message;
    const QStringList symbols = shownSymbols();
    QTextDocument document; // measured as the label lays it out: subscripts may widen a line
    document.setDefaultFont(font);
    document.setDocumentMargin(0);
    document.setTextWidth(room);
    const auto height = [&](const QString &text) {
        document.setHtml(symbolHtmlKnown(text, symbols));
        return int(std::ceil(document.size().height()));
    };
    if (height(shown) > maxHeight) {
        // cut to three lines' worth and step back until the wrapped text fits (word breaks
        // waste part of each line); each step is a tenth of a line, so this ends quickly
        int width = statusMessageLines * room;
        do {
            width -= std::max(1, room / 10);
            shown = metrics.elidedText(message, Qt::ElideRight, width);
        } while (width > room && height(shown) > maxHeight);
    }
    m_statusText->setText(symbolHtmlKnown(shown, symbols));
    // While presenting, the bar keeps two lines' height whatever the message: a bar that grew
    // for a long message moved the sliders and the Play bar under the teacher's pointer.
    const int least = (m_presenting ? 2 : 1) * metrics.lineSpacing();
    m_statusText->setFixedHeight(std::max(least, message.isEmpty() ? 0 : height(shown)));
}

QStringList MainWindow::shownSymbols() const
{
    const Mechanism &mechanism = *m_document->mechanism();
    QStringList symbols;
    for (const VariableInfo &info : mechanism.variableInfo())
        symbols << toQString(info.symbol);
    for (const ParameterInfo &info : mechanism.parameterInfo())
        symbols << toQString(info.symbol);
    for (const ReportEntry &entry : mechanism.reportLayout().entries)
        symbols << toQString(entry.symbol);
    return symbols;
}

} // namespace pkm
