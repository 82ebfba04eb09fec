// Switching the running program between English, Serbian (Cyrillic and Latin) and Russian:
// the choice follows the system locale at first and is remembered; the switch re-translates
// the real widgets at once — menus, docks, the design panel, the plots, every text a person
// sees — formats numbers by the language's locale, and exports (the parameter sheet) follow.
#include "designpanel.h"
#include "document/document.h"
#include "kinds/fourbar/fourbarpanel.h"
#include "document/language.h"
#include "gui/mainwindow.h"
#include "modebar.h"
#include "kinds/pjoint/pjointcurves.h"
#include "kinds/pjoint/pjointplots.h"
#include "export/sheet.h"
#include "kinds/kindmodule.h"
#include "text.h"
#include "support/app.h"
#include "valuestable.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAction>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QApplication>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using namespace pkm;
using namespace pkm::test;

namespace {

/// Every text the window shows: labels, buttons, group titles, tabs, menus, dock titles,
/// headers, plot axes and legends, the status bar's permanent labels.
QStringList visibleTexts(QWidget *root)
{
    QStringList texts;
    const auto add = [&texts](const QString &t) {
        if (!t.trimmed().isEmpty())
            texts << t;
    };
    for (QLabel *w : root->findChildren<QLabel *>()) {
        if (w->isVisibleTo(root))
            add(w->text());
    }
    for (QAbstractButton *w : root->findChildren<QAbstractButton *>()) {
        if (w->isVisibleTo(root)) {
            add(w->text());
            add(w->toolTip());
        }
    }
    for (QWidget *w : root->findChildren<QWidget *>()) { // every tooltip a pointer can find
        if (w->isVisibleTo(root))
            add(w->toolTip());
    }
    for (QAction *a : root->findChildren<QAction *>())
        add(a->toolTip());
    for (QGroupBox *w : root->findChildren<QGroupBox *>()) {
        if (w->isVisibleTo(root))
            add(w->title());
    }
    for (QTabBar *w : root->findChildren<QTabBar *>()) {
        for (int i = 0; i < w->count(); ++i)
            add(w->tabText(i));
    }
    for (QDockWidget *w : root->findChildren<QDockWidget *>())
        add(w->windowTitle());
    for (QTreeWidget *w : root->findChildren<QTreeWidget *>()) {
        if (!w->isVisibleTo(root))
            continue;
        for (int c = 0; c < w->columnCount(); ++c)
            add(w->headerItem()->text(c));
        for (int i = 0; i < w->topLevelItemCount(); ++i) {
            QTreeWidgetItem *item = w->topLevelItem(i);
            add(item->text(0));
            for (int k = 0; k < item->childCount(); ++k)
                add(item->child(k)->text(w->columnCount() - 1));
        }
    }
    for (QCustomPlot *plot : root->findChildren<QCustomPlot *>()) {
        if (!plot->isVisibleTo(root))
            continue;
        for (QCPAxis *axis : plot->axisRect() ? plot->axisRect()->axes() : QList<QCPAxis *>())
            add(axis->label());
        for (int i = 0; i < plot->plottableCount(); ++i)
            add(plot->plottable(i)->name());
    }
    if (auto *window = qobject_cast<QMainWindow *>(root)) {
        for (QAction *menu : window->menuBar()->actions()) {
            add(menu->text());
            if (menu->menu()) {
                for (QAction *item : menu->menu()->actions())
                    add(item->text());
            }
        }
    }
    return texts;
}

/// The line of a field's tooltip that gives the parameter's key ("lead"), in the language.
QRegularExpression parameterKey()
{
    const QString line = QCoreApplication::translate("pkm::DesignPanel", "Name in design files and on the command line: %1");
    return QRegularExpression(QRegularExpression::escape(line.section(QStringLiteral("%1"), 0, 0)) + QStringLiteral("\\w+"));
}

/// English words left in a Russian window: runs of three or more Latin letters, bar names
/// and symbols that are the same in every language.
QStringList englishWords(const QStringList &texts)
{
    static const QRegularExpression word(QStringLiteral("(?<![\\w_])[A-Za-z]{3,}(?![\\w_])"));
    static const QStringList same = {
        QStringLiteral("PKM"), QStringLiteral("Studio"), QStringLiteral("MOMA"), QStringLiteral("DXF"),
        QStringLiteral("GIF"), QStringLiteral("WebM"), QStringLiteral("PDF"), QStringLiteral("JSON"), QStringLiteral("CSV"),
        QStringLiteral("PNG"), QStringLiteral("SVG"), QStringLiteral("det"), QStringLiteral("min"),
        QStringLiteral("max"), QStringLiteral("rec"), QStringLiteral("cos"), QStringLiteral("sin"),
        QStringLiteral("glide"), QStringLiteral("English"), QStringLiteral("Srpski"), QStringLiteral("latinica"),
        QStringLiteral("Ctrl"), QStringLiteral("Shift"), QStringLiteral("Bennett"), QStringLiteral("nbsp"),
        QStringLiteral("Esc"), QStringLiteral("Page"), QStringLiteral("Down"), // key caps, printed on every keyboard
        QStringLiteral("sub"), QStringLiteral("sup"), QStringLiteral("span"), QStringLiteral("style"),
        QStringLiteral("color"), QStringLiteral("html"), QStringLiteral("href"), QStringLiteral("div"),
        QStringLiteral("font"), QStringLiteral("weight"), QStringLiteral("bold"), QStringLiteral("table"),
    };
    QStringList found;
    for (const QString &t : texts) {
        QString plain = t;
        plain.replace(QStringLiteral("<sub>"), QStringLiteral("_")); // "F<sub>max</sub>": a symbol's index
        plain.remove(QRegularExpression(QStringLiteral("<[^>]*>"))); // markup is not text
        plain.remove(parameterKey()); // a key of files and the CLI, the same in every language
        for (auto it = word.globalMatch(plain); it.hasNext();) {
            const QString w = it.next().captured();
            if (!same.contains(w, Qt::CaseInsensitive))
                found << QStringLiteral("“") + w + QStringLiteral("” in “") + t.left(120) + QStringLiteral("”");
        }
    }
    found.removeDuplicates();
    return found;
}

QAction *languageAction(MainWindow &window, const QString &code)
{
    return window.findChild<QAction *>(QStringLiteral("language_") + code);
}

void switchTo(MainWindow &window, const QString &code)
{
    QAction *action = languageAction(window, code);
    QVERIFY(action);
    action->trigger();
    QCoreApplication::processEvents(); // LanguageChange is posted
    QCoreApplication::processEvents();
    QCOMPARE(language::current(), code);
    QVERIFY(action->isChecked());
}

QString fileMenuText(MainWindow &window)
{
    return window.menuBar()->actions().value(0)->text();
}

} // namespace

