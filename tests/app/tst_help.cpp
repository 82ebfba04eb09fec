// Help inside the program (issue 18): F1 opens the user guide with its headings and pictures in
// the chosen language, links and the find field work, Shift+F1 enters What's This with a
// translated text on every panel, and long messages are never cut — neither the linkage view's
// toast nor the status bar's message at 1280×720, in all four languages.
#include "gui/guidewindow.h"
#include "gui/mainwindow.h"

#include "designpanel.h"
#include "document/document.h"
#include "document/language.h"
#include "equationspanel.h"
#include "kinds/workspacepanel.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "playbar.h"
#include "quantityformat.h"
#include "scenepainter.h"
#include "support/app.h"
#include "valuestable.h"
#include "variablepanel.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QStatusBar>
#include <QScrollBar>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>

using namespace pkm;
using namespace pkm::test;

namespace {

QStringList headings(const QTextDocument *document)
{
    QStringList found;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() > 0)
            found << block.text();
    }
    return found;
}

/// The pictures of `document` as its browser loads them: name → image.
QList<QImage> pictures(QTextDocument *document)
{
    QList<QImage> images;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextCharFormat format = it.fragment().charFormat();
            if (format.isImageFormat())
                images << document->resource(QTextDocument::ImageResource, QUrl(format.toImageFormat().name())).value<QImage>();
        }
    }
    return images;
}

QStringList links(const QTextDocument *document)
{
    QStringList found;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            if (it.fragment().charFormat().isAnchor())
                found << it.fragment().charFormat().anchorHref();
        }
    }
    return found;
}

} // namespace

