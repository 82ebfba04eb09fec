// The governing equations every kind lists (core/equations.h): at poses across each kind's
// ranges the printed formula worked out from the numbers shown gives the printed result,
// within the precision it is printed to, and a result the report has is the report's value;
// at singular poses the results are ∞ or —, never a huge number.

#include "equations.h"
#include "kinds/fivebar/fivebar.h"
#include "kinds/oxglide/oxglide.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace pkm;

namespace {

/// The home pose and poses with each variable moved to a quarter and three quarters of its
/// range (those the kind solves).
std::vector<Pose> posesAcross(const Mechanism &m)
{
    std::vector<Pose> poses{m.homePose()};
    for (int v = 0; v < int(m.variableInfo().size()); ++v) {
        const Interval range = m.variableRange(v);
        for (double share : {0.25, 0.75}) {
            if (auto pose = m.solveWith(m.homePose(), v, range.min + share * (range.max - range.min)))
                poses.push_back(*pose);
        }
    }
    return poses;
}

/// The number a printed value starts with ("−12.50 mm" → −12.5), NaN for ∞ and —.
double parsePrinted(const std::string &printed)
{
    QString text = QString::fromStdString(printed);
    text.replace(QStringLiteral("−"), QStringLiteral("-"));
    const QRegularExpressionMatch match = QRegularExpression(QStringLiteral("^-?[0-9]+(\\.[0-9]+)?")).match(text);
    return match.hasMatch() ? match.captured(0).toDouble() : std::numeric_limits<double>::quiet_NaN();
}

/// No number of more than nine digits before the point in a line: a huge number at a singular
/// pose, where ∞ or — belongs.
bool hasHugeNumber(const std::string &line)
{
    return QRegularExpression(QStringLiteral("[0-9]{10,}")).match(QString::fromStdString(line)).hasMatch();
}

} // namespace

class TestEquations : public QObject
{
    Q_OBJECT

private slots:
    void everyKindAgreesWithItsFormulas_data() { test::addKindRows(); }
    void everyKindAgreesWithItsFormulas()
    {
        QFETCH(QString, kind);
        const MechanismPtr m = test::makeKind(kind.toStdString());
        const std::vector<Pose> poses = posesAcross(*m);
        QVERIFY(poses.size() > 1);
        for (const Pose &pose : poses) {
            const std::vector<Equation> equations = mechanismEquations(*m, pose);
            QVERIFY2(equations.size() >= 4, qPrintable(kind));
            Singularity singularity;
            const std::vector<double> report = test::evaluated(*m, pose, &singularity);
            for (const Equation &e : equations) {
                const QByteArray what = QByteArray::fromStdString(e.symbolic);
                QVERIFY2(!e.title.empty() && !e.symbolic.empty() && !e.source.empty(), what);
                // every number is used and every %n has a number
                for (std::size_t n = 0; n < e.numbers.size(); ++n)
                    QVERIFY2(e.substituted.find(joinText({"%", std::to_string(n + 1)})) != std::string::npos, what);
                QVERIFY2(fillEquation(e, plainEquationNumber).find('%') == std::string::npos, what);
                if (!e.resultName.empty()) {
                    const ReportEntry *entry = m->reportLayout().find(e.resultName);
                    QVERIFY2(entry, what);
                    QCOMPARE(e.result.value, report[std::size_t(entry->offset)]);
                }
                if (e.substituted.empty() || !std::isfinite(e.result.value) || singularity.type != SingularityType::None)
                    continue;
                // the printed formula with the numbers gives the printed result to its precision
                const std::string printed = plainEquationNumber(e.result);
                const double shown = parsePrinted(printed);
                QVERIFY2(std::isfinite(shown), printed.c_str());
                double expected = e.result.unit.toDisplay(e.formula);
                const bool angle = std::string_view(e.result.unit.symbol).starts_with("°");
                if (angle) // the same angle, whatever turn it is given in
                    expected = shown + std::remainder(expected - shown, 360.0);
                const double tolerance = 0.5 * std::pow(10.0, -e.result.decimals) * 1.001 + 1e-9 * std::abs(expected);
                QVERIFY2(std::abs(shown - expected) <= tolerance,
                         qPrintable(QStringLiteral("%1: printed %2, the formula gives %3")
                                        .arg(QString::fromStdString(e.symbolic), QString::fromStdString(printed))
                                        .arg(expected, 0, 'g', 12)));
            }
        }
    }

    void theTextHasTheNumbersPutIn()
    {
        const MechanismPtr m = test::makeKind("pjoint");
        auto pose = m->solveWith(m->homePose(), m->variableIndex("theta"), 0.0);
        QVERIFY(pose);
        const std::vector<Equation> equations = mechanismEquations(*m, *pose);
        QCOMPARE(equationText(equations.front()),
                 std::string("d = a·√(1 + k² + 2k·sin θ)\n  = 170.00·√(1 + 0.4000² + 2·0.4000·sin 0.00°) = 183.10 mm"));
        QVERIFY(equations.front().source.find("(2)") != std::string::npos);
    }

