// Tests of the `pkm` command against the contract in CLI.md: the real binary run through
// QProcess (exit codes, stdout/stderr separation, JSON keys, CSV shape, the prototype's
// published numbers), plus in-process checks of runCli() and the number formatter.

#include "cli.h"
#include "numberformat.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

using namespace pkm;

namespace {

constexpr double degree = std::numbers::pi / 180.0;

struct Run {
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
};

Run runPkm(const QStringList &arguments, const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(PKM_BINARY_DIR "/pkm"), arguments);
    Run run;
    if (!process.waitForStarted(10000) || !process.waitForFinished(60000))
        return run;
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

QJsonObject evalJson(const QStringList &sets, int *exitCode = nullptr)
{
    QStringList arguments{QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--json")};
    for (const QString &set : sets)
        arguments << QStringLiteral("--set") << set;
    const Run run = runPkm(arguments);
    if (exitCode)
        *exitCode = run.exitCode;
    return QJsonDocument::fromJson(run.out).object();
}

QString number(double value)
{
    return QString::number(value, 'g', 17);
}

/// Runs runCli() in this process, capturing what it writes.
Run runInProcess(const QStringList &arguments)
{
    std::FILE *out = std::tmpfile();
    std::FILE *err = std::tmpfile();
    Run run;
    run.exitCode = runCli(arguments, out, err);
    for (auto [file, bytes] : {std::pair{out, &run.out}, std::pair{err, &run.err}}) {
        std::fflush(file);
        std::rewind(file);
        char buffer[4096];
        std::size_t n = 0;
        while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0)
            bytes->append(buffer, static_cast<qsizetype>(n));
        std::fclose(file);
    }
    return run;
}

std::string referenceGeneral15(double value)
{
    if (value == 0.0)
        value = 0.0;
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 15).ptr);
}

/// A mechanism that is not a П-joint, with a 2×2 Jacobian and a quantity that is not finite,
/// to check that the CLI is generic and prints null where a value does not exist.
class FakeMechanism final : public Mechanism
{
public:
    std::string_view kind() const override { return "fake"; }
    const std::vector<ParameterInfo> &parameterInfo() const override
    {
        static const std::vector<ParameterInfo> infos = {
            {"l", "l", "link length", units::millimetre, ParameterGroup::Geometry, {0.0, 1e9}, true, false, true, 2, 1}};
        return infos;
    }
    ParameterSet parameters() const override { return {{"l", 100.0}}; }
    Result<MechanismPtr> withParameter(std::string_view, double) const override
    {
        return Failure{FailureKind::UnknownName, "l", "not settable"};
    }
    const std::vector<VariableInfo> &variableInfo() const override
    {
        static const std::vector<VariableInfo> infos = {{"q", "q", "input", units::millimetre, true, 2},
                                                        {"x", "x", "output", units::angle, false, 2}};
        return infos;
    }
    Interval variableRange(int) const override { return {-1.0, 1.0}; }
    Pose homePose() const override
    {
        Pose pose;
        pose.inputs = Coordinates::Constant(1, 0.5);
        pose.outputs = Coordinates::Constant(1, 0.25);
        return pose;
    }
    Result<Pose> solveDirect(const Coordinates &, const Pose *) const override { return homePose(); }
    Result<Pose> solveInverse(const Coordinates &, const Pose *) const override { return homePose(); }
    const ReportLayout &reportLayout() const override
    {
        static const ReportLayout layout = [] {
            ReportLayout l;
            l.entries.push_back({ReportGroup::Pose, "x", "x", "output", units::angle, 1, 1, 0, 2});
            l.entries.push_back({ReportGroup::Jacobian, "J", "J", "Jacobian", units::millimetre, 2, 2, 1, 3});
            l.entries.push_back({ReportGroup::Derived, "ratio", "r", "ratio", units::none, 1, 1, 5, 3});
            l.size = 6;
            return l;
        }();
        return layout;
    }
    Singularity evaluate(const Pose &pose, std::span<double> values) const override
    {
        values[0] = pose.outputs[0];
        values[1] = 1.0;
        values[2] = 2.0;
        values[3] = 3.0;
        values[4] = -0.0;
        values[5] = std::numeric_limits<double>::infinity(); // e.g. 1/J at a singular pose
        return {SingularityType::Direct, 0.0};
    }
    Jacobians jacobians(const Pose &) const override
    {
        return {Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(2, 2)};
    }
    Scene scene(const Pose &) const override { return {}; }
    Result<Pose> dragHandle(const Pose &current, int, const Eigen::Vector2d &) const override { return current; }
};

} // namespace

