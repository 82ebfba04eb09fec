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
#include <QTranslator>

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

    /// A Design panel of `kind` in `area`, as the Design dock holds it: never scrolled sideways.
    static DesignPanel *panelIn(QScrollArea &area, const QByteArray &kind)
    {
        auto *panel = new DesignPanel;
        area.setWidget(panel);
        area.setWidgetResizable(true);
        area.setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        panel->setMechanism(makeKind(kind.constData()));
        return panel;
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
        DesignPanel *panel = panelIn(area, kind);
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

    // At every width the panel's rows either fit side by side or stand stacked: a width just
    // under what they need side by side (the estimate was 8 px short) cut each line's end.
    void noWidthCutsTheRows_data()
    {
        QTest::addColumn<QByteArray>("kind");
        QTest::addColumn<QString>("language");
        for (const char *language : {"en", "ru", "sr", "sr_Latn"})
            for (const char *kind : {"pjoint", "moma", "fivebar", "planar-parallel"})
                QTest::addRow("%s %s", language, kind) << QByteArray(kind) << QString::fromLatin1(language);
    }
    void noWidthCutsTheRows()
    {
        QFETCH(QByteArray, kind);
        QFETCH(QString, language);
        QTranslator catalogue;
        if (language != QLatin1String("en")) {
            QVERIFY(catalogue.load(QStringLiteral(":/i18n/pkm_studio_") + language));
            QCoreApplication::installTranslator(&catalogue);
        }
        QScrollArea area;
        DesignPanel *panel = panelIn(area, kind);
        area.resize(420, 600);
        area.show();
        QVERIFY(QTest::qWaitForWindowExposed(&area));
        int besideAt = 0;
        for (int width = 420; width >= 270; width -= 2) {
            area.resize(width, 600);
            QTest::qWait(1);
            QCoreApplication::processEvents();
            const int view = area.viewport()->width();
            QVERIFY2(panel->minimumSizeHint().width() <= view,
                     qPrintable(QStringLiteral("%1 px wanted in a view of %2").arg(panel->minimumSizeHint().width()).arg(view)));
            if (besideAndUnder(panel).first > 0)
                besideAt = view;
        }
        QVERIFY(besideAt > 0); // stacking at 230 px is fieldsGoUnderTheirLabelsWhenNarrow's
    }
};

QTEST_MAIN(TestDesignPanel)
#include "tst_designpanel.moc"
