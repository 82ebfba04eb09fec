// The document: the only writer of the design and the pose; undo/redo of design edits.
#include "document/document.h"

#include "kinds/moma/moma.h"
#include "kinds/pjoint/pjoint.h"

#include <algorithm>
#include <QSignalSpy>
#include <QTest>

using namespace pkm;

namespace {
double parameter(const Document &document, const char *name)
{
    return document.mechanism()->parameters().at(name);
}
} // namespace

class TestDocument : public QObject
{
    Q_OBJECT

private slots:
    void startsWithPrototype()
    {
        Document document;
        QCOMPARE(document.mechanism()->kind(), std::string_view("pjoint"));
        QCOMPARE(parameter(document, "a"), 170.0);
        QCOMPARE(parameter(document, "b"), 68.0);
        QCOMPARE(document.pose().outputs[0], 0.0);
        QVERIFY(!document.undoStack()->canUndo());
    }

    void parameterEditUndoRedo()
    {
        Document document;
        QSignalSpy designSpy(&document, &Document::designChanged);
        QVERIFY(document.setParameter(QStringLiteral("a"), 200).ok());
        QCOMPARE(parameter(document, "a"), 200.0);
        QCOMPARE(designSpy.count(), 1);
        QVERIFY(document.setParameter(QStringLiteral("k"), 0.5).ok());
        QCOMPARE(parameter(document, "b"), 100.0);
        QCOMPARE(document.undoStack()->count(), 2);
        document.undoStack()->undo();
        QCOMPARE(parameter(document, "b"), 68.0);
        document.undoStack()->undo();
        QCOMPARE(parameter(document, "a"), 170.0);
        document.undoStack()->redo();
        QCOMPARE(parameter(document, "a"), 200.0);
        QCOMPARE(designSpy.count(), 5);
    }

    void steppingMergesIntoOneStep()
    {
        Document document;
        for (int i = 1; i <= 5; ++i)
            QVERIFY(document.setParameter(QStringLiteral("a"), 170 + i, i > 1).ok());
        QCOMPARE(document.undoStack()->count(), 1);
        document.undoStack()->undo();
        QCOMPARE(parameter(document, "a"), 170.0);
        // a stepping sequence that comes back to the start leaves nothing to undo
        Document other;
        QVERIFY(other.setParameter(QStringLiteral("a"), 171, true).ok());
        QVERIFY(other.setParameter(QStringLiteral("a"), 170, true).ok());
        QCOMPARE(other.undoStack()->count(), 0);
        // typed edits stay separate steps
        QVERIFY(other.setParameter(QStringLiteral("a"), 180).ok());
        QVERIFY(other.setParameter(QStringLiteral("a"), 190).ok());
        QCOMPARE(other.undoStack()->count(), 2);
    }

