// Design files and presets: every preset loads, save → load is exact, bad files are refused
// with a message naming the file.
#include "document/designfile.h"
#include "support/app.h"

#include <cmath>

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace pkm;

class TestDesignFile : public QObject
{
    Q_OBJECT

private slots:
    void presetsLoad()
    {
        const QList<PresetInfo> presets = designfile::presets();
        QStringList ids;
        for (const PresetInfo &preset : presets) {
            ids << preset.id;
            auto design = designfile::load(preset.id);
            QVERIFY2(design.ok(), design ? "" : design.failure().message.c_str());
            QCOMPARE(design->id, preset.id);
            QCOMPARE(QString::fromUtf8(design->mechanism->kind().data()), preset.kind);
            QVERIFY(!design->title.isEmpty());
        }
        for (const char *id : {"pjoint-prototype", "pjoint-study-k03", "pjoint-study-k04", "pjoint-study-k05"})
            QVERIFY2(ids.contains(QLatin1String(id)), id);
    }

    void prototypeValues()
    {
        auto design = designfile::load(QStringLiteral("pjoint-prototype"));
        QVERIFY(design.ok());
        const ParameterSet p = design->mechanism->parameters();
        QCOMPARE(p.at("a"), 170.0);
        QCOMPARE(p.at("k"), 0.4);
        QCOMPARE(p.at("theta_max"), 60 * units::degree);
        QCOMPARE(p.at("lead"), 2.54);
        QCOMPARE(p.at("step"), 0.0127);
        QCOMPARE(p.at("speed_max"), 50.0);
        QCOMPARE(p.at("force_max"), 130.0);
    }

