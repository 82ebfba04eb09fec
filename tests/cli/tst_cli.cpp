// Tests of the `pkm` command against the reference in docs/cli.md: the real binary run through
// QProcess (exit codes, stdout/stderr separation, JSON keys, CSV shape, the prototype's
// published numbers), plus in-process checks of runCli() and the number formatter.

#include "cli/cli.h"
#include "cli/drawingcommands.h"
#include "cli/cliworkspace.h"
#include "export/workspacepictures.h"
#include "report/numberformat.h"
#include "scenepainter.h"
#include "support/app.h"
#include "support/process.h"

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <random>

using namespace pkm;
using namespace pkm::test;

namespace {

constexpr double degree = std::numbers::pi / 180.0;

/// The mobility `pkm eval --json` reports for the designs of each kind at a regular pose:
/// Chebyshev's W (−100: null, a spatial chain), Somov–Malyshev's W, the mobility (numerical and
/// finite), the actuated freedoms and whether they control the mechanism. Chebyshev's W differs
/// from the mobility only for an overconstrained planar chain, and the verdict must say why.
struct ExpectedMobility {
    int chebyshev;
    int somovMalyshev;
    int numerical;
    int actuators;
    bool fullyActuated;
};
const std::map<QString, ExpectedMobility> &expectedMobility()
{
    static const std::map<QString, ExpectedMobility> expected {
        {QStringLiteral("fourbar"), {1, -2, 1, 1, true}},
        {QStringLiteral("pjoint"), {1, -5, 1, 1, true}},
        {QStringLiteral("moma"), {2, -1, 2, 2, true}},
        {QStringLiteral("fivebar"), {2, -1, 2, 2, true}},
        // spatial, as built: the platform swings in its plane besides z, x_AB, x_CD (mobility.h)
        {QStringLiteral("oxglide"), {-100, 1, 4, 3, false}},
        // the leg library's presets, by preset: their chains differ
        {QStringLiteral("pp-5r"), {2, -1, 2, 2, true}},
        {QStringLiteral("pp-2prr-moma3a"), {2, -1, 2, 2, true}},
        {QStringLiteral("pp-3rpr"), {3, -3, 3, 3, true}},
        {QStringLiteral("pp-3rrr"), {3, -3, 3, 3, true}},
        {QStringLiteral("pp-3prr"), {3, -3, 3, 3, true}},
        {QStringLiteral("pp-5r-pjoint"), {2, -13, 2, 2, true}},
        // the second distal parallelogram repeats the first one's constraint on φ: Chebyshev
        // counts it and gives 1, one planar loop equation is redundant, the mobility is 2
        {QStringLiteral("pp-pa-pjoint"), {1, -20, 2, 2, true}},
    };
    return expected;
}

/// The first pose variable of each kind's caption ("pjoint-prototype — d = 183.10 mm, …").
const std::map<QString, QString> &firstCaptionSymbol()
{
    static const std::map<QString, QString> symbols {{QStringLiteral("pjoint"), QStringLiteral("d")},
        {QStringLiteral("moma"), QStringLiteral("p₁")}, {QStringLiteral("oxglide"), QStringLiteral("x_AB")},
        {QStringLiteral("fourbar"), QStringLiteral("α")}, {QStringLiteral("fivebar"), QStringLiteral("θ₁")},
        {QStringLiteral("planar-parallel"), QStringLiteral("q₁")}};
    return symbols;
}

/// Runs `pkm ARGUMENTS... --json` and parses stdout; the exit status goes to `exitCode`.
QJsonObject runJson(QStringList arguments, int *exitCode = nullptr)
{
    return pkmJson(arguments << QStringLiteral("--json"), exitCode);
}

QString number(double value)
{
    return QString::number(value, 'g', 17);
}

/// Whether `pkm list --json` lists the preset with its mechanism kind and a title.
bool listedInJson(const QString &id, const QString &kind)
{
    const Run json = runPkm({QStringLiteral("list"), QStringLiteral("--json")});
    if (json.exitCode != 0)
        return false;
    const QJsonArray presets = QJsonDocument::fromJson(json.out).object().value(QStringLiteral("presets")).toArray();
    for (const QJsonValue &preset : presets) {
        const QJsonObject object = preset.toObject();
        if (object.value(QStringLiteral("id")).toString() == id)
            return object.value(QStringLiteral("mechanism")).toString() == kind
                && !object.value(QStringLiteral("title")).toString().isEmpty();
    }
    return false;
}

/// The environment of a machine without a display: no DISPLAY, no WAYLAND_DISPLAY.
QProcessEnvironment withoutDisplay()
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("DISPLAY"));
    environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
    // A 3D picture loads Mesa's OpenGL driver, whose allocations an Asan build's LeakSanitizer
    // reports after the driver is unloaded at exit: not the project's leaks (ignored elsewhere).
    QString sanitizer = environment.value(QStringLiteral("ASAN_OPTIONS"));
    environment.insert(QStringLiteral("ASAN_OPTIONS"), sanitizer.append(QStringLiteral(":detect_leaks=0")));
    return environment;
}

/// The colours of a picture with the number of pixels of each.
QHash<QRgb, qsizetype> colourCounts(const QImage &image)
{
    QHash<QRgb, qsizetype> counts;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
        const QRgb *line = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x)
            ++counts[line[x] | 0xff000000u];
    }
    return counts;
}

/// The most frequent colour of a picture.
QRgb dominantColour(const QImage &image)
{
    const QHash<QRgb, qsizetype> counts = colourCounts(image);
    QRgb best = 0;
    qsizetype most = -1;
    for (auto it = counts.begin(); it != counts.end(); ++it) {
        if (it.value() > most) {
            most = it.value();
            best = it.key();
        }
    }
    return best;
}

/// Pixels farther than `tolerance` (per channel) from `colour`.
qsizetype pixelsUnlike(const QImage &image, QRgb colour, int tolerance = 24)
{
    qsizetype count = 0;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
        const QRgb *line = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x) {
            const QRgb p = line[x];
            count += std::abs(qRed(p) - qRed(colour)) > tolerance || std::abs(qGreen(p) - qGreen(colour)) > tolerance
                || std::abs(qBlue(p) - qBlue(colour)) > tolerance;
        }
    }
    return count;
}

QStringList directoryEntries(const QTemporaryDir &directory)
{
    return QDir(directory.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden);
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
    KinematicChain kinematicChain(const Pose &) const override { return {}; } // none: the report says so
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
    void evalAllModes_data();
    void evalAllModes();

    void momaEvalJsonHasContractKeys_data();
    void momaEvalJsonHasContractKeys();
    void momaInverseThenDirect();
    void momaSingularPose();
    void singularPosesAreExact_data();
    void singularPosesAreExact();

    void oxglideEvalJsonHasContractKeys_data();
    void oxglideEvalJsonHasContractKeys();
    void oxglideEvalPrototype();
    void oxglideInverseInXForm();
    void oxglideBadMode();
    void oxglideInputsOfTheOtherForm();
    void oxglideWorkspaceAreas();
    void oxglideMapJson();
    void detMapColoursShowTheBulk();
    void oxglideList();

    void fourbarEvalJsonHasContractKeys_data();
    void fourbarEvalJsonHasContractKeys();
    void fourbarAlphaBeyondLimit();
    void fourbarSweepFullTurn();

    void evalMobility_data();
    void evalMobility();
    void evalMobilityText();

    void workspaceJson();
    void workspaceModes();
    void workspaceText();
    void workspaceSet();
    void workspacePng();
    void workspaceSvg();
    void mapJson_data();
    void mapJson();
    void mapText();
    void mapPng();
    void picturesShowSingularCurves();
    void mapCsv();
    void outputFileErrors();
    void mapColourLimitIgnoresSpikes();

    void render2dPng_data();
    void render2dPng();
    void render2dCaptionAndPose();
    void render2dSvgAndPdf();
    void render3dWithoutDisplay();
    void render3dVectorFiles();
    void render3dWithoutXvfb();
    void renderErrors_data();
    void renderErrors();
    void renderInProcessNeedsGui();
    void lightProgramLoadsNoGuiLibrary();
    void drawingWithoutPkmDrawFailsClearly();

    void sweepCsv_data();
    void sweepCsv();
    void sweepOverDiagonal();
    void sweepJson();
    void sweepParameter();

    void errors_data();
    void errors();
    void help_data();
    void help();
    void helpNamesEveryJsonKey_data();
    void helpNamesEveryJsonKey();

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
    cli::registerDrawingCommands(); // runCli() in-process runs every command, as pkm-draw does
    QVERIFY(QFileInfo::exists(QStringLiteral(PKM_BINARY_DIR "/pkm")));
    QVERIFY(m_temporary.isValid());
    m_brokenFile = m_temporary.filePath(QStringLiteral("broken.pkm.json"));
    QFile file(m_brokenFile);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "pkm-studio-design", "version": 1, "mechanism": "pjoint", "parameters": {"a": 17)");
}

// -- eval --json: the keys docs/cli.md gives for pjoint ----------------------------------------

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
    static const QJsonObject root = prototypeEval({QStringLiteral("theta=20")});
    const QJsonValue value = root.value(group).toObject().value(key);
    QVERIFY2(value.isDouble(), qPrintable(group + QLatin1Char('.') + key + QStringLiteral(" is missing")));
    QVERIFY(std::isfinite(value.toDouble()));
}

void TestCli::evalJsonTopLevel()
{
    int exitCode = -1;
    const QJsonObject root = prototypeEval({}, &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.keys().size(), 8);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("pjoint"));
    for (const char *key : {"parameters", "pose", "jacobian", "singularity", "derived", "capability", "mobility"})
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
    const QJsonObject derived = prototypeEval({}).value(QStringLiteral("derived")).toObject();
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
    const QJsonObject inverse = prototypeEval({QStringLiteral("theta=") + number(theta)}, &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject pose = inverse.value(QStringLiteral("pose")).toObject();
    const double d = pose.value(QStringLiteral("d")).toDouble();
    QCOMPARE(d, a * std::sqrt(1 + k * k + 2 * k * std::sin(theta * degree))); // (2)
    QCOMPARE(pose.value(QStringLiteral("theta")).toDouble(), theta);

    // J = a·sin μ (docs/mathematics.md, section 1), read back from the JSON.
    const double mu = pose.value(QStringLiteral("mu")).toDouble();
    const double J = inverse.value(QStringLiteral("jacobian")).toObject().value(QStringLiteral("J")).toDouble();
    QCOMPARE(J, a * std::sin(mu * degree));

    const QJsonObject direct = prototypeEval({QStringLiteral("d=") + number(d)}, &exitCode);
    QCOMPARE(exitCode, 0);
    const double back = direct.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble();
    QVERIFY2(std::abs(back - theta) < 1e-9, qPrintable(number(back)));
}

void TestCli::settingKResizesCoupler()
{
    int exitCode = -1;
    const QJsonObject parameters
        = prototypeEval({QStringLiteral("k=0.5")}, &exitCode).value(QStringLiteral("parameters")).toObject();
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
        const QJsonObject parameters = prototypeEval(sets, &exitCode).value(QStringLiteral("parameters")).toObject();
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
    const QJsonObject root = prototypeEval({QStringLiteral("theta=70"), QStringLiteral("theta_max=80")}, &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("theta")).toDouble(), 70.0);
    // A new a keeps the stored θ = 0 and re-solves d for the new design.
    const QJsonObject pose = prototypeEval({QStringLiteral("a=200")}).value(QStringLiteral("pose")).toObject();
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

    QVERIFY(listedInJson(QStringLiteral("pjoint-prototype"), QStringLiteral("pjoint")));
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

// -- moma: eval ----------------------------------------------------------------------------

void TestCli::momaEvalJsonHasContractKeys_data()
{
    QTest::addColumn<QString>("group");
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("size"); // 0: a number, 2: a 2×2 row-major nested array
    const auto add = [](const char *group, std::initializer_list<const char *> keys, int size) {
        for (const char *key : keys)
            QTest::addRow("%s.%s", group, key) << QString::fromLatin1(group) << QString::fromLatin1(key) << size;
    };
    add("parameters", {"R1x", "R1y", "R2x", "R2y", "alpha1", "alpha2", "l1", "l2", "p_min", "p_max", "branch1",
                       "branch2", "assembly"}, 0);
    add("pose", {"p1", "p2", "x", "y"}, 0);
    add("jacobian", {"Jp", "Jx", "J"}, 2);
    add("jacobian", {"det_J", "det_Jp", "det_Jx"}, 0);
}

namespace {
/// One contract key of an `eval --json` answer: a finite number (size 0) or a size × size
/// array of numbers; and a singularity class that is one of the four.
void checkContractKey(const QJsonObject &root, const QString &group, const QString &key, int size)
{
    const QJsonValue value = root.value(group).toObject().value(key);
    if (size == 0) {
        QVERIFY2(value.isDouble(), qPrintable(group + QLatin1Char('.') + key + QStringLiteral(" is missing")));
        QVERIFY(std::isfinite(value.toDouble()));
    } else {
        const QJsonArray rows = value.toArray();
        QCOMPARE(rows.size(), size);
        for (const QJsonValue &row : rows) {
            QCOMPARE(row.toArray().size(), size);
            for (const QJsonValue &element : row.toArray())
                QVERIFY(element.isDouble());
        }
    }
    const QString type = root.value(QStringLiteral("singularity")).toObject().value(QStringLiteral("type")).toString();
    QVERIFY2(QStringList({QStringLiteral("none"), QStringLiteral("inverse"), QStringLiteral("direct"),
                          QStringLiteral("combined")})
                 .contains(type),
             qPrintable(type));
}
} // namespace