class TestCli : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();

    void evalJsonHasContractKeys_data();
    void evalJsonHasContractKeys();
    void evalJsonTopLevel();
    void prototypeNumbers();
    void inverseThenDirect_data();
    void inverseThenDirect();
    void settingKResizesCoupler();
    void parameterOrderDoesNotMatter();
    void couplerGivenTwiceIsRefused();
    void changedParameterKeepsPose();
    void storedPoseFallsBackToHome();
    void designFile();
    void list();
    void show();
    void evalText();

    void sweepCsv_data();
    void sweepCsv();
    void sweepOverDiagonal();
    void sweepJson();
    void sweepParameter();

    void errors_data();
    void errors();
    void help_data();
    void help();

    void inProcessMatchesBinary();
    void numbersAreGeneral15_data();
    void numbersAreGeneral15();
    void fastNumbersMatchToChars();
    void numbersIgnoreLocale();
    void notFiniteIsNullAndMatricesNest();

private:
    QTemporaryDir m_temporary;
    QString m_brokenFile;
};

void TestCli::initTestCase()
{
    QVERIFY(QFileInfo::exists(QStringLiteral(PKM_BINARY_DIR "/pkm")));
    QVERIFY(m_temporary.isValid());
    m_brokenFile = m_temporary.filePath(QStringLiteral("broken.pkm.json"));
    QFile file(m_brokenFile);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "pkm-studio-design", "version": 1, "mechanism": "pjoint", "parameters": {"a": 17)");
}

// -- eval --json: the keys CLI.md requires for pjoint ----------------------------------------

void TestCli::evalJsonHasContractKeys_data()
{
    QTest::addColumn<QString>("group");
    QTest::addColumn<QString>("key");
    const auto add = [](const char *group, std::initializer_list<const char *> keys) {
        for (const char *key : keys)
            QTest::addRow("%s.%s", group, key) << QString::fromLatin1(group) << QString::fromLatin1(key);
    };
    add("parameters",
        {"a", "b", "k", "theta_min", "theta_max", "lead", "step", "speed_max", "force_max", "efficiency"});
    add("pose", {"theta", "d", "phi", "mu"});
    add("jacobian", {"J", "J_inv", "J_d", "J_theta", "dJ_dtheta"});
    add("derived", {"torque", "speed", "resolution", "motor_torque", "d_min", "d_max", "stroke"});
}

void TestCli::evalJsonHasContractKeys()
{
    QFETCH(QString, group);
    QFETCH(QString, key);
    static const QJsonObject root = evalJson({QStringLiteral("theta=20")});
    const QJsonValue value = root.value(group).toObject().value(key);
    QVERIFY2(value.isDouble(), qPrintable(group + QLatin1Char('.') + key + QStringLiteral(" is missing")));
    QVERIFY(std::isfinite(value.toDouble()));
}

void TestCli::evalJsonTopLevel()
{
    int exitCode = -1;
    const QJsonObject root = evalJson({}, &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.keys().size(), 6);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("pjoint"));
    for (const char *key : {"parameters", "pose", "jacobian", "singularity", "derived"})
        QVERIFY2(root.value(QLatin1String(key)).isObject(), key);
    const QJsonObject singularity = root.value(QStringLiteral("singularity")).toObject();
    QCOMPARE(singularity.value(QStringLiteral("type")).toString(), QStringLiteral("none"));
    QVERIFY(singularity.value(QStringLiteral("margin")).isDouble());
    QVERIFY(singularity.value(QStringLiteral("undefined")).toArray().isEmpty());
    // The preset's stored pose, and every parameter including the derived k.
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble(), 0.0);
    QCOMPARE(root.value(QStringLiteral("parameters")).toObject().value(QStringLiteral("k")).toDouble(), 0.4);
}

void TestCli::prototypeNumbers()
{
    // Section 4.2 / Table 1: d_max ≈ 231.4, d_min ≈ 116.2, stroke ≈ 115.2 mm.
    const QJsonObject derived = evalJson({}).value(QStringLiteral("derived")).toObject();
    QVERIFY(std::abs(derived.value(QStringLiteral("d_max")).toDouble() - 231.4) < 0.05);
    QVERIFY(std::abs(derived.value(QStringLiteral("d_min")).toDouble() - 116.2) < 0.05);
    QVERIFY(std::abs(derived.value(QStringLiteral("stroke")).toDouble() - 115.2) < 0.05);
}

void TestCli::inverseThenDirect_data()
{
    QTest::addColumn<double>("theta");
    for (double theta : {-60.0, -45.0, -10.0, 0.0, 30.0, 59.5, 60.0})
        QTest::addRow("theta=%g", theta) << theta;
}