    void saveLoadRoundTrip()
    {
        auto design = designfile::load(QStringLiteral("pjoint-prototype"));
        auto changed = designfile::setDisplayParameter(design->mechanism, QStringLiteral("a"), 183.25);
        QVERIFY(changed.ok());
        design->mechanism = *changed;
        auto pose = designfile::solveDisplayVariables(*design->mechanism, design->pose, {{QStringLiteral("theta"), 17.5}});
        QVERIFY(pose.ok());
        design->pose = *pose;
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("mine.pkm.json"));
        QVERIFY(designfile::save(*design, path).ok());
        auto loaded = designfile::load(path);
        QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
        QCOMPARE(loaded->mechanism->parameters(), design->mechanism->parameters());
        QVERIFY(std::abs(loaded->pose.outputs[0] - design->pose.outputs[0]) < 1e-15);
        QCOMPARE(designfile::serialize(*loaded), designfile::serialize(*design));
    }

    void everyPresetSavesToAFixedPoint_data() { pkm::test::addEveryPresetRows(); }

    /// Saving a design and reading it back gives the same file, again and again: the inputs
    /// are written to 15 digits, and the pose solved from them must not drift (the П-joint
    /// study at θ = 0 came back at θ = 1e-12°, and every save moved it on).
    void everyPresetSavesToAFixedPoint()
    {
        PKM_FETCH_PRESET(preset);
        auto design = designfile::load(preset);
        QVERIFY2(design.ok(), design ? "" : design.failure().message.c_str());
        const QByteArray saved = designfile::serialize(*design);
        auto again = designfile::parse(saved, QStringLiteral("saved"));
        QVERIFY2(again.ok(), again ? "" : again.failure().message.c_str());
        QCOMPARE(designfile::serialize(*again), saved);
    }

    /// Found by fuzzing: a free platform whose three legs hold the same platform point (the
    /// leg library's defaults, B₁ = B₂ = B₃) turns freely at any pose (a direct singularity):
    /// its inputs hold every φ, and the φ solved from them was not the one saved, so the saved
    /// file did not read back. The file's own pose holds its inputs and is kept.
    void savedPoseOfAFreelyTurningPlatformReadsBack()
    {
        const QByteArray file = R"({"format": "pkm-studio-design", "version": 1, "mechanism": "planar-parallel",
  "parameters": {"platform": "free", "theta3_min": -180, "theta3_max": 180, "working3": 1, "assembly": 1},
  "pose": {"x": 50, "y": 150}})";
        auto design = designfile::parse(file, QStringLiteral("fuzzed.pkm.json"));
        QVERIFY2(design.ok(), design ? "" : design.failure().message.c_str());
        const QByteArray saved = designfile::serialize(*design);
        auto again = designfile::parse(saved, QStringLiteral("saved"));
        QVERIFY2(again.ok(), again ? "" : again.failure().message.c_str());
        QCOMPARE(designfile::serialize(*again), saved);
    }

    /// Found by fuzzing: a 3-RRR/RPR platform whose home pose amplifies round-off. The outputs
    /// solved from the written inputs drift, so the reader solves the inputs from the written
    /// outputs — and those came back as q1 = 40.0000000000003, so the second save differed from
    /// the first. The inputs the file wrote are kept when they agree to the digits written.
    void savedPoseOfAMixedPlatformIsAFixedPoint()
    {
        const QByteArray file = R"({
  "format": "pkm-studio-design", "version": 1, "id": "pp-3rrr", "mechanism": "planar-parallel",
  "parameters": {
    "platform": "free",
    "leg1_type": "RRR", "A1x": 0, "A1y": 0, "A2x": 400, "A2y": 0, "B2x": 43.30127, "B2y": -25.0,
    "r2": 120, "l2": 150, "alpha2": 0, "a2": 170, "k2": 0.4, "q2_min": 10, "q2_max": 581,
    "theta2_min": -180, "theta2_max": 180, "working2": 1,
    "A3x": 200, "A3y": 346.410162, "B2x": 0.0, "B3y": 50.0, "r3": 120, "l1": 150, "alpha3": 0,
    "a3": 170, "k3": 0.4, "q3_min": 10, "q3_max": 200, "theta3_min": -180, "theta3_max": 180,
    "working3": 1, "assembly": 1, "phi_map": 0
  }
})";
        auto design = designfile::parse(file, QStringLiteral("fuzzed.pkm.json"));
        QVERIFY2(design.ok(), design ? "" : design.failure().message.c_str());
        QByteArray saved = designfile::serialize(*design);
        for (int round = 0; round < 3; ++round) {
            auto again = designfile::parse(saved, QStringLiteral("saved"));
            QVERIFY2(again.ok(), again ? "" : again.failure().message.c_str());
            QCOMPARE(designfile::serialize(*again), saved);
            // The pose read back is the saved one to the digits written.
            for (int i = 0; i < design->pose.inputs.size(); ++i)
                QVERIFY(std::abs(again->pose.inputs[i] - design->pose.inputs[i]) <= 1e-11 * std::max(1.0, std::abs(design->pose.inputs[i])));
            saved = designfile::serialize(*again);
        }
    }

    /// A file's own text reaches a dialog or a terminal escaped and cut short: a control
    /// character or a megabyte name in a file cannot clear the screen or fill it.
    void messagesQuoteTheFileSafely()
    {
        const QByteArray head = "{\"format\": \"pkm-studio-design\", \"version\": 2, \"mechanism\": \"pjoint\", "
                                "\"parameters\": {\"";
        for (const QByteArray &name : {QByteArray("a\u0007\u001b[2Jb"), QByteArray(100000, 'x')}) {
            auto parsed = designfile::parse(head + name + "\": 1}}", QStringLiteral("bad\x1b.pkm.json"));
            QVERIFY(!parsed.ok());
            const std::string &message = parsed.failure().message;
            for (const char c : message)
                QVERIFY2(static_cast<unsigned char>(c) >= 0x20, message.c_str());
            QVERIFY2(message.size() < 400, message.c_str());
            QVERIFY2(QString::fromStdString(message).contains(QStringLiteral("unknown parameter")), message.c_str());
        }
        auto bell = designfile::parse(head + "a\\u0007\": 1}}", QStringLiteral("bad.pkm.json"));
        QVERIFY(QString::fromStdString(bell.failure().message).contains(QStringLiteral("a\\x07")));
    }

    void versionTwoSavesEveryVariable()
    {
        // The O-X glide's z is an input the outputs do not determine: version 1 lost it.
        auto design = designfile::load(QStringLiteral("oxglide-prototype"));
        QVERIFY(design.ok());
        auto moved = designfile::solveDisplayVariables(*design->mechanism, design->pose,
                                                       {{QStringLiteral("x_AB"), 20.0}, {QStringLiteral("x_CD"), 100.0},
                                                        {QStringLiteral("z"), 123.0}});
        QVERIFY2(moved.ok(), moved ? "" : moved.failure().message.c_str());
        design->pose = *moved;
        const QJsonObject root = QJsonDocument::fromJson(designfile::serialize(*design)).object();
        QCOMPARE(root.value(QStringLiteral("version")).toInt(), designfile::formatVersion);
        QCOMPARE(designfile::formatVersion, 2);
        const QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
        for (const char *name : {"x_AB", "x_CD", "z", "x", "y"})
            QVERIFY2(pose.contains(QLatin1String(name)), name);
        auto loaded = designfile::parse(designfile::serialize(*design), QStringLiteral("memory"));
        QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
        QCOMPARE(loaded->pose.inputs[2], 123.0);
        QVERIFY((loaded->pose.inputs - design->pose.inputs).norm() < 1e-12);
        QVERIFY((loaded->pose.outputs - design->pose.outputs).norm() < 1e-12);
        QCOMPARE(designfile::serialize(*loaded), designfile::serialize(*design));
    }

    void savedValuesReadAsTyped()
    {
        // 60° kept in radians is 59.99999999999999° again: the file says 60, and reads back
        auto design = designfile::load(QStringLiteral("pjoint-prototype"));
        QVERIFY(design.ok());
        auto changed = designfile::setDisplayParameter(design->mechanism, QStringLiteral("theta_max"), 60.0);
        QVERIFY2(changed.ok(), changed ? "" : changed.failure().message.c_str());
        design->mechanism = *changed;
        const QByteArray file = designfile::serialize(*design);
        QVERIFY2(!file.contains("9999999"), file.constData());
        const QJsonObject parameters = QJsonDocument::fromJson(file).object().value(QStringLiteral("parameters")).toObject();
        QCOMPARE(parameters.value(QStringLiteral("theta_max")).toDouble(), 60.0);
        auto loaded = designfile::parse(file, QStringLiteral("memory"));
        QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
        QCOMPARE(loaded->mechanism->parameters().at("theta_max"), design->mechanism->parameters().at("theta_max"));
    }

    void crankRockerKeepsItsCrankAngle()
    {
        // A crank-rocker passes each rocker angle twice per turn: the inputs say which.
        auto design = designfile::load(QStringLiteral("fourbar-example"));
        QVERIFY(design.ok());
        for (double alpha : {60.0, 300.0}) {
            auto posed = designfile::solveDisplayVariables(*design->mechanism, design->pose,
                                                           {{QStringLiteral("alpha"), alpha}});
            QVERIFY(posed.ok());
            design->pose = *posed;
            auto loaded = designfile::parse(designfile::serialize(*design), QStringLiteral("memory"));
            QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
            QVERIFY(std::abs(loaded->pose.inputs[0] - posed->inputs[0]) < 1e-12);
        }
    }

    void versionOneFilesAreUpgraded()
    {
        // As PKM Studio 0.1 wrote them: the outputs only.
        const QByteArray v1 = R"({"format": "pkm-studio-design", "version": 1, "title": "old",
            "mechanism": "oxglide", "parameters": {"l": 80, "s": 20, "L": 130, "a": 15, "z_min": 0,
            "z_max": 150, "mode": 1}, "pose": {"x": 60, "y": 65}})";
        auto loaded = designfile::parse(v1, QStringLiteral("old.pkm.json"));
        QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
        QCOMPARE(loaded->pose.outputs[0], 60.0);
        QCOMPARE(loaded->pose.outputs[1], 65.0);
        const QJsonObject saved = QJsonDocument::fromJson(designfile::serialize(*loaded)).object();
        QCOMPARE(saved.value(QStringLiteral("version")).toInt(), 2);
        QCOMPARE(saved.value(QStringLiteral("pose")).toObject().size(), 5);
    }

    void inconsistentPoseIsRefused()
    {
        auto design = designfile::load(QStringLiteral("pjoint-prototype"));
        QJsonObject root = QJsonDocument::fromJson(designfile::serialize(*design)).object();
        QJsonObject pose = root.value(QStringLiteral("pose")).toObject();
        pose.insert(QStringLiteral("theta"), pose.value(QStringLiteral("theta")).toDouble() + 5.0);
        root.insert(QStringLiteral("pose"), pose);
        auto loaded = designfile::parse(QJsonDocument(root).toJson(), QStringLiteral("edited.pkm.json"));
        QVERIFY(!loaded.ok());
        const QString message = QString::fromStdString(loaded.failure().message);
        QVERIFY2(message.contains(QStringLiteral("edited.pkm.json")) && message.contains(QStringLiteral("theta")),
                 qPrintable(message));
    }

    void badFiles_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        const QByteArray head = R"({"format": "pkm-studio-design", "version": 1, "mechanism": "pjoint", )";
        QTest::newRow("not json") << QByteArray("{ broken") << "not valid JSON";
        QTest::newRow("other format") << QByteArray(R"({"format": "x"})") << "not a PKM Studio design";
        QTest::newRow("newer version")
            << QByteArray(R"({"format": "pkm-studio-design", "version": 99, "mechanism": "pjoint"})") << "newer";
        QTest::newRow("unknown kind")
            << QByteArray(R"({"format": "pkm-studio-design", "version": 1, "mechanism": "robot"})") << "unknown mechanism";
        QTest::newRow("unknown parameter") << QByteArray(head + R"("parameters": {"zz": 1}})") << "unknown parameter 'zz'";
        QTest::newRow("text value") << QByteArray(head + R"("parameters": {"a": "long"}})") << "'a' is not a number";
        QTest::newRow("invalid value") << QByteArray(head + R"("parameters": {"a": -1}})") << "a (crank";
        QTest::newRow("pose out of range") << QByteArray(head + R"("pose": {"theta": 80}})") << "θ = 80";
        const QByteArray glide = R"({"format": "pkm-studio-design", "version": 1, "mechanism": "oxglide", )";
        QTest::newRow("unknown form") << QByteArray(glide + R"("parameters": {"mode": "Q"}})")
                                      << "'mode' must be a number or one of O, X, not 'Q'";
        QTest::newRow("form number") << QByteArray(glide + R"("parameters": {"mode": 0}})") << "mode = 0 is invalid";
    }

    void modeByName()
    {
        // a mode parameter may be given by its name; z goes with the outputs
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("crossed.pkm.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "pkm-studio-design", "version": 1, "mechanism": "oxglide",
                      "parameters": {"mode": "X"}, "pose": {"x": 65, "y": 40, "z": 30}})");
        file.close();
        auto loaded = designfile::load(path);
        QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());
        QCOMPARE(loaded->mechanism->parameters().at("mode"), -1.0);
        QCOMPARE(loaded->pose.outputs[1], 40.0);
        QCOMPARE(loaded->pose.inputs[2], 30.0);
        QVERIFY(loaded->pose.inputs[0] > loaded->pose.inputs[1]); // crossed
    }
    void badFiles()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.pkm.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
        file.close();
        auto loaded = designfile::load(path);
        QVERIFY(!loaded.ok());
        const QString message = QString::fromStdString(loaded.failure().message);
        QVERIFY2(message.contains(expected), qPrintable(message));
        QVERIFY2(message.contains(path), qPrintable(message));
    }

    void missingFileAndPreset()
    {
        QVERIFY(!designfile::load(QStringLiteral("/nonexistent/x.pkm.json")).ok());
        auto none = designfile::load(QStringLiteral("no-such-preset"));
        QVERIFY(!none.ok());
        QVERIFY(QString::fromStdString(none.failure().message).contains(QStringLiteral("no-such-preset")));
    }

    void saveIsAtomic()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("keep.pkm.json"));
        auto design = designfile::load(QStringLiteral("pjoint-prototype"));
        QVERIFY(designfile::save(*design, path).ok());
        QFile before(path);
        QVERIFY(before.open(QIODevice::ReadOnly));
        const QByteArray original = before.readAll();
        before.close();
        // a save into a folder that does not exist fails and names the path
        auto failed = designfile::save(*design, dir.filePath(QStringLiteral("missing/dir/x.pkm.json")));
        QVERIFY(!failed.ok());
        QVERIFY(QString::fromStdString(failed.failure().message).contains(QStringLiteral("missing/dir")));
        QFile after(path);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), original);
        after.close();

        // Saving over the file writes a new one and renames it into place (QSaveFile): a reader
        // holding the old file, or a crash mid-write, never sees half a design.
        struct stat before_{}, replaced{};
        QVERIFY(::stat(QFile::encodeName(path).constData(), &before_) == 0);
        QFile reader(path);
        QVERIFY(reader.open(QIODevice::ReadOnly));
        auto changed = designfile::setDisplayParameter(design->mechanism, QStringLiteral("a"), 200);
        design->mechanism = *changed;
        design->pose = design->mechanism->homePose();
        QVERIFY(designfile::save(*design, path).ok());
        QVERIFY(::stat(QFile::encodeName(path).constData(), &replaced) == 0);
        QVERIFY(replaced.st_ino != before_.st_ino);
        QCOMPARE(reader.readAll(), original); // the old content, whole
        QVERIFY(designfile::load(path)->mechanism->parameters().at("a") == 200.0);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("keep.pkm.json")});
    }
};

QTEST_MAIN(TestDesignFile)
#include "tst_designfile.moc"