class TestHelp : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    /// The window's panels that must explain themselves in What's This.
    QList<QWidget *> panels() const
    {
        MainWindow &w = *m_window;
        return {w.linkageView(), w.variablePanel(), w.playBar(), w.designPanel(), w.valuesTable(), w.mobilityPanel(),
                w.equationsPanel(), w.workspacePanel(), w.view3d(), w.modeBar()};
    }

    /// What a rich-text label shows, as plain text.
    static QString plainOf(const QString &html)
    {
        QTextDocument document;
        document.setHtml(html);
        return document.toPlainText();
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

    void guideSources()
    {
        QVERIFY(guideSource(QStringLiteral("en")).endsWith(QStringLiteral("guide.en.md")));
        QVERIFY(guideSource(QStringLiteral("ru")).endsWith(QStringLiteral("guide.ru.md")));
        QVERIFY(guideSource(QStringLiteral("sr")).endsWith(QStringLiteral("guide.sr.md")));
        QVERIFY(guideSource(QStringLiteral("sr_Latn")).endsWith(QStringLiteral("guide.sr_Latn.md")));
        // a language without a guide of its own reads the English one
        QVERIFY(guideSource(QStringLiteral("de")).endsWith(QStringLiteral("guide.en.md")));
        // everything the English guide links to is built in
        QVERIFY(QFile::exists(QStringLiteral(":/guide/docs/cli.md")));
    }

    void f1OpensTheGuide_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("title");
        QTest::addColumn<QString>("section");
        QTest::newRow("en") << QStringLiteral("en") << QStringLiteral("PKM Studio User Guide") << QStringLiteral("In the classroom: Play, bookmarks and presentation mode");
        QTest::newRow("ru") << QStringLiteral("ru") << QStringLiteral("Руководство пользователя PKM Studio") << QStringLiteral("Активный П-шарнир");
        QTest::newRow("sr") << QStringLiteral("sr") << QStringLiteral("Упутство за PKM Studio") << QStringLiteral("Активни П-зглоб");
        QTest::newRow("sr_Latn") << QStringLiteral("sr_Latn") << QStringLiteral("Uputstvo za PKM Studio") << QStringLiteral("Aktivni P-zglob");
    }

    void f1OpensTheGuide()
    {
        QFETCH(QString, language);
        QFETCH(QString, title);
        QFETCH(QString, section);
        QVERIFY(language::apply(language));
        QCoreApplication::processEvents(); // the posted LanguageChange
        m_window->activateWindow();
        QTRY_COMPARE(QApplication::activeWindow(), m_window); // F1 is the main window's shortcut
        QTest::keyClick(m_window, Qt::Key_F1);
        GuideWindow *guide = m_window->guideWindow();
        QVERIFY(guide);
        QTRY_VERIFY(guide->isVisible());
        QTextDocument *document = guide->browser()->document();
        const QStringList found = headings(document);
        QVERIFY2(found.size() >= 4, qPrintable(found.join(QStringLiteral(" | "))));
        QCOMPARE(found.first(), title);
        QVERIFY2(found.contains(section), qPrintable(found.join(QStringLiteral(" | "))));
        const QList<QImage> images = pictures(document);
        QVERIFY(!images.isEmpty());
        // the first picture is the window in the guide's language (the Russian guide opened
        // with the English window)
        if (language != QLatin1String("en")) {
            const QString own = QStringLiteral("screenshot.%1.png").arg(language);
            QVERIFY(QFile::exists(QStringLiteral(":/guide/docs/") + own));
            const QString markdown = document->toMarkdown();
            QVERIFY2(markdown.indexOf(QStringLiteral(".png")) == markdown.indexOf(own) + own.size() - 4,
                     qPrintable(markdown.left(300)));
        }
        for (const QImage &image : images) {
            QVERIFY(!image.isNull());
            QCOMPARE_GT(image.width(), 300); // a screenshot, not an empty placeholder
            QCOMPARE_LE(image.width(), 820); // scaled to read beside the text
        }
        guide->close();
    }

    void guideLinksAndFind()
    {
        QVERIFY(language::apply(QStringLiteral("ru")));
        QCoreApplication::processEvents();
        m_window->showGuide();
        GuideWindow *guide = m_window->guideWindow();
        QTextBrowser *browser = guide->browser();
        // the translation links to the whole English guide, and the link leads there
        QVERIFY(links(browser->document()).contains(QStringLiteral("guide.en.md")));
        browser->setSource(browser->source().resolved(QUrl(QStringLiteral("guide.en.md"))));
        QCOMPARE(headings(browser->document()).value(0), QStringLiteral("PKM Studio User Guide"));
        QVERIFY(browser->isBackwardAvailable());
        browser->backward();
        QCOMPARE(headings(browser->document()).value(0), QStringLiteral("Руководство пользователя PKM Studio"));
        // Ctrl+F puts the focus in the find field; Enter finds, round the guide
        guide->activateWindow();
        QTRY_COMPARE(QApplication::activeWindow(), guide);
        QTest::keyClick(guide, Qt::Key_F, Qt::ControlModifier);
        QTRY_VERIFY(guide->findField()->hasFocus());
        guide->findField()->setText(QStringLiteral("закладк"));
        QVERIFY(guide->findNext());
        QCOMPARE(browser->textCursor().selectedText().toLower(), QStringLiteral("закладк"));
        const int first = browser->textCursor().position();
        QVERIFY(guide->findNext());
        QVERIFY(browser->textCursor().position() != first);
        // each match in the middle of the page, not on its bottom edge (where a scroll is left)
        for (int i = 0; i < 4; ++i) {
            QVERIFY(guide->findNext());
            const QRect match = browser->cursorRect();
            const int height = browser->viewport()->height();
            QScrollBar *bar = browser->verticalScrollBar();
            if (bar->value() > bar->minimum() && bar->value() < bar->maximum())
                QVERIFY2(match.top() >= height / 4 - 2 && match.bottom() <= 3 * height / 4 + 2,
                         qPrintable(QStringLiteral("a match at %1–%2 px of %3").arg(match.top()).arg(match.bottom()).arg(height)));
        }
        guide->findField()->setText(QStringLiteral("no such word anywhere"));
        QVERIFY(!guide->findNext());
        // a change of language brings the guide of the new language
        QVERIFY(language::apply(QStringLiteral("en")));
        QCoreApplication::processEvents();
        QCOMPARE(headings(browser->document()).value(0), QStringLiteral("PKM Studio User Guide"));
        // Esc in the find field empties it, and then closes the guide
        guide->activateWindow();
        guide->findField()->setFocus();
        QTRY_VERIFY(guide->findField()->hasFocus());
        QTest::keyClick(guide->findField(), Qt::Key_Escape);
        QVERIFY(guide->findField()->text().isEmpty());
        QVERIFY(guide->isVisible());
        QTest::keyClick(guide->findField(), Qt::Key_Escape);
        QTRY_VERIFY(!guide->isVisible());
    }

    void whatsThisOnEveryPanel()
    {
        QAction *action = m_window->findChild<QAction *>(QStringLiteral("whatsThisAction"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F1));
        QVERIFY(language::apply(QStringLiteral("en")));
        QCoreApplication::processEvents();
        QStringList english;
        for (QWidget *panel : panels()) {
            QVERIFY2(!panel->whatsThis().isEmpty(), panel->metaObject()->className());
            english << panel->whatsThis();
        }
        for (const char *code : {"ru", "sr", "sr_Latn"}) {
            QVERIFY(language::apply(QString::fromLatin1(code)));
            QCoreApplication::processEvents();
            const QList<QWidget *> all = panels();
            for (int i = 0; i < all.size(); ++i) {
                const QString text = all[i]->whatsThis();
                QVERIFY2(!text.isEmpty() && text != english[i],
                         qPrintable(QStringLiteral("%1 in %2: %3").arg(QString::fromLatin1(all[i]->metaObject()->className()), QString::fromLatin1(code), text)));
            }
        }
        QVERIFY(language::apply(QStringLiteral("en")));
    }

    void longMessagesAreWhole_data()
    {
        QTest::addColumn<QString>("language");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"})
            QTest::newRow(code) << QString::fromLatin1(code);
    }

    /// At 1280×720 the limit and singularity notes, and a long error, are shown whole: in the
    /// linkage view's toast (wrapped inside the view) and in the status bar.
    void longMessagesAreWhole()
    {
        QFETCH(QString, language);
        QVERIFY(language::apply(language));
        QCoreApplication::processEvents(); // the posted LanguageChange
        MainWindow &w = *m_window;
        w.resize(1280, 720);
        QVERIFY(w.openDesign(QStringLiteral("pjoint-prototype")));
        QCoreApplication::processEvents();
        QStringList messages;
        const MechanismPtr mechanism = w.document()->mechanism();
        QStringList symbols;
        for (const VariableInfo &info : mechanism->variableInfo())
            symbols << toQString(info.symbol);
        for (const ParameterInfo &info : mechanism->parameterInfo())
            symbols << toQString(info.symbol);
        for (int i = 0; i < int(mechanism->variableInfo().size()); ++i) {
            for (bool top : {false, true}) {
                const Interval range = w.document()->mechanism()->variableRange(i);
                QVERIFY(w.document()->setVariable(i, top ? range.max : range.min));
                QCoreApplication::processEvents();
                QVERIFY(!w.linkageView()->message().isEmpty());
                messages << w.linkageView()->message();
            }
        }
        // an error as long as a failed move's explanation and a reason after it, and one longer
        // than three lines of the bar
        messages << messages.join(QStringLiteral(" "));
        messages << QStringList(4, messages.last()).join(QStringLiteral(" "));

        QStatusBar *bar = w.statusBar();
        QLabel *text = bar->findChild<QLabel *>(QStringLiteral("statusText"));
        QVERIFY(text);
        QLabel *readOut = nullptr;
        for (QLabel *label : bar->findChildren<QLabel *>()) {
            if (label != text && !label->text().isEmpty())
                readOut = label;
        }
        QVERIFY(readOut);
        int wrapped = 0, cut = 0;
        for (const QString &message : std::as_const(messages)) {
            // the toast: every line inside the view, the whole text inside the box (for the
            // messages the view shows: the last one is for the status bar alone)
            LinkageView *view = w.linkageView();
            if (&message != &messages.last()) {
            const QRectF area(view->rect());
            const auto layout = ScenePainter::messageLayout(area, message, view->sceneStyle(), view);
            QVERIFY2(area.contains(layout.box), qPrintable(QStringLiteral("box %1×%2 at %3,%4 in %5×%6: %7").arg(layout.box.width()).arg(layout.box.height()).arg(layout.box.x()).arg(layout.box.y()).arg(area.width()).arg(area.height()).arg(message)));
            const QFontMetricsF metrics(layout.font, view);
            const QRectF needed = metrics.boundingRect(layout.text, layout.flags, message);
            QVERIFY2(layout.text.adjusted(-0.5, -0.5, 0.5, 0.5).contains(needed),
                     qPrintable(QStringLiteral("“%1” needs %2×%3 px, has %4×%5 px")
                                    .arg(message).arg(needed.width()).arg(needed.height())
                                    .arg(layout.text.width()).arg(layout.text.height())));
            if (metrics.horizontalAdvance(message) > layout.text.width()) // too long for a line: it wraps
                QCOMPARE_GT(layout.text.height(), 1.5 * metrics.height());
            }

            // the status bar: the message whole (or, past three lines, cut with an ellipsis),
            // wrapped inside its label, the label inside the bar and clear of the read-out
            emit w.workspacePanel()->statusMessage(message, true);
            QCoreApplication::processEvents();
            QCOMPARE(bar->currentMessage(), message);
            QCOMPARE(bar->toolTip(), message); // whole in the tooltip in any case
            const QString shown = plainOf(text->text()); // the label lowers the symbols
            if (shown != plainOf(symbolHtmlKnown(message, symbols))) {
                QVERIFY2(shown.endsWith(QChar(0x2026)) && plainOf(symbolHtmlKnown(message, symbols)).startsWith(shown.chopped(1)),
                         qPrintable(shown));
                ++cut;
            }
            const QFontMetrics font(text->font());
            QVERIFY(text->font().bold()); // an error
            const QRect box = font.boundingRect(QRect(0, 0, text->contentsRect().width(), 100000), Qt::TextWordWrap, shown);
            QVERIFY2(box.height() <= text->contentsRect().height() && box.height() <= 3 * font.lineSpacing(),
                     qPrintable(QStringLiteral("“%1” needs %2 px in height, has %3 px").arg(shown).arg(box.height()).arg(text->contentsRect().height())));
            if (box.height() > font.lineSpacing())
                ++wrapped;
            QVERIFY2(bar->rect().contains(text->geometry()), qPrintable(message));
            if (readOut->isVisible())
                QVERIFY(readOut->x() >= text->geometry().right());
        }
        QCOMPARE_GE(wrapped, 1); // the bar's width was passed and the message wrapped
        QCOMPARE(cut, 1);        // only the message longer than three lines is cut
        // the read-out comes back when the message goes, and the bar is one line again
        bar->clearMessage();
        QCoreApplication::processEvents();
        QVERIFY(readOut->isVisible());
        QVERIFY(bar->toolTip().isEmpty());
        QVERIFY(text->text().isEmpty());
        QTRY_VERIFY2(bar->height() <= 2 * QFontMetrics(bar->font()).lineSpacing() + 8, qPrintable(QString::number(bar->height())));
    }

    void messageKeepsTheMechanismInSight()
    {
        // a mechanism low in the view (a five-bar in a view the mode buttons squeeze): the
        // message goes to the top; one high in the view leaves it at the bottom, as ever
        const QRectF area(0, 0, 370, 260);
        const QString message = QStringLiteral("Singular pose (direct): the mechanism cannot be driven here.");
        const SceneStyle style;
        const auto low = ScenePainter::messageLayout(area, message, style, nullptr, QRectF(100, 120, 160, 120));
        const auto high = ScenePainter::messageLayout(area, message, style, nullptr, QRectF(100, 10, 160, 120));
        const auto none = ScenePainter::messageLayout(area, message, style, nullptr);
        QCOMPARE_LT(low.box.bottom(), 120.0);
        QCOMPARE(high.box, none.box);
        QCOMPARE_GT(none.box.top(), 130.0);
        QCOMPARE(low.message, message);
        // one that fills the view, covered wherever the whole message goes: its headline in
        // a corner clear of it (the whole message is the status bar's)
        const QRectF drawing(80, 60, 200, 140);
        const auto full = ScenePainter::messageLayout(area, message, style, nullptr, drawing);
        QCOMPARE(full.message, QStringLiteral("Singular pose (direct)"));
        QVERIFY(area.contains(full.box));
        QVERIFY2(!full.box.intersects(drawing), qPrintable(QStringLiteral("%1,%2 %3×%4").arg(full.box.x()).arg(full.box.y()).arg(full.box.width()).arg(full.box.height())));
        QVERIFY(full.text.contains(QFontMetricsF(full.font).boundingRect(full.text, full.flags, full.message)));
        // a joint is never under the headline where a corner leaves them all free: in Russian
        // the five-bar's headline took four lines beside the scale bar, over A and θ₁
        const QRectF narrow(0, 0, 340, 300), spread(20, 20, 300, 260);
        const std::vector<QPointF> joints {{70, 250}, {170, 45}, {125, 140}, {215, 140}, {225, 250}};
        const QString russian = QStringLiteral("Особое положение (обратной кинематики): C на границе рабочего пространства.");
        const auto clear = ScenePainter::messageLayout(narrow, russian, style, nullptr, spread, joints);
        const double ring = style.pivotRadius + 4.0;
        for (const QPointF &joint : joints)
            QVERIFY2(!clear.box.adjusted(-ring, -ring, ring, ring).contains(joint),
                     qPrintable(QStringLiteral("the note at %1,%2 %3×%4 covers the joint at %5,%6").arg(clear.box.x()).arg(clear.box.y())
                                    .arg(clear.box.width()).arg(clear.box.height()).arg(joint.x()).arg(joint.y())));
    }

    void statusLowersOnlySymbols()
    {
        // "x_AB" in a message reads as the drawings and the values panel write it, with a
        // lowered AB; a file name with '_' in the same message keeps it, and nothing is markup
        MainWindow &w = *m_window;
        QVERIFY(w.openDesign(QStringLiteral("oxglide-prototype")));
        QCoreApplication::processEvents();
        emit w.workspacePanel()->statusMessage(QStringLiteral("x_CD − x_AB = s <b>in</b> my_design.pkm"), false);
        QCoreApplication::processEvents();
        const QString html = w.statusBar()->findChild<QLabel *>(QStringLiteral("statusText"))->text();
        QVERIFY2(html.contains(QStringLiteral("x<sub>CD</sub> − x<sub>AB</sub> = s")), qPrintable(html));
        QVERIFY2(html.contains(QStringLiteral("&lt;b&gt;in&lt;/b&gt; my_design.pkm")), qPrintable(html));
        QCOMPARE(plainOf(html), QStringLiteral("xCD − xAB = s <b>in</b> my_design.pkm"));
        w.statusBar()->clearMessage();
    }
};

QTEST_MAIN(TestHelp)
#include "tst_help.moc"