void TestCli::inverseThenDirect()
{
    QFETCH(double, theta);
    const double a = 170.0;
    const double k = 0.4;
    int exitCode = -1;
    const QJsonObject inverse = evalJson({QStringLiteral("theta=") + number(theta)}, &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject pose = inverse.value(QStringLiteral("pose")).toObject();
    const double d = pose.value(QStringLiteral("d")).toDouble();
    QCOMPARE(d, a * std::sqrt(1 + k * k + 2 * k * std::sin(theta * degree))); // (2)
    QCOMPARE(pose.value(QStringLiteral("theta")).toDouble(), theta);

    // J = a·sin μ (DOMAIN §1), read back from the JSON.
    const double mu = pose.value(QStringLiteral("mu")).toDouble();
    const double J = inverse.value(QStringLiteral("jacobian")).toObject().value(QStringLiteral("J")).toDouble();
    QCOMPARE(J, a * std::sin(mu * degree));

    const QJsonObject direct = evalJson({QStringLiteral("d=") + number(d)}, &exitCode);
    QCOMPARE(exitCode, 0);
    const double back = direct.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble();
    QVERIFY2(std::abs(back - theta) < 1e-9, qPrintable(number(back)));
}

void TestCli::settingKResizesCoupler()
{
    int exitCode = -1;
    const QJsonObject parameters = evalJson({QStringLiteral("k=0.5")}, &exitCode).value(QStringLiteral("parameters")).toObject();
    QCOMPARE(exitCode, 0);
    QCOMPARE(parameters.value(QStringLiteral("b")).toDouble(), 85.0);
    QCOMPARE(parameters.value(QStringLiteral("a")).toDouble(), 170.0);
    QCOMPARE(parameters.value(QStringLiteral("k")).toDouble(), 0.5);
}

void TestCli::parameterOrderDoesNotMatter()
{
    // k with a: the coupler is k·a with the new a, in either order.
    for (const QStringList &sets : {QStringList {QStringLiteral("k=0.5"), QStringLiteral("a=200")},
                                    QStringList {QStringLiteral("a=200"), QStringLiteral("k=0.5")}}) {
        int exitCode = -1;
        const QJsonObject parameters = evalJson(sets, &exitCode).value(QStringLiteral("parameters")).toObject();
        QCOMPARE(exitCode, 0);
        QCOMPARE(parameters.value(QStringLiteral("b")).toDouble(), 100.0);
        QCOMPARE(parameters.value(QStringLiteral("k")).toDouble(), 0.5);
    }
}

void TestCli::couplerGivenTwiceIsRefused()
{
    const Run run = runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                            QStringLiteral("k=0.5"), QStringLiteral("--set"), QStringLiteral("b=70")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QVERIFY2(run.err.contains("give b or k, not both"), run.err.constData());
    QCOMPARE(run.err.count('\n'), 1);
}

void TestCli::changedParameterKeepsPose()
{
    // --set applies the parameters first, then the pose: θ = 70° is reachable once θ_max = 80°.
    int exitCode = -1;
    const QJsonObject root = evalJson({QStringLiteral("theta=70"), QStringLiteral("theta_max=80")}, &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble(), 70.0);
    // A new a keeps the stored θ = 0 and re-solves d for the new design.
    const QJsonObject pose = evalJson({QStringLiteral("a=200")}).value(QStringLiteral("pose")).toObject();
    QCOMPARE(pose.value(QStringLiteral("theta")).toDouble(), 0.0);
    QCOMPARE(pose.value(QStringLiteral("d")).toDouble(), std::sqrt(200.0 * 200.0 + 68.0 * 68.0));
}

void TestCli::storedPoseFallsBackToHome()
{
    // θ = 0 is outside [10, 60]: the home pose is used and a note says so on stderr.
    const Run run = runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--json"),
                            QStringLiteral("--set"), QStringLiteral("theta_min=10")});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject pose = QJsonDocument::fromJson(run.out).object().value(QStringLiteral("pose")).toObject();
    QCOMPARE(pose.value(QStringLiteral("theta")).toDouble(), 10.0);
    QVERIFY(run.err.contains("home pose"));
}

void TestCli::designFile()
{
    const QString path = QStringLiteral(PKM_TEST_DATA_DIR "/custom.pkm.json");
    const Run run = runPkm({QStringLiteral("eval"), path, QStringLiteral("--json")});
    QCOMPARE(run.exitCode, 0);
    const QJsonObject root = QJsonDocument::fromJson(run.out).object();
    QCOMPARE(root.value(QStringLiteral("parameters")).toObject().value(QStringLiteral("k")).toDouble(), 0.3);
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble(), 20.0);
}

