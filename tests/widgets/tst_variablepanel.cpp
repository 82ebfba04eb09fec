// The variable panel's rows in a panel of fixed width: the limits beside the sliders give way
// whenever the rows need their room, not only when the panel is resized.
#include "variablepanel.h"
#include "registry.h"

#include <QAbstractSpinBox>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QLabel>
#include <QTest>

#include <cmath>

using namespace pkm;

class TestVariablePanel : public QObject
{
    Q_OBJECT

    /// The spin boxes that the panel's edge cuts.
    static QStringList cutSpinBoxes(const VariablePanel &panel)
    {
        QStringList cut;
        for (const QAbstractSpinBox *spin : panel.findChildren<QAbstractSpinBox *>()) {
            if (spin->isVisible() && !panel.rect().contains(spin->geometry()))
                cut << spin->text();
        }
        return cut;
    }

private slots:
    /// A larger text (presentation mode's) widens the spin boxes a moment after the panel's
    /// font changes, with no resize to follow: the limits must go then, or the spin boxes were
    /// cut at the panel's edge, their arrows lost (the Russian O-X glide at 1280×720).
    void limitsGiveWayToALargerText()
    {
        const Result<MechanismPtr> oxglide = createMechanism("oxglide", {});
        QVERIFY(oxglide);
        VariablePanel panel;
        panel.setMechanism(*oxglide);
        panel.setPose((*oxglide)->homePose());
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        // as wide as the rows need with their limits, and no wider
        panel.setFixedWidth(panel.QWidget::minimumSizeHint().width() + 4);
        QApplication::processEvents();
        const auto limitsShown = [&panel] {
            for (const QLabel *label : panel.findChildren<QLabel *>()) {
                if (label->text().contains(QStringLiteral("130")) && label->isVisible())
                    return true;
            }
            return false;
        };
        QVERIFY(limitsShown());
        QVERIFY(cutSpinBoxes(panel).isEmpty());

        QFont larger = panel.font();
        larger.setPointSizeF(1.6 * larger.pointSizeF());
        panel.setFont(larger);
        QTest::qWait(50); // the queued widths, and the layout
        QTRY_VERIFY(!limitsShown());
        QVERIFY2(cutSpinBoxes(panel).isEmpty(), qPrintable(cutSpinBoxes(panel).join(QStringLiteral(", "))));
    }

    /// A pose beyond an output's range (an estimate for the 3-RP̲R's x, which a pose at another
    /// orientation passes) reads as it is: the spin box held to the range showed 18.50 mm where
    /// the status bar said 19.41 mm.
    void aValueBeyondTheRangeReadsAsItIs()
    {
        const Result<MechanismPtr> moma = createMechanism("moma", {});
        QVERIFY(moma);
        const Mechanism &m = **moma;
        VariablePanel panel;
        panel.setMechanism(*moma);
        const int x = m.inputCount(); // the first output
        const Interval range = m.variableRange(x);
        Pose pose = m.homePose();
        pose.outputs[0] = range.max + 0.92;
        panel.setPose(pose);
        const auto boxes = panel.findChildren<QDoubleSpinBox *>(); // the rows', in order
        QCOMPARE(boxes.size(), qsizetype(m.variableInfo().size()));
        const double expected = m.variableInfo()[std::size_t(x)].unit.toDisplay(range.max + 0.92);
        QVERIFY2(std::abs(boxes[x]->value() - expected) <= 0.5 * std::pow(10.0, -boxes[x]->decimals()) + 1e-12,
                 qPrintable(QStringLiteral("%1 shown for %2").arg(boxes[x]->value()).arg(expected)));
    }

    /// Typing a number past the range is not cut short: "199" where y ends at 196.1 mm kept
    /// "19" (Qt's validator refused the last key). Entered, the value stops at the end.
    void typingPastTheRangeStopsAtItsEnd()
    {
        const Result<MechanismPtr> fivebar = createMechanism("fivebar", {});
        QVERIFY(fivebar);
        const Mechanism &m = **fivebar;
        VariablePanel panel;
        panel.setMechanism(*fivebar);
        panel.setPose(m.homePose());
        double edited = 0.0;
        int variable = -1;
        connect(&panel, &VariablePanel::variableEdited, this, [&](int i, double value) {
            variable = i;
            edited = value;
        });
        const int y = m.inputCount() + 1;
        QDoubleSpinBox *box = panel.spinBox(y);
        const double top = box->maximum();
        QVERIFY(top < 199.0);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, QStringLiteral("199"));
        QVERIFY2(box->text().startsWith(QStringLiteral("199")), qPrintable(box->text()));
        QTest::keyClick(box, Qt::Key_Return);
        QCOMPARE(box->value(), top);
        QCOMPARE(variable, y);
        QCOMPARE(edited, m.variableInfo()[std::size_t(y)].unit.fromDisplay(top));
    }
};

QTEST_MAIN(TestVariablePanel)
#include "tst_variablepanel.moc"