void TestCli::momaEvalJsonHasContractKeys()
{
    QFETCH(QString, group);
    QFETCH(QString, key);
    QFETCH(int, size);
    static int exitCode = -1;
    static const QJsonObject root = runJson(args({"eval", "moma-3a"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("moma"));
    checkContractKey(root, group, key, size);
}

void TestCli::momaInverseThenDirect()
{
    // J is row-major: det J from its rows is det_J, and det J = det J_x / det J_p.
    int exitCode = -1;
    const QJsonObject inverse = runJson(args({"eval", "moma-3a", "--set", "x=10", "--set", "y=-250"}), &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject pose = inverse.value(QStringLiteral("pose")).toObject();
    QCOMPARE(pose.value(QStringLiteral("x")).toDouble(), 10.0);
    QCOMPARE(pose.value(QStringLiteral("y")).toDouble(), -250.0);
    const QJsonObject jacobian = inverse.value(QStringLiteral("jacobian")).toObject();
    const QJsonArray J = jacobian.value(QStringLiteral("J")).toArray();
    const double det = J[0].toArray()[0].toDouble() * J[1].toArray()[1].toDouble()
        - J[0].toArray()[1].toDouble() * J[1].toArray()[0].toDouble();
    const double detJ = jacobian.value(QStringLiteral("det_J")).toDouble();
    QVERIFY2(std::abs(det - detJ) < 1e-9 * std::abs(detJ), qPrintable(number(det) + QLatin1Char(' ') + number(detJ)));
    QVERIFY(std::abs(detJ * jacobian.value(QStringLiteral("det_Jp")).toDouble()
                     - jacobian.value(QStringLiteral("det_Jx")).toDouble())
            < 1e-6 * std::abs(jacobian.value(QStringLiteral("det_Jx")).toDouble()));
    QVERIFY(detJ < 0); // 3a in this convention

    const double p1 = pose.value(QStringLiteral("p1")).toDouble();
    const double p2 = pose.value(QStringLiteral("p2")).toDouble();
    const QJsonObject direct = runJson(
        {QStringLiteral("eval"), QStringLiteral("moma-3a"), QStringLiteral("--set"), QStringLiteral("p1=") + number(p1),
         QStringLiteral("--set"), QStringLiteral("p2=") + number(p2)},
        &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject back = direct.value(QStringLiteral("pose")).toObject();
    QVERIFY(std::abs(back.value(QStringLiteral("x")).toDouble() - 10.0) < 1e-9);
    QVERIFY(std::abs(back.value(QStringLiteral("y")).toDouble() + 250.0) < 1e-9);
}

void TestCli::evalAllModes_data()
{
    QTest::addColumn<QString>("design");
    QTest::addColumn<int>("modes");
    QTest::addColumn<QStringList>("outputs");
    // the 3-RPR preset's home pose has six real assembly modes
    QTest::newRow("pp-3rpr") << QStringLiteral("pp-3rpr") << 6 << args({"x", "y", "phi"});
    // a five-bar has two: C on either side of B→D
    QTest::newRow("fivebar-example") << QStringLiteral("fivebar-example") << 2 << args({"x", "y"});
    QTest::newRow("pp-5r") << QStringLiteral("pp-5r") << 2 << args({"x", "y"});
}

void TestCli::evalAllModes()
{
    QFETCH(QString, design);
    QFETCH(int, modes);
    QFETCH(QStringList, outputs);
    int exitCode = -1;
    const QJsonObject root = runJson(args({"eval"}) << design << QStringLiteral("--all-modes") << QStringLiteral("--json"), &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonArray found = root.value(QStringLiteral("assembly_modes")).toArray();
    QCOMPARE(found.size(), modes);
    // the pose itself is one of them, and they are distinct
    const QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
    int own = 0;
    for (qsizetype i = 0; i < found.size(); ++i) {
        const QJsonObject mode = found[i].toObject();
        QCOMPARE(mode.size(), outputs.size());
        double distance = 0.0;
        for (const QString &name : outputs) {
            QVERIFY2(mode.value(name).isDouble(), qPrintable(name));
            distance += std::abs(mode.value(name).toDouble() - pose.value(name).toDouble());
        }
        own += distance < 1e-6 ? 1 : 0;
        for (qsizetype j = 0; j < i; ++j) {
            double apart = 0.0;
            for (const QString &name : outputs)
                apart += std::abs(mode.value(name).toDouble() - found[j].toObject().value(name).toDouble());
            QVERIFY2(apart > 1e-6, "two modes are the same pose");
        }
    }
    QCOMPARE(own, 1);
    // each is a pose of the design: solving its outputs gives the same inputs
    for (const QJsonValue &value : found) {
        const QJsonObject mode = value.toObject();
        QStringList solve = args({"eval"}) << design;
        for (const QString &name : outputs)
            solve << QStringLiteral("--set") << name + QLatin1Char('=') + QString::number(mode.value(name).toDouble(), 'g', 17);
        if (design == QStringLiteral("pp-3rpr")) {
            // the struts' lengths are the inputs whatever the mode
            const QJsonObject solved = runJson(QStringList(solve) << QStringLiteral("--json"), &exitCode);
            QCOMPARE(exitCode, 0);
            for (const char *input : {"q1", "q2", "q3"})
                QVERIFY(std::abs(solved.value(QStringLiteral("pose")).toObject().value(QLatin1String(input)).toDouble()
                            - pose.value(QLatin1String(input)).toDouble()) < 1e-6);
        }
    }
    // the text output lists them, the pose's own marked
    const Run text = runPkm(args({"eval"}) << design << QStringLiteral("--all-modes"));
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.out.contains("Assembly modes at these inputs"));
    QVERIFY(text.out.contains(" *"));
}

void TestCli::singularPosesAreExact_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("type");
    QTest::addColumn<QStringList>("infinite");
    QTest::addColumn<QStringList>("zero");
    // both legs stretched at the top of the workspace: C = (50, √(200² − 50²)) mm; a formula a
    // hair's breadth from it gave det J ≈ 10¹³ rad²/mm² in the values panel
    QTest::newRow("five-bar legs stretched")
        << args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=193.64916731037084"}) << QStringLiteral("inverse")
        << args({"J", "det_J", "cond"}) << args({"det_Jq"});
    // 10⁻¹³ mm inside, where the formulas give det J ≈ 10¹²: classified singular (margin below
    // 10⁻⁷), so the same exact values
    QTest::newRow("five-bar a hair inside")
        << args({"eval", "fivebar-example", "--set", "x=50", "--set", "y=193.6491673103707"}) << QStringLiteral("inverse")
        << args({"J", "det_J", "cond"}) << args({"det_Jq"});
}

void TestCli::singularPosesAreExact()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, type);
    QFETCH(QStringList, infinite);
    QFETCH(QStringList, zero);
    const Run json = runPkm(QStringList(arguments) << QStringLiteral("--json"));
    QVERIFY2(json.exitCode == 0, json.err.constData());
    const QJsonObject root = QJsonDocument::fromJson(json.out).object();
    const QJsonObject singularity = root.value(QStringLiteral("singularity")).toObject();
    const QJsonObject jacobian = root.value(QStringLiteral("jacobian")).toObject();
    QCOMPARE(singularity.value(QStringLiteral("type")).toString(), type);
    QVERIFY(!singularity.value(QStringLiteral("reason")).toString().isEmpty());
    const QJsonArray listed = singularity.value(QStringLiteral("infinite")).toArray();
    for (const QString &name : infinite) {
        QVERIFY2(listed.contains(name), qPrintable(name));
        QVERIFY2(singularity.value(QStringLiteral("undefined")).toArray().contains(name), qPrintable(name));
    }
    for (const QString &name : zero)
        QCOMPARE(jacobian.value(name).toDouble(), 0.0);
    // and the text says ∞, never a huge number
    const Run text = runPkm(arguments);
    QCOMPARE(text.exitCode, 0);
    const QString out = QString::fromUtf8(text.out);
    QVERIFY(out.contains(QStringLiteral("∞")));
    static const QRegularExpression huge(QStringLiteral("\\b\\d{9,}"));
    QVERIFY2(!huge.match(out).hasMatch(), qPrintable(huge.match(out).captured()));
}

void TestCli::momaSingularPose()
{
    // 3c in the other assembly mode reaches (195, 195) mm, where both links are perpendicular
    // to their guides: det J_p = 0, det J and J's second row are infinite.
    const QStringList arguments = args({"eval", "moma-3c", "--set", "assembly=-1", "--set", "x=195", "--set", "y=195"});
    const Run json = runPkm(QStringList(arguments) << QStringLiteral("--json"));
    QCOMPARE(json.exitCode, 0);
    QJsonParseError error;
    const QJsonObject root = QJsonDocument::fromJson(json.out, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    // no bare inf or nan (the key "infinite" is a word, not a number)
    static const QRegularExpression bareNumber(QStringLiteral("\\b(-?inf|nan)\\b"), QRegularExpression::CaseInsensitiveOption);
    QVERIFY(!bareNumber.match(QString::fromUtf8(json.out)).hasMatch());
    const QJsonObject jacobian = root.value(QStringLiteral("jacobian")).toObject();
    QVERIFY(jacobian.value(QStringLiteral("det_J")).isNull());
    QCOMPARE(jacobian.value(QStringLiteral("det_Jp")).toDouble(), 0.0);
    QVERIFY(jacobian.value(QStringLiteral("det_Jx")).isDouble());
    QCOMPARE(jacobian.value(QStringLiteral("J")).toArray().size(), 2);
    const QJsonObject singularity = root.value(QStringLiteral("singularity")).toObject();
    QCOMPARE(singularity.value(QStringLiteral("type")).toString(), QStringLiteral("inverse"));
    QVERIFY(singularity.value(QStringLiteral("undefined")).toArray().contains(QStringLiteral("det_J")));
    // unbounded, not undefined: J = −J_p⁻¹·J_x does not exist there, and the reason says so
    const QJsonArray infinite = singularity.value(QStringLiteral("infinite")).toArray();
    QVERIFY(infinite.contains(QStringLiteral("det_J")));
    QVERIFY(infinite.contains(QStringLiteral("J")));
    QVERIFY(infinite.contains(QStringLiteral("cond")));
    QVERIFY(singularity.value(QStringLiteral("reason")).toString().startsWith(QStringLiteral("inverse singularity")));

    const Run text = runPkm(arguments);
    QCOMPARE(text.exitCode, 0);
    const QString out = QString::fromUtf8(text.out);
    QVERIFY(out.contains(QStringLiteral("∞")));
    static const QRegularExpression notANumber(QStringLiteral("\\b(-?inf|nan)\\b"),
                                               QRegularExpression::CaseInsensitiveOption);
    QVERIFY2(!notANumber.match(out).hasMatch(), qPrintable(notANumber.match(out).captured()));
    QVERIFY(out.contains(QStringLiteral("inverse")));

    // Elsewhere on y = 195 mm only leg 1 is singular; the JSON stays valid whatever the values.
    const Run edge = runPkm(args({"eval", "moma-3c", "--set", "assembly=-1", "--set", "x=190", "--set", "y=195",
                                  "--json"}));
    QCOMPARE(edge.exitCode, 0);
    const QJsonObject edgeRoot = QJsonDocument::fromJson(edge.out, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(edgeRoot.value(QStringLiteral("singularity")).toObject().value(QStringLiteral("type")).toString(),
             QStringLiteral("inverse"));
    const QJsonValue detJ = edgeRoot.value(QStringLiteral("jacobian")).toObject().value(QStringLiteral("det_J"));
    QVERIFY(detJ.isNull() || std::abs(detJ.toDouble()) > 1e6);
}

// -- oxglide -------------------------------------------------------------------------------

namespace {

/// The exact area (mm²) of one form's planar workspace of the O-X glide, integrated slice by
/// slice (docs/mathematics.md, section 3): at height y, with w = √(l² − y²), the platform centre reaches
///   O: x ∈ [s/2 + w, L − s/2 − w]        (width L − s − 2w, positive above w = (L − s)/2)
///   X: x ∈ [|w − s/2|, L − |w − s/2|]    (width L + s − 2w below w = s/2, L − s + 2w above)
/// and ∫ w dy = ½(y·w + l²·asin(y/l)). For the prototype (l = 80, s = 20, L = 130 mm) this is
/// 753.33 mm² (O) and 2125.33 mm² (X).
double oxglideArea(double l, double s, double L, bool crossed)
{
    const auto primitive = [l](double y) { return 0.5 * (y * std::sqrt(l * l - y * y) + l * l * std::asin(y / l)); };
    const auto height = [l](double w) { return w < l ? std::sqrt(l * l - w * w) : 0.0; }; // where √(l² − y²) = w
    if (!crossed) {
        const double y0 = height((L - s) / 2);
        return (L - s) * (l - y0) - 2 * (primitive(l) - primitive(y0));
    }
    const double yh = height(s / 2);
    const double y1 = height((L + s) / 2);
    return (L + s) * (yh - y1) - 2 * (primitive(yh) - primitive(y1)) + (L - s) * (l - yh)
        + 2 * (primitive(l) - primitive(yh));
}

double jsonNumber(const QJsonObject &object, const char *key)
{
    return object.value(QLatin1String(key)).toDouble(std::numeric_limits<double>::quiet_NaN());
}

} // namespace

void TestCli::oxglideEvalJsonHasContractKeys_data()
{
    QTest::addColumn<QString>("group");
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("size"); // 0: a number, 2: a 2×2 row-major nested array
    const auto add = [](const char *group, std::initializer_list<const char *> keys, int size) {
        for (const char *key : keys)
            QTest::addRow("%s.%s", group, key) << QString::fromLatin1(group) << QString::fromLatin1(key) << size;
    };
    add("parameters", {"l", "s", "L", "a", "z_min", "z_max"}, 0);
    add("pose", {"x_AB", "x_CD", "x", "y", "z"}, 0);
    add("jacobian", {"J"}, 2);
    add("jacobian", {"det_J"}, 0);
}

void TestCli::oxglideEvalJsonHasContractKeys()
{
    QFETCH(QString, group);
    QFETCH(QString, key);
    QFETCH(int, size);
    static int exitCode = -1;
    static const QJsonObject root = runJson(args({"eval", "oxglide-prototype"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("oxglide"));
    checkContractKey(root, group, key, size);
    // the form is a word
    QCOMPARE(root.value(QStringLiteral("pose")).toObject().value(QStringLiteral("mode")).toString(), QStringLiteral("O"));
}

void TestCli::oxglideEvalPrototype()
{
    // The preset's pose: x_AB = 15, x_CD = 115 mm in the O form, so T = (65, √(80² − 40²)) mm,
    // w = 40 mm; J = [1, y/w; 1, −y/w], det J = −2y/w, no singularity.
    int exitCode = -1;
    const QJsonObject root = runJson(args({"eval", "oxglide-prototype"}), &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    QCOMPARE(jsonNumber(parameters, "l"), 80.0);
    QCOMPARE(jsonNumber(parameters, "s"), 20.0);
    QCOMPARE(jsonNumber(parameters, "L"), 130.0);
    const QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
    QCOMPARE(jsonNumber(pose, "x_AB"), 15.0);
    QCOMPARE(jsonNumber(pose, "x_CD"), 115.0);
    QCOMPARE(jsonNumber(pose, "z"), 75.0);
    QCOMPARE(jsonNumber(pose, "x"), 65.0);
    const double y = std::sqrt(80.0 * 80.0 - 40.0 * 40.0);
    QVERIFY(std::abs(jsonNumber(pose, "y") - y) < 1e-12);
    const QJsonObject jacobian = root.value(QStringLiteral("jacobian")).toObject();
    const QJsonArray J = jacobian.value(QStringLiteral("J")).toArray();
    QVERIFY(std::abs(J[0].toArray()[0].toDouble() - 1.0) < 1e-12);
    QVERIFY(std::abs(J[0].toArray()[1].toDouble() - y / 40) < 1e-12);
    QVERIFY(std::abs(J[1].toArray()[1].toDouble() + y / 40) < 1e-12);
    const double det = J[0].toArray()[0].toDouble() * J[1].toArray()[1].toDouble()
        - J[0].toArray()[1].toDouble() * J[1].toArray()[0].toDouble();
    QVERIFY(std::abs(jsonNumber(jacobian, "det_J") - det) < 1e-12);
    QVERIFY(std::abs(det + 2 * y / 40) < 1e-12);
    QCOMPARE(root.value(QStringLiteral("singularity")).toObject().value(QStringLiteral("type")).toString(),
             QStringLiteral("none"));
}

void TestCli::oxglideInverseInXForm()
{
    // mode=X with the outputs and z together (z is an independent axis): x_AB = x − s/2 + w,
    // x_CD = x + s/2 − w with w = √(80² − 60²) = √2800 mm.
    int exitCode = -1;
    const QJsonObject root = runJson(
        args({"eval", "oxglide-prototype", "--set", "mode=X", "--set", "x=65", "--set", "y=60", "--set", "z=10"}),
        &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(jsonNumber(root.value(QStringLiteral("parameters")).toObject(), "mode"), -1.0);
    const QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
    QCOMPARE(pose.value(QStringLiteral("mode")).toString(), QStringLiteral("X"));
    QCOMPARE(jsonNumber(pose, "x"), 65.0);
    QCOMPARE(jsonNumber(pose, "y"), 60.0);
    QCOMPARE(jsonNumber(pose, "z"), 10.0);
    const double w = std::sqrt(2800.0);
    const double xAB = jsonNumber(pose, "x_AB"), xCD = jsonNumber(pose, "x_CD");
    QVERIFY(std::abs(xAB - (55 + w)) < 1e-9);
    QVERIFY(std::abs(xCD - (75 - w)) < 1e-9);
    // det J = +2y/w in the X form
    QVERIFY(std::abs(jsonNumber(root.value(QStringLiteral("jacobian")).toObject(), "det_J") - 120 / w) < 1e-9);

    // … and back: the inputs give the point again (the corrected "− s" direct kinematics)
    const QJsonObject direct = runJson({QStringLiteral("eval"), QStringLiteral("oxglide-prototype"),
                                        QStringLiteral("--set"), QStringLiteral("mode=X"), QStringLiteral("--set"),
                                        QStringLiteral("x_AB=") + number(xAB), QStringLiteral("--set"),
                                        QStringLiteral("x_CD=") + number(xCD)},
                                       &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject back = direct.value(QStringLiteral("pose")).toObject();
    QVERIFY(std::abs(jsonNumber(back, "x") - 65) < 1e-9);
    QVERIFY(std::abs(jsonNumber(back, "y") - 60) < 1e-9);
    QCOMPARE(back.value(QStringLiteral("mode")).toString(), QStringLiteral("X"));
}

void TestCli::oxglideBadMode()
{
    const Run run = runPkm(args({"eval", "oxglide-prototype", "--set", "mode=Q"}));
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QCOMPARE(run.err.count('\n'), 1); // one line
    QVERIFY(run.err.startsWith("pkm: "));
    const QString message = QString::fromUtf8(run.err);
    QVERIFY2(message.contains(QStringLiteral("mode")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("Q")), qPrintable(message));
    static const QRegularExpression allowed(QStringLiteral("\\bO\\b.*\\bX\\b"));
    QVERIFY2(allowed.match(message).hasMatch(), qPrintable(message)); // names the allowed O and X
    // a number other than ±1 is refused as well, the names and ±1 are taken
    const Run half = runPkm(args({"eval", "oxglide-prototype", "--set", "mode=0.5"}));
    QCOMPARE(half.exitCode, 2);
    QVERIFY(half.out.isEmpty());
    QVERIFY(half.err.contains("mode"));
    for (const char *mode : {"mode=O", "mode=X", "mode=1", "mode=-1"}) {
        const Run good = runPkm(args({"eval", "oxglide-prototype", "--set", mode, "--set", "x=65", "--set", "y=70"}));
        QVERIFY2(good.exitCode == 0, good.err.constData());
    }
}

void TestCli::oxglideInputsOfTheOtherForm()
{
    // x_CD − x_AB = 10 mm < s: slider positions of the crossed form, refused by the O design
    // (the pairs would have passed the O↔X singularity).
    const Run run = runPkm(args({"eval", "oxglide-prototype", "--set", "x_AB=60", "--set", "x_CD=70"}));
    QCOMPARE(run.exitCode, 3);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QCOMPARE(run.err.count('\n'), 1);
    const QString message = QString::fromUtf8(run.err);
    QVERIFY2(message.contains(QStringLiteral("form")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("crossed (X)")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("x_CD")), qPrintable(message));
    const Run json = runPkm(args({"eval", "oxglide-prototype", "--set", "x_AB=60", "--set", "x_CD=70", "--json"}));
    QCOMPARE(json.exitCode, 3);
    QVERIFY(json.out.isEmpty());
    // the X design takes them: y = ½√(4l² − (x_CD − x_AB − s)²) = ½√(25600 − 100)
    int exitCode = -1;
    const QJsonObject crossed = runJson(
        args({"eval", "oxglide-prototype", "--set", "mode=X", "--set", "x_AB=60", "--set", "x_CD=70"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QVERIFY(std::abs(jsonNumber(crossed.value(QStringLiteral("pose")).toObject(), "y") - 0.5 * std::sqrt(25500.0))
            < 1e-9);
}

void TestCli::oxglideWorkspaceAreas()
{
    const double exactO = oxglideArea(80, 20, 130, false), exactX = oxglideArea(80, 20, 130, true);
    QVERIFY(std::abs(exactO - 753.33) < 0.01);
    QVERIFY(std::abs(exactX - 2125.33) < 0.01);
    for (const char *grid : {"400", "1600"}) {
        int exitCode = -1;
        const QJsonObject root = runJson(args({"workspace", "oxglide-prototype", "--grid", grid}), &exitCode);
        QCOMPARE(exitCode, 0);
        QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("oxglide"));
        for (const char *key : {"area", "area_O", "area_X", "area_union", "area_grid", "area_O_grid", "area_X_grid"})
            QVERIFY2(root.value(QLatin1String(key)).isDouble(), key);
        // the areas known in closed form are given as the areas, the grid's counts beside them
        QVERIFY(std::abs(jsonNumber(root, "area_O") - exactO) < 1e-9 * exactO);
        QVERIFY(std::abs(jsonNumber(root, "area_X") - exactX) < 1e-9 * exactX);
        QCOMPARE(jsonNumber(root, "area"), jsonNumber(root, "area_O")); // the preset works in the O form
        QVERIFY(std::abs(jsonNumber(root, "volume") - exactO * jsonNumber(root, "travel")) < 1e-9 * jsonNumber(root, "volume"));
        const double area = jsonNumber(root, "area_grid"), areaO = jsonNumber(root, "area_O_grid");
        const double areaX = jsonNumber(root, "area_X_grid"), areaUnion = jsonNumber(root, "area_union");
        QCOMPARE(areaO, area);
        // The O workspace lies inside the X one (the O slice [s/2 + w, L − s/2 − w] inside the
        // X slice [|w − s/2|, L − |w − s/2|]), so the union is the X workspace.
        QCOMPARE(areaUnion, areaX);
        QVERIFY(areaX > areaO); // fig. 5: the X form is the larger
        qInfo("--grid %s: area_O %.2f mm² (exact %.2f), area_X %.2f mm² (exact %.2f)", grid, areaO, exactO, areaX,
              exactX);
        const double tolerance = QByteArray(grid) == "1600" ? 0.01 : 0.03;
        QVERIFY2(std::abs(areaO - exactO) < tolerance * exactO, qPrintable(number(areaO)));
        QVERIFY2(std::abs(areaX - exactX) < tolerance * exactX, qPrintable(number(areaX)));
        // the closed-form areas beside the grid's estimates, the same whatever the grid
        const QJsonObject exact = root.value(QStringLiteral("exact_areas")).toObject();
        QVERIFY(std::abs(jsonNumber(exact, "area_O") - exactO) < 1e-9 * exactO);
        QVERIFY(std::abs(jsonNumber(exact, "area_X") - exactX) < 1e-9 * exactX);
        QCOMPARE(jsonNumber(exact, "area"), jsonNumber(exact, "area_O"));
        // one entry per form, the current one is O
        const QJsonArray modes = root.value(QStringLiteral("modes")).toArray();
        QCOMPARE(modes.size(), 2);
        for (const QJsonValue &value : modes) {
            const QJsonObject mode = value.toObject();
            const bool crossed = mode.value(QStringLiteral("mode")).toString() == QLatin1String("X");
            QCOMPARE(mode.value(QStringLiteral("current")).toBool(), !crossed);
            QCOMPARE(jsonNumber(mode, "area"), crossed ? areaX : areaO);
        }
    }
    // a kind without closed-form areas says so
    int exitCode = -1;
    const QJsonObject moma = runJson(args({"workspace", "moma-3a", "--grid", "100"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QVERIFY(moma.contains(QStringLiteral("exact_areas")));
    QVERIFY(moma.value(QStringLiteral("exact_areas")).isNull());
    QVERIFY(!moma.contains(QStringLiteral("area_grid"))); // its area is the grid's, and says so once
    // and the text output gives the exact area first, the grid's marked as such
    const Run text = runPkm(args({"workspace", "oxglide-prototype"}));
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.out.contains("area (exact)"));
    QVERIFY(text.out.contains("area (grid)"));
    QVERIFY(text.out.contains("753.3"));
    // in the X form "area" is the X workspace and the union stays the same
    const QJsonObject crossed = runJson(args({"workspace", "oxglide-prototype", "--grid", "400", "--set", "mode=X"}),
                                        &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(jsonNumber(crossed, "area"), jsonNumber(crossed, "area_X"));
    QCOMPARE(jsonNumber(crossed, "area_union"), jsonNumber(crossed, "area_X_grid"));
    QCOMPARE(jsonNumber(crossed, "area_grid"), jsonNumber(crossed, "area_X_grid"));
    QVERIFY(std::abs(jsonNumber(crossed, "area") - oxglideArea(80, 20, 130, true)) < 1e-9 * jsonNumber(crossed, "area"));
}

void TestCli::oxglideMapJson()
{
    int exitCode = -1;
    const QJsonObject root = runJson(args({"map", "oxglide-prototype"}), &exitCode);
    QCOMPARE(exitCode, 0);
    for (const char *key : {"grid", "bounds", "reachable_cells", "min", "max", "near_singular_cells", "seconds"})
        QVERIFY2(root.contains(QLatin1String(key)), key);
    const QJsonObject grid = root.value(QStringLiteral("grid")).toObject();
    QCOMPARE(std::max(grid.value(QStringLiteral("columns")).toInt(), grid.value(QStringLiteral("rows")).toInt()), 400);
    const QJsonObject bounds = root.value(QStringLiteral("bounds")).toObject();
    // the O workspace: s/2 ≤ x ≤ L − s/2, √(80² − 55²) ≤ y ≤ l (to within a cell)
    const double cell = jsonNumber(root, "cell_size");
    QVERIFY(jsonNumber(bounds, "x_min") >= 10 - cell && jsonNumber(bounds, "x_max") <= 120 + cell);
    QVERIFY(jsonNumber(bounds, "y_min") >= std::sqrt(6400.0 - 3025.0) - cell);
    QVERIFY(jsonNumber(bounds, "y_max") <= 80 + cell);
    // det J = −2y/w < 0 all over the O workspace, and |det J| grows without bound towards y = l
    QVERIFY(jsonNumber(root, "min") <= jsonNumber(root, "max"));
    QVERIFY2(jsonNumber(root, "max") < 0, qPrintable(number(jsonNumber(root, "max"))));
    QVERIFY(jsonNumber(root, "min") < -10);
    const double reachable = jsonNumber(root, "reachable_cells");
    QVERIFY(reachable > 0);
    QVERIFY(jsonNumber(root, "near_singular_cells") > 0); // the cells next to y = l
    QVERIFY(jsonNumber(root, "near_singular_cells") <= reachable);
    QVERIFY(jsonNumber(root, "seconds") >= 0);
    const QJsonObject workspace = runJson(args({"workspace", "oxglide-prototype"}));
    QCOMPARE(root.value(QStringLiteral("reachable_cells")), workspace.value(QStringLiteral("reachable_cells")));
    // the condition number is at least 1
    const QJsonObject cond
        = runJson(args({"map", "oxglide-prototype", "--quantity", "cond", "--grid", "200"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QVERIFY(jsonNumber(cond, "min") >= 1.0 - 1e-6);
}

void TestCli::oxglideList()
{
    const Run text = runPkm(args({"list"}));
    QCOMPARE(text.exitCode, 0);
    bool found = false;
    for (const QByteArray &line : text.out.split('\n')) {
        if (line.startsWith("oxglide-prototype ")) {
            found = true;
            QVERIFY(line.contains(" oxglide "));
        }
    }
    QVERIFY(found);
    QVERIFY(listedInJson(QStringLiteral("oxglide-prototype"), QStringLiteral("oxglide")));
}

// -- workspace and map ---------------------------------------------------------------------

void TestCli::workspaceJson()
{
    int exitCode = -1;
    const QJsonObject root = runJson(args({"workspace", "moma-3a"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("moma"));
    const double area = root.value(QStringLiteral("area")).toDouble();
    QVERIFY2(std::abs(area - 19300.0) < 0.01 * 19300.0, qPrintable(number(area))); // fig. 6a
    const QJsonObject grid = root.value(QStringLiteral("grid")).toObject();
    QCOMPARE(grid.value(QStringLiteral("resolution")).toInt(), 400); // the default
    QCOMPARE(std::max(grid.value(QStringLiteral("columns")).toInt(), grid.value(QStringLiteral("rows")).toInt()), 400);
    const double cell = root.value(QStringLiteral("cell_size")).toDouble();
    const double cells = root.value(QStringLiteral("reachable_cells")).toDouble();
    QVERIFY(cells > 0);
    QVERIFY(std::abs(cells * cell * cell - area) < 1e-6 * area);
    const QJsonObject bounds = root.value(QStringLiteral("bounds")).toObject();
    for (const char *key : {"x_min", "x_max", "y_min", "y_max"}) {
        QVERIFY2(bounds.value(QLatin1String(key)).isDouble(), key);
        QVERIFY2(grid.value(QLatin1String(key)).isDouble(), key);
    }
    // 3a is symmetric about x = 0 and lies below the guides' reference points
    QVERIFY(std::abs(bounds.value(QStringLiteral("x_min")).toDouble() + bounds.value(QStringLiteral("x_max")).toDouble())
            < 1e-6);
    QVERIFY(bounds.value(QStringLiteral("y_max")).toDouble() < 0);
    QVERIFY(bounds.value(QStringLiteral("x_min")).toDouble() >= grid.value(QStringLiteral("x_min")).toDouble());
    QVERIFY(bounds.value(QStringLiteral("y_max")).toDouble() <= grid.value(QStringLiteral("y_max")).toDouble());
    QVERIFY(root.value(QStringLiteral("seconds")).toDouble() >= 0);
}

void TestCli::workspaceModes()
{
    int exitCode = -1;
    const QJsonObject root = runJson(args({"workspace", "moma-3c", "--grid", "100"}), &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonArray modes = root.value(QStringLiteral("modes")).toArray();
    QCOMPARE(modes.size(), 8); // branch1 × branch2 × assembly
    int current = 0;
    QSet<QString> combinations;
    for (const QJsonValue &value : modes) {
        const QJsonObject mode = value.toObject();
        QString key;
        for (const char *name : {"branch1", "branch2", "assembly"}) {
            const double sign = mode.value(QLatin1String(name)).toDouble();
            QVERIFY(sign == 1.0 || sign == -1.0);
            key += QString::number(sign);
        }
        combinations.insert(key);
        QVERIFY(mode.value(QStringLiteral("area")).toDouble() >= 0);
        if (mode.value(QStringLiteral("area")).toDouble() == 0)
            QVERIFY(!mode.value(QStringLiteral("note")).toString().isEmpty());
        if (mode.value(QStringLiteral("current")).toBool()) {
            ++current;
            // the preset's modes: β₁ = β₂ = −1, σ = +1
            QCOMPARE(key, QStringLiteral("-1-11"));
            QCOMPARE(mode.value(QStringLiteral("area")).toDouble(), root.value(QStringLiteral("area")).toDouble());
        }
    }
    QCOMPARE(current, 1);
    QCOMPARE(combinations.size(), 8);

    // --set assembly=-1 makes another combination the current one, with its own area.
    const QJsonObject other = runJson(args({"workspace", "moma-3c", "--grid", "100", "--set", "assembly=-1"}), &exitCode);
    QCOMPARE(exitCode, 0);
    for (const QJsonValue &value : other.value(QStringLiteral("modes")).toArray()) {
        const QJsonObject mode = value.toObject();
        if (mode.value(QStringLiteral("current")).toBool()) {
            QCOMPARE(mode.value(QStringLiteral("assembly")).toDouble(), -1.0);
            QCOMPARE(mode.value(QStringLiteral("area")).toDouble(), other.value(QStringLiteral("area")).toDouble());
        }
    }
    QVERIFY(other.value(QStringLiteral("area")).toDouble() < root.value(QStringLiteral("area")).toDouble());
}

void TestCli::workspaceText()
{
    const Run run = runPkm(args({"workspace", "moma-3a", "--grid", "100"}));
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.err.isEmpty());
    const QString out = QString::fromUtf8(run.out);
    QVERIFY(out.contains(QStringLiteral("Design     moma-3a")));
    QVERIFY(out.contains(QStringLiteral("area")));
    QVERIFY(out.contains(QStringLiteral("mm²")));
    QVERIFY(out.contains(QStringLiteral("current")));
    QVERIFY(out.contains(QStringLiteral("branch1")));
    const QJsonObject json = runJson(args({"workspace", "moma-3a", "--grid", "100"}));
    const QString area = QString::number(json.value(QStringLiteral("area")).toDouble(), 'f', 1);
    QVERIFY2(out.contains(area), qPrintable(area));
}

void TestCli::workspaceSet()
{
    int exitCode = -1;
    const QJsonObject plain = runJson(args({"workspace", "moma-3a", "--grid", "100"}), &exitCode);
    const QJsonObject changed = runJson(
        args({"workspace", "moma-3a", "--grid", "100", "--set", "gamma1=-3", "--set", "l1=200"}), &exitCode);
    QCOMPARE(exitCode, 0);
    const QJsonObject parameters = changed.value(QStringLiteral("parameters")).toObject();
    QVERIFY(std::abs(parameters.value(QStringLiteral("gamma1")).toDouble() + 3.0) < 1e-9);
    QCOMPARE(parameters.value(QStringLiteral("l1")).toDouble(), 200.0);
    QVERIFY(changed.value(QStringLiteral("area")).toDouble() > 0);
    QVERIFY(changed.value(QStringLiteral("area")).toDouble() != plain.value(QStringLiteral("area")).toDouble());
    // the map takes the same --set
    const QJsonObject map = runJson(
        args({"map", "moma-3a", "--grid", "100", "--set", "gamma1=-3", "--set", "l1=200"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(map.value(QStringLiteral("reachable_cells")), changed.value(QStringLiteral("reachable_cells")));
}

void TestCli::workspacePng()
{
    QTemporaryDir directory;
    const QString path = directory.filePath(QStringLiteral("workspace.png"));
    int exitCode = -1;
    const QJsonObject root = runJson({QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                      QStringLiteral("100"), QStringLiteral("-o"), path},
                                     &exitCode);
    QCOMPARE(exitCode, 0);
    QVERIFY(root.contains(QStringLiteral("area"))); // the JSON still goes to stdout
    QImage image(path);
    QVERIFY(!image.isNull());
    const QJsonObject grid = root.value(QStringLiteral("grid")).toObject();
    const int columns = grid.value(QStringLiteral("columns")).toInt();
    const int rows = grid.value(QStringLiteral("rows")).toInt();
    // a whole number of pixels per cell, at least 400 along the longer side
    QVERIFY(std::max(image.width(), image.height()) >= 400);
    QCOMPARE(image.width() % columns, 0);
    QCOMPARE(image.width() / columns, image.height() / rows);
    QCOMPARE(image.height() % rows, 0);
    // white outside, light blue inside: 3a's workspace is a shield, wide at the top (y up)
    QCOMPARE(image.pixel(0, image.height() - 1), qRgb(255, 255, 255));
    QVERIFY(image.pixel(image.width() / 2, image.height() / 2) != qRgb(255, 255, 255));
    int topRow = 0, bottomRow = 0;
    for (int x = 0; x < image.width(); ++x) {
        topRow += image.pixel(x, image.height() / 8) != qRgb(255, 255, 255);
        bottomRow += image.pixel(x, image.height() * 7 / 8) != qRgb(255, 255, 255);
    }
    QVERIFY2(topRow > bottomRow, qPrintable(QString::number(topRow) + QLatin1Char(' ') + QString::number(bottomRow)));
}

void TestCli::workspaceSvg()
{
    QTemporaryDir directory;
    // 3c on this grid has reachable cells that touch at a corner only
    for (const char *design : {"moma-3a", "moma-3c"}) {
        const QString path = directory.filePath(QStringLiteral("%1.SVG").arg(QLatin1String(design)));
        const QStringList arguments{QStringLiteral("workspace"), QLatin1String(design), QStringLiteral("--grid"),
                                    QStringLiteral("200"), QStringLiteral("-o"), path};
        const Run run = runPkm(arguments);
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains(path.toUtf8()));
        const QJsonObject root = runJson(arguments);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray svg = file.readAll();
        QVERIFY(svg.contains("<svg"));
        QVERIFY(svg.contains("<path"));
        QXmlStreamReader xml(svg);
        QString d;
        QStringList viewBox;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement)
                continue;
            if (xml.name() == QLatin1String("svg"))
                viewBox = xml.attributes().value(QStringLiteral("viewBox")).toString().split(QLatin1Char(' '));
            if (xml.name() == QLatin1String("path"))
                d = xml.attributes().value(QStringLiteral("d")).toString();
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(d.startsWith(QLatin1Char('M')));
        QVERIFY(d.endsWith(QLatin1Char('Z')));
        QCOMPARE(viewBox.size(), 4);
        // In mm with y flipped: the viewBox holds the reachable cells.
        const QJsonObject bounds = root.value(QStringLiteral("bounds")).toObject();
        const double left = viewBox[0].toDouble(), top = viewBox[1].toDouble();
        QVERIFY(left < bounds.value(QStringLiteral("x_min")).toDouble());
        QVERIFY(left + viewBox[2].toDouble() > bounds.value(QStringLiteral("x_max")).toDouble());
        QVERIFY(top < -bounds.value(QStringLiteral("y_max")).toDouble());
        QVERIFY(top + viewBox[3].toDouble() > -bounds.value(QStringLiteral("y_min")).toDouble());
        // The loops enclose exactly the reachable cells: their areas add up to the workspace's
        // (all loops turn the same way, holes the other way), so none crosses itself.
        double area = 0;
        for (const QString &loop : d.split(QLatin1Char('Z'), Qt::SkipEmptyParts)) {
            QList<QPointF> points;
            for (const QString &vertex : loop.split(QRegularExpression(QStringLiteral("[ML]")), Qt::SkipEmptyParts)) {
                const QStringList xy = vertex.split(QLatin1Char(','));
                QCOMPARE(xy.size(), 2);
                points.append(QPointF(xy[0].toDouble(), -xy[1].toDouble()));
            }
            for (qsizetype i = 0; i < points.size(); ++i) {
                const QPointF &a = points[i], &b = points[(i + 1) % points.size()];
                area += 0.5 * (a.x() * b.y() - b.x() * a.y());
            }
        }
        const double expected = root.value(QStringLiteral("area")).toDouble();
        QVERIFY2(std::abs(std::abs(area) - expected) < 1e-6 * expected, qPrintable(number(area) + QLatin1Char(' ') + number(expected)));
    }
}

void TestCli::mapJson_data()
{
    QTest::addColumn<QString>("design");
    QTest::addColumn<QString>("quantity");
    QTest::newRow("3a det") << QStringLiteral("moma-3a") << QStringLiteral("det");
    QTest::newRow("3a cond") << QStringLiteral("moma-3a") << QStringLiteral("cond");
    QTest::newRow("3c det") << QStringLiteral("moma-3c") << QStringLiteral("det");
    QTest::newRow("3d cond") << QStringLiteral("moma-3d") << QStringLiteral("cond");
}

void TestCli::mapJson()
{
    QFETCH(QString, design);
    QFETCH(QString, quantity);
    int exitCode = -1;
    const QJsonObject root = runJson(
        {QStringLiteral("map"), design, QStringLiteral("--grid"), QStringLiteral("100"), QStringLiteral("--quantity"),
         quantity},
        &exitCode);
    QCOMPARE(exitCode, 0);
    for (const char *key : {"grid", "bounds", "reachable_cells", "min", "max", "near_singular_cells", "seconds",
                            "quantity", "cell_size"})
        QVERIFY2(root.contains(QLatin1String(key)), key);
    QCOMPARE(root.value(QStringLiteral("quantity")).toString(), quantity);
    const QJsonObject grid = root.value(QStringLiteral("grid")).toObject();
    QCOMPARE(std::max(grid.value(QStringLiteral("columns")).toInt(), grid.value(QStringLiteral("rows")).toInt()), 100);
    const double min = root.value(QStringLiteral("min")).toDouble();
    const double max = root.value(QStringLiteral("max")).toDouble();
    QVERIFY(min <= max);
    if (quantity == QLatin1String("cond"))
        QVERIFY2(min >= 1.0 - 1e-6, qPrintable(number(min)));
    if (design == QLatin1String("moma-3a") && quantity == QLatin1String("det"))
        QVERIFY2(max < 0, qPrintable(number(max))); // det J < 0 all over 3a's workspace
    QVERIFY(root.value(QStringLiteral("near_singular_cells")).toInt()
            <= root.value(QStringLiteral("reachable_cells")).toInt());

    // the same cells as the workspace on the same grid
    const QJsonObject workspace = runJson({QStringLiteral("workspace"), design, QStringLiteral("--grid"),
                                           QStringLiteral("100")});
    QCOMPARE(root.value(QStringLiteral("reachable_cells")), workspace.value(QStringLiteral("reachable_cells")));
    QCOMPARE(root.value(QStringLiteral("bounds")), workspace.value(QStringLiteral("bounds")));
}

void TestCli::mapText()
{
    const Run run = runPkm(args({"map", "moma-3a", "--grid", "50"}));
    QCOMPARE(run.exitCode, 0);
    const QString out = QString::fromUtf8(run.out);
    for (const char *text : {"Map of det J", "reachable cells", "near-singular cells", "min", "max"})
        QVERIFY2(out.contains(QLatin1String(text)), text);
    const Run cond = runPkm(args({"map", "moma-3a", "--grid", "50", "--quantity", "cond"}));
    QCOMPARE(cond.exitCode, 0);
    QVERIFY(cond.out.contains("condition number"));
}

void TestCli::mapPng()
{
    QTemporaryDir directory;
    for (const char *quantity : {"det", "cond"}) {
        const QString path = directory.filePath(QStringLiteral("map-%1.png").arg(QLatin1String(quantity)));
        int exitCode = -1;
        const QJsonObject root = runJson({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                          QStringLiteral("100"), QStringLiteral("--quantity"),
                                          QLatin1String(quantity), QStringLiteral("-o"), path},
                                         &exitCode);
        QCOMPARE(exitCode, 0);
        const QImage image(path);
        QVERIFY(!image.isNull());
        const QJsonObject grid = root.value(QStringLiteral("grid")).toObject();
        QCOMPARE(image.width(), grid.value(QStringLiteral("columns")).toInt());
        QCOMPARE(image.height(), grid.value(QStringLiteral("rows")).toInt());
        QVERIFY(image.hasAlphaChannel());
        int opaque = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x)
                opaque += qAlpha(image.pixel(x, y)) == 255;
        }
        QCOMPARE(opaque, root.value(QStringLiteral("reachable_cells")).toInt()); // the rest is transparent
        // y up: 3a's workspace is wide at the top, pointed at the bottom
        QVERIFY(qAlpha(image.pixel(image.width() / 2, image.height() / 4)) == 255);
        QVERIFY(qAlpha(image.pixel(1, image.height() - 2)) == 0);
        if (QLatin1String(quantity) == QLatin1String("det")) {
            // det J < 0 everywhere: blue, not red
            const QRgb centre = image.pixel(image.width() / 2, image.height() / 2);
            QVERIFY(qBlue(centre) > qRed(centre));
            QVERIFY(root.value(QStringLiteral("colour_scale")).toObject().value(QStringLiteral("max")).toDouble() > 0);
        }
    }
}

void TestCli::detMapColoursShowTheBulk()
{
    // The O-X glide's O form: half its cells have det J between −2 and −5, 2 % near −136 at the
    // singular edge. The colours must not be stretched over the edge's spikes, or the map shows
    // white: the bulk gets a fair share of the scale, and the clipped tail stays small.
    QTemporaryDir directory;
    const QString png = directory.filePath(QStringLiteral("o.png")), csv = directory.filePath(QStringLiteral("o.csv"));
    int exitCode = -1;
    const QJsonObject root = runJson(args({"map", "oxglide-prototype", "-o"}) << png, &exitCode);
    QCOMPARE(exitCode, 0);
    const double limit = root.value(QStringLiteral("colour_scale")).toObject().value(QStringLiteral("max")).toDouble();
    QVERIFY(limit > 0.0);
    QCOMPARE(runPkm(args({"map", "oxglide-prototype", "-o"}) << csv).exitCode, 0);
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    std::vector<double> magnitudes;
    file.readLine(); // x,y,value,margin
    while (!file.atEnd()) {
        const QList<QByteArray> fields = file.readLine().trimmed().split(',');
        bool ok = false;
        const double value = fields.size() >= 3 ? fields[2].toDouble(&ok) : 0.0;
        if (ok && std::isfinite(value))
            magnitudes.push_back(std::abs(value));
    }
    QVERIFY(magnitudes.size() > 1000);
    std::sort(magnitudes.begin(), magnitudes.end());
    const double median = magnitudes[magnitudes.size() / 2];
    const auto clipped = std::size_t(magnitudes.end() - std::upper_bound(magnitudes.begin(), magnitudes.end(), limit));
    QVERIFY2(median >= 0.1 * limit, qPrintable(QStringLiteral("median |det J| %1, colours end at %2").arg(median).arg(limit)));
    QVERIFY2(clipped <= magnitudes.size() / 10, qPrintable(QStringLiteral("%1 of %2 cells clipped").arg(clipped).arg(magnitudes.size())));
}

void TestCli::mapCsv()
{
    QTemporaryDir directory;
    const QString path = directory.filePath(QStringLiteral("map.csv"));
    int exitCode = -1;
    const QJsonObject root = runJson({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                                      QStringLiteral("100"), QStringLiteral("-o"), path},
                                     &exitCode);
    QCOMPARE(exitCode, 0);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray csv = file.readAll();
    QVERIFY(csv.endsWith('\n'));
    const QList<QByteArray> lines = csv.chopped(1).split('\n');
    QCOMPARE(lines.front(), QByteArray("x,y,value,margin"));
    QCOMPARE(lines.size() - 1, root.value(QStringLiteral("reachable_cells")).toInt());
    const QJsonObject bounds = root.value(QStringLiteral("bounds")).toObject();
    double min = std::numeric_limits<double>::infinity(), max = -min;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        QCOMPARE(fields.size(), 4);
        bool ok[4] = {};
        const double x = fields[0].toDouble(&ok[0]);
        const double y = fields[1].toDouble(&ok[1]);
        const double value = fields[2].toDouble(&ok[2]);
        const double margin = fields[3].toDouble(&ok[3]);
        QVERIFY2(ok[0] && ok[1] && ok[2] && ok[3], lines[i].constData());
        QVERIFY(x > bounds.value(QStringLiteral("x_min")).toDouble() && x < bounds.value(QStringLiteral("x_max")).toDouble());
        QVERIFY(y > bounds.value(QStringLiteral("y_min")).toDouble() && y < bounds.value(QStringLiteral("y_max")).toDouble());
        QVERIFY(margin >= 0 && margin <= 1);
        min = std::min(min, value);
        max = std::max(max, value);
    }
    // the summary's min and max are the map's, up to float precision
    QVERIFY(std::abs(min - root.value(QStringLiteral("min")).toDouble()) < 1e-6 * std::abs(min));
    QVERIFY(std::abs(max - root.value(QStringLiteral("max")).toDouble()) < 1e-6 * std::abs(max));
    QVERIFY(max < 0);
}

void TestCli::outputFileErrors()
{
    QTemporaryDir directory;
    // A directory where the file should go: exit 1, the culprit named, nothing on stdout, no
    // temporary file left behind.
    QVERIFY(QDir(directory.path()).mkdir(QStringLiteral("taken.png")));
    const QString taken = directory.filePath(QStringLiteral("taken.png"));
    for (const QStringList &arguments :
         {QStringList{QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"), QStringLiteral("20"),
                      QStringLiteral("-o"), taken},
          QStringList{QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                      QStringLiteral("20"), QStringLiteral("--json"), QStringLiteral("-o"), taken}}) {
        const Run run = runPkm(arguments);
        QCOMPARE(run.exitCode, 1);
        QVERIFY(run.out.isEmpty());
        QVERIFY2(run.err.contains(taken.toUtf8()), run.err.constData());
        QCOMPARE(run.err.count('\n'), 1);
    }
    QCOMPARE(QDir(directory.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             QStringList{QStringLiteral("taken.png")});

    const QString missing = directory.filePath(QStringLiteral("no/such/dir/map.csv"));
    const Run run = runPkm({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                            QStringLiteral("20"), QStringLiteral("-o"), missing});
    QCOMPARE(run.exitCode, 1);
    QVERIFY(run.out.isEmpty());
    QVERIFY(run.err.contains(missing.toUtf8()));
    QVERIFY(!QFile::exists(missing));

    // A failing command leaves an existing file as it was.
    const QString existing = directory.filePath(QStringLiteral("existing.csv"));
    {
        QFile file(existing);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("keep me\n");
    }
    for (const QStringList &arguments :
         {QStringList{QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--set"),
                      QStringLiteral("l1=-4"), QStringLiteral("-o"), existing},
          QStringList{QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--set"),
                      QStringLiteral("p_min=100"), QStringLiteral("--set"), QStringLiteral("p_max=100.001"),
                      QStringLiteral("--grid"), QStringLiteral("10"), QStringLiteral("-o"), existing}}) {
        const Run failed = runPkm(arguments);
        QVERIFY(failed.exitCode == 2 || failed.exitCode == 3);
        QFile file(existing);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("keep me\n"));
    }
    // and a successful one replaces it
    QCOMPARE(runPkm({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"), QStringLiteral("10"),
                     QStringLiteral("-o"), existing})
                 .exitCode,
             0);
    QFile file(existing);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().startsWith("x,y,value,margin\n"));
}

void TestCli::picturesShowSingularCurves()
{
    // The map and workspace pictures carry the singular curves, as the map view does: inverse
    // ones dark red, direct ones dashed black, on the workspace only (outside stays transparent).
    MapGrid grid;
    grid.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(100, 100));
    grid.columns = grid.rows = 100;
    std::vector<float> cells(grid.cells(), -1.0f);
    for (int r = 0; r < 100; ++r) {
        for (int c = 80; c < 100; ++c)
            cells[std::size_t(r) * 100 + std::size_t(c)] = std::numeric_limits<float>::quiet_NaN(); // x > 80 unreachable
    }
    const std::vector<SingularCurve> curves = {
        {SingularCurve::Type::Inverse, "inverse", {Eigen::Vector2d(0, 25.5), Eigen::Vector2d(100, 25.5)}},
        {SingularCurve::Type::Direct, "direct", {Eigen::Vector2d(40.5, 0), Eigen::Vector2d(40.5, 100)}}};
    const QImage plain = pictures::mapImage(grid, cells, MapQuantity::Determinant, 1.0);
    const QImage image = pictures::mapImage(grid, cells, MapQuantity::Determinant, 1.0, curves);
    QCOMPARE(image.size(), plain.size());
    const QRgb red = image.pixel(20, 100 - 26); // y up: y = 25.5 mm is row 74 from the top
    QVERIFY2(qRed(red) > 120 && qGreen(red) < 60 && qBlue(red) < 60, qPrintable(QString::number(red, 16)));
    int dark = 0;
    for (int y = 0; y < 100; ++y) {
        const QRgb p = image.pixel(40, y);
        dark += qRed(p) < 70 && qGreen(p) < 70 && qBlue(p) < 70;
    }
    QVERIFY2(dark > 30 && dark < 90, qPrintable(QString::number(dark))); // dashed
    for (int y = 0; y < 100; ++y) {
        for (int x = 80; x < 100; ++x)
            QCOMPARE(qAlpha(image.pixel(x, y)), 0);
    }
    QCOMPARE(plain.pixel(20, 100 - 26), plain.pixel(20, 10));

    // the five-bar's map from pkm, all blue (det J < 0): its inverse curves (a leg stretched)
    // run red along the outer edge
    QTemporaryDir directory;
    for (const char *design : {"fivebar-example", "pp-5r"}) {
        const QString path = directory.filePath(QStringLiteral("%1.png").arg(QLatin1String(design)));
        const Run run = runPkm(args({"map", design, "--grid", "300", "-o"}) << path);
        QCOMPARE(run.exitCode, 0);
        const QImage map(path);
        QVERIFY(!map.isNull());
        qsizetype red = 0;
        for (int y = 0; y < map.height(); ++y) {
            for (int x = 0; x < map.width(); ++x) {
                const QRgb p = map.pixel(x, y);
                red += qAlpha(p) == 255 && qRed(p) > qGreen(p) + 60 && qRed(p) > qBlue(p) + 60;
            }
        }
        QVERIFY2(red > 100, qPrintable(QStringLiteral("%1: %2 red pixels").arg(QLatin1String(design)).arg(red)));
    }
}

void TestCli::mapColourLimitIgnoresSpikes()
{
    // det J near an inverse singularity grows without bound: a few spikes must not set the
    // colour scale, or everything else would be white.
    std::vector<float> values;
    for (int i = 0; i < 1000; ++i)
        values.push_back(-1.0f - static_cast<float>(i) / 1000.0f);
    for (int i = 0; i < 10; ++i)
        values.push_back(-1e9f);
    values.push_back(-std::numeric_limits<float>::infinity());
    values.push_back(std::numeric_limits<float>::quiet_NaN());
    const double limit = report::mapColourLimit(values, MapQuantity::Determinant);
    QVERIFY2(limit > 1.9 && limit <= 2.0, qPrintable(number(limit)));
    QCOMPARE(report::mapColourLimit(values, MapQuantity::Condition), 100.0);

    MapGrid grid;
    grid.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 1));
    grid.columns = 2;
    grid.rows = 1;
    const std::vector<float> cells = {-1.0f, std::numeric_limits<float>::quiet_NaN()};
    const QImage image = pictures::mapImage(grid, cells, MapQuantity::Determinant, 1.0);
    QCOMPARE(image.size(), QSize(2, 1));
    QCOMPARE(qAlpha(image.pixel(1, 0)), 0);
    QVERIFY(qBlue(image.pixel(0, 0)) > qRed(image.pixel(0, 0)));
}

// -- render --------------------------------------------------------------------------------

void TestCli::render2dPng_data()
{
    addPresetPerKindRows("design");
}

void TestCli::render2dPng()
{
    PKM_FETCH_PRESET(design);
    const auto symbol = firstCaptionSymbol().find(kindOfPreset(design));
    QVERIFY2(symbol != firstCaptionSymbol().end(),
        qPrintable(QStringLiteral("no caption symbol of %1's kind: add it to firstCaptionSymbol()").arg(design)));
    const QString captionStart = design + QStringLiteral(" — ") + symbol->second + QStringLiteral(" = ");
    QTemporaryDir directory;
    const QString path = directory.filePath(design + QStringLiteral(".png"));
    {
        QFile old(path); // an older file is replaced, atomically
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("not a picture");
    }
    const Run run = runPkm({QStringLiteral("render"), design, QStringLiteral("-o"), path});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QCOMPARE(QString::fromUtf8(run.out), QStringLiteral("Wrote %1 (1600 × 1200 pixels, 2D view)\n").arg(path));
    QCOMPARE(directoryEntries(directory), QStringList{design + QStringLiteral(".png")}); // no temporary left

    QVERIFY(fileBytes(path).startsWith("\x89PNG\r\n\x1a\n"));
    const QImage image(path, "PNG");
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(1600, 1200));
    // the light background of the 2D view, its grid at the corners, the mechanism drawn on it
    const SceneStyle style;
    const QList<QRgb> backgrounds{style.background.rgb(), style.gridMinor.rgb(), style.gridMajor.rgb()};
    QCOMPARE(dominantColour(image), style.background.rgb());
    for (const QPoint corner : {QPoint(0, 0), QPoint(1599, 0), QPoint(0, 1199), QPoint(1599, 1199)})
        QVERIFY2(backgrounds.contains(image.pixel(corner) | 0xff000000u), qPrintable(QString::number(image.pixel(corner), 16)));
    QVERIFY(colourCounts(image).size() > 50); // not uniform: links, joints, text, antialiasing
    const qsizetype drawn = pixelsUnlike(image, style.background.rgb());
    QVERIFY2(drawn > 20000 && drawn < 1600 * 1200 / 2, qPrintable(QString::number(drawn)));
    // the caption names the design and the pose; the PNG's title is the caption
    QVERIFY2(image.text(QStringLiteral("Title")).startsWith(captionStart), qPrintable(image.text(QStringLiteral("Title"))));
}

void TestCli::render2dCaptionAndPose()
{
    QTemporaryDir directory;
    const auto render = [&](const QString &name, QStringList extra) {
        const QString path = directory.filePath(name);
        QStringList arguments{QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--size"),
                              QStringLiteral("800x600"), QStringLiteral("-o"), path};
        arguments += extra;
        const Run run = runPkm(arguments);
        if (run.exitCode != 0)
            qWarning("%s", run.err.constData());
        return run.exitCode == 0 ? QImage(path) : QImage();
    };
    const QImage plus = render(QStringLiteral("plus.png"), args({"--set", "theta=30"}));
    const QImage minus = render(QStringLiteral("minus.png"), args({"--set", "theta=-30"}));
    const QImage bare = render(QStringLiteral("bare.png"), args({"--set", "theta=30", "--no-caption"}));
    for (const QImage *image : {&plus, &minus, &bare})
        QCOMPARE(image->size(), QSize(800, 600));
    QVERIFY(plus != minus);
    QCOMPARE(plus.text(QStringLiteral("Title")), QStringLiteral("pjoint-prototype — d = 212.33 mm, θ = 30.00°"));
    QVERIFY(minus.text(QStringLiteral("Title")).endsWith(QStringLiteral("θ = −30.00°"))); // the drawings' minus
    // The caption sits in the bottom-left corner and moves nothing else.
    QVERIFY(plus.copy(0, 0, 800, 520) == bare.copy(0, 0, 800, 520));
    QVERIFY(plus.copy(0, 540, 400, 60) != bare.copy(0, 540, 400, 60));
    QVERIFY(plus.copy(600, 0, 200, 600) == bare.copy(600, 0, 200, 600)); // the scale bar's side
}

void TestCli::render2dSvgAndPdf()
{
    QTemporaryDir directory;
    const QString svgPath = directory.filePath(QStringLiteral("moma.svg"));
    const Run svg = runPkm(args({"render", "moma-3a", "--set", "x=20", "--set", "y=-250"}) << QStringLiteral("-o") << svgPath);
    QCOMPARE(svg.exitCode, 0);
    QVERIFY(svg.err.isEmpty());
    QCOMPARE(QString::fromUtf8(svg.out), QStringLiteral("Wrote %1 (1600 × 1200, vector, 2D view)\n").arg(svgPath));
    const QByteArray xml = fileBytes(svgPath);
    QVERIFY(xml.startsWith("<?xml"));
    QVERIFY(xml.contains("<svg"));
    QXmlStreamReader reader(xml);
    int paths = 0, texts = 0;
    QString viewBox;
    while (!reader.atEnd()) {
        if (reader.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (reader.name() == QLatin1String("svg"))
            viewBox = reader.attributes().value(QLatin1String("viewBox")).toString();
        paths += reader.name() == QLatin1String("path") || reader.name() == QLatin1String("polyline");
        texts += reader.name() == QLatin1String("text");
    }
    QVERIFY2(!reader.hasError(), qPrintable(reader.errorString()));
    QCOMPARE(viewBox.simplified(), QStringLiteral("0 0 1600 1200"));
    QVERIFY2(paths > 10, qPrintable(QString::number(paths))); // vectors, not an embedded picture
    QVERIFY(!xml.contains("<image"));
    QVERIFY(texts > 5); // labels, scale bar, caption
    QVERIFY(xml.contains("moma-3a — p₁ = "));

    const QString pdfPath = directory.filePath(QStringLiteral("pjoint.pdf"));
    const Run pdf = runPkm(args({"render", "pjoint-prototype", "--set", "theta=45", "--output"}) << pdfPath);
    QCOMPARE(pdf.exitCode, 0);
    QVERIFY(pdf.err.isEmpty());
    QCOMPARE(QString::fromUtf8(pdf.out),
             QStringLiteral("Wrote %1 (297.0 × 222.8 mm page, vector, 2D view)\n").arg(pdfPath));
    const QByteArray document = fileBytes(pdfPath);
    QVERIFY(document.startsWith("%PDF"));
    QVERIFY(document.trimmed().endsWith("%%EOF"));
    // one landscape page with the picture's proportions, 297 mm (842 pt) wide, no embedded picture
    QCOMPARE(document.count("/Type /Page\n") + document.count("/Type /Page\r") + document.count("/Type /Page "), 1);
    QVERIFY2(document.contains("/MediaBox [0 0 842"), document.mid(document.indexOf("MediaBox"), 40).constData());
    QVERIFY(!document.contains("/Subtype /Image"));
    QVERIFY(document.size() > 5000);
    QCOMPARE(directoryEntries(directory), (QStringList{QStringLiteral("moma.svg"), QStringLiteral("pjoint.pdf")}));
}

void TestCli::render3dWithoutDisplay()
{
    // The issue's "done when": on a machine without a display, `pkm render PRESET --view 3d -o
    // x.png` writes a clean picture (pkm runs itself under xvfb-run).
    QTemporaryDir directory;
    const QProcessEnvironment environment = withoutDisplay();
    const QString xvfbRun = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
    if (xvfbRun.isEmpty()) {
        const Run run = runPkm(args({"render", "pjoint-prototype", "--view", "3d", "-o"})
                                   << directory.filePath(QStringLiteral("x.png")),
                               environment);
        QCOMPARE(run.exitCode, 3);
        QVERIFY(run.err.contains("xvfb-run is missing"));
        QVERIFY(directoryEntries(directory).isEmpty());
        QSKIP("xvfb-run is not installed (Debian package xvfb): only its error was checked");
    }
    const auto render = [&](const QString &name, const QStringList &extra, QByteArray *out = nullptr) {
        const QString path = directory.filePath(name);
        QStringList arguments{QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--view"),
                              QStringLiteral("3d"), QStringLiteral("--size"), QStringLiteral("800x600"),
                              QStringLiteral("-o"), path};
        arguments += extra;
        const Run run = runPkm(arguments, environment);
        if (run.exitCode != 0 || !run.err.isEmpty())
            qWarning("exit %d: %s", run.exitCode, run.err.constData());
        if (out)
            *out = run.out;
        return run.exitCode == 0 && run.err.isEmpty() ? QImage(path, "PNG") : QImage();
    };
    QByteArray out;
    const QImage iso = render(QStringLiteral("iso.png"), args({"--set", "theta=30"}), &out);
    QCOMPARE(QString::fromUtf8(out),
             QStringLiteral("Wrote %1 (800 × 600 pixels, 3D isometric view, perspective)\n")
                 .arg(directory.filePath(QStringLiteral("iso.png"))));
    const QImage other = render(QStringLiteral("other.png"), args({"--set", "theta=-30"}));
    const QImage front = render(QStringLiteral("front.png"), args({"--set", "theta=30", "--camera", "front"}));
    const QImage flat = render(QStringLiteral("flat.png"),
                               args({"--set", "theta=30", "--camera", "front", "--orthographic", "--no-caption"}));
    const QRgb background = SceneStyle().background.rgb();
    for (const QImage *image : {&iso, &other, &front, &flat}) {
        QVERIFY(!image->isNull());
        QCOMPARE(image->size(), QSize(800, 600));
        QCOMPARE(image->pixel(0, 0) | 0xff000000u, background); // the 3D view's light background
        QCOMPARE(dominantColour(*image), background);
        QVERIFY(colourCounts(*image).size() > 100); // shaded solids, not a blank frame
        const qsizetype drawn = pixelsUnlike(*image, background);
        QVERIFY2(drawn > 800 * 600 / 50, qPrintable(QString::number(drawn))); // the model is in the picture
    }
    QVERIFY(iso.text(QStringLiteral("Title")).endsWith(QStringLiteral("θ = 30.00°")));
    // another pose, another camera, another projection: other pictures
    // (above the caption, which names the pose too)
    QVERIFY(iso.copy(0, 0, 800, 500) != other.copy(0, 0, 800, 500));
    QVERIFY(iso.copy(0, 0, 800, 500) != front.copy(0, 0, 800, 500));
    QVERIFY(front.copy(0, 0, 800, 500) != flat.copy(0, 0, 800, 500));
    // the 3D model is green (links) and grey (base): the picture is in colour
    bool green = false;
    for (int y = 0; y < iso.height() && !green; ++y) {
        for (int x = 0; x < iso.width() && !green; ++x) {
            const QRgb p = iso.pixel(x, y);
            green = qGreen(p) > qRed(p) + 40 && qGreen(p) > qBlue(p) + 20;
        }
    }
    QVERIFY(green);
    // Xvfb is gone and nothing but the pictures is left
    QCOMPARE(directoryEntries(directory).size(), 4);
}

void TestCli::render3dVectorFiles()
{
    // SVG and PDF of the 3D view hold the rendered picture.
    QTemporaryDir directory;
    if (QStandardPaths::findExecutable(QStringLiteral("xvfb-run")).isEmpty())
        QSKIP("xvfb-run is not installed (Debian package xvfb)");
    const QString svgPath = directory.filePath(QStringLiteral("o.svg"));
    const Run svg = runPkm(args({"render", "oxglide-prototype", "--view", "3d", "--camera", "top", "--size", "400x300",
                                 "-o"})
                               << svgPath,
                           withoutDisplay());
    QCOMPARE(svg.exitCode, 0);
    QVERIFY(svg.out.contains("400 × 300-pixel picture embedded, 3D top view, perspective"));
    const QByteArray xml = fileBytes(svgPath);
    QVERIFY(xml.startsWith("<?xml"));
    QVERIFY(xml.contains("<image"));
    QVERIFY(xml.contains("data:image/png;base64,"));

    const QString pdfPath = directory.filePath(QStringLiteral("o.pdf"));
    const Run pdf = runPkm(args({"render", "oxglide-prototype", "--view", "3d", "--size", "300x400", "-o"}) << pdfPath,
                           withoutDisplay());
    QCOMPARE(pdf.exitCode, 0);
    QVERIFY(pdf.out.contains("(222.8 × 297.0 mm page, a 300 × 400-pixel picture"));
    const QByteArray document = fileBytes(pdfPath);
    QVERIFY(document.startsWith("%PDF"));
    QVERIFY(document.contains("/Subtype /Image"));
    QVERIFY2(document.contains("/MediaBox [0 0 631"), document.mid(document.indexOf("MediaBox"), 40).constData());

    // A note about the pose is printed once, not again by the run under Xvfb.
    const Run note = runPkm(args({"render", "pjoint-prototype", "--view", "3d", "--set", "theta_min=10", "--size",
                                  "200x200", "-o"})
                                << directory.filePath(QStringLiteral("note.png")),
                            withoutDisplay());
    QCOMPARE(note.exitCode, 0);
    QCOMPARE(note.err.count('\n'), 1);
    QVERIFY2(note.err.startsWith("pkm: note: ") && note.err.contains("home pose"), note.err.constData());
    QVERIFY(QImage(directory.filePath(QStringLiteral("note.png"))).size() == QSize(200, 200));
}

void TestCli::render3dWithoutXvfb()
{
    // No display and no xvfb-run on the PATH: one sentence that says what to install, exit 3,
    // no file.
    QTemporaryDir directory;
    QProcessEnvironment environment = withoutDisplay();
    environment.insert(QStringLiteral("PATH"), directory.filePath(QStringLiteral("empty")));
    const QString path = directory.filePath(QStringLiteral("x.png"));
    const Run run = runPkm(args({"render", "moma-3a", "--view", "3d", "-o"}) << path, environment);
    QCOMPARE(run.exitCode, 3);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(QString::fromUtf8(run.err),
             QStringLiteral("pkm: 3D pictures need OpenGL: there is no display and xvfb-run is missing (install the "
                            "Debian package xvfb).\n"));
    QVERIFY(directoryEntries(directory).isEmpty());

    // Told to stay on a platform without OpenGL (as under Xvfb, which pkm never leaves): the
    // reason from the OpenGL probe.
    environment = withoutDisplay();
    environment.insert(QStringLiteral("PKM_RENDER_UNDER_XVFB"), QStringLiteral("1"));
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    const Run probe = runPkm(args({"render", "moma-3a", "--view", "3d", "-o"}) << path, environment);
    QCOMPARE(probe.exitCode, 3);
    QCOMPARE(probe.err.count('\n'), 1);
    QVERIFY2(probe.err.startsWith("pkm: 3D pictures need OpenGL 3.3: ") && probe.err.contains("offscreen"),
             probe.err.constData());
    QVERIFY(directoryEntries(directory).isEmpty());
}

void TestCli::renderErrors_data()
{
    QTest::addColumn<QStringList>("arguments"); // OUT: the output file
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("culprit");
    QTest::newRow("bad --view") << args({"render", "pjoint-prototype", "--view", "4d", "-o", "OUT.png"}) << 2
                                << QStringLiteral("--view 4d");
    QTest::newRow("--size too small") << args({"render", "pjoint-prototype", "--size", "10x10", "-o", "OUT.png"}) << 2
                                      << QStringLiteral("--size 10x10");
    QTest::newRow("--size too large") << args({"render", "moma-3a", "--size", "8001x600", "-o", "OUT.png"}) << 2
                                      << QStringLiteral("--size 8001x600");
    QTest::newRow("--size not WxH") << args({"render", "moma-3a", "--size", "800", "-o", "OUT.svg"}) << 2
                                    << QStringLiteral("--size 800");
    QTest::newRow("--size fractional") << args({"render", "moma-3a", "--size", "800x600.5", "-o", "OUT.png"}) << 2
                                       << QStringLiteral("--size 800x600.5");
    QTest::newRow("unknown extension") << args({"render", "moma-3a", "-o", "OUT.bmp"}) << 2 << QStringLiteral(".bmp");
    QTest::newRow("no extension") << args({"render", "moma-3a", "-o", "OUT"}) << 2 << QStringLiteral(".png, .svg, .pdf, .gif, .mp4 or .webm");
    QTest::newRow("missing -o") << args({"render", "moma-3a"}) << 2 << QStringLiteral("-o FILE");
    QTest::newRow("missing -o in 3d") << args({"render", "moma-3a", "--view", "3d"}) << 2 << QStringLiteral("-o FILE");
    QTest::newRow("bad --camera") << args({"render", "moma-3a", "--view", "3d", "--camera", "diagonal", "-o", "OUT.png"})
                                  << 2 << QStringLiteral("--camera diagonal");
    QTest::newRow("--camera in 2d") << args({"render", "moma-3a", "--camera", "top", "-o", "OUT.png"}) << 2
                                    << QStringLiteral("--view 3d");
    QTest::newRow("--orthographic in 2d") << args({"render", "moma-3a", "--orthographic", "-o", "OUT.png"}) << 2
                                          << QStringLiteral("--orthographic");
    QTest::newRow("unknown --set") << args({"render", "moma-3a", "--set", "zz=1", "-o", "OUT.png"}) << 2
                                   << QStringLiteral("zz");
    QTest::newRow("unreachable --set") << args({"render", "pjoint-prototype", "--set", "theta=75", "-o", "OUT.png"})
                                       << 3 << QStringLiteral("theta=75");
    QTest::newRow("unreachable --set, svg") << args({"render", "moma-3a", "--set", "x=0", "--set", "y=100", "-o", "OUT.svg"})
                                            << 3 << QStringLiteral("--set");
    QTest::newRow("unreachable --set, 3d") << args({"render", "pjoint-prototype", "--view", "3d", "--set", "theta=-75",
                                                    "-o", "OUT.png"})
                                           << 3 << QStringLiteral("theta=-75");
    QTest::newRow("unknown design, 3d") << args({"render", "no-such-design", "--view", "3d", "-o", "OUT.pdf"}) << 2
                                        << QStringLiteral("no-such-design");
    QTest::newRow("folder missing") << args({"render", "moma-3a", "-o", "OUT/missing/x.png"}) << 1
                                    << QStringLiteral("missing/x.png");
    // A video's sides are even and at most 4K UHD's (export/videowriter.h).
    const QStringList crank = args({"render", "fourbar-example", "--var", "alpha", "--from", "0", "--to", "90",
                                    "--steps", "3"});
    QTest::newRow("video --size odd") << crank + args({"--size", "641x480", "-o", "OUT.mp4"}) << 2
                                      << QStringLiteral("--size 641x480: A video is 32 to 3840 pixels wide");
    QTest::newRow("video --size past 4K") << crank + args({"--size", "4000x2000", "-o", "OUT.webm"}) << 2
                                          << QStringLiteral("--size 4000x2000");
    QTest::newRow("video in 3d") << crank + args({"--view", "3d", "-o", "OUT.mp4"}) << 2
                                 << QStringLiteral("A video is drawn from the 2D view");
    QTest::newRow("video folder missing") << crank + args({"-o", "OUT/missing/x.webm"}) << 1
                                          << QStringLiteral("missing/x.webm");
    QTest::newRow("video, --var unknown") << args({"render", "fourbar-example", "--var", "zz", "--from", "0", "--to",
                                                   "1", "--steps", "3", "-o", "OUT.mp4"})
                                          << 2 << QStringLiteral("--var zz");
}

void TestCli::renderErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, culprit);
    QTemporaryDir directory;
    const QString base = directory.filePath(QStringLiteral("picture"));
    QString output;
    for (QString &argument : arguments) {
        if (argument.startsWith(QLatin1String("OUT"))) {
            argument.replace(0, 3, base);
            output = argument;
        }
    }
    // An existing file at the path stays as it was.
    const QByteArray old("an older file that must survive");
    if (!output.isEmpty() && !output.contains(QLatin1String("missing"))) {
        QFile file(output);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(old);
    }
    const QStringList before = directoryEntries(directory);
    // without a display, so that a 3D command line that fails fails before Xvfb is started
    const Run run = runPkm(arguments, withoutDisplay());
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.err.endsWith(".\n"));
    QVERIFY(run.err.startsWith("pkm: "));
    QVERIFY2(QString::fromUtf8(run.err).contains(culprit), run.err.constData());
    QCOMPARE(directoryEntries(directory), before); // nothing created, no temporary left
    if (!before.isEmpty())
        QCOMPARE(fileBytes(output), old);
}

void TestCli::lightProgramLoadsNoGuiLibrary()
{
    // `pkm` links only QtCore: eval, sweep, workspace --json and map --json start without the
    // GUI libraries; the commands that draw run in pkm-draw, which has them all.
    const auto libraries = [](const QString &program) {
        QProcess ldd;
        ldd.start(QStringLiteral("ldd"), {program});
        if (!ldd.waitForFinished(30000))
            return QByteArray();
        return ldd.readAllStandardOutput();
    };
    const QByteArray light = libraries(QStringLiteral(PKM_BINARY_DIR "/pkm"));
    QVERIFY2(light.contains("libQt6Core"), light.constData());
    for (const char *heavy : {"libQt6Gui", "libQt6Widgets", "libQt6OpenGL", "libQCustomPlot", "libGL", "libEGL", "libX11"})
        QVERIFY2(!light.contains(heavy), heavy);
    const QByteArray drawing = libraries(QStringLiteral(PKM_BINARY_DIR "/pkm-draw"));
    QVERIFY2(drawing.contains("libQt6Widgets") && drawing.contains("libQCustomPlot"), drawing.constData());
    // …and the drawing commands still work through `pkm`
    QTemporaryDir directory;
    const QString picture = directory.filePath(QStringLiteral("ws.png"));
    const Run run = runPkm({QStringLiteral("workspace"), QStringLiteral("moma-3a"), QStringLiteral("--grid"),
                            QStringLiteral("100"), QStringLiteral("-o"), picture});
    QCOMPARE(run.exitCode, 0);
    const QImage image(picture);
    QVERIFY(std::max(image.width(), image.height()) >= 400);
}

void TestCli::drawingWithoutPkmDrawFailsClearly()
{
    // A `pkm` copied away from pkm-draw answers every command that does not draw, and refuses
    // the drawing ones with one sentence, writing no file.
    QTemporaryDir directory;
    const QString lone = directory.filePath(QStringLiteral("pkm"));
    QVERIFY(QFile::copy(QStringLiteral(PKM_BINARY_DIR "/pkm"), lone));
    const auto run = [&](const QStringList &arguments) {
        QProcess process;
        process.start(lone, arguments);
        Run result;
        if (!process.waitForFinished(30000))
            return result;
        result.exitCode = process.exitCode();
        result.out = process.readAllStandardOutput();
        result.err = process.readAllStandardError();
        return result;
    };
    QCOMPARE(run({QStringLiteral("eval"), QStringLiteral("pjoint-prototype"), QStringLiteral("--json")}).exitCode, 0);
    const QString picture = directory.filePath(QStringLiteral("x.png"));
    const Run render = run({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), picture});
    QCOMPARE(render.exitCode, int(CliUsageError));
    QVERIFY(render.out.isEmpty());
    QCOMPARE(render.err.count('\n'), 1);
    QVERIFY2(render.err.contains("pkm-draw"), render.err.constData());
    const Run map = run({QStringLiteral("map"), QStringLiteral("moma-3a"), QStringLiteral("--grid"), QStringLiteral("50"),
                         QStringLiteral("-o"), picture});
    QCOMPARE(map.exitCode, int(CliOutputError));
    QVERIFY(map.out.isEmpty());
    QVERIFY2(map.err.contains("pkm-draw"), map.err.constData());
    QVERIFY(!QFileInfo::exists(picture));
}

void TestCli::renderInProcessNeedsGui()
{
    // runCli() in a QCoreApplication (this test) cannot draw: a clear failure, no file.
    QTemporaryDir directory;
    const QString path = directory.filePath(QStringLiteral("x.png"));
    const Run flat = runInProcess({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("-o"), path});
    QCOMPARE(flat.exitCode, int(CliOutputError));
    QVERIFY(flat.out.isEmpty());
    QVERIFY2(flat.err.contains("QGuiApplication"), flat.err.constData());
    const Run solid = runInProcess({QStringLiteral("render"), QStringLiteral("pjoint-prototype"), QStringLiteral("--view"),
                                    QStringLiteral("3d"), QStringLiteral("-o"), path});
    QCOMPARE(solid.exitCode, int(CliNoSolution));
    QCOMPARE(solid.err.count('\n'), 1);
    QVERIFY(directoryEntries(directory).isEmpty());
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
    const QJsonObject eval = prototypeEval({QStringLiteral("theta=30")});
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

    QTest::newRow("map of a П-joint") << args({"map", "pjoint-prototype"}) << 2
                                      << QStringLiteral("The active П-joint has no planar workspace");
    QTest::newRow("workspace of a П-joint") << args({"workspace", "pjoint-prototype"}) << 2
                                            << QStringLiteral("pjoint-prototype");
    QTest::newRow("grid too small") << args({"workspace", "moma-3a", "--grid", "5"}) << 2 << QStringLiteral("--grid 5");
    QTest::newRow("grid too large") << args({"map", "moma-3a", "--grid", "4001"}) << 2 << QStringLiteral("--grid 4001");
    QTest::newRow("grid fractional") << args({"map", "moma-3a", "--grid", "20.5"}) << 2 << QStringLiteral("--grid");
    QTest::newRow("grid not a number") << args({"map", "moma-3a", "--grid", "abc"}) << 2 << QStringLiteral("abc");
    QTest::newRow("bad quantity") << args({"map", "moma-3a", "--quantity", "jacobian"}) << 2
                                  << QStringLiteral("jacobian");
    QTest::newRow("quantity of workspace") << args({"workspace", "moma-3a", "--quantity", "det"}) << 2
                                           << QStringLiteral("--quantity");
    QTest::newRow("workspace unknown extension") << args({"workspace", "moma-3a", "-o", "out.bmp"}) << 2
                                                 << QStringLiteral("out.bmp");
    QTest::newRow("map unknown extension") << args({"map", "moma-3a", "-o", "out.svg"}) << 2
                                           << QStringLiteral("out.svg");
    QTest::newRow("output without extension") << args({"map", "moma-3a", "--output", "picture"}) << 2
                                              << QStringLiteral("picture");
    QTest::newRow("-o without file") << args({"map", "moma-3a", "-o"}) << 2 << QStringLiteral("-o");
    QTest::newRow("map invalid --set") << args({"map", "moma-3a", "--set", "l1=-4"}) << 2 << QStringLiteral("l1=-4");
    QTest::newRow("workspace unknown --set") << args({"workspace", "moma-3a", "--set", "zz=1"}) << 2
                                             << QStringLiteral("zz");
    QTest::newRow("map bad mode") << args({"map", "moma-3a", "--set", "assembly=0.5"}) << 2
                                  << QStringLiteral("assembly");
    QTest::newRow("map empty") << args({"map", "moma-3a", "--set", "p_min=100", "--set", "p_max=100.001", "--grid", "10"})
                               << 3 << QStringLiteral("moma-3a");
    QTest::newRow("workspace empty")
        << args({"workspace", "moma-3a", "--set", "p_min=100", "--set", "p_max=100.001", "--grid", "10"}) << 3
        << QStringLiteral("--grid");
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
    QTest::newRow("--help lists workspace") << QStringList{QStringLiteral("--help")}
                                            << QStringLiteral("workspace DESIGN [--grid K]");
    QTest::newRow("--help lists map") << QStringList{QStringLiteral("--help")}
                                      << QStringLiteral("map    DESIGN [--grid K] [--quantity det|cond|range|force_worst|…|spec|tolerance]");
    QTest::newRow("workspace --help") << args({"workspace", "--help"}) << QStringLiteral("Usage: pkm workspace");
    QTest::newRow("help map") << args({"help", "map"}) << QStringLiteral("Usage: pkm map");
    QTest::newRow("map -h wins over errors") << args({"map", "--grid", "1", "-h"}) << QStringLiteral("-o FILE.csv");
    QTest::newRow("--help lists render") << QStringList{QStringLiteral("--help")}
                                         << QStringLiteral("render DESIGN [--set N=V]... [--view 2d|3d]");
    QTest::newRow("render --help") << args({"render", "--help"}) << QStringLiteral("Usage: pkm render DESIGN");
    QTest::newRow("help render") << args({"help", "render"}) << QStringLiteral("--camera VIEW");
    QTest::newRow("render -h wins over errors") << args({"render", "--view", "5d", "-h"}) << QStringLiteral("xvfb-run");
}

void TestCli::helpNamesEveryJsonKey_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("command");
    QTest::newRow("show") << args({"show", "pjoint-prototype", "--json"}) << QStringLiteral("show");
    QTest::newRow("eval") << args({"eval", "pjoint-prototype", "--json"}) << QStringLiteral("eval");
    QTest::newRow("sweep") << args({"sweep", "pjoint-prototype", "--var", "theta", "--from", "0", "--to", "10", "--steps",
                                    "2", "--json"})
                           << QStringLiteral("sweep");
    QTest::newRow("workspace") << args({"workspace", "moma-3a", "--grid", "50", "--json"}) << QStringLiteral("workspace");
    QTest::newRow("map") << args({"map", "moma-3a", "--grid", "50", "--json"}) << QStringLiteral("map");
}

// Each command's help names every top-level key of its JSON, so that a script's author
// finds them all there.
void TestCli::helpNamesEveryJsonKey()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, command);
    const Run run = runPkm(arguments);
    QCOMPARE(run.exitCode, 0);
    const QJsonObject json = QJsonDocument::fromJson(run.out).object();
    QVERIFY(!json.isEmpty());
    const QString help = QString::fromUtf8(runPkm({command, QStringLiteral("--help")}).out);
    for (const QString &key : json.keys())
        QVERIFY2(help.contains(QLatin1Char('"') + key + QLatin1Char('"')), qPrintable(command + QStringLiteral(": ") + key));
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
    report::appendNumber(text, value);
    QCOMPARE(QString::fromStdString(text), expected);
}

void TestCli::fastNumbersMatchToChars()
{
    // writeNumber() takes a fast path for most values; it must give std::to_chars' text.
    std::mt19937_64 random(20240601);
    std::uniform_real_distribution<double> exponent(-8.0, 18.0);
    char buffer[report::maxNumberLength];
    const auto check = [&](double value) {
        const std::string text(buffer, report::writeNumber(buffer, value));
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
    // near a tie of the 15th digit, where the fast path needs the product's exact error
    std::uniform_int_distribution<std::uint64_t> fifteenDigits(100000000000000, 999999999999999);
    std::uniform_int_distribution<int> shift(-18, 14);
    for (int i = 0; i < 1000000; ++i) {
        const double tie = (static_cast<double>(fifteenDigits(random)) + 0.5) * std::pow(10.0, shift(random));
        for (double value : {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e300)})
            check(value);
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
    // no kinematic chain: the mobility's numbers are null and the verdict says why
    const QJsonObject mobility = root.value(QStringLiteral("mobility")).toObject();
    QVERIFY(mobility.value(QStringLiteral("numerical")).isNull());
    QVERIFY(mobility.value(QStringLiteral("formula_fails")).isNull());
    QVERIFY(mobility.value(QStringLiteral("verdict")).toString().contains(QStringLiteral("no kinematic chain")));
}

// -- fourbar --------------------------------------------------------------------------------

void TestCli::fourbarEvalJsonHasContractKeys_data()
{
    QTest::addColumn<QString>("group");
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("size"); // 0: a number
    const auto add = [](const char *group, std::initializer_list<const char *> keys) {
        for (const char *key : keys)
            QTest::addRow("%s.%s", group, key) << QString::fromLatin1(group) << QString::fromLatin1(key) << 0;
    };
    add("parameters", {"AB", "BC", "CD", "AD", "omega1"});
    add("pose", {"alpha", "gamma", "delta", "delta1", "beta"});
    add("derived", {"omega3", "epsilon3", "i31"});
}

void TestCli::fourbarEvalJsonHasContractKeys()
{
    QFETCH(QString, group);
    QFETCH(QString, key);
    QFETCH(int, size);
    static int exitCode = -1;
    static const QJsonObject root = runJson(args({"eval", "fourbar-example"}), &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(root.value(QStringLiteral("mechanism")).toString(), QStringLiteral("fourbar"));
    checkContractKey(root, group, key, size);
    // the Grashof class is a word; the example is a crank-rocker at α = 60° (degrees in JSON)
    const QJsonObject derived = root.value(QStringLiteral("derived")).toObject();
    QCOMPARE(derived.value(QStringLiteral("grashof")).toString(), QStringLiteral("crank-rocker"));
    const QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
    QCOMPARE(jsonNumber(pose, "alpha"), 60.0);
    // the angles close the quadrilateral: α + β + γ + δ = 360°
    const double sum = jsonNumber(pose, "alpha") + jsonNumber(pose, "beta") + jsonNumber(pose, "gamma")
        + jsonNumber(pose, "delta");
    QVERIFY2(std::abs(sum - 360.0) < 1e-9, qPrintable(QString::number(sum, 'g', 17)));
    // ω₃ = i₃₁·ω₁ with ω₁ = 10 rad/s
    QVERIFY(std::abs(jsonNumber(derived, "omega3") - 10.0 * jsonNumber(derived, "i31")) < 1e-12);
    QCOMPARE(jsonNumber(root.value(QStringLiteral("parameters")).toObject(), "omega1"), 10.0);
}

void TestCli::fourbarAlphaBeyondLimit()
{
    // AB = 100 mm makes the example a triple-rocker: α is limited to ±acos(−0.6714…) = ±132.19°.
    const double limit = std::acos((100.0 * 100 + 140.0 * 140 - 220.0 * 220) / (2 * 100.0 * 140)) / degree;
    int exitCode = -1;
    const QJsonObject inside = runJson({QStringLiteral("eval"), QStringLiteral("fourbar-example"), QStringLiteral("--set"),
                                        QStringLiteral("AB=100"), QStringLiteral("--set"),
                                        QStringLiteral("alpha=") + number(limit - 1.0)},
                                       &exitCode);
    QCOMPARE(exitCode, 0);
    QCOMPARE(inside.value(QStringLiteral("derived")).toObject().value(QStringLiteral("grashof")).toString(),
             QStringLiteral("triple-rocker"));
    const Run run = runPkm(args({"eval", "fourbar-example", "--set", "AB=100", "--set", "alpha=150"}));
    QCOMPARE(run.exitCode, 3);
    QVERIFY2(run.out.isEmpty(), run.out.constData());
    QCOMPARE(run.err.count('\n'), 1); // one line
    const QString message = QString::fromUtf8(run.err);
    QVERIFY2(message.contains(QStringLiteral("alpha")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("150")), qPrintable(message));
    QVERIFY2(message.contains(QString::fromStdString(formatNumber(limit, 3))), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("BC + CD")), qPrintable(message));
    const Run json = runPkm(args({"eval", "fourbar-example", "--set", "AB=100", "--set", "alpha=150", "--json"}));
    QCOMPARE(json.exitCode, 3);
    QVERIFY(json.out.isEmpty());
}

void TestCli::fourbarSweepFullTurn()
{
    const Run run = runPkm(args({"sweep", "fourbar-example", "--var", "alpha", "--from", "0", "--to", "360", "--steps",
                                 "37", "--csv"}));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    const QList<QByteArray> lines = run.out.chopped(1).split('\n');
    QCOMPARE(lines.size(), 38);
    const QList<QByteArray> header = lines.front().split(',');
    for (const char *column : {"alpha", "delta", "gamma", "delta1", "beta", "omega3", "epsilon3", "i31"})
        QVERIFY2(header.contains(column), column);
    const auto alpha = header.indexOf("alpha"), delta = header.indexOf("delta");
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        QCOMPARE(fields.size(), header.size());
        QVERIFY(std::abs(fields[alpha].toDouble() - 10.0 * double(i - 1)) < 1e-9);
        // the rocker swings between its limits 34.05° and 81.79°
        QVERIFY(fields[delta].toDouble() > 34.0 && fields[delta].toDouble() < 81.8);
    }
    // a full turn brings the rocker back
    QCOMPARE(lines[1].split(',')[delta].toDouble(), lines.back().split(',')[delta].toDouble());
}

// -- eval: mobility ---------------------------------------------------------------------------

void TestCli::evalMobility_data()
{
    addEveryPresetRows();
}

/// eval --json has "mobility": the formulas, the rank, and the verdict; the other keys stay.
void TestCli::evalMobility()
{
    QFETCH(QString, preset);
    int exitCode = -1;
    const QJsonObject root = runJson({QStringLiteral("eval"), preset}, &exitCode);
    QCOMPARE(exitCode, 0);
    const QString kind = root.value(QStringLiteral("mechanism")).toString();
    // a preset of its own (the planar parallel mechanism's legs make different chains), else the kind's
    auto expected = expectedMobility().find(preset);
    if (expected == expectedMobility().end())
        expected = expectedMobility().find(kind);
    QVERIFY2(expected != expectedMobility().end(),
        qPrintable(QStringLiteral("no expected mobility of kind %1: add it to expectedMobility()").arg(kind)));
    const auto [chebyshev, somovMalyshev, numerical, actuators, fullyActuated] = expected->second;
    const QJsonObject m = root.value(QStringLiteral("mobility")).toObject();
    if (chebyshev == -100)
        QVERIFY(m.value(QStringLiteral("chebyshev")).isNull());
    else
        QCOMPARE(m.value(QStringLiteral("chebyshev")).toInt(-100), chebyshev);
    QCOMPARE(m.value(QStringLiteral("somov_malyshev")).toInt(-100), somovMalyshev);
    QCOMPARE(m.value(QStringLiteral("numerical")).toInt(-100), numerical);
    QCOMPARE(m.value(QStringLiteral("finite")).toInt(-100), numerical);
    QCOMPARE(m.value(QStringLiteral("singular")).toBool(true), false);
    QCOMPARE(m.value(QStringLiteral("actuators")).toInt(-100), actuators);
    QCOMPARE(m.value(QStringLiteral("fully_actuated")).toBool(!fullyActuated), fullyActuated);
    // Somov–Malyshev fails for all of them: planar loops, or the O-X glide's redundant ones
    QCOMPARE(m.value(QStringLiteral("somov_malyshev_fails")).toBool(false), true);
    QCOMPARE(m.value(QStringLiteral("formula_fails")).toBool(false), true);
    const bool chebyshevFails = chebyshev != -100 && chebyshev != numerical;
    QCOMPARE(m.value(QStringLiteral("chebyshev_fails")).toBool(!chebyshevFails), chebyshevFails);
    if (chebyshev != -100)
        QCOMPARE(m.value(QStringLiteral("planar_redundant_constraints")).toInt(-100), numerical - chebyshev);
    if (chebyshevFails) {
        const QString wrong = QStringLiteral("Chebyshev's W = %1 is wrong: %2 planar loop equation").arg(chebyshev).arg(numerical - chebyshev);
        QVERIFY2(m.value(QStringLiteral("verdict")).toString().contains(wrong), qPrintable(m.value(QStringLiteral("verdict")).toString()));
    }
    QCOMPARE(m.value(QStringLiteral("redundant_constraints")).toInt(-100), numerical - somovMalyshev);
    const QJsonObject pairs = m.value(QStringLiteral("pairs")).toObject();
    QCOMPARE(pairs.keys().size(), 5);
    int counted = 0;
    for (const QString &key : pairs.keys())
        counted += pairs.value(key).toInt();
    QVERIFY(counted >= 4);
    QVERIFY(m.value(QStringLiteral("moving_links")).toInt() >= 3);
    QVERIFY(m.value(QStringLiteral("loops")).toInt() >= 1);
    QVERIFY(!m.value(QStringLiteral("chain")).toString().isEmpty());
    QVERIFY(m.value(QStringLiteral("verdict")).toString().endsWith(QLatin1Char('.')));
}

void TestCli::evalMobilityText()
{
    const Run run = runPkm(args({"eval", "fourbar-example"}));
    QCOMPARE(run.exitCode, 0);
    const QString out = QString::fromUtf8(run.out);
    const QStringList lines = out.split(QLatin1Char('\n'));
    QVERIFY(lines.contains(QStringLiteral("Mobility")));
    QVERIFY(out.contains(QStringLiteral("Chebyshev: W = 3n − 2P₅ − P₄")));
    QVERIFY(out.contains(QStringLiteral("Somov–Malyshev's W = −2 is wrong")));
    QVERIFY(out.contains(QStringLiteral("pairs of class 5 (1 freedom: revolute, prismatic, screw)")));
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