    void aNegativeNumberIsBracketed()
    {
        Equation e{.symbolic = "y = x − c", .substituted = "%1 − %2", .numbers = {equations::length(3.0), equations::length(-5.0)},
                   .result = equations::length(8.0)};
        QCOMPARE(fillEquation(e, plainEquationNumber), std::string("3.00 − (−5.00)"));
        // bare where it opens a bracket or a list, as in a matrix; bracketed where raised to a power
        e.substituted = "%2·%1 + det[(%2, %1); (%1, %2)] + (%2)² + √(%2² + 1)";
        QCOMPARE(fillEquation(e, plainEquationNumber),
                 std::string("−5.00·3.00 + det[(−5.00, 3.00); (3.00, −5.00)] + (−5.00)² + √((−5.00)² + 1)"));
    }

    void everyDeterminantHasItsEquation_data() { test::addKindRows(); }
    void everyDeterminantHasItsEquation()
    {
        // det J = det J_x / det J_q: each determinant put into it has an equation of its own,
        // which says how it is worked out and where it vanishes, and each has a unit
        QFETCH(QString, kind);
        const MechanismPtr m = test::makeKind(kind.toStdString());
        const std::vector<Equation> equations = mechanismEquations(*m, m->homePose());
        std::set<std::string> own;
        for (const Equation &e : equations)
            own.insert(e.resultName);
        for (const ReportEntry &entry : m->reportLayout().entries) {
            if (!entry.name.starts_with("det_"))
                continue;
            QVERIFY2(own.count(entry.name), entry.name.c_str());
        }
        // a heading is set in bold, which runs a dot over a letter into it: "ḋ" read as "d"
        for (const Equation &e : equations) {
            const QString title = QString::fromStdString(e.title);
            for (const QChar c : title.normalized(QString::NormalizationForm_D))
                QVERIFY2(c != QChar(0x0307) && c != QChar(0x0308), e.title.c_str());
        }
        // a J_q entry of a leg carries its unit, as the determinant it is a factor of does
        for (const Equation &e : equations) {
            if (e.symbolic.starts_with("(J_q)"))
                QVERIFY2(!std::string_view(e.result.unit.symbol).empty(), e.symbolic.c_str());
        }
    }

    /// The O-X glide at the O↔X crossing (w = 0: combined) and the five-bar with leg 1 stretched
    /// (inverse): det J and κ(J) are — or ∞ as the values panel shows them, no line carries a
    /// huge number, and the notes are still there.
    void singularPosesShowInfinityOrUndefined()
    {
        const MechanismPtr glide = test::makeKind("oxglide");
        const OxGlideDesign &g = static_cast<const OxGlide &>(*glide).design();
        Pose crossing;
        crossing.inputs = test::triple(65.0 - 0.5 * g.width, 65.0 + 0.5 * g.width, 0.0);
        crossing.outputs = test::pair(65.0, g.rod);
        checkSingular(*glide, crossing, SingularityType::Combined, {{"det_J", "—"}, {"cond", "∞"}});

        const MechanismPtr five = test::makeKind("fivebar");
        const FiveBarDesign &d = static_cast<const FiveBar &>(*five).design();
        const double up = std::numbers::pi / 3; // leg 1 stretched at 60°
        const Eigen::Vector2d C = (d.crank[0] + d.link[0]) * Eigen::Vector2d(std::cos(up), std::sin(up));
        Eigen::Vector2d D;
        QCOMPARE(fivebar::circleIntersection(fivebar::groundJoint(d, 1), d.crank[1], C, d.link[1], -1, D, 1e-9),
                 fivebar::Meet::Yes);
        Pose stretched;
        stretched.inputs = test::pair(up, std::atan2(D.y(), D.x() - d.ground));
        stretched.outputs = test::pair(C.x(), C.y());
        checkSingular(*five, stretched, SingularityType::Inverse, {{"det_J", "∞"}});
    }

private:
    void checkSingular(const Mechanism &m, const Pose &pose, SingularityType type,
                       const std::vector<std::pair<std::string, std::string>> &expected)
    {
        Singularity singularity;
        test::evaluated(m, pose, &singularity);
        QCOMPARE(int(singularity.type), int(type));
        const std::vector<Equation> equations = mechanismEquations(m, pose);
        for (const auto &[name, shown] : expected) {
            bool found = false;
            for (const Equation &e : equations) {
                if (e.resultName != name)
                    continue;
                found = true;
                QCOMPARE(plainEquationNumber(e.result), shown);
            }
            QVERIFY2(found, name.c_str());
        }
        for (const Equation &e : equations)
            QVERIFY2(!hasHugeNumber(equationText(e)), equationText(e).c_str());
    }
};

QTEST_GUILESS_MAIN(TestEquations)
#include "tst_equations.moc"
