// The main window projected in a classroom: it fits 1024×768 and 1280×720 with no text cut off
// in any of the four languages, presentation mode shows the linkage, its plot and large text
// and gives the working layout back, and the text size reaches labels, plots and the drawing.
#include "gui/mainwindow.h"

#include "document/document.h"
#include "document/language.h"
#include "kinds/kindpanel.h"
#include "linkageview.h"
#include "playbar.h"
#include "scenelayout.h"
#include "scenepainter.h"
#include "plotfocus.h"
#include "textscale.h"
#include "variablepanel.h"
#include "modebar.h"
#include "support/app.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QAbstractSpinBox>
#include <QMenu>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QScreen>
#include <QSettings>

#include <memory>
#include <QStatusBar>
#include <QTabBar>
#include <QScrollArea>
#include <QTest>
#include <QTextDocument>
#include <QToolBar>

using namespace pkm;
using namespace pkm::test;

namespace {

/// The width `label` needs for its text on one line (rich text measured as laid out).
int neededWidth(const QLabel *label)
{
    if (label->wordWrap())
        return 0;
    if (Qt::mightBeRichText(label->text()) || label->textFormat() == Qt::RichText) {
        QTextDocument document;
        document.setDefaultFont(label->font());
        document.setDocumentMargin(0);
        document.setHtml(label->text());
        return qCeil(document.idealWidth());
    }
    QString text = label->text();
    if (label->buddy()) // "&Map:" shows as "Map:", its mnemonic underlined
        text.replace(QRegularExpression(QStringLiteral("&(.)")), QStringLiteral("\\1"));
    int width = 0;
    for (const QString &line : text.split(QLatin1Char('\n')))
        width = std::max(width, label->fontMetrics().horizontalAdvance(line));
    return width;
}

/// Every visible label and button inside `root` whose text is wider than the room it has, as
/// "class 'text' needs N px, has M px".
QStringList clippedTexts(QWidget *root)
{
    QStringList clipped;
    const auto visible = [root](QWidget *widget) { return widget->isVisibleTo(root) && widget->width() > 0; };
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (!visible(label) || label->text().isEmpty() || !label->pixmap().isNull())
            continue;
        const int room = label->contentsRect().width() - 2 * label->margin() - label->indent() * 0;
        const int needed = neededWidth(label);
        if (needed > room + 1)
            clipped << QStringLiteral("QLabel '%1' needs %2 px, has %3 px").arg(label->text().left(60)).arg(needed).arg(room);
        // a wrapped text cut at the bottom: the 3-P̲RR's "(input, actuated)" when its mode
        // buttons took four rows under the sliders
        const int high = label->wordWrap() && label->height() > 0 ? label->heightForWidth(label->width()) : 0;
        if (high > label->height() + 1)
            clipped << QStringLiteral("QLabel '%1' needs %2 px high, has %3 px").arg(label->text().left(60)).arg(high).arg(label->height());
    }
    for (QAbstractButton *button : root->findChildren<QAbstractButton *>()) {
        if (!visible(button) || button->text().isEmpty())
            continue;
        const QSize hint = button->sizeHint();
        if (hint.width() > button->width() + 1)
            clipped << QStringLiteral("%1 '%2' needs %3 px, has %4 px")
                           .arg(QString::fromLatin1(button->metaObject()->className()), button->text().left(60))
                           .arg(hint.width())
                           .arg(button->width());
    }
    // Spin boxes: the number with its unit inside the field.
    for (QAbstractSpinBox *box : root->findChildren<QAbstractSpinBox *>()) {
        auto *edit = box->findChild<QLineEdit *>();
        if (!visible(box) || !edit)
            continue;
        const int needed = edit->fontMetrics().horizontalAdvance(edit->text());
        const int room = edit->width() - 4;
        if (needed > room)
            clipped << QStringLiteral("spin box '%1' needs %2 px, has %3 px").arg(edit->text()).arg(needed).arg(room);
    }
    // Tabs (the docks tabified with the values) elide a text that does not fit.
    for (QTabBar *bar : root->findChildren<QTabBar *>()) {
        if (!visible(bar))
            continue;
        for (int i = 0; i < bar->count(); ++i) {
            const int needed = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
            const int room = bar->tabRect(i).width() - bar->fontMetrics().averageCharWidth();
            if (needed > room)
                clipped << QStringLiteral("tab '%1' needs %2 px, has %3 px").arg(bar->tabText(i)).arg(needed).arg(room);
        }
    }
    // A panel that scrolls sideways hides the right end of every line behind the scroll
    // bar's view (the Russian MOMA note "(γ₁ = −5°," cut after "−5"): a label inside is whole,
    // but not in sight.
    for (QScrollArea *area : root->findChildren<QScrollArea *>()) {
        if (!visible(area) || !area->widget() || !area->widget()->isVisibleTo(root))
            continue;
        const int needed = area->widget()->width(), room = area->viewport()->width();
        if (needed > room + 1)
            clipped << QStringLiteral("scroll area of a %1 is %2 px wide in a %3 px view")
                           .arg(QLatin1String(area->widget()->metaObject()->className()))
                           .arg(needed)
                           .arg(room);
    }
    for (QComboBox *box : root->findChildren<QComboBox *>()) {
        if (!visible(box))
            continue;
        const int needed = box->fontMetrics().horizontalAdvance(box->currentText());
        // the text's room: the box less its frame and drop-down arrow, as the style draws them
        QStyleOptionComboBox option;
        option.initFrom(box);
        option.editable = box->isEditable();
        const int room = box->style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, box).width();
        if (needed > room + 1)
            clipped << QStringLiteral("QComboBox '%1' needs %2 px, has %3 px").arg(box->currentText().left(60)).arg(needed).arg(room);
    }
    return clipped;
}

} // namespace

