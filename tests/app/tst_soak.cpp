// GUI soak test: thousands of random but reproducible actions on the real main window, as a
// careless user makes them — drags in the view (on the handles and anywhere), the mouse wheel,
// slider keys, values typed into the joint fields and the Design panel (good ones, ones out of
// range, 1e308, nan, words), mode switches, undo and redo, Play, bookmarks and the language.
// After every action the window must be consistent: the document's pose is finite, the joint
// fields show it, the view draws it, and nothing on screen reads nan, inf or a 13-digit number.
// Each episode opens a preset; at its end everything is undone, and the design file must be
// byte-identical to the preset's (with the pose, which is not an edit, put back).
//
// PKM_SOAK_SEED and PKM_SOAK_ACTIONS change the seed and the number of actions; a failure
// names the seed, the episode and the action, so that it can be replayed.
#include "gui/mainwindow.h"

#include "designpanel.h"
#include "document/designfile.h"
#include "document/document.h"
#include "linkageview.h"
#include "modebar.h"
#include "support/app.h"
#include "valuestable.h"
#include "variablepanel.h"

#include <QAbstractButton>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSlider>
#include <QStatusBar>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>
#include <QWheelEvent>

#include <cmath>
#include <random>

using namespace pkm;
using namespace pkm::test;

/// QVERIFY2 with the failure's context made only when it fails (describe() saves a file).
#define SOAK_VERIFY(condition, what)                                                                                   \
    do {                                                                                                               \
        if (!(condition))                                                                                              \
            QFAIL(qPrintable(describe(what)));                                                                         \
    } while (false)

namespace {

quint64 environmentNumber(const char *name, quint64 fallback)
{
    bool ok = false;
    const quint64 value = qEnvironmentVariable(name).toULongLong(&ok);
    return ok ? value : fallback;
}

/// What a user may type into a number field: a plausible value, one far out, and junk.
QString typedValue(std::mt19937_64 &random, double current)
{
    static const QStringList junk{QStringLiteral("1e308"), QStringLiteral("-1e308"), QStringLiteral("nan"),
                                  QStringLiteral("inf"), QStringLiteral("abc"), QStringLiteral(""),
                                  QStringLiteral("0"), QStringLiteral("-0"), QStringLiteral("1e-300"),
                                  QStringLiteral("12,5"), QStringLiteral("--3"), QStringLiteral("\x1b[2J")};
    std::uniform_real_distribution<double> factor(0.5, 1.5);
    switch (random() % 4) {
    case 0:
        return junk[qsizetype(random() % quint64(junk.size()))];
    case 1:
        return QString::number(current * 1000.0 + 7.0);
    default:
        return QString::number(current * factor(random) + (current == 0.0 ? factor(random) : 0.0), 'g', 6);
    }
}

void typeInto(QLineEdit *edit, const QString &text)
{
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

/// Text that must never be shown for a value: nan, inf, or a number of 13 digits and more.
const QRegularExpression &nonsense()
{
    static const QRegularExpression pattern(QStringLiteral("\\b(nan|inf|infinity)\\b|\\d{13,}"),
                                            QRegularExpression::CaseInsensitiveOption);
    return pattern;
}

} // namespace

class TestSoak : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;
    std::mt19937_64 m_random;
    QString m_where; ///< "seed S, episode E, action A (what)" for failure messages
    QMap<QString, double> m_time; ///< milliseconds spent per kind of action
    QMap<QString, int> m_count;
    int m_episodeStart = 0; ///< the undo stack's index when the episode's preset was opened

    /// The first action of the window whose shortcut is `key`.
    QAction *actionWith(const QKeySequence &key) const
    {
        for (QAction *action : m_window->findChildren<QAction *>())
            if (action->shortcut() == key)
                return action;
        return nullptr;
    }

    /// The failure's context: where in the run, and the pose (core units) and design.
    QString describe(const QString &what) const
    {
        const Pose &pose = m_window->document()->pose();
        QStringList values;
        for (double v : pose.inputs)
            values << QString::number(v, 'g', 17);
        values << QStringLiteral("|");
        for (double v : pose.outputs)
            values << QString::number(v, 'g', 17);
        // the design as it stood, to open in PKM Studio or `pkm eval`
        const QString saved = QDir::temp().filePath(QStringLiteral("pkm-soak-failure.pkm.json"));
        const bool written = bool(designfile::save(m_window->document()->design(), saved));
        return m_where + QStringLiteral(": ") + what + QStringLiteral("\npose ") + values.join(QLatin1Char(' ')) +
               (written ? QStringLiteral("\ndesign saved in ") + saved : QString());
    }