void TestCli::list()
{
    const Run text = runPkm({QStringLiteral("list")});
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.err.isEmpty());
    const QList<QByteArray> lines = text.out.trimmed().split('\n');
    QVERIFY(lines.size() >= 2);
    bool found = false;
    for (const QByteArray &line : lines) {
        if (line.startsWith("pjoint-prototype ")) {
            found = true;
            QVERIFY(line.contains(" pjoint "));
            // Aligned columns: the kind starts where the header's MECHANISM does.
            QCOMPARE(QString::fromUtf8(line).indexOf(QStringLiteral(" pjoint ")) + 1,
                     QString::fromUtf8(lines.front()).indexOf(QStringLiteral("MECHANISM")));
        }
    }
    QVERIFY(found);

    const Run json = runPkm({QStringLiteral("list"), QStringLiteral("--json")});
    QCOMPARE(json.exitCode, 0);
    const QJsonArray presets = QJsonDocument::fromJson(json.out).object().value(QStringLiteral("presets")).toArray();
    found = false;
    for (const QJsonValue &preset : presets) {
        const QJsonObject object = preset.toObject();
        if (object.value(QStringLiteral("id")).toString() == QLatin1String("pjoint-prototype")) {
            found = true;
            QCOMPARE(object.value(QStringLiteral("mechanism")).toString(), QStringLiteral("pjoint"));
            QVERIFY(!object.value(QStringLiteral("title")).toString().isEmpty());
        }
    }
    QVERIFY(found);
}

void TestCli::show()
{
    const Run json = runPkm({QStringLiteral("show"), QStringLiteral("pjoint-prototype"), QStringLiteral("--json")});
    QCOMPARE(json.exitCode, 0);
    const QJsonObject root = QJsonDocument::fromJson(json.out).object();
    const QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    const QJsonObject a = parameters.value(QStringLiteral("a")).toObject();
    QCOMPARE(a.value(QStringLiteral("value")).toDouble(), 170.0);
    QCOMPARE(a.value(QStringLiteral("unit")).toString(), QStringLiteral("mm"));
    QCOMPARE(a.value(QStringLiteral("min")).toDouble(), 0.0);
    QVERIFY(a.value(QStringLiteral("max")).isNull()); // unbounded
    QCOMPARE(a.value(QStringLiteral("min_open")).toBool(), true);
    const QJsonObject thetaMax = parameters.value(QStringLiteral("theta_max")).toObject();
    QCOMPARE(thetaMax.value(QStringLiteral("max")).toDouble(), 90.0); // displayed in degrees
    QCOMPARE(thetaMax.value(QStringLiteral("unit")).toString(), QStringLiteral("°"));
    QCOMPARE(parameters.value(QStringLiteral("k")).toObject().value(QStringLiteral("stored")).toBool(), false);
    const QJsonObject variables = root.value(QStringLiteral("variables")).toObject();
    QCOMPARE(variables.value(QStringLiteral("d")).toObject().value(QStringLiteral("actuated")).toBool(), true);
    QCOMPARE(variables.value(QStringLiteral("theta")).toObject().value(QStringLiteral("actuated")).toBool(), false);
    QCOMPARE(variables.value(QStringLiteral("theta")).toObject().value(QStringLiteral("min")).toDouble(), -60.0);
    QVERIFY(std::abs(variables.value(QStringLiteral("d")).toObject().value(QStringLiteral("max")).toDouble() - 231.4)
            < 0.05);
    QVERIFY(root.value(QStringLiteral("warnings")).isArray());
    QVERIFY(root.value(QStringLiteral("quantities")).toObject().contains(QStringLiteral("J_inv")));

    const Run text = runPkm({QStringLiteral("show"), QStringLiteral("pjoint-prototype")});
    QCOMPARE(text.exitCode, 0);
    const QString out = QString::fromUtf8(text.out);
    QVERIFY(out.contains(QStringLiteral("(-90, 90)")));
    QVERIFY(out.contains(QStringLiteral("(0, ∞)")));
    QVERIFY(out.contains(QStringLiteral("derived")));
    QVERIFY(out.contains(QStringLiteral("input")));
}

void TestCli::evalText()
{
    const Run run = runPkm({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                            QStringLiteral("theta=30")});
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = QString::fromUtf8(run.out).split(QLatin1Char('\n'));
    for (const char *heading : {"Parameters", "Pose", "Jacobian", "Singularity", "Derived"})
        QVERIFY2(lines.contains(QLatin1String(heading)), heading);
    // Aligned: the values are right-aligned in one column, so "30.00" (θ) and "212.33" (d)
    // end at the same place.
    qsizetype thetaEnd = -1;
    qsizetype dEnd = -1;
    for (const QString &line : lines) {
        if (line.startsWith(QStringLiteral("  θ ")))
            thetaEnd = line.indexOf(QStringLiteral("30.00")) + 5;
        if (line.startsWith(QStringLiteral("  d ")))
            dEnd = line.indexOf(QStringLiteral("212.33")) + 6;
    }
    QVERIFY(thetaEnd > 5);
    QCOMPARE(thetaEnd, dEnd);
}

// -- sweep ---------------------------------------------------------------------------------