    void invalidEditKeepsDesign_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("value");
        QTest::newRow("a negative") << "a" << -5.0;
        QTest::newRow("b zero") << "b" << 0.0;
        QTest::newRow("theta_min above max") << "theta_min" << 70.0;
        QTest::newRow("theta_max outside") << "theta_max" << 95.0;
        QTest::newRow("force zero") << "force_max" << 0.0;
        QTest::newRow("unknown") << "zz" << 1.0;
    }
    void invalidEditKeepsDesign()
    {
        QFETCH(QString, name);
        QFETCH(double, value);
        Document document;
        QSignalSpy designSpy(&document, &Document::designChanged);
        auto result = document.setParameter(name, value);
        QVERIFY(!result.ok());
        QCOMPARE(QString::fromStdString(result.failure().culprit), name);
        QCOMPARE(designSpy.count(), 0);
        QCOMPARE(parameter(document, "a"), 170.0);
        QVERIFY(!document.undoStack()->canUndo());
    }

    void poseFollowsAndStopsAtLimits()
    {
        Document document;
        const Mechanism &m = *document.mechanism();
        QSignalSpy poseSpy(&document, &Document::poseChanged);
        QVERIFY(document.setVariable(PJoint::variableTheta, 30 * units::degree).ok());
        QCOMPARE(poseSpy.count(), 1);
        const auto &joint = static_cast<const PJoint &>(m);
        QCOMPARE(document.pose().inputs[0], pjoint::diagonal(joint.design(), 30 * units::degree));
        QVERIFY(document.limitNote().isEmpty());
        // past the limit: stops at it, and says why
        QVERIFY(document.setVariable(PJoint::variableTheta, 80 * units::degree).ok());
        QCOMPARE(document.pose().outputs[0], 60 * units::degree);
        QVERIFY(document.limitNote().startsWith(QStringLiteral("θ stops at its upper limit 60")));
        QVERIFY(document.setVariable(PJoint::variableD, 10.0).ok());
        QCOMPARE(document.pose().inputs[0], joint.dMin());
        QVERIFY(document.limitNote().startsWith(QStringLiteral("d stops at its lower limit 116")));
        // pose moves are not design edits
        QVERIFY(!document.undoStack()->canUndo());
    }

    /// A crank that turns fully has no limit: at α = 0° or 360° the four-bar says nothing (it
    /// said "α stops at its lower limit" on opening at 0°, although nothing had moved), while a
    /// crank that only rocks still names its limit.
    void aCrankThatTurnsFullyHasNoLimit()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("fourbar-example")).ok());
        QVERIFY(turnsFully(*document.mechanism(), 0));
        for (const double alpha : {0.0, 360.0}) {
            QVERIFY(document.setVariable(0, alpha * units::degree).ok());
            QVERIFY2(document.limitNote().isEmpty(), qPrintable(document.limitNote()));
        }
        QVERIFY(document.setParameter(QStringLiteral("AB"), 130.0).ok()); // a double rocker
        QVERIFY(!turnsFully(*document.mechanism(), 0));
        QVERIFY(document.setVariable(0, 0.0).ok());
        QVERIFY2(document.limitNote().startsWith(QStringLiteral("α stops at its lower limit")),
                 qPrintable(document.limitNote()));
    }

    /// Where the five-bar's distal links line up, its two assembly modes meet: the pose stops
    /// there and says "switch to the other assembly mode to go on", so that switch is offered
    /// there (it was dropped as a ghost on the pose itself), and the pose goes on from it.
    void twoAssemblyModesMeetAtADirectSingularity()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("fivebar-example")).ok());
        const int y = 3;
        QCOMPARE(QString::fromStdString(document.mechanism()->variableInfo()[y].name), QStringLiteral("y"));
        (void)document.setVariable(y, 19.0); // beyond the line BD in this mode: stops on it
        std::vector<double> values(document.mechanism()->reportLayout().size);
        const SingularityType here = document.mechanism()->evaluate(document.pose(), values).type;
        QVERIFY(here == SingularityType::Direct || here == SingularityType::Combined);
        const std::vector<ModeAlternative> alternatives = document.modeAlternatives();
        const auto other = std::find_if(alternatives.begin(), alternatives.end(), [](const ModeAlternative &a) {
            return a.changes.count("assembly") && a.changes.size() == 1;
        });
        QVERIFY(other != alternatives.end());
        const double assembly = document.mechanism()->parameters().at("assembly");
        QCOMPARE(other->changes.at("assembly"), -assembly);
        QVERIFY(document.switchMode(*other).ok());
        QCOMPARE(document.mechanism()->parameters().at("assembly"), -assembly);
        QVERIFY(document.setVariable(y, 19.0).ok()); // on, in the other mode
        QCOMPARE(document.mechanism()->variableValue(document.pose(), y), 19.0);
        // at a regular pose the mode the design is in is never offered
        for (const ModeAlternative &a : document.modeAlternatives())
            QVERIFY(!(a.changes.size() == 1 && a.changes.count("assembly") && a.changes.at("assembly") == -assembly));
    }

    /// The 3-RP̲R's x range is the workspace's extent at one orientation; a pose at another
    /// passes it (x = 19.29 mm at q₁ = 19.83 mm, the range ending at 18.49 mm). Nothing stops x
    /// there, and no note says it does ("x stops at its upper limit 18.49 mm" was shown).
    /// A 3-DOF platform's x and y ranges hold its poses at every orientation, not only at
    /// φ_map: q₁ = 19.83 mm gave x = 19.29 mm past a range that ended at 18.49 mm, and the
    /// note said "x stops at its upper limit".
    void outputRangesCoverEveryOrientation()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("pp-3rpr")).ok());
        const Mechanism &m = *document.mechanism();
        QVERIFY(document.setVariable(0, 19.83).ok());
        const int x = m.inputCount(), y = x + 1;
        QCOMPARE_GT(m.variableValue(document.pose(), x), 19.2);
        QVERIFY2(!document.limitNote().contains(QStringLiteral("x stops")), qPrintable(document.limitNote()));
        // every pose of a grid of the inputs, at whatever angle it has
        int poses = 0;
        for (double q1 = 5.0; q1 <= 30.0; q1 += 2.5) {
            for (double q2 = 5.0; q2 <= 30.0; q2 += 2.5) {
                for (double q3 = 5.0; q3 <= 30.0; q3 += 2.5) {
                    Coordinates q(3);
                    q << q1, q2, q3;
                    const auto pose = m.solveDirect(q);
                    if (!pose)
                        continue;
                    ++poses;
                    for (const int output : {x, y}) {
                        const Interval range = m.variableRange(output);
                        const double value = m.variableValue(*pose, output);
                        QVERIFY2(value >= range.min && value <= range.max,
                                 qPrintable(QStringLiteral("%1 = %2 at q = (%3, %4, %5), outside [%6, %7]")
                                                .arg(output == x ? QStringLiteral("x") : QStringLiteral("y")).arg(value).arg(q1).arg(q2).arg(q3)
                                                .arg(range.min).arg(range.max)));
                    }
                }
            }
        }
        QCOMPARE_GT(poses, 100);
    }

    void designChangeKeepsOutputs()
    {
        Document document;
        QVERIFY(document.setVariable(PJoint::variableTheta, 30 * units::degree).ok());
        QVERIFY(document.setParameter(QStringLiteral("k"), 0.5).ok());
        QCOMPARE(document.pose().outputs[0], 30 * units::degree);
        QCOMPARE(document.pose().inputs[0], 170 * std::sqrt(1 + 0.25 + 2 * 0.5 * 0.5));
        // narrowing the range below the pose stops the pose at the new limit
        QVERIFY(document.setParameter(QStringLiteral("theta_max"), 20).ok());
        QCOMPARE(document.pose().outputs[0], 20 * units::degree);
    }

    void openPresetIsUndoable()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("pjoint-study-k05")).ok());
        QCOMPARE(parameter(document, "a"), 1000.0);
        document.undoStack()->undo();
        QCOMPARE(parameter(document, "a"), 170.0);
        auto missing = document.open(QStringLiteral("no-such-preset"));
        QVERIFY(!missing.ok());
        QCOMPARE(parameter(document, "a"), 170.0);
    }

    void dragHandle()
    {
        Document document;
        const Eigen::Vector2d B(68, 0);
        const double theta = -45 * units::degree;
        QVERIFY(document.dragHandle(0, B + 50 * Eigen::Vector2d(std::sin(theta), std::cos(theta))).ok());
        QVERIFY(std::abs(document.pose().outputs[0] - theta) < 1e-12);
    }
    // -- MOMA: the platform, the modes and the limits of the workspace ------------------------

    void momaDragStopsAtTheWorkspaceEdge()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("moma-3a")).ok());
        const Pose start = document.pose();
        // far below the workspace: the move fails, names why, and the platform goes as far as
        // it can — onto the edge, not left where it was
        auto moved = document.dragHandle(0, Eigen::Vector2d(start.outputs[0], -2000.0));
        QVERIFY(!moved.ok());
        QVERIFY(!moved.failure().message.empty());
        QVERIFY(document.lastMoveWasPartial());
        const Pose edge = document.pose();
        QVERIFY(edge.outputs[1] < start.outputs[1] - 50.0);
        QVERIFY(std::isfinite(edge.outputs[0]) && std::isfinite(edge.outputs[1]));
        // the pose is a real pose of the design, its sliders inside the stroke
        auto check = document.mechanism()->solveInverse(edge.outputs);
        QVERIFY(check.ok());
        QVERIFY(std::abs(check->inputs[0] - edge.inputs[0]) < 1e-6);
        // and it sits at a limit: one slider at the end of its stroke (to within the bisection)
        const double pMax = parameter(document, "p_max");
        QVERIFY(std::max(edge.inputs[0], edge.inputs[1]) > pMax - 1e-3);
    }

    void momaSliderBeyondReachStopsAtLastPose()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("moma-3a")).ok());
        // p₂ = 0 with p₁ = 200: the links cannot meet; p₁ goes as far as it can
        QVERIFY(document.setVariable(Moma::variableP2, 0.0).ok());
        auto moved = document.setVariable(Moma::variableP1, 200.0);
        const Pose pose = document.pose();
        if (!moved.ok()) {
            QVERIFY(document.lastMoveWasPartial());
            QVERIFY(pose.inputs[0] > 100.0 && pose.inputs[0] < 200.0);
        }
        QVERIFY(document.mechanism()->solveDirect(pose.inputs).ok());
    }

    void momaMapClickMovesThePlatform()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("moma-3b")).ok());
        Coordinates target(2);
        target << 20.0, -250.0;
        QVERIFY(document.moveOutputsTo(target).ok());
        QCOMPARE(document.pose().outputs[0], 20.0);
        QCOMPARE(document.pose().outputs[1], -250.0);
    }

    void momaModeSwitchIsExplicitAndUndoable()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("moma-3d")).ok());
        const auto alternatives = document.modeAlternatives();
        QVERIFY(!alternatives.empty());
        const double assembly = parameter(document, "assembly");
        // moving the sliders never changes the mode
        for (double p = 0; p <= 200; p += 10) {
            document.setVariable(Moma::variableP1, p);
            QCOMPARE(parameter(document, "assembly"), assembly);
        }
        const int before = document.undoStack()->count();
        const ModeAlternative alternative = alternatives.front();
        QVERIFY(document.switchMode(alternative).ok());
        QCOMPARE(document.undoStack()->count(), before + 1);
        for (const auto &[name, value] : alternative.changes)
            QCOMPARE(parameter(document, name.c_str()), value);
        QVERIFY(document.pose().inputs.isApprox(alternative.pose.inputs));
        document.undoStack()->undo();
        QCOMPARE(parameter(document, "assembly"), assembly);
    }

    void momaGuideTurnKeepsThePlatform()
    {
        Document document;
        QVERIFY(document.open(QStringLiteral("moma-3a")).ok());
        const Pose before = document.pose();
        QVERIFY(document.setParameter(QStringLiteral("gamma1"), -3.0).ok());
        QVERIFY(std::abs(parameter(document, "alpha1") - 267.0 * units::degree) < 1e-12);
        QVERIFY(document.pose().outputs.isApprox(before.outputs));
        // an empty workspace is refused and the design kept
        auto refused = document.setParameter(QStringLiteral("l1"), 5.0);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.failure().culprit, std::string("l1"));
        QCOMPARE(parameter(document, "l1"), 195.0);
    }
};

QTEST_MAIN(TestDocument)
#include "tst_document.moc"
