// What `pkm` does with hostile or careless input (issue 21): a design file is read in a bounded
// way (a device that never ends, a file of megabytes, a page-long description are refused
// with one sentence naming the limit); a message never sends a control character from a file
// or an argument to the terminal, and never repeats a megabyte; a value said to be outside a
// range is printed with the digits that show why.

#include "support/process.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace pkm::test;

namespace {
QString writeFile(const QTemporaryDir &dir, const char *name, const QByteArray &bytes)
{
    const QString path = dir.filePath(QLatin1String(name));
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(bytes);
    return path;
}

/// moma-3a as a file, with `replace` applied to its text.
QByteArray preset(const QByteArray &from = {}, const QByteArray &to = {})
{
    QFile file(QStringLiteral(PKM_PRESET_DIR "/moma-3a.pkm.json"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QByteArray bytes = file.readAll();
    if (!from.isEmpty())
        bytes.replace(from, to);
    return bytes;
}

/// One line on stderr, exit status 2, nothing on stdout, no control character but the newline.
void refusedInOneSafeLine(const Run &run)
{
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(run.err.count('\n'), 1);
    QVERIFY(run.err.endsWith('\n'));
    for (const char c : run.err.chopped(1))
        QVERIFY2(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, run.err.constData());
}
} // namespace

class TestCliLimits : public QObject
{
    Q_OBJECT

private slots:
    void endlessDeviceIsRefused()
    {
        const Run run = runPkm(args({"eval", "/dev/zero"}));
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.contains("larger than 1 MiB"), run.err.constData());
    }

    void largeFileIsRefused()
    {
        QTemporaryDir dir;
        // valid JSON of 2 MB: a description padded far beyond any design's
        const QByteArray big = preset("\"title\":", "\"padding\": \"" + QByteArray(2 << 20, 'x') + "\", \"title\":");
        QVERIFY(big.size() > (2 << 20));
        const Run run = runPkm({QStringLiteral("eval"), writeFile(dir, "big.pkm.json", big)});
        refusedInOneSafeLine(run);
        QVERIFY(run.err.contains("larger than 1 MiB"));
    }

    void longDescriptionIsRefused()
    {
        QTemporaryDir dir;
        const QByteArray bytes = preset("\"description\": \"", "\"description\": \"" + QByteArray(20000, 'y'));
        const Run run = runPkm({QStringLiteral("sheet"), writeFile(dir, "long.pkm.json", bytes), QStringLiteral("-o"),
                                dir.filePath(QStringLiteral("s.json"))});
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.contains("description") && run.err.contains("10000"), run.err.constData());
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("s.json"))));
    }

    void fileContentCannotReachTheTerminal()
    {
        QTemporaryDir dir;
        // a parameter name with a clear-screen, a colour, a newline and a bell in it
        const QByteArray bytes = preset("\"parameters\": {", "\"parameters\": {\"\\u001b[2J\\u001b[31mfake\\nline\\u0007\": 1, ");
        const Run run = runPkm({QStringLiteral("eval"), writeFile(dir, "hostile.pkm.json", bytes)});
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.contains("\\x1B[2J"), run.err.constData());
    }

    void hugeArgumentIsCut()
    {
        const QString name(100000, QLatin1Char('n')); // near the longest argument Linux passes
        const Run run = runPkm({QStringLiteral("eval"), QStringLiteral("moma-3a"), QStringLiteral("--set"), name + QStringLiteral("=1")});
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.size() < 4000, qPrintable(QString::number(run.err.size())));
        QVERIFY(run.err.contains("…"));
    }

    /// The sheet of a mechanism kilometres large is drawn at its scale without painting it at
    /// every larger one (it took 32 s and 340 MB when the bounds were found by painting).
    void hugeDesignSheet()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.json"));
        const Run run = runPkm({QStringLiteral("sheet"), QStringLiteral("pjoint-prototype"), QStringLiteral("--set"),
                                QStringLiteral("a=1e7"), QStringLiteral("-o"), path});
        QCOMPARE(run.exitCode, 0);
        const QByteArray sheet = fileBytes(path);
        QVERIFY(sheet.contains("\"drawing\""));
        QVERIFY(sheet.contains("1:"));
    }

    /// A ratio that makes a length infinite is blamed as itself (it was "b = not a number").
    void hugeRatioIsBlamedAsItself()
    {
        const Run run = runPkm(args({"eval", "pjoint-prototype", "--set", "k=1e308"}));
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.contains("k = b/a = ∞ is out of proportion") && !run.err.contains("not a number"),
                 run.err.constData());
    }

    /// The product of frames and size is bounded, not only each (1000 steps of 8000 × 8000
    /// ran for ever); refused before anything is drawn or written.
    void animationPixelsAreBounded()
    {
        QTemporaryDir dir;
        const QString gif = dir.filePath(QStringLiteral("big.gif"));
        const Run run = runPkm({QStringLiteral("render"), QStringLiteral("fourbar-example"), QStringLiteral("--var"),
                                QStringLiteral("alpha"), QStringLiteral("--from"), QStringLiteral("0"), QStringLiteral("--to"),
                                QStringLiteral("360"), QStringLiteral("--steps"), QStringLiteral("1000"), QStringLiteral("--size"),
                                QStringLiteral("8000x8000"), QStringLiteral("-o"), gif});
        refusedInOneSafeLine(run);
        QVERIFY2(run.err.contains("1000 million pixels"), run.err.constData());
        QVERIFY(!QFile::exists(gif));
    }

    void outsideShowsWhy_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QByteArray>("shown");
        QTest::newRow("pjoint theta") << args({"eval", "pjoint-prototype", "--set", "theta=60.000001"}) << QByteArray("60.000001");
        QTest::newRow("pp input") << args({"eval", "pp-3rpr", "--set", "q1=30.0000004"}) << QByteArray("30.0000004");
        QTest::newRow("four-bar crank") << args({"eval", "fourbar-example", "--set", "alpha=360.0000001"}) << QByteArray("360.0000001°");
        QTest::newRow("MOMA slider") << args({"eval", "moma-3a", "--set", "p1=200.000001", "--set", "p2=100"})
                                     << QByteArray("200.000001 mm");
    }
    void outsideShowsWhy()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QByteArray, shown);
        const Run run = runPkm(arguments);
        QVERIFY(run.exitCode != 0);
        QVERIFY2(run.err.contains(shown), run.err.constData());
    }

    /// A point out of reach is given to the hundredth, as the fields give it, and the length it
    /// is out of is named by its symbol, as the panels write it (l₁, not the file's name l1).
    void unreachablePointInSymbols()
    {
        const Run run = runPkm(args({"eval", "moma-3a", "--set", "x=83"}));
        QVERIFY(run.exitCode != 0);
        QVERIFY2(run.err.contains("(83, -261.5) mm") && run.err.contains("l\u2081 = 195 mm"), run.err.constData());
    }
};

QTEST_MAIN(TestCliLimits)
#include "tst_clilimits.moc"