void TestCli::sweepCsv_data()
{
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("steps");
    QTest::newRow("full range") << -60.0 << 60.0 << 7;
    QTest::newRow("downwards") << 60.0 << -60.0 << 4;
    QTest::newRow("two steps") << -12.5 << 33.25 << 2;
    QTest::newRow("one step is A") << 10.0 << 20.0 << 1;
    QTest::newRow("thousand") << -60.0 << 40.0 << 1000;
}

void TestCli::sweepCsv()
{
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, steps);
    const Run run = runPkm({QStringLiteral("sweep"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                            QStringLiteral("theta"), QStringLiteral("--from"), number(from), QStringLiteral("--to"),
                            number(to), QStringLiteral("--steps"), QString::number(steps)});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    QVERIFY(run.out.endsWith('\n'));
    const QList<QByteArray> lines = run.out.chopped(1).split('\n');
    QCOMPARE(lines.size(), steps + 1);
    const QList<QByteArray> header = lines.front().split(',');
    for (const char *column : {"theta", "d", "phi", "mu", "J", "J_inv", "J_d", "J_theta", "dJ_dtheta", "singularity",
                               "singularity_margin", "torque", "speed", "resolution", "motor_torque", "d_min",
                               "d_max", "stroke"})
        QVERIFY2(header.contains(column), column);
    const auto thetaColumn = header.indexOf("theta");
    for (qsizetype i = 1; i < lines.size(); ++i)
        QCOMPARE(lines[i].split(',').size(), header.size());
    QCOMPARE(lines[1].split(',')[thetaColumn].toDouble(), from);
    QCOMPARE(lines.back().split(',')[thetaColumn].toDouble(), steps == 1 ? from : to);
    if (steps > 2) {
        const double second = lines[2].split(',')[thetaColumn].toDouble();
        QVERIFY(std::abs(second - (from + (to - from) / (steps - 1))) < 1e-9);
    }
}

void TestCli::sweepOverDiagonal()
{
    // Sweeping the actuated input solves the direct problem at every step.
    const Run run = runPkm({QStringLiteral("sweep"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                            QStringLiteral("d"), QStringLiteral("--from"), QStringLiteral("120"),
                            QStringLiteral("--to"), QStringLiteral("230"), QStringLiteral("--steps"),
                            QStringLiteral("12"), QStringLiteral("--csv")});
    QCOMPARE(run.exitCode, 0);
    const QList<QByteArray> lines = run.out.chopped(1).split('\n');
    QCOMPARE(lines.size(), 13);
    const QList<QByteArray> header = lines.front().split(',');
    const auto d = header.indexOf("d");
    const auto theta = header.indexOf("theta");
    double previous = -90.0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        QCOMPARE(fields[d].toDouble(), 120.0 + 10.0 * static_cast<double>(i - 1));
        QVERIFY(fields[theta].toDouble() > previous); // d grows with θ
        previous = fields[theta].toDouble();
    }
}

