// The Design panel in a dock narrower than a label's longest word, its field and its unit side
// by side: each field goes under its label, so that no line is cut at the panel's edge (the
// dock's panel does not scroll sideways; a Russian MOMA note lost "°," after "γ₁ = −5"); in a
// wide dock each label stands beside its field again.
#include "designpanel.h"
#include "support/kinematics.h"

#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QTest>

using namespace pkm;
using namespace pkm::test;

class TestDesignPanel : public QObject
{
    Q_OBJECT

private:
    /// How many of the shown fields stand beside their label's first line, and how many under it.
    static std::pair<int, int> besideAndUnder(DesignPanel *panel)
    {
        int beside = 0, under = 0;
        for (QLabel *label : panel->findChildren<QLabel *>()) {
            QWidget *field = label->buddy();
            if (!field || !field->isVisibleTo(panel) || !label->isVisibleTo(panel))
                continue;
            const int fieldTop = field->mapTo(panel, QPoint(0, 0)).y();
            const int labelTop = label->mapTo(panel, QPoint(0, 0)).y();
            (fieldTop >= labelTop + label->height() - 2 ? under : beside) += 1;
        }
        return {beside, under};
    }

private slots:
    void fieldsGoUnderTheirLabelsWhenNarrow_data()
    {
        QTest::addColumn<QByteArray>("kind");
        for (const char *kind : {"pjoint", "moma", "fivebar", "planar-parallel"})
            QTest::newRow(kind) << QByteArray(kind);
    }
    void fieldsGoUnderTheirLabelsWhenNarrow()
    {
        QFETCH(QByteArray, kind);
        QScrollArea area;
        auto *panel = new DesignPanel;
        area.setWidget(panel);
        area.setWidgetResizable(true);
        area.setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        panel->setMechanism(makeKind(kind.constData()));
        panel->setNote(QStringLiteral("A design's title (a = 170 mm, k = 0.4)"), QStringLiteral("Its note. More."));
        area.resize(420, 600);
        area.show();
        QVERIFY(QTest::qWaitForWindowExposed(&area));
        QTest::qWait(20);
        const auto [wideBeside, wideUnder] = besideAndUnder(panel);
        QVERIFY(wideBeside > 0);
        QCOMPARE(panel->width(), area.viewport()->width());
        area.resize(230, 600);
        QTest::qWait(20);
        const auto [narrowBeside, narrowUnder] = besideAndUnder(panel);
        // nothing wider than what is in sight, and every field under its label
        QCOMPARE(panel->width(), area.viewport()->width());
        QCOMPARE(narrowBeside, 0);
        QVERIFY(narrowUnder > wideUnder);
        area.resize(420, 600);
        QTest::qWait(20);
        QCOMPARE(besideAndUnder(panel), std::make_pair(wideBeside, wideUnder));
    }
};

QTEST_MAIN(TestDesignPanel)
#include "tst_designpanel.moc"