class TestClassroom : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    /// Puts the window at 1280×720 in its normal mode, whatever an earlier test left (leaving
    /// presentation mode gives back the size the window had before, not this one).
    bool atProjectorSize()
    {
        m_window->setPresentationMode(false);
        m_window->showNormal();
        m_window->resize(1280, 720);
        const bool sized = QTest::qWaitFor([this] { return m_window->size() == QSize(1280, 720); }, 2000);
        QTest::qWait(50); // the splitters share out the width, the view fits anew
        QCoreApplication::processEvents();
        return sized;
    }

    /// No text cut in the window at `size`, in the current row's language and design.
    void nothingClippedAt(const QSize &size)
    {
        QFETCH(QString, language);
        QFETCH(QString, preset);
        QVERIFY(language::apply(language)); // English again in cleanupTestCase()
        QVERIFY(m_window->openDesign(preset));
        m_window->resize(size);
        QTest::qWait(50);
        QCoreApplication::processEvents();
        // the layouts settle in a few rounds of posted events (a Design panel that puts its
        // fields under the labels, then its scroll bar): on a busy machine after 50 ms
        QStringList clipped;
        QTRY_VERIFY2_WITH_TIMEOUT((clipped = clippedTexts(m_window)).isEmpty(), qPrintable(clipped.join(QStringLiteral("\n"))), 2000);
        // The window keeps the size asked for: nothing pushed it wider or taller.
        QCOMPARE(m_window->size(), size);
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow(QSize(1280, 720));
        QVERIFY(m_window);
    }
    void cleanupTestCase()
    {
        language::apply(QStringLiteral("en"));
        delete m_window;
    }

    void fitsSmallScreens_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("preset");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"}) {
            for (const PresetInfo &preset : everyPreset())
                QTest::addRow("%s %s", code, qPrintable(preset.id)) << QString::fromLatin1(code) << preset.id;
        }
    }

    /// 1024×768 with the docks, the linkage and the kind's panel side by side, in each language
    /// and after any other design (in Russian, MOMA's comparison row asked for 1247 px).
    void fitsSmallScreens()
    {
        QFETCH(QString, language);
        QFETCH(QString, preset);
        QVERIFY(language::apply(language));
        const auto english = qScopeGuard([] { language::apply(QStringLiteral("en")); });
        QVERIFY(m_window->openDesign(preset));
        QCoreApplication::processEvents();
        const QSize minimum = m_window->minimumSizeHint().expandedTo(m_window->minimumSize());
        if (qEnvironmentVariableIsSet("PKM_DEBUG_SIZES")) {
            for (QWidget *w : m_window->findChildren<QWidget *>()) {
                const QSize m = w->minimumSizeHint().expandedTo(w->minimumSize());
                if (w->isVisibleTo(m_window) && m.width() > 200)
                    qDebug() << w->metaObject()->className() << w->objectName() << m;
            }
        }
        QVERIFY2(minimum.width() <= 1024 && minimum.height() <= 720,
                 qPrintable(QStringLiteral("the window asks for at least %1×%2").arg(minimum.width()).arg(minimum.height())));
    }

    void nothingClippedAt1280x720_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("preset");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"}) {
            for (const char *preset : {"pjoint-prototype", "moma-3a", "oxglide-prototype", "fourbar-example", "fivebar-example",
                                       "pp-3rpr", "pp-3prr"}) {
                QTest::addRow("%s %s", code, preset) << QString::fromLatin1(code) << QString::fromLatin1(preset);
            }
        }
    }

    void nothingClippedAt1280x720() { nothingClippedAt(QSize(1280, 720)); }

    void nothingClippedAt1024x768_data() { nothingClippedAt1280x720_data(); }
    /// The other projector: the docks and the panels narrower, taller.
    void nothingClippedAt1024x768() { nothingClippedAt(QSize(1024, 768)); }

    void presentationModeAndBack()
    {
        language::apply(QStringLiteral("en"));
        MainWindow &w = *m_window;
        QVERIFY(w.openDesign(QStringLiteral("moma-3a")));
        auto *design = w.findChild<QDockWidget *>(QStringLiteral("designDock"));
        QVERIFY(design && design->isVisible());
        const double before = QApplication::font().pointSizeF();
        QAction *presentation = w.findChild<QAction *>(QStringLiteral("presentationAction"));
        QVERIFY(presentation);
        presentation->trigger();
        QVERIFY(w.isPresenting());
        QVERIFY(!design->isVisible());
        QVERIFY(w.findChild<QToolBar *>(QStringLiteral("playToolBar"))->isVisible());
        QVERIFY(w.linkageView()->isVisible());
        // 150 % until the teacher picks another size for presentations
        QCOMPARE_LT(std::abs(QApplication::font().pointSizeF() - 1.5 * before), 0.01);
        QCOMPARE(w.linkageView()->sceneStyle().ink, QColor(Qt::black));
        QTest::keyClick(&w, Qt::Key_Escape);
        QVERIFY(!w.isPresenting());
        QVERIFY(design->isVisible());
        QCOMPARE_LT(std::abs(QApplication::font().pointSizeF() - before), 0.01);
    }

    /// While presenting, a status message of two lines does not move the Play bar or the
    /// sliders: the bar keeps two lines' height from the start (a bar that grew for a long
    /// message moved the controls by a line under the teacher's pointer).
    void playBarStaysPutWhilePresenting()
    {
        language::apply(QStringLiteral("ru"));
        MainWindow &w = *m_window;
        QVERIFY(w.openDesign(QStringLiteral("fivebar-example")));
        w.findChild<QAction *>(QStringLiteral("presentationAction"))->trigger();
        QVERIFY(w.isPresenting());
        auto *play = w.findChild<QToolBar *>(QStringLiteral("playToolBar"));
        QVERIFY(play);
        w.statusBar()->showMessage(QStringLiteral("short"));
        QTest::qWait(100);
        const int before = play->mapTo(&w, QPoint(0, 0)).y();
        QString twoLines; // about one and a half bars wide, whatever the text size
        while (w.statusBar()->fontMetrics().horizontalAdvance(twoLines) < 1.4 * w.statusBar()->width())
            twoLines += QStringLiteral("a long message ");
        w.statusBar()->showMessage(twoLines);
        QTest::qWait(100);
        const int longer = play->mapTo(&w, QPoint(0, 0)).y();
        w.statusBar()->showMessage(QString());
        QTest::qWait(100);
        const int after = play->mapTo(&w, QPoint(0, 0)).y();
        QTest::keyClick(&w, Qt::Key_Escape);
        language::apply(QStringLiteral("en"));
        QCOMPARE(longer, before);
        QCOMPARE(after, before);
    }

    /// Presentation mode on a projector's 1280×720 screen and 150 % text, in all four
    /// languages: no label or button is cut, no wrapped label is shorter than its lines (the
    /// sliders' "q₁ (input, actuated)" lost its second line under a 3-DOF design's six rows),
    /// the rows are one line each, a 3-RP̲R's five other assembly modes fit one caption and
    /// five numbers, and every plot's title and legend lie inside the plot (the O-X glide's
    /// fig. 5 title and areas ran off both sides).
    void nothingClippedWhilePresenting_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("preset");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"}) {
            for (const char *preset : {"oxglide-prototype", "pp-3rpr", "moma-3a", "fivebar-example"})
                QTest::addRow("%s %s", code, preset) << QString::fromLatin1(code) << QString::fromLatin1(preset);
        }
    }
    void nothingClippedWhilePresenting()
    {
        QFETCH(QString, language);
        QFETCH(QString, preset);
        MainWindow &w = *m_window;
        QVERIFY(language::apply(language));
        w.setPresentationMode(false); // whatever an earlier row left
        QVERIFY(w.openDesign(preset));
        w.showNormal();
        w.resize(1000, 700);
        w.findChild<QAction *>(QStringLiteral("presentationAction"))->trigger();
        QVERIFY(w.isPresenting());
        const auto leave = qScopeGuard([&w] { // a failed row leaves the window as it found it
            w.setPresentationMode(false);
            language::apply(QStringLiteral("en"));
        });
        QTest::qWait(150); // the fonts and the wrapped texts laid out anew
        // the window fits the projector (the test's screen is 1280×720), as full screen gives it
        // (once settled: the row before's design and language are laid out again in turn)
        const auto least = [&w] { return w.minimumSizeHint().expandedTo(w.minimumSize()); };
        QTRY_VERIFY2(least().width() <= 1280 && least().height() <= 720,
                     qPrintable(QStringLiteral("presenting, the window asks for %1×%2").arg(least().width()).arg(least().height())));
        w.resize(1280, 720);
        QTRY_COMPARE(w.size(), QSize(1280, 720));
        QTest::qWait(150); // the splitter shared out for the width the window has
        QCoreApplication::processEvents();
        QStringList clipped = clippedTexts(&w);
        QVERIFY(w.variablePanel()->isCompact());
        for (QLabel *label : w.variablePanel()->findChildren<QLabel *>()) {
            if (label->text().contains(QLatin1String("<b>")) && label->height() > 2.2 * label->fontMetrics().height())
                clipped << QStringLiteral("slider label '%1' takes %2 px").arg(label->text()).arg(label->height());
        }
        for (QCustomPlot *plot : w.findChildren<QCustomPlot *>()) {
            if (!plot->isVisibleTo(&w) || plot->width() <= 0)
                continue;
            plot->replot(QCustomPlot::rpImmediateRefresh);
            const QRect room = plot->rect().adjusted(-1, -1, 1, 1);
            for (QCPLayoutElement *element : plot->plotLayout()->elements(true)) {
                if (auto *scale = qobject_cast<QCPColorScale *>(element)) {
                    // along the scale: each line within its length ("det J (цвета ограничены на"
                    // lost its "d" past the top)
                    const QFontMetrics metrics(scale->axis()->labelFont());
                    const int length = scale->axis()->axisRect()->height();
                    for (const QString &line : scale->label().split(QLatin1Char('\n'))) {
                        if (metrics.horizontalAdvance(line) > length)
                            clipped << QStringLiteral("colour scale label '%1' needs %2 px, has %3 px").arg(line)
                                           .arg(metrics.horizontalAdvance(line)).arg(length);
                    }
                }
                if (auto *title = qobject_cast<QCPTextElement *>(element)) {
                    const QFontMetrics metrics(title->font());
                    for (const QString &line : title->text().split(QLatin1Char('\n'))) {
                        if (metrics.horizontalAdvance(line) > plot->width())
                            clipped << QStringLiteral("plot title '%1' needs %2 px, has %3 px").arg(line).arg(metrics.horizontalAdvance(line)).arg(plot->width());
                    }
                }
            }
            QCPLegend *legend = plot->legend;
            for (int i = 0; legend && legend->visible() && i < legend->itemCount(); ++i) {
                QCPAbstractLegendItem *item = legend->item(i);
                if (item && !room.contains(item->outerRect()))
                    clipped << QStringLiteral("legend item %1 of a plot at %2,%3 %4×%5 px lies outside it").arg(i)
                                   .arg(item->outerRect().x()).arg(item->outerRect().y()).arg(item->outerRect().width()).arg(item->outerRect().height());
            }
        }
        if (preset == QLatin1String("pp-3rpr")) {
            // the numbers on the buttons, one caption before them
            int numbers = 0;
            for (int i = 0; w.modeBar()->button(i); ++i)
                numbers += w.modeBar()->button(i)->text().toInt() > 0;
            QCOMPARE_GE(numbers, 5);
        }
        QTest::keyClick(&w, Qt::Key_Escape);
        QVERIFY(!w.isPresenting());
        QVERIFY(!w.variablePanel()->isCompact());
        language::apply(QStringLiteral("en"));
        QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join(QStringLiteral("\n"))));
    }

    /// A design opened while presenting, as `pkm-studio --lang ru --presentation` does: the
    /// limits beside the sliders went only at the next resize, so the Russian O-X glide's spin
    /// boxes were cut at the panel's edge, their arrows lost.
    void spinBoxesWholeInADesignOpenedWhilePresenting()
    {
        QVERIFY(language::apply(QStringLiteral("ru")));
        const auto english = qScopeGuard([] { language::apply(QStringLiteral("en")); });
        std::unique_ptr<MainWindow> window(freshMainWindow(QSize(1280, 720))); // as at start-up
        QVERIFY(window);
        MainWindow &w = *window;
        w.setPresentationMode(true);
        const auto leave = qScopeGuard([&w] { w.setPresentationMode(false); }); // the application's font back
        QVERIFY(w.openDesign(QStringLiteral("oxglide-prototype")));
        const auto cut = [&w] { // waited for: the limits' texts come queued, in the new language
            QStringList cut;
            for (QAbstractSpinBox *spin : w.variablePanel()->findChildren<QAbstractSpinBox *>()) {
                if (spin->isVisible() && spin->visibleRegion().boundingRect() != spin->rect())
                    cut << QStringLiteral("'%1' shows %2 of %3 px").arg(spin->text())
                               .arg(spin->visibleRegion().boundingRect().width()).arg(spin->width());
            }
            return cut.join(QStringLiteral("; "));
        };
        QTRY_VERIFY2_WITH_TIMEOUT(cut().isEmpty(), qPrintable(cut()), 5000);
    }

    void fitsTheScreenAtStartUp_data() { fitsSmallScreens_data(); }
    /// Before it is shown, as pkm-studio starts (a design opened, then the screen's size set),
    /// the window asks for no more than a 1024×768 or 1280×720 projector: the four-bar's link
    /// lengths, one to a line in a page not laid out yet, made it ask 754 px of height, and it
    /// opened 34 px taller than the screen, its status bar out of sight. Shown at 1024×768, it
    /// stays so: the Russian 3-P̲RR's legs, as wide as "постоянная ориентация", made it 1051 px.
    void fitsTheScreenAtStartUp()
    {
        QFETCH(QString, language);
        QFETCH(QString, preset);
        QVERIFY(language::apply(language));
        const auto english = qScopeGuard([] { language::apply(QStringLiteral("en")); });
        MainWindow w;
        QVERIFY(w.openDesign(preset));
        const QSize least = w.minimumSizeHint().expandedTo(w.minimumSize());
        QVERIFY2(least.width() <= 1024 && least.height() <= 720,
                 qPrintable(QStringLiteral("the window asks for %1×%2").arg(least.width()).arg(least.height())));
        // and shown at 1024×768, it keeps that size: nothing asks for more as it is laid out
        w.setGeometry(QRect(QPoint(0, 0), QSize(1024, 768)));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTest::qWait(100);
        QCOMPARE(w.size(), QSize(1024, 768));
        QStringList clipped;
        QTRY_VERIFY2_WITH_TIMEOUT((clipped = clippedTexts(&w)).isEmpty(), qPrintable(clipped.join(QStringLiteral("\n"))), 2000);
    }

    void labelsAreWholeAfterFit_data() { addEveryPresetRows(); }

    /// After Fit at 1280×720 no label of the 2D drawing is cut by the view's edge or covered by
    /// the scale bar: labels keep their size in pixels, so a narrow view cut the O-X glide's
    /// "B · 2a" at its edge and the scale bar covered "C · 3a".
    void labelsAreWholeAfterFit()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(m_window->openDesign(preset));
        QVERIFY(atProjectorSize());
        LinkageView *view = m_window->linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        QRectF room(view->rect());
        room.setBottom(room.bottom() - ScenePainter::scaleBarHeight(view->sceneStyle(), view));
        // The drawing as the view paints it: each name it has room for whole inside the view and
        // above the scale bar. Fit is what gives the room: a name that the drawing alone would
        // put in sight (not a far point's, the four-bar's instant centre) must not be left out.
        const auto boxOf = [](const drawing::Primitive &item, const drawing::Text &text) {
            drawing::Text sized = text;
            const QFontMetricsF metrics(text.font);
            sized.box = sized.box.isEmpty() ? QSizeF(metrics.horizontalAdvance(text.text), metrics.height()) : sized.box;
            drawing::DrawList one;
            one.add(sized, item.layer, item.medium);
            return drawing::bounds(one, false);
        };
        QStringList shown, wanted;
        drawing::LabelPlaces places;
        for (const drawing::Primitive &item : viewLayout(view, places).items) {
            const auto *text = std::get_if<drawing::Text>(&item.shape);
            if (!text || !drawing::shownOnScreen(item.medium))
                continue;
            const QRectF box = boxOf(item, *text);
            shown << text->text;
            QVERIFY2(room.contains(box), qPrintable(QStringLiteral("'%1' at x %2–%3, y %4–%5 in %6 × %7").arg(text->text)
                .arg(box.left()).arg(box.right()).arg(box.top()).arg(box.bottom()).arg(room.width()).arg(room.height())));
        }
        for (const drawing::Primitive &item : drawing::layoutScene(view->scene(), view->mapping(), view->sceneStyle()).items) {
            const auto *text = std::get_if<drawing::Text>(&item.shape);
            if (!text || !drawing::shownOnScreen(item.medium))
                continue;
            const QRectF box = boxOf(item, *text);
            if (box.intersects(room.adjusted(-box.width(), -2.0 * box.height(), box.width(), 2.0 * box.height())))
                wanted << text->text;
        }
        QVERIFY(!wanted.isEmpty());
        for (const QString &name : std::as_const(wanted))
            QVERIFY2(shown.contains(name), qPrintable(QStringLiteral("'%1' is left out after Fit").arg(name)));
    }

    /// Fit frames the linkage, not its ghosts' points of interest: the crossed branch's instant
    /// centre lies far out when AB and DC are nearly parallel, and the fit took it in, leaving
    /// the four-bar's 140 mm ground about a quarter of the view's width, in a corner. The motion
    /// box (both branches) replaced the rocker's whole circle too.
    void fitFramesTheFourBar()
    {
        MainWindow &w = *m_window;
        QVERIFY(w.openDesign(QStringLiteral("fourbar-example")));
        QVERIFY(atProjectorSize());
        LinkageView *view = w.linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        const ViewMapping mapping = view->mapping();
        const QPointF A = mapping.toDevice(Eigen::Vector2d(0.0, 0.0));
        const QPointF D = mapping.toDevice(Eigen::Vector2d(140.0, 0.0));
        QCOMPARE_GT(D.x() - A.x(), 0.5 * view->width());
        for (const SceneJoint &joint : view->scene().joints) {
            if (joint.kind != JointKind::Point)
                QVERIFY(QRectF(view->rect()).contains(mapping.toDevice(Eigen::Vector2d(joint.position.head<2>()))));
            // The instant centre P lies out of sight at this pose: its name is not drawn in sight
        // either, with a leader to nowhere.
        drawing::LayoutOptions options;
        options.labelRoom = QRectF(view->rect()).adjusted(2.0, 2.0, -2.0, -2.0);
        QStringList names;
        for (const drawing::Primitive &item : drawing::layoutScene(view->scene(), mapping, view->sceneStyle(), options).items) {
            if (const auto *text = std::get_if<drawing::Text>(&item.shape); text && drawing::shownOnScreen(item.medium))
                names << text->text;
        }
        bool pOutside = false;
        for (const SceneJoint &joint : view->scene().joints) {
            if (joint.label == "P")
                pOutside = !options.labelRoom.contains(mapping.toDevice(Eigen::Vector2d(joint.position.head<2>())));
        }
        QVERIFY(pOutside);
        QVERIFY2(!names.contains(QStringLiteral("P")) && names.contains(QStringLiteral("B")), qPrintable(names.join(QLatin1Char(' '))));
    }
    }

    void textSizeReachesPlotsAndDrawing()
    {
        MainWindow &w = *m_window;
        QVERIFY(w.openDesign(QStringLiteral("pjoint-prototype")));
        QCustomPlot *plot = nullptr; // the kind's plots (the Tolerances dock's has no legend)
        for (QCustomPlot *candidate : w.findChildren<QCustomPlot *>()) {
            if (!plot && candidate->objectName() != QLatin1String("tolerancePlot"))
                plot = candidate;
        }
        QVERIFY(plot);
        const double tick = plot->xAxis->tickLabelFont().pointSizeF();
        QVERIFY(plot->legend->itemCount() > 0 && plot->legend->item(0));
        const double legendItem = plot->legend->item(0)->font().pointSizeF();
        const double label = w.linkageView()->sceneStyle().fontPixels;
        const double app = QApplication::font().pointSizeF();
        QAction *twice = w.findChild<QAction *>(QStringLiteral("textSize_200"));
        QVERIFY(twice);
        twice->trigger();
        QCOMPARE_LT(std::abs(plot->xAxis->tickLabelFont().pointSizeF() - 2 * tick), 0.01);
        // twice, not four times: the legend hands its font to its items
        QCOMPARE_LT(std::abs(plot->legend->item(0)->font().pointSizeF() - 2 * legendItem), 0.01);
        QCOMPARE_LT(std::abs(w.linkageView()->sceneStyle().fontPixels - 2 * label), 0.01);
        QCOMPARE_LT(std::abs(QApplication::font().pointSizeF() - 2 * app), 0.01);
        // One plot a page at this size, as in presentation mode; all three are back at 100 %.
        const auto shownOnPage = [&] {
            const QList<QCustomPlot *> plots = plotfocus::plots(w.currentPanel()); // figs. 8–10 first
            int shown = 0;
            for (QCustomPlot *other : plots)
                shown += other->parentWidget() == plots.first()->parentWidget() && !other->isHidden();
            return shown;
        };
        QCOMPARE(shownOnPage(), 1);
        QVERIFY(!w.isPresenting());
        // Remembered, and back to normal with 100 %.
        QCOMPARE(QSettings().value(QStringLiteral("view/textSize")).toInt(), 200);
        w.findChild<QAction *>(QStringLiteral("textSize_100"))->trigger();
        QCOMPARE_LT(std::abs(plot->xAxis->tickLabelFont().pointSizeF() - tick), 0.01);
        QCOMPARE_LT(std::abs(textscale::factor() - 1.0), 1e-12);
        QCOMPARE(shownOnPage(), 3);
    }
};

QTEST_MAIN(TestClassroom)
#include "tst_classroom.moc"