void TestCli::sweepJson()
{
    const Run run = runPkm({QStringLiteral("sweep"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                            QStringLiteral("theta"), QStringLiteral("--from"), QStringLiteral("-60"),
                            QStringLiteral("--to"), QStringLiteral("60"), QStringLiteral("--steps"),
                            QStringLiteral("9001"), QStringLiteral("--json")});
    QCOMPARE(run.exitCode, 0);
    QJsonParseError error;
    const QJsonObject root = QJsonDocument::fromJson(run.out, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("pjoint"));
    QCOMPARE(root.value(QStringLiteral("sweep")).toObject().value(QStringLiteral("steps")).toInt(), 9001);
    const QJsonArray rows = root.value(QStringLiteral("rows")).toArray();
    QCOMPARE(rows.size(), 9001);
    const auto theta = [&](qsizetype i) {
        return rows[i].toObject().value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble();
    };
    QCOMPARE(theta(0), -60.0);
    QCOMPARE(theta(rows.size() - 1), 60.0);
    const QJsonObject row = rows[6750].toObject(); // θ = -60 + 120·6750/9000 = 30
    QCOMPARE(theta(6750), 30.0);
    for (const char *key : {"pose", "jacobian", "singularity", "derived"})
        QVERIFY2(row.value(QLatin1String(key)).isObject(), key);
    // The row holds exactly what eval prints for the same pose.
    const QJsonObject eval = evalJson({QStringLiteral("theta=30")});
    for (const char *key : {"pose", "jacobian", "singularity", "derived"})
        QCOMPARE(row.value(QLatin1String(key)), eval.value(QLatin1String(key)));
}

void TestCli::sweepParameter()
{
    const Run run = runPkm({QStringLiteral("sweep"), QStringLiteral("pjoint-prototype"), QStringLiteral("--var"),
                            QStringLiteral("k"), QStringLiteral("--from"), QStringLiteral("0.3"),
                            QStringLiteral("--to"), QStringLiteral("0.5"), QStringLiteral("--steps"),
                            QStringLiteral("3"), QStringLiteral("--set"), QStringLiteral("theta=30")});
    QCOMPARE(run.exitCode, 0);
    const QList<QByteArray> lines = run.out.chopped(1).split('\n');
    QCOMPARE(lines.size(), 4);
    const QList<QByteArray> header = lines.front().split(',');
    const auto b = header.indexOf("b");
    const auto theta = header.indexOf("theta");
    QVERIFY(b >= 0);
    QCOMPARE(lines[1].split(',')[b].toDouble(), 51.0);
    QCOMPARE(lines[2].split(',')[b].toDouble(), 68.0);
    QCOMPARE(lines[3].split(',')[b].toDouble(), 85.0);
    QCOMPARE(lines[3].split(',')[theta].toDouble(), 30.0);
}

// -- errors: one sentence naming the culprit on stderr, nothing on stdout ----------------------

void TestCli::errors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("culprit");
    const QString design = QStringLiteral("pjoint-prototype");
    const auto eval = [&](const char *set) {
        return QStringList{QStringLiteral("eval"), design, QStringLiteral("--set"), QString::fromUtf8(set)};
    };
    const auto sweep = [&](std::initializer_list<const char *> extra) {
        QStringList arguments{QStringLiteral("sweep"), design};
        for (const char *argument : extra)
            arguments << QString::fromUtf8(argument);
        return arguments;
    };
    QTest::newRow("negative a") << eval("a=-5") << 2 << QStringLiteral("a=-5");
    QTest::newRow("a not a number") << eval("a=abc") << 2 << QStringLiteral("abc");
    QTest::newRow("decimal comma") << eval("a=1,5") << 2 << QStringLiteral("1,5");
    QTest::newRow("theta out of range") << eval("theta=75") << 3 << QStringLiteral("theta");
    QTest::newRow("d unreachable") << eval("d=500") << 3 << QStringLiteral("d=500");
    QTest::newRow("d outside stroke") << eval("d=110") << 3 << QStringLiteral("d=110");
    QTest::newRow("unknown parameter") << eval("zz=1") << 2 << QStringLiteral("zz");
    QTest::newRow("theta_min above theta_max") << eval("theta_min=70") << 2 << QStringLiteral("theta_min");
    QTest::newRow("not NAME=VALUE") << eval("theta") << 2 << QStringLiteral("theta");
    QTest::newRow("inputs and outputs")
        << QStringList{QStringLiteral("eval"), design, QStringLiteral("--set"), QStringLiteral("d=150"),
                       QStringLiteral("--set"), QStringLiteral("theta=3")}
        << 2 << QStringLiteral("d=150");
    QTest::newRow("unknown command") << QStringList{QStringLiteral("frobnicate")} << 2 << QStringLiteral("frobnicate");
    QTest::newRow("no command") << QStringList{} << 2 << QStringLiteral("command");
    QTest::newRow("missing DESIGN") << QStringList{QStringLiteral("eval")} << 2 << QStringLiteral("DESIGN");
    QTest::newRow("unknown option") << QStringList{QStringLiteral("eval"), design, QStringLiteral("--bogus")} << 2
                                    << QStringLiteral("--bogus");
    QTest::newRow("option of another command")
        << QStringList{QStringLiteral("show"), design, QStringLiteral("--var"), QStringLiteral("theta")} << 2
        << QStringLiteral("--var");
    QTest::newRow("--set without value") << QStringList{QStringLiteral("eval"), design, QStringLiteral("--set")} << 2
                                         << QStringLiteral("--set");
    QTest::newRow("unknown preset") << QStringList{QStringLiteral("eval"), QStringLiteral("no-such-preset")} << 2
                                    << QStringLiteral("no-such-preset");
    QTest::newRow("nonexistent file")
        << QStringList{QStringLiteral("eval"), QStringLiteral("/nonexistent/dir/design.pkm.json")} << 2
        << QStringLiteral("/nonexistent/dir/design.pkm.json");
    QTest::newRow("damaged file") << QStringList{QStringLiteral("eval"), m_brokenFile} << 2 << m_brokenFile;
    QTest::newRow("damaged file, show") << QStringList{QStringLiteral("show"), m_brokenFile} << 2 << m_brokenFile;
    QTest::newRow("sweep step out of range")
        << sweep({"--var", "theta", "--from", "0", "--to", "80", "--steps", "9"}) << 3 << QStringLiteral("theta = 70");
    QTest::newRow("sweep unknown variable")
        << sweep({"--var", "zz", "--from", "0", "--to", "1", "--steps", "2"}) << 2 << QStringLiteral("zz");
    QTest::newRow("sweep without --steps") << sweep({"--var", "theta", "--from", "0", "--to", "1"}) << 2
                                           << QStringLiteral("--steps");
    QTest::newRow("sweep zero steps") << sweep({"--var", "theta", "--from", "0", "--to", "1", "--steps", "0"}) << 2
                                      << QStringLiteral("--steps");
    QTest::newRow("sweep fractional steps")
        << sweep({"--var", "theta", "--from", "0", "--to", "1", "--steps", "2.5"}) << 2 << QStringLiteral("--steps");
    QTest::newRow("sweep --from not a number")
        << sweep({"--var", "theta", "--from", "abc", "--to", "1", "--steps", "2"}) << 2 << QStringLiteral("abc");
    QTest::newRow("sweep --csv and --json")
        << sweep({"--var", "theta", "--from", "0", "--to", "1", "--steps", "2", "--csv", "--json"}) << 2
        << QStringLiteral("--json");
    QTest::newRow("sweep invalid parameter value")
        << sweep({"--var", "k", "--from", "0.3", "--to", "-1", "--steps", "3"}) << 2 << QStringLiteral("k = -0.35");
}