class TestLanguages : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void cleanup()
    {
        language::apply(QStringLiteral("en"));
        QCoreApplication::processEvents();
    }

    // The first start speaks the system's language; a choice is remembered over it.
    void defaultFollowsSystem()
    {
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("ru_RU"))), QStringLiteral("ru"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("sr_RS"))), QStringLiteral("sr"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("sr_Cyrl_RS"))), QStringLiteral("sr"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("sr_Latn_RS"))), QStringLiteral("sr_Latn"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("sr_Latn_ME"))), QStringLiteral("sr_Latn"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("en_GB"))), QStringLiteral("en"));
        QCOMPARE(language::bestFor(QLocale(QStringLiteral("de_DE"))), QStringLiteral("en"));
        QSettings().remove(QStringLiteral("language"));
        QCOMPARE(language::preferred(), language::bestFor(QLocale::system()));
        language::remember(QStringLiteral("sr_Latn"));
        QCOMPARE(language::preferred(), QStringLiteral("sr_Latn"));
        language::remember(QStringLiteral("klingon")); // not a language: ignored
        QCOMPARE(language::preferred(), QStringLiteral("sr_Latn"));
        QSettings().remove(QStringLiteral("language"));
    }

    // Numbers never group their thousands: "d = 1,077.0 mm" in a tracer and "a = 1,000 mm" in
    // a subtitle read as two numbers where ',' is the decimal point, and nothing else groups.
    void numbersHaveNoGroupSeparator()
    {
        const std::pair<const char *, const char *> expected[] = {
            {"en", "d = 1077.0 mm"}, {"ru", "d = 1077,0 мм"}, {"sr", "d = 1077,0 mm"}, {"sr_Latn", "d = 1077,0 mm"}};
        for (const auto &[code, tracer] : expected) {
            QVERIFY2(language::apply(QString::fromLatin1(code)), code);
            QCOMPARE(QLocale().toString(1000.0, 'g', 6).size(), 4);
            QCOMPARE(pjointcurves::valueText(PJointPlots::DiagonalPlot, 1077.04), QString::fromUtf8(tracer));
        }
    }

    // The Language menu switches every widget at once and remembers the choice.
    void switchRetranslatesTheWindow()
    {
        QVERIFY(language::apply(QStringLiteral("en")));
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QCoreApplication::processEvents();
        QCOMPARE(fileMenuText(window), QStringLiteral("&File"));
        const QStringList english = visibleTexts(&window);
        QVERIFY(english.contains(QStringLiteral("Values")));

        for (const QString &code : {QStringLiteral("ru"), QStringLiteral("sr"), QStringLiteral("sr_Latn")}) {
            switchTo(window, code);
            QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), code);
            const QString file = QCoreApplication::translate("pkm::MainWindow", "&File");
            QVERIFY(file != QStringLiteral("&File"));
            QCOMPARE(fileMenuText(window), file);
            const QStringList now = visibleTexts(&window);
            QVERIFY(!now.contains(QStringLiteral("Values")));
            // the design panel names the П-joint's crank in the language (a core label)
            const QString crank = QCoreApplication::translate("core", "crank (lever) length");
            QVERIFY(crank != QStringLiteral("crank (lever) length"));
            bool found = false;
            for (QLabel *label : window.designPanel()->findChildren<QLabel *>())
                found = found || label->text().contains(crank);
            QVERIFY2(found, qPrintable(code));
            // everything that was English reads differently now, but for the languages' own
            // names in the Language menu
            QStringList kept;
            for (const QString &t : now) {
                if (!english.contains(t) || !t.contains(QRegularExpression(QStringLiteral("[A-Za-z]{4,}"))))
                    continue;
                bool ownName = false;
                for (const language::Language &l : language::all())
                    ownName = ownName || t == l.nativeName;
                if (!ownName)
                    kept << t;
            }
            QVERIFY2(kept.isEmpty(), qPrintable(code + QStringLiteral(": ") + kept.join(QStringLiteral(" / "))));
        }
        switchTo(window, QStringLiteral("en"));
        QCOMPARE(fileMenuText(window), QStringLiteral("&File"));
        QCOMPARE(visibleTexts(&window).size(), english.size());
    }

    // In Russian no English word is left on the screen, for every kind of mechanism, and the
    // numbers have a decimal comma.
    void nothingLeftInEnglish_data()
    {
        addPresetPerKindRows(); // every kind of mechanism, as it comes with the program
    }
    void nothingLeftInEnglish()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(language::apply(QStringLiteral("en")));
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(window.openDesign(preset));
        QCoreApplication::processEvents();
        switchTo(window, QStringLiteral("ru"));
        QTest::qWait(50);
        const QStringList left = englishWords(visibleTexts(&window));
        QVERIFY2(left.isEmpty(), qPrintable(left.join(QStringLiteral("\n"))));
        // the pose in the status bar: "θ = 60,00°"
        bool comma = false;
        for (QLabel *label : window.statusBar()->findChildren<QLabel *>())
            comma = comma || label->text().contains(QRegularExpression(QStringLiteral("\\d,\\d")));
        QVERIFY(comma);
    }

    // The design note shows its first sentence whole in every language: the abbreviations
    // before a figure number ("fig. 3a", "рис. 3a", "сл. 3a") do not end it.
    void noteShowsTheWholeFirstSentence_data()
    {
        QTest::addColumn<QString>("code");
        for (const char *code : {"en", "ru", "sr", "sr_Latn"})
            QTest::newRow(code) << QString::fromLatin1(code);
    }
    void noteShowsTheWholeFirstSentence()
    {
        QFETCH(QString, code);
        QVERIFY(language::apply(code));
        MainWindow window;
        window.resize(1920, 1080);
        window.show();
        QVERIFY(window.openDesign(QStringLiteral("moma-3a")));
        auto *note = window.designPanel()->findChild<QLabel *>(QStringLiteral("designNote"));
        QVERIFY(note);
        QVERIFY(note->isVisibleTo(&window));
        QTRY_VERIFY(window.designPanel()->parentWidget()->height() > 300); // laid out
        QString shown = note->text();
        shown.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
        // the first sentence names the figure, both reference points and both turns
        for (const char *part : {"3a", "R₁ = (−100, 0)", "R₂ = (100, 0)", "γ₁ = −5°", "γ₂ = +5°"})
            QVERIFY2(shown.contains(QString::fromUtf8(part)), qPrintable(code + QStringLiteral(": ") + shown));
        // and only the first: the rest opens on request
        QVERIFY2(!shown.contains(QStringLiteral("195")), qPrintable(shown));

        // on a projector's 1280×720 the first field is in sight whole, below a shorter note
        window.resize(1280, 720);
        QWidget *viewport = window.designPanel()->parentWidget();
        QTRY_COMPARE(window.size(), QSize(1280, 720));
        QLineEdit *first = nullptr;
        for (QLineEdit *field : window.designPanel()->findChildren<QLineEdit *>()) {
            if (field->isVisibleTo(&window) && (!first || field->mapTo(viewport, QPoint()).y() < first->mapTo(viewport, QPoint()).y()))
                first = field;
        }
        QVERIFY(first);
        QTRY_VERIFY2(viewport->rect().contains(QRect(first->mapTo(viewport, QPoint()), first->size())), qPrintable(code));
        emit note->linkActivated(QStringLiteral("#toggle")); // "more…" opens all of it
        QVERIFY2(note->text().contains(QStringLiteral("195")), qPrintable(note->text()));
    }

    // Core's sentences come in the language too, with its numbers.
    void coreSentencesFollow()
    {
        QVERIFY(language::apply(QStringLiteral("en")));
        MainWindow window;
        window.show();
        switchTo(window, QStringLiteral("ru"));
        auto refused = window.document()->setParameter(QStringLiteral("a"), -1.5, false); // a must be positive
        QVERIFY(!refused);
        const QString message = QString::fromStdString(refused.failure().message);
        QVERIFY2(message.contains(QRegularExpression(QStringLiteral("[а-яА-Я]{4,}"))), qPrintable(message));
        QVERIFY2(!message.contains(QStringLiteral("must")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("1,5")), qPrintable(message)); // the number the Russian way
    }

    // A length the four-bar panel refused keeps its reason on screen; a switch of language
    // gives the reason in the new language.
    void refusedLengthFollows()
    {
        QVERIFY(language::apply(QStringLiteral("en")));
        MainWindow window;
        window.show();
        QVERIFY(window.openDesign(QStringLiteral("fourbar-example")));
        FourBarPanel *panel = window.kindPanel<FourBarPanel>();
        panel->lengthSpinBox(QStringLiteral("AB"))->setValue(400.0); // longer than BC + CD + AD
        QVERIFY(panel->linkMessage()->text().contains(QStringLiteral("cannot close the loop")));
        switchTo(window, QStringLiteral("ru"));
        const QString message = panel->linkMessage()->text();
        QVERIFY2(!message.contains(QStringLiteral("cannot")), qPrintable(message));
        QVERIFY2(message.contains(QRegularExpression(QStringLiteral("[а-я]{4,}"))), qPrintable(message));
        QVERIFY2(message.startsWith(QStringLiteral("AB = 400")), qPrintable(message));
    }

    // Qt's own widgets speak the language too, Serbian included, for which Debian ships no Qt
    // catalogue: the file dialog Qt draws where the desktop offers none, and the context menu
    // of a field.
    void qtWidgetsFollow_data()
    {
        QTest::addColumn<QString>("code");
        for (const char *code : {"ru", "sr", "sr_Latn"})
            QTest::newRow(code) << QString::fromLatin1(code);
    }
    void qtWidgetsFollow()
    {
        QFETCH(QString, code);
        QVERIFY(language::apply(code));
        QFileDialog dialog(nullptr, QStringLiteral("PKM Studio"));
        dialog.setOption(QFileDialog::DontUseNativeDialog);
        dialog.setAcceptMode(QFileDialog::AcceptSave);
        QStringList texts;
        for (QLabel *label : dialog.findChildren<QLabel *>())
            texts << label->text();
        for (QAbstractButton *button : dialog.findChildren<QAbstractButton *>())
            texts << button->text() << button->toolTip();
        QLineEdit field;
        std::unique_ptr<QMenu> menu(field.createStandardContextMenu());
        for (QAction *action : menu->actions())
            texts << action->text().section(QLatin1Char('\t'), 0, 0); // without the shortcut
        texts.removeAll(QString());
        for (const char *english : {"Look in:", "File &name:", "Files of type:", "&Save", "Cancel", "Create New Folder",
                                    "&Copy", "&Paste", "Select All"})
            QVERIFY2(!texts.contains(QString::fromLatin1(english)), qPrintable(code + QStringLiteral(": ") + QString::fromLatin1(english)));
        const QString fileName = QCoreApplication::translate("QFileDialog", "File &name:");
        QVERIFY2(texts.contains(fileName), qPrintable(texts.join(QStringLiteral(" | "))));
        QVERIFY(texts.contains(QCoreApplication::translate("QLineEdit", "&Copy")));
    }

    // Longer texts do not push the window apart: at 1920 × 1080 in Russian the five-bar's three
    // mode buttons wrap into a second row inside the middle, the docks keep their widths, and
    // the values table shows its values whole, a long matrix cut with "…" instead.
    void longerTextsFitTheWindow()
    {
        QVERIFY(language::apply(QStringLiteral("en")));
        MainWindow window;
        window.resize(1920, 1080);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openDesign(QStringLiteral("fivebar-example")));
        QTest::qWait(50);
        const int englishDock = window.valuesTable()->width();
        switchTo(window, QStringLiteral("ru"));
        QTest::qWait(50);
        ModeBar *bar = window.modeBar();
        QCOMPARE(bar->labels().size(), 3);
        const QRect inside = bar->rect();
        int rows = 0, lastTop = -1;
        for (int i = 0; i < 3; ++i) {
            QAbstractButton *button = bar->button(i);
            const QRect where(button->mapTo(bar, QPoint(0, 0)), button->size());
            QVERIFY2(inside.contains(where), qPrintable(button->text()));
            QVERIFY(button->width() >= button->sizeHint().width()); // the whole text
            rows += where.top() != lastTop ? 1 : 0;
            lastTop = where.top();
        }
        QVERIFY(rows >= 2);
        // the legs' working modes share one caption in Russian, their buttons the leg numbers
        QCOMPARE(bar->button(1)->text(), QStringLiteral("1"));
        QCOMPARE(bar->button(2)->text(), QStringLiteral("2"));
        QCOMPARE(bar->button(1)->mapTo(bar, QPoint()).y(), bar->button(2)->mapTo(bar, QPoint()).y());
        const QList<QLabel *> captions = bar->findChildren<QLabel *>();
        QVERIFY(std::any_of(captions.begin(), captions.end(), [](const QLabel *label) {
            return label->text() == QStringLiteral("→ другой рабочий режим, нога:");
        }));
        QVERIFY(bar->button(1)->toolTip().contains(QStringLiteral("нога 1")));
        QVERIFY2(window.valuesTable()->width() >= englishDock - 2,
                 qPrintable(QStringLiteral("%1 < %2").arg(window.valuesTable()->width()).arg(englishDock)));
        ValuesTable *table = window.valuesTable();
        QVERIFY(table->columnWidth(0) + table->columnWidth(1) <= table->viewport()->width());
        const QTreeWidgetItem *theta = table->topLevelItem(1); // θ₁, under "Pose"
        QVERIFY(table->fontMetrics().horizontalAdvance(theta->text(1)) < table->columnWidth(1));
    }

    // A sheet exported in Russian has Russian headings; its JSON keys and numbers stay
    // locale-independent.
    void russianSheet()
    {
        QVERIFY(language::apply(QStringLiteral("ru")));
        MainWindow window;
        const sheet::Source source{"pjoint-prototype", window.document()->design().title,
                                   window.document()->design().description, window.document()->design().requirements};
        const sheet::Sheet built = kinds::buildSheet(*window.document()->mechanism(), window.document()->pose(), source);
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("ru.pdf"));
        const QString json = dir.filePath(QStringLiteral("ru.json"));
        QVERIFY(!sheet::save(built, pdf.toStdString()));
        QVERIFY(!sheet::save(built, json.toStdString()));

        const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
        if (pdftotext.isEmpty())
            QSKIP("pdftotext (poppler-utils) is not installed");
        QProcess process;
        process.start(pdftotext, {QStringLiteral("-enc"), QStringLiteral("UTF-8"), pdf, QStringLiteral("-")});
        QVERIFY(process.waitForFinished(30000));
        const QString text = QString::fromUtf8(process.readAllStandardOutput());
        for (const char *heading : {"Parameter sheet", "Design parameters"}) {
            const QString russian = QCoreApplication::translate("Sheet", heading);
            QVERIFY2(russian != QString::fromLatin1(heading), heading);
            QVERIFY2(text.contains(russian), qPrintable(russian + QStringLiteral(" not in:\n") + text.left(2000)));
        }
        QVERIFY(!text.contains(QStringLiteral("Design parameters")));

        QFile file(json);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray content = file.readAll();
        QVERIFY(content.contains("\"sections\""));
        QVERIFY(QRegularExpression(QStringLiteral("\\d\\.\\d")).match(QString::fromUtf8(content)).hasMatch());
    }
};

QTEST_MAIN(TestLanguages)
#include "tst_languages.moc"