    /// Document, joint fields, view and texts agree; QVERIFY2 names the action that broke it.
    void checkConsistent()
    {
        MainWindow &w = *m_window;
        const Mechanism &mechanism = *w.document()->mechanism();
        const Pose &pose = w.document()->pose();
        const int count = mechanism.inputCount() + mechanism.outputCount();
        SOAK_VERIFY(pose.inputs.allFinite() && pose.outputs.allFinite(), QStringLiteral("pose not finite"));
        for (int i = 0; i < count; ++i) {
            QDoubleSpinBox *box = w.variablePanel()->spinBox(i);
            if (!box)
                continue;
            const VariableInfo &info = mechanism.variableInfo()[std::size_t(i)];
            const double shown = info.unit.toDisplay(mechanism.variableValue(pose, i));
            const double step = std::pow(10.0, -box->decimals());
            SOAK_VERIFY(std::abs(box->value() - std::clamp(shown, box->minimum(), box->maximum())) <= step,
                        QStringLiteral("field %1 shows %2, the pose has %3")
                            .arg(QString::fromStdString(info.name))
                            .arg(box->value())
                            .arg(shown));
        }
        // the view draws the document's pose
        const Scene expected = mechanism.scene(pose);
        const Scene &drawn = w.linkageView()->scene();
        SOAK_VERIFY(drawn.joints.size() == expected.joints.size(), QStringLiteral("joints drawn"));
        for (std::size_t j = 0; j < expected.joints.size(); ++j)
            SOAK_VERIFY((drawn.joints[j].position - expected.joints[j].position).norm() <=
                            1e-9 * (1 + expected.joints[j].position.norm()),
                        QStringLiteral("joint %1 drawn away from the pose").arg(j));
        // nothing shown reads as nonsense: labels, buttons, values, status bar, view message
        QStringList shown{w.statusBar()->currentMessage(), w.linkageView()->shownMessage()};
        for (QLabel *label : w.findChildren<QLabel *>())
            if (label->isVisible())
                shown << label->text();
        for (QAbstractButton *button : w.findChildren<QAbstractButton *>())
            if (button->isVisible())
                shown << button->text();
        for (QTreeWidgetItemIterator it(w.valuesTable()); *it; ++it)
            for (int column = 0; column < w.valuesTable()->columnCount(); ++column)
                shown << (*it)->text(column);
        // what the user typed may be quoted back ("„inf“ is not a number"): that is not a value
        static const QRegularExpression quotedText(QStringLiteral("„[^“]*“|“[^”]*”|«[^»]*»|'[^']*'|\"[^\"]*\""));
        for (QString text : shown) {
            text.remove(quotedText);
            const auto match = nonsense().match(text);
            SOAK_VERIFY(!match.hasMatch(), QStringLiteral("shown: '%1'").arg(text.left(300)));
        }
    }