void TestCli::errors()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, culprit);
    const Run run = runPkm(arguments);
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QVERIFY(run.err.endsWith('\n'));
    QCOMPARE(run.err.count('\n'), 1); // one line
    const QString message = QString::fromUtf8(run.err);
    QVERIFY2(message.contains(culprit), qPrintable(message));
    QVERIFY(message.startsWith(QStringLiteral("pkm: ")));
    QVERIFY(message.trimmed().endsWith(QLatin1Char('.')));
}

void TestCli::help_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("expected");
    QTest::newRow("--help") << QStringList{QStringLiteral("--help")} << QStringLiteral("Usage: pkm COMMAND");
    QTest::newRow("help eval") << QStringList{QStringLiteral("help"), QStringLiteral("eval")}
                               << QStringLiteral("Usage: pkm eval");
    QTest::newRow("eval --help") << QStringList{QStringLiteral("eval"), QStringLiteral("--help")}
                                 << QStringLiteral("Usage: pkm eval");
    QTest::newRow("sweep -h wins over errors")
        << QStringList{QStringLiteral("sweep"), QStringLiteral("--bogus"), QStringLiteral("-h")}
        << QStringLiteral("exits with status 3");
    QTest::newRow("list --help") << QStringList{QStringLiteral("list"), QStringLiteral("--help")}
                                 << QStringLiteral("Usage: pkm list");
    QTest::newRow("show --help") << QStringList{QStringLiteral("show"), QStringLiteral("--help")}
                                 << QStringLiteral("Usage: pkm show");
    QTest::newRow("--version") << QStringList{QStringLiteral("--version")} << QStringLiteral("pkm " PKM_VERSION);
}

void TestCli::help()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, expected);
    const Run run = runPkm(arguments);
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    QVERIFY2(QString::fromUtf8(run.out).contains(expected), run.out.constData());
}

// -- in-process ----------------------------------------------------------------------------

void TestCli::inProcessMatchesBinary()
{
    const QStringList arguments{QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                                QStringLiteral("theta=30"), QStringLiteral("--json")};
    const Run inside = runInProcess(arguments);
    const Run outside = runPkm(arguments);
    QCOMPARE(inside.exitCode, 0);
    QCOMPARE(inside.out, outside.out);

    const Run failure = runInProcess({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"),
                                      QStringLiteral("--set"), QStringLiteral("theta=75")});
    QCOMPARE(failure.exitCode, int(CliNoSolution));
    QVERIFY(failure.out.isEmpty());
    QVERIFY(failure.err.contains("theta=75"));
}

void TestCli::numbersAreGeneral15_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("integer") << 30.0 << QStringLiteral("30");
    QTest::newRow("degree noise") << 29.999999999999996 << QStringLiteral("30");
    QTest::newRow("0.1 + 0.2") << 0.1 + 0.2 << QStringLiteral("0.3");
    QTest::newRow("negative zero") << -0.0 << QStringLiteral("0");
    QTest::newRow("negative") << -116.195923613971 << QStringLiteral("-116.195923613971");
    QTest::newRow("small") << 0.000123456789012345678 << QStringLiteral("0.000123456789012346");
    QTest::newRow("tiny") << 1e-5 << QStringLiteral("1e-05");
    QTest::newRow("large") << 1e20 << QStringLiteral("1e+20");
    QTest::newRow("just below 1e15") << 999999999999999.0 << QStringLiteral("999999999999999");
    QTest::newRow("rounds up to 1e15") << 999999999999999.9 << QStringLiteral("1e+15");
    QTest::newRow("pi") << std::numbers::pi << QStringLiteral("3.14159265358979");
}

void TestCli::numbersAreGeneral15()
{
    QFETCH(double, value);
    QFETCH(QString, expected);
    std::string text;
    cli::appendNumber(text, value);
    QCOMPARE(QString::fromStdString(text), expected);
}

