// The values panel (widgets/valuestable.h) a hair from a singular pose that the kind still calls
// regular: the capability group reports what the actuators deliver as at the singular pose
// (∞ and 0, never the rigid model's 10⁷ N), its title says so and its tooltip says why; back at a
// regular pose the title and the finite values return.

#include "kinds/fivebar/fivebar.h"
#include "support/kinematics.h"
#include "quantityformat.h"
#include "symboltext.h"
#include "valuestable.h"

#include <QApplication>
#include <QLabel>
#include <QTest>
#include <QTextDocument>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

using namespace pkm;

class TestValuesTable : public QObject
{
    Q_OBJECT

    /// The group row titled "Capability…", or nullptr.
    static const QTreeWidgetItem *capabilityGroup(const ValuesTable &table)
    {
        const QTreeWidget *tree = &table;
        for (int i = 0; i < tree->topLevelItemCount(); ++i) {
            if (tree->topLevelItem(i)->text(0).startsWith(QLatin1String("Capability")))
                return tree->topLevelItem(i);
        }
        return nullptr;
    }

private slots:
    void nearSingularCapability()
    {
        const MechanismPtr m = test::make(FiveBarDesign{});
        ValuesTable table;
        table.setMechanism(m);
        // both legs 200 mm long: stretched at C = (50, √(200² − 50²)); 10⁻¹¹ mm below it
        const auto near = m->solveInverse(test::pair(50.0, 193.64916731037));
        QVERIFY(near.ok());
        Singularity kindClass;
        test::evaluated(*m, *near, &kindClass);
        QCOMPARE(kindClass.type, SingularityType::None);
        table.setPose(*near);
        const QTreeWidgetItem *group = capabilityGroup(table);
        QVERIFY(group);
        QCOMPARE(group->text(0), QStringLiteral("Capability: as at a singular pose"));
        QVERIFY(table.valueText(QStringLiteral("capability")).contains(QLatin1String("inverse singularity")));
        QVERIFY(table.valueText(QStringLiteral("force_worst")).contains(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("stiffness_worst")).contains(QStringLiteral("∞")));
        QVERIFY(!table.valueText(QStringLiteral("force_best")).contains(QLatin1Char('e')));
        // J and det J too: ∞ as at the singularity, not the rigid model's −2.2·10⁹ rad²/mm²
        QVERIFY(table.valueText(QStringLiteral("det_J")).startsWith(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("J")).startsWith(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("singularity")).startsWith(QLatin1String("near inverse")));

        // 0.02 mm above the direct singularity at C = (50, √(80² − 70²)), where B, C and D are in
        // line: the kind's margin is 3·10⁻⁴, the platform holds no force and its error is ∞
        const auto nearDirect = m->solveInverse(test::pair(50.0, 38.75));
        QVERIFY(nearDirect.ok());
        test::evaluated(*m, *nearDirect, &kindClass);
        QCOMPARE(kindClass.type, SingularityType::None);
        table.setPose(*nearDirect);
        QCOMPARE(capabilityGroup(table)->text(0), QStringLiteral("Capability: as at a singular pose"));
        QVERIFY(table.valueText(QStringLiteral("capability")).contains(QLatin1String("direct singularity")));
        QVERIFY(table.valueText(QStringLiteral("resolution_worst")).contains(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("force_worst")).startsWith(QLatin1Char('0')));
        QVERIFY(table.valueText(QStringLiteral("cond")).startsWith(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("singularity")).startsWith(QLatin1String("near direct")));

        const auto regular = m->solveInverse(test::pair(50.0, 150.0));
        QVERIFY(regular.ok());
        table.setPose(*regular);
        QCOMPARE(capabilityGroup(table)->text(0), QStringLiteral("Capability"));
        QVERIFY(table.valueText(QStringLiteral("capability")).isEmpty());
        QVERIFY(!table.valueText(QStringLiteral("force_worst")).contains(QStringLiteral("∞")));
        QVERIFY(!table.valueText(QStringLiteral("det_J")).contains(QStringLiteral("∞")));
        QVERIFY(table.valueText(QStringLiteral("singularity")).startsWith(QLatin1String("none")));
    }
    /// The meaning column lowers subscripts as the symbol column does, and still ends a
    /// meaning too long for it with "…" (it showed "J_d = 2a·cos θ" with its underscore).
    void meaningsLowerSubscripts()
    {
        // a meaning too long for the values panel's column: lowered, and ended with "…" where
        // it no longer fits (the column elided the plain "J_d = 2a·cos θ" before)
        const QString meaning = QStringLiteral("J_d = 2a·cos θ, the derivative of d with respect to θ");
        const QFont font = QApplication::font();
        QCOMPARE(symbolHtmlElided(meaning, font, 10000), symbolHtml(meaning));
        for (int width : {60, 120, 200}) {
            const QString shown = symbolHtmlElided(meaning, font, width);
            QVERIFY2(shown.startsWith(QStringLiteral("J<sub>d</sub>")) && shown.endsWith(QStringLiteral("…")),
                qPrintable(shown));
            QTextDocument document;
            document.setDefaultFont(font);
            document.setDocumentMargin(0);
            document.setHtml(shown);
            QCOMPARE_LE(document.idealWidth(), width);
        }
    }
    /// In a dock as narrow as a projector leaves (340 px), the "Meaning" column showed "crank
    /// angl…" and nothing more: a strip below the table then gives the meaning of the row under
    /// the pointer in full, and goes while the column is wide enough.
    void meaningStripShowsWhatTheColumnCuts()
    {
        QWidget box;
        auto *layout = new QVBoxLayout(&box);
        auto *table = new ValuesTable;
        layout->addWidget(table, 1);
        QLabel *strip = table->meaningStrip();
        QCOMPARE(table->meaningStrip(), strip); // one strip
        layout->addWidget(strip);
        const MechanismPtr m = test::make(FiveBarDesign{});
        table->setMechanism(m);
        table->setPose(m->homePose());
        box.resize(340, 400);
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        QTRY_VERIFY(strip->isVisible());
        QVERIFY2(strip->text().contains(QLatin1String("Point at a row")), qPrintable(strip->text()));
        const QTreeWidget *tree = table;
        QTreeWidgetItem *row = nullptr;
        for (int i = 0; i < tree->topLevelItemCount() && !row; ++i) {
            if (tree->topLevelItem(i)->data(0, Qt::UserRole).toString() == QLatin1String("det_Jq"))
                row = tree->topLevelItem(i);
        }
        QVERIFY(row);
        QVERIFY(!row->text(2).isEmpty());
        emit table->itemEntered(row, 0);
        QCOMPARE(strip->text(), QStringLiteral("<b>%1</b> — %2").arg(symbolHtml(row->text(0)), symbolHtml(row->text(2))));
        // a group's title has no meaning: the row's stays
        emit table->itemEntered(tree->topLevelItem(0), 0);
        QVERIFY(strip->text().contains(symbolHtml(row->text(2))));
        // wide enough for every meaning: no strip
        box.resize(1400, 400);
        QTRY_VERIFY(!strip->isVisible());
        // and narrow again: the strip returns, with the same row
        box.resize(340, 400);
        QTRY_VERIFY(strip->isVisible());
        QVERIFY(strip->text().contains(symbolHtml(row->text(2))));
    }
};

QTEST_MAIN(TestValuesTable)
#include "tst_valuestable.moc"
