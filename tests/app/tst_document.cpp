// The document: the only writer of the design and the pose; undo/redo of design edits.
#include "document.h"

#include "pjoint.h"

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
};

QTEST_MAIN(TestDocument)
#include "tst_document.moc"