void TestCli::fastNumbersMatchToChars()
{
    // writeNumber() takes a fast path for most values; it must give std::to_chars' text.
    std::mt19937_64 random(20240601);
    std::uniform_real_distribution<double> exponent(-8.0, 18.0);
    char buffer[cli::maxNumberLength];
    const auto check = [&](double value) {
        const std::string text(buffer, cli::writeNumber(buffer, value));
        if (text != referenceGeneral15(value)) {
            QFAIL(qPrintable(QStringLiteral("%1: %2 instead of %3")
                                 .arg(number(value), QString::fromStdString(text),
                                      QString::fromStdString(referenceGeneral15(value)))));
        }
    };
    for (int i = 0; i < 2000000; ++i) {
        const double value = std::pow(10.0, exponent(random));
        check(i % 2 ? value : -value);
    }
    for (int i = 0; i < 1000000; ++i) {
        const std::uint64_t bits = random();
        double value;
        std::memcpy(&value, &bits, sizeof value);
        if (std::isfinite(value))
            check(value);
    }
    for (int i = -200000; i <= 200000; ++i) {
        check(i / 1000.0);
        check(i * degree / degree);
        check(i / 7.0);
    }
    for (int power = -6; power <= 16; ++power) {
        const double p = std::pow(10.0, power);
        for (double value : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e300), p * 0.99999999999999995,
                             p * 9.999999999999995, p * 1.0000000000000005, p * 5.0000000000000005})
            check(value);
    }
}

void TestCli::numbersIgnoreLocale()
{
    // QCoreApplication calls setlocale(LC_ALL, ""): a decimal-comma locale must change nothing.
    // The locale is compiled into a temporary folder (localedef, Debian package "locales"),
    // so the test needs no system-wide locale and runs the real binary under it.
    QTemporaryDir locales;
    QVERIFY(locales.isValid());
    QProcess localedef;
    localedef.start(QStringLiteral("localedef"),
                    {QStringLiteral("-i"), QStringLiteral("de_DE"), QStringLiteral("-f"), QStringLiteral("UTF-8"),
                     locales.filePath(QStringLiteral("de_DE.UTF-8"))});
    QVERIFY2(localedef.waitForFinished(60000), "localedef did not finish");
    QVERIFY2(localedef.exitCode() == 0 || QFile::exists(locales.filePath(QStringLiteral("de_DE.UTF-8/LC_NUMERIC"))),
             localedef.readAllStandardError().constData());

    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("LOCPATH"), locales.path());
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("de_DE.UTF-8"));
    const QStringList arguments {QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                                 QStringLiteral("theta=30.5"), QStringLiteral("--json")};
    const Run german = runPkm(arguments, environment);
    const Run plain = runPkm(arguments);
    QCOMPARE(german.exitCode, 0);
    QVERIFY(german.out.contains("\"theta\": 30.5"));
    QCOMPARE(german.out, plain.out);
    // and the comma locale really is in force in such a process
    QProcess localeCheck;
    localeCheck.setProcessEnvironment(environment);
    localeCheck.start(QStringLiteral("locale"), {QStringLiteral("decimal_point")});
    QVERIFY(localeCheck.waitForFinished(10000));
    QCOMPARE(localeCheck.readAllStandardOutput().trimmed(), QByteArray(","));
}

void TestCli::notFiniteIsNullAndMatricesNest()
{
    const FakeMechanism fake;
    const QByteArray json = QByteArray::fromStdString(cli::evalJson(fake, fake.homePose()));
    QJsonParseError error;
    const QJsonObject root = QJsonDocument::fromJson(json, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("fake"));
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("x")).toDouble(),
             0.25 / degree);
    const QJsonArray J = root.value(QStringLiteral("jacobian")).toObject().value(QStringLiteral("J")).toArray();
    QCOMPARE(J.size(), 2);
    QCOMPARE(J[0].toArray().size(), 2);
    QCOMPARE(J[0].toArray()[1].toDouble(), 2.0);
    QCOMPARE(J[1].toArray()[0].toDouble(), 3.0);
    QVERIFY(!json.contains("-0")); // −0 is printed as 0
    const QJsonObject derived = root.value(QStringLiteral("derived")).toObject();
    QVERIFY(derived.contains(QStringLiteral("ratio")));
    QVERIFY(derived.value(QStringLiteral("ratio")).isNull());
    const QJsonObject singularity = root.value(QStringLiteral("singularity")).toObject();
    QCOMPARE(singularity.value(QStringLiteral("type")).toString(), QStringLiteral("direct"));
    QCOMPARE(singularity.value(QStringLiteral("undefined")).toArray(), QJsonArray{QStringLiteral("ratio")});
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
