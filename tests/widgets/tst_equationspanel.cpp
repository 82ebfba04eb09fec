// The equations panel (widgets/equationspanel.h): for every kind its equations are shown and each
// result reads exactly as the values panel shows the same quantity; the text follows the pose
// (a hidden panel catches up when shown); at a singular pose it says ∞ or —, as the values do.

#include "equationspanel.h"
#include "kinds/oxglide/oxglide.h"
#include "support/kinematics.h"
#include "support/planardesigns.h"
#include "valuestable.h"

#include <QLocale>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QTest>
#include <QAbstractTextDocumentLayout>
#include <QTextBlock>
#include <QTextLayout>
#include <QTextDocument>

#include <cmath>

using namespace pkm;

class TestEquationsPanel : public QObject
{
    Q_OBJECT

    /// Every result that is a scalar of the report reads as the values panel reads it.
    static void compareWithValues(const EquationsPanel &panel, const ValuesTable &values, const Mechanism &m)
    {
        const std::vector<Equation> &equations = panel.shownEquations();
        QVERIFY(!equations.empty());
        int compared = 0;
        for (int i = 0; i < int(equations.size()); ++i) {
            const std::string &name = equations[std::size_t(i)].resultName;
            const ReportEntry *entry = name.empty() ? nullptr : m.reportLayout().find(name);
            QVERIFY(panel.substitutedText(i).endsWith(panel.resultText(i)));
            if (!entry || entry->rows * entry->cols != 1)
                continue;
            QCOMPARE(panel.resultText(i), values.valueText(QString::fromStdString(name)));
            ++compared;
        }
        QVERIFY2(compared >= 2, "too few results to hold against the values panel");
    }

private slots:
    void readsAsTheValuesPanel_data() { test::addKindRows(); }
    void readsAsTheValuesPanel()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = test::makeKind(kind.toStdString());
        EquationsPanel panel;
        ValuesTable values;
        panel.show();
        panel.setMechanism(m);
        values.setMechanism(m);
        Pose pose = m->homePose();
        panel.setPose(pose);
        values.setPose(pose);
        compareWithValues(panel, values, *m);
        // another pose: the first variable at three quarters of its range
        const Interval range = m->variableRange(0);
        if (auto moved = m->solveWith(pose, 0, range.min + 0.75 * (range.max - range.min))) {
            panel.setPose(*moved);
            values.setPose(*moved);
            compareWithValues(panel, values, *m);
        }
    }

    void numbersRewrittenInPlaceReadAsAFreshPage_data() { test::addKindRows(); }
    void numbersRewrittenInPlaceReadAsAFreshPage()
    {
        // A slider step rewrites only the lines of numbers (the page is not built again): what
        // it shows must be what a panel that built its page at that pose shows, results bold.
        QFETCH(QString, kind);
        const MechanismPtr m = test::makeKind(kind.toStdString());
        EquationsPanel stepped;
        stepped.show();
        stepped.setMechanism(m);
        Pose pose = m->homePose();
        stepped.setPose(pose);
        const Interval range = m->variableRange(0);
        for (double fraction : {0.3, 0.6, 0.8}) {
            auto moved = m->solveWith(pose, 0, range.min + fraction * (range.max - range.min));
            if (!moved)
                continue;
            pose = *moved;
            stepped.setPose(pose);
            EquationsPanel fresh;
            fresh.show();
            fresh.setMechanism(m);
            fresh.setPose(pose);
            QCOMPARE(stepped.toPlainText(), fresh.toPlainText());
            for (int i = 0; i < int(stepped.shownEquations().size()); ++i)
                QCOMPARE(stepped.resultText(i), fresh.resultText(i));
        }
        // the results are still bold, and no undo history grows under the slider
        QVERIFY(!stepped.document()->isUndoAvailable());
        QStringList bold;
        for (QTextBlock block = stepped.document()->begin(); block.isValid(); block = block.next()) {
            for (auto it = block.begin(); !it.atEnd(); ++it) {
                if (it.fragment().charFormat().fontWeight() == QFont::Bold)
                    // the spaces that do not break as spaces; the joiners that keep "rad/s" whole unseen
                    bold << it.fragment().text().replace(QChar(0x00A0), QLatin1Char(' ')).remove(QChar(0x2060)).remove(QChar(0x200B));
            }
        }
        for (int i = 0; i < int(stepped.shownEquations().size()); ++i)
            QVERIFY2(bold.contains(stepped.resultText(i)), qPrintable(stepped.resultText(i)));
    }

    void followsThePose()
    {
        const MechanismPtr m = test::makeKind("pjoint");
        const int theta = m->variableIndex("theta");
        EquationsPanel panel;
        panel.show();
        panel.setMechanism(m);
        auto at0 = m->solveWith(m->homePose(), theta, 0.0);
        auto at30 = m->solveWith(m->homePose(), theta, 30.0 * units::degree);
        QVERIFY(at0 && at30);
        panel.setPose(*at0);
        QCOMPARE(panel.resultText(0), QStringLiteral("183.10 mm"));
        QVERIFY(panel.toPlainText().contains(QStringLiteral("sin 0.00°")));
        panel.setPose(*at30);
        QCOMPARE(panel.resultText(0), QStringLiteral("212.33 mm")); // 170·√(1.16 + 0.8·sin 30°)
        QVERIFY(panel.toPlainText().contains(QStringLiteral("sin 30.00°")));
        // hidden (a tab behind another): no work until it is shown, then the latest pose
        panel.hide();
        panel.setPose(*at0);
        QCOMPARE(panel.resultText(0), QStringLiteral("212.33 mm"));
        panel.show();
        QCOMPARE(panel.resultText(0), QStringLiteral("183.10 mm"));
    }

    /// The page says first that the numbers put in are rounded: MOMA 3c's C₁ worked out by
    /// hand from the shown x = −40.70 mm is 48138.0 mm², the page's exact value 48140.9 mm².
    void saysTheNumbersAreRounded()
    {
        const MechanismPtr m = test::makeKind("moma");
        EquationsPanel panel;
        panel.show();
        panel.setMechanism(m);
        panel.setPose(m->homePose());
        const QString first = panel.document()->firstBlock().text();
        QCOMPARE(first, QString::fromStdString(equations::roundingNote()));
        QVERIFY(first.contains(QStringLiteral("rounded")));
        QVERIFY(panel.toPlainText().indexOf(first) == 0);
    }

    /// A narrow panel wraps a line between terms: not inside a number ("17879,3" / "79" in a
    /// product of numbers with no place to break) nor after a unit's slash ("рад/" / "с").
    void wrapsBetweenTerms_data()
    {
        test::addKindRows();
        // its det J_x is a 3×3 matrix of numbers, one long list
        QTest::newRow("3-RPR") << QStringLiteral("planar-parallel/3-RPR");
        // and with a decimal comma, which the list's separators must not be taken for
        QTest::newRow("3-RPR ru") << QStringLiteral("planar-parallel/3-RPR ru");
    }
    void wrapsBetweenTerms()
    {
        QFETCH(QString, kind);
        const bool russian = kind.endsWith(QStringLiteral(" ru"));
        const QLocale before;
        if (russian)
            QLocale::setDefault(QLocale(QLocale::Russian, QLocale::Russia));
        const auto restore = qScopeGuard([&] { QLocale::setDefault(before); });
        const MechanismPtr m = kind.startsWith(QStringLiteral("planar-parallel/3-RPR"))
            ? test::makeKind("planar-parallel", test::legdesigns::threeRpr())
            : test::makeKind(kind.toStdString());
        EquationsPanel panel;
        panel.resize(190, 800);
        panel.show();
        panel.setMechanism(m);
        panel.setPose(m->homePose());
        QTextDocument *document = panel.document();
        QStringList bad;
        for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
            document->documentLayout()->blockBoundingRect(block); // laid out
            const QString text = block.text();
            for (int i = 1; i < block.layout()->lineCount(); ++i) {
                const int at = block.layout()->lineAt(i).textStart();
                if (at <= 0 || at >= text.size())
                    continue;
                const QChar before = text.at(at - 1), after = text.at(at);
                // not inside a number or a unit, nor between a sign and its term
                if (((before.isDigit() || before == u'/') && after.isLetterOrNumber()) || before == QChar(0x2212))
                    bad << text.left(at) + QStringLiteral(" | ") + text.mid(at);
            }
        }
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join(QLatin1Char('\n'))));
    }

    void singularPoseSaysSo()
    {
        const MechanismPtr m = test::makeKind("oxglide");
        const OxGlideDesign &g = static_cast<const OxGlide &>(*m).design();
        Pose crossing; // the O↔X crossing, rods parallel and perpendicular to the guides
        crossing.inputs = test::triple(65.0 - 0.5 * g.width, 65.0 + 0.5 * g.width, 0.0);
        crossing.outputs = test::pair(65.0, g.rod);
        EquationsPanel panel;
        ValuesTable values;
        panel.show();
        panel.setMechanism(m);
        values.setMechanism(m);
        panel.setPose(crossing);
        values.setPose(crossing);
        compareWithValues(panel, values, *m);
        QStringList results;
        for (int i = 0; i < int(panel.shownEquations().size()); ++i)
            results << panel.resultText(i);
        QVERIFY(results.contains(QStringLiteral("—"))); // det J: 0 and ∞ at once
        QVERIFY(results.contains(QStringLiteral("∞")));  // κ(J)
        QVERIFY2(!QRegularExpression(QStringLiteral("[0-9]{10,}")).match(panel.toPlainText()).hasMatch(),
                 qPrintable(panel.toPlainText()));
    }
};

QTEST_MAIN(TestEquationsPanel)
#include "tst_equationspanel.moc"