    /// One random action; returns what it was.
    QString act()
    {
        MainWindow &w = *m_window;
        const Mechanism &mechanism = *w.document()->mechanism();
        const int variables = mechanism.inputCount() + mechanism.outputCount();
        LinkageView *view = w.linkageView();
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const auto pick = [&](int n) { return n <= 0 ? 0 : int(m_random() % quint64(n)); };
        const QPointF anywhere(view->width() * unit(m_random), view->height() * unit(m_random));
        switch (m_random() % 12) {
        case 0:
        case 1: { // drag a handle somewhere
            const int handles = int(view->scene().handles.size());
            if (handles == 0)
                return QStringLiteral("no handle");
            const int handle = pick(handles);
            const QPointF from = view->handlePosition(handle);
            const QPointF to = from + QPointF((unit(m_random) - 0.5) * 300, (unit(m_random) - 0.5) * 300);
            drag(view, from, to, 1 + pick(6));
            return QStringLiteral("drag handle %1").arg(handle);
        }
        case 2: // a drag that starts anywhere (pans, or misses)
            drag(view, anywhere, anywhere + QPointF(40, -30), 3);
            return QStringLiteral("drag anywhere");
        case 3: { // the wheel (zoom)
            const QPoint delta(0, m_random() % 2 ? 120 : -120);
            QWheelEvent wheel(anywhere, view->mapToGlobal(anywhere), QPoint(), delta, Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(view, &wheel);
            return QStringLiteral("wheel");
        }
        case 4: { // slider keys
            QSlider *slider = w.variablePanel()->slider(pick(variables));
            if (!slider || !slider->isEnabled())
                return QStringLiteral("no slider");
            static const Qt::Key keys[] = {Qt::Key_PageUp, Qt::Key_PageDown, Qt::Key_Left, Qt::Key_Right, Qt::Key_Home, Qt::Key_End};
            const Qt::Key key = keys[pick(6)];
            slider->setFocus();
            QTest::keyClick(slider, key);
            return QStringLiteral("slider key %1").arg(int(key));
        }
        case 5: { // a value typed into a joint field
            const int variable = pick(variables);
            QDoubleSpinBox *box = w.variablePanel()->spinBox(variable);
            if (!box || !box->isEnabled())
                return QStringLiteral("no joint field");
            const QString text = typedValue(m_random, box->value());
            typeInto(box->findChild<QLineEdit *>(), text);
            return QStringLiteral("joint field %1 '%2'").arg(variable).arg(text);
        }
        case 6:
        case 7: { // a value typed into a design field
            QList<QLineEdit *> fields;
            for (QLineEdit *field : w.designPanel()->findChildren<QLineEdit *>())
                if (field->isVisible() && field->isEnabled() && !field->isReadOnly())
                    fields << field;
            if (fields.isEmpty())
                return QStringLiteral("no design field");
            QLineEdit *field = fields[pick(int(fields.size()))];
            const QString text = typedValue(m_random, QLocale().toDouble(field->text()));
            typeInto(field, text);
            return QStringLiteral("design field %1 '%2'").arg(field->objectName(), text);
        }
        case 8: { // undo or redo, as the Edit menu does (not past the episode's start: its end undoes to there)
            const bool undo = m_random() % 3 && w.document()->undoStack()->index() > m_episodeStart;
            QAction *action = actionWith(undo ? QKeySequence::Undo : QKeySequence::Redo);
            if (!action)
                return QStringLiteral("no undo action");
            action->trigger();
            return action->shortcut().toString();
        }
        case 9: { // another working or assembly mode
            const int modes = int(w.modeBar()->labels().size());
            if (modes == 0)
                return QStringLiteral("no mode");
            QAbstractButton *button = w.modeBar()->button(pick(modes));
            if (!button || !button->isVisible() || !button->isEnabled())
                return QStringLiteral("mode button hidden");
            const QString label = button->text(); // the click rebuilds the bar
            QTest::mouseClick(button, Qt::LeftButton);
            return QStringLiteral("mode %1").arg(label);
        }
        case 10: { // Play for a moment
            w.setPlaying(true);
            QTest::qWait(30);
            w.setPlaying(false);
            return QStringLiteral("play");
        }
        default: { // a bookmark, or the language
            if (m_random() % 4 == 0) {
                static const QStringList languages{QStringLiteral("ru"), QStringLiteral("sr"), QStringLiteral("sr_Latn"),
                                                   QStringLiteral("en")};
                const QString code = languages[pick(4)];
                w.setLanguage(code);
                return QStringLiteral("language %1").arg(code);
            }
            if (QAction *bookmark = actionWith(QKeySequence(Qt::CTRL | Qt::Key_B))) {
                bookmark->trigger();
                return QStringLiteral("bookmark");
            }
            return QStringLiteral("no bookmark action");
        }
        }
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1280, 720});
        QVERIFY(m_window);
        m_window->setQuestion([](const QString &, const QString &, QMessageBox::StandardButtons) { return QMessageBox::Discard; });
    }

    void cleanupTestCase()
    {
        m_window->setLanguage(QStringLiteral("en"));
        delete m_window;
    }

    void randomActions()
    {
        const quint64 seed = environmentNumber("PKM_SOAK_SEED", 20261202);
        const int total = int(environmentNumber("PKM_SOAK_ACTIONS", 2000));
        const int perEpisode = 100;
        m_random.seed(seed);
        const QList<PresetInfo> presets = everyPreset();
        QVERIFY(!presets.isEmpty());
        int done = 0;
        for (int episode = 0; done < total; ++episode) {
            const PresetInfo &preset = presets[qsizetype(m_random() % quint64(presets.size()))];
            m_where = QStringLiteral("seed %1, episode %2, open %3").arg(seed).arg(episode).arg(preset.id);
            QVERIFY2(m_window->openDesign(preset.id), qPrintable(m_where));
            QUndoStack *stack = m_window->document()->undoStack();
            const int start = stack->index();
            m_episodeStart = start;
            const Design opened = m_window->document()->design();
            const QByteArray before = designfile::serialize(opened);
            checkConsistent();
            for (int a = 0; a < perEpisode && done < total; ++a, ++done) {
                m_where = QStringLiteral("seed %1, episode %2 (%3), action %4").arg(seed).arg(episode).arg(preset.id).arg(a);
                QElapsedTimer timer;
                timer.start();
                const QString what = act();
                QCoreApplication::processEvents();
                const QString kind = what.section(QLatin1Char(' '), 0, 1);
                m_time[kind] += timer.nsecsElapsed() * 1e-6;
                ++m_count[kind];
                m_where += QStringLiteral(" (%1)").arg(what);
                checkConsistent();
                if (QTest::currentTestFailed())
                    return;
            }
            // Undo everything this episode did, as the Edit menu does.
            QAction *undo = actionWith(QKeySequence::Undo);
            QVERIFY(undo);
            for (int guard = 0; stack->index() > start && guard < 10000; ++guard)
                undo->trigger();
            m_where = QStringLiteral("seed %1, episode %2 (%3), undo all").arg(seed).arg(episode).arg(preset.id);
            QCOMPARE(stack->index(), start);
            checkConsistent();
            Design after = m_window->document()->design();
            after.pose = opened.pose; // the pose is where the mechanism stands, not an edit
            QVERIFY2(designfile::serialize(after) == before, qPrintable(m_where + QStringLiteral(": the design file differs")));
        }
        qInfo("%d actions, seed %llu; milliseconds per action:", done, static_cast<unsigned long long>(seed));
        for (auto it = m_time.cbegin(); it != m_time.cend(); ++it)
            qInfo("  %-24s %5d × %8.1f", qPrintable(it.key()), m_count[it.key()], it.value() / m_count[it.key()]);
    }
};

QTEST_MAIN(TestSoak)
#include "tst_soak.moc"
