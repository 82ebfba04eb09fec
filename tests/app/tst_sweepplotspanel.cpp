// The generic panel of a kind with one input and no panel of its own: its curve is the
// mechanism's own report along the input's range (evaluate() at the poses the direct kinematics
// gives), with gaps where no pose exists, never a NaN or an inf on an axis; the cursor follows
// the pose; a new design of the same kind keeps the quantity chosen, and so does a language
// switch. The П-joint and the four-bar stand in for such a kind: the panel only reads the
// Mechanism interface.

#include "kinds/sweepplotspanel.h"

#include "registry.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QtTest>

#include <cmath>

using namespace pkm;

namespace {

MechanismPtr make(std::string_view kind, const ParameterSet &parameters = {})
{
    auto made = createMechanism(kind, parameters);
    return made ? *made : nullptr;
}

/// The value of the report entry `name` at `pose`, display unit.
double reportValue(const Mechanism &mechanism, const Pose &pose, const std::string &name)
{
    std::vector<double> values(static_cast<std::size_t>(mechanism.reportLayout().size));
    mechanism.evaluate(pose, values);
    const ReportEntry *entry = mechanism.reportLayout().find(name);
    return entry->unit.toDisplay(values[static_cast<std::size_t>(entry->offset)]);
}

} // namespace

class TestSweepPlotsPanel : public QObject
{
    Q_OBJECT

private slots:
    void showsOnlyOneInputKinds()
    {
        QVERIFY(SweepPlotsPanel::canShow(*make("pjoint")));
        QVERIFY(SweepPlotsPanel::canShow(*make("fourbar")));
        QVERIFY(!SweepPlotsPanel::canShow(*make("moma"))); // two inputs
    }

    void curveIsTheReportAlongTheInput()
    {
        const MechanismPtr mechanism = make("pjoint");
        SweepPlotsPanel panel;
        panel.resize(800, 600);
        panel.setDesign(mechanism, QStringLiteral("test"));
        panel.setPose(mechanism->homePose());
        QVERIFY(panel.quantityBox()->count() > 3);
        const int index = panel.quantityBox()->findData(QStringLiteral("J"));
        QVERIFY(index >= 0);
        panel.quantityBox()->setCurrentIndex(index);
        QCOMPARE(panel.inputs().size(), panel.values().size());
        QVERIFY(panel.inputs().size() > 100);
        const VariableInfo &input = mechanism->variableInfo().front();
        for (std::size_t i = 0; i < panel.inputs().size(); i += 40) {
            Coordinates q = mechanism->homePose().inputs;
            q[0] = input.unit.fromDisplay(panel.inputs()[i]);
            const auto pose = mechanism->solveDirect(q);
            QVERIFY(pose.ok());
            QVERIFY(std::abs(panel.values()[i] - reportValue(*mechanism, *pose, "J")) < 1e-9 * std::abs(panel.values()[i]) + 1e-12);
        }
        // the cursor is at the pose
        QCOMPARE(panel.cursorInput(), input.unit.toDisplay(mechanism->homePose().inputs[0]));
        const QCPRange y = panel.plot()->yAxis->range();
        QVERIFY(std::isfinite(y.lower) && std::isfinite(y.upper) && y.upper > y.lower);
    }

    void partialCrankKeepsFiniteAxes()
    {
        // A crank-rocker with a long crank turns only part of the way: steps the loop cannot
        // close are gaps (NaN in the samples), and the axes stay finite.
        const MechanismPtr mechanism = make("fourbar", {{"AB", 130.0}});
        QVERIFY(mechanism);
        SweepPlotsPanel panel;
        panel.setDesign(mechanism, QStringLiteral("test"));
        panel.setPose(mechanism->homePose());
        int finite = 0;
        for (double value : panel.values()) {
            QVERIFY(std::isfinite(value) || std::isnan(value)); // a gap, never an inf
            finite += std::isfinite(value) ? 1 : 0;
        }
        QVERIFY(finite > 10);
        const QCPRange y = panel.plot()->yAxis->range();
        QVERIFY(std::isfinite(y.lower) && std::isfinite(y.upper));
    }

    void keepsTheChoiceForTheSameKind()
    {
        SweepPlotsPanel panel;
        panel.setDesign(make("pjoint"), QStringLiteral("a"));
        panel.quantityBox()->setCurrentIndex(panel.quantityBox()->findData(QStringLiteral("mu")));
        panel.setDesign(make("pjoint", {{"k", 0.5}}), QStringLiteral("b"));
        QCOMPARE(panel.quantityBox()->currentData().toString(), QStringLiteral("mu"));
        QEvent change(QEvent::LanguageChange);
        QCoreApplication::sendEvent(&panel, &change);
        QCOMPARE(panel.quantityBox()->currentData().toString(), QStringLiteral("mu"));
    }
};

QTEST_MAIN(TestSweepPlotsPanel)
#include "tst_sweepplotspanel.moc"
