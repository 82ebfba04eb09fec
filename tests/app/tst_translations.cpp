// The catalogues themselves: complete (no unfinished, vanished or obsolete entries), up to date
// with the sources (lupdate run again finds nothing new), faithful (every placeholder and tag
// of the source kept, %n in every plural form), in the right alphabet, with the glossary's
// terms (those of the source documents), Serbian Latin letter for letter the Serbian Cyrillic, and loadable.
#include "document/language.h"
#include "text.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using namespace pkm;

namespace {

struct Message {
    QString context;
    QString source;
    QString comment;
    bool numerus = false;
    QString type; ///< "", "unfinished", "vanished", "obsolete"
    QStringList forms;
};

QList<Message> readCatalogue(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = path + QStringLiteral(": ") + file.errorString();
        return {};
    }
    QList<Message> messages;
    QXmlStreamReader xml(&file);
    QString context;
    Message current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == u"name") {
            context = xml.readElementText();
        } else if (name == u"message") {
            current = Message{};
            current.context = context;
            current.numerus = xml.attributes().value(QStringLiteral("numerus")) == QStringLiteral("yes");
        } else if (name == u"source") {
            current.source = xml.readElementText();
        } else if (name == u"comment") {
            current.comment = xml.readElementText();
        } else if (name == u"translation") {
            current.type = xml.attributes().value(QStringLiteral("type")).toString();
            if (!current.numerus) {
                current.forms = {xml.readElementText()};
                messages.append(current);
            } else {
                while (xml.readNextStartElement()) {
                    if (xml.name() == u"numerusform")
                        current.forms.append(xml.readElementText());
                    else
                        xml.skipCurrentElement();
                }
                messages.append(current);
            }
        }
    }
    if (xml.hasError())
        *error = path + QStringLiteral(": ") + xml.errorString();
    return messages;
}

QString translationsDir()
{
    return QStringLiteral(PKM_SOURCE_DIR "/translations");
}

QString tsPath(const QString &code)
{
    return translationsDir() + QStringLiteral("/pkm_studio_") + code + QStringLiteral(".ts");
}

QString describe(const Message &m)
{
    return m.context + QStringLiteral(" / “") + m.source.left(80) + QStringLiteral("”");
}

/// Placeholders (%1…%9, %n, %L1) and HTML tags, sorted, as the translation must keep them.
QStringList markers(const QString &text, bool withPlural)
{
    static const QRegularExpression marker(QStringLiteral("%L?[1-9]|%n|</?[a-zA-Z][a-zA-Z0-9]*"));
    QStringList found;
    for (auto it = marker.globalMatch(text); it.hasNext();) {
        const QString m = it.next().captured();
        if (m == QStringLiteral("%n") && !withPlural)
            continue;
        found << m.toLower();
    }
    found.sort();
    return found;
}

const QStringList languages = {QStringLiteral("en"), QStringLiteral("sr"), QStringLiteral("sr_Latn"),
                               QStringLiteral("ru")};

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private slots:
    void complete_data()
    {
        QTest::addColumn<QString>("code");
        for (const QString &code : languages)
            QTest::newRow(qPrintable(code)) << code;
    }

    // No entry waits for a translator, and none is left from strings the code no longer has.
    void complete()
    {
        QFETCH(QString, code);
        QString error;
        const QList<Message> messages = readCatalogue(tsPath(code), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(messages.size() >= (code == QStringLiteral("en") ? 10 : 1000));
        for (const Message &m : messages) {
            QVERIFY2(m.type.isEmpty(), qPrintable(code + QStringLiteral(": ") + m.type + QStringLiteral(": ") + describe(m)));
            QVERIFY2(!m.forms.isEmpty(), qPrintable(describe(m)));
            for (const QString &form : m.forms)
                QVERIFY2(!form.trimmed().isEmpty() || m.source.trimmed().isEmpty(),
                         qPrintable(code + QStringLiteral(": empty: ") + describe(m)));
            // English carries only the plurals (one and other); Russian and Serbian have three.
            if (m.numerus)
                QCOMPARE(m.forms.size(), code == QStringLiteral("en") ? 2 : 3);
            else
                QVERIFY2(code != QStringLiteral("en"), qPrintable(QStringLiteral("not a plural: ") + describe(m)));
        }
    }

    // Every %1 and tag of the source is in every form of the translation, nothing more.
    void faithful_data() { complete_data(); }
    void faithful()
    {
        QFETCH(QString, code);
        QString error;
        const QList<Message> messages = readCatalogue(tsPath(code), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        for (const Message &m : messages) {
            const QStringList wanted = markers(m.source, m.numerus);
            for (const QString &form : m.forms) {
                QVERIFY2(markers(form, m.numerus) == wanted,
                         qPrintable(code + QStringLiteral(": “") + form + QStringLiteral("” for ") + describe(m)));
            }
        }
    }

    // Running lupdate over the sources again adds nothing and drops nothing: every string of
    // the code is in every catalogue.
    void upToDate()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        for (const QString &code : languages) {
            const QString copy = dir.filePath(QFileInfo(tsPath(code)).fileName());
            QVERIFY(QFile::copy(tsPath(code), copy));
            QStringList arguments = {QStringLiteral(PKM_SOURCE_DIR "/core"), QStringLiteral(PKM_SOURCE_DIR "/widgets"),
                                     QStringLiteral(PKM_SOURCE_DIR "/app"), QStringLiteral(PKM_PRESET_TEXTS),
                                     QStringLiteral("-no-obsolete"),
                                     QStringLiteral("-locations"), QStringLiteral("none"),
                                     QStringLiteral("-no-ui-lines"), QStringLiteral("-silent")};
            if (code == QStringLiteral("en"))
                arguments << QStringLiteral("-pluralonly");
            arguments << QStringLiteral("-ts") << copy;
            QProcess lupdate;
            lupdate.start(QStringLiteral(PKM_LUPDATE), arguments);
            QVERIFY(lupdate.waitForFinished(120000));
            QVERIFY2(lupdate.exitCode() == 0, lupdate.readAllStandardError().constData());
            QString error;
            const QList<Message> before = readCatalogue(tsPath(code), &error);
            const QList<Message> after = readCatalogue(copy, &error);
            QVERIFY2(error.isEmpty(), qPrintable(error));
            for (const Message &m : after)
                QVERIFY2(m.type.isEmpty(), qPrintable(code + QStringLiteral(": not in the catalogue: ") + describe(m)));
            QCOMPARE(after.size(), before.size());
        }
    }

    // Serbian Cyrillic uses no Russian letters, Russian no Serbian ones, Serbian Latin no
    // Cyrillic at all; and Latin is the Cyrillic letter for letter (scripts/serbian-latin).
    void alphabets()
    {
        const QString russianOnly = QStringLiteral("ыэюяйщъьё");
        const QString serbianOnly = QStringLiteral("ђјљњћџ");
        const QRegularExpression cyrillic(QStringLiteral("[\\x{0400}-\\x{04FF}]"));
        for (const QString &code : {QStringLiteral("sr"), QStringLiteral("ru"), QStringLiteral("sr_Latn")}) {
            QString error;
            for (const Message &m : readCatalogue(tsPath(code), &error)) {
                for (const QString &form : m.forms) {
                    const QString lower = form.toLower();
                    const QString wrong = code == QStringLiteral("sr") ? russianOnly
                        : code == QStringLiteral("ru")                 ? serbianOnly
                                                                       : QString();
                    for (QChar c : wrong)
                        QVERIFY2(!lower.contains(c), qPrintable(code + QStringLiteral(": “") + form + QStringLiteral("”")));
                    if (code == QStringLiteral("sr_Latn"))
                        QVERIFY2(!cyrillic.match(form).hasMatch(), qPrintable(QStringLiteral("sr_Latn: “") + form + QStringLiteral("”")));
                }
            }
            QVERIFY2(error.isEmpty(), qPrintable(error));
        }
        QProcess check;
        check.start(QStringLiteral("python3"), {QStringLiteral(PKM_SOURCE_DIR "/scripts/serbian-latin"), QStringLiteral("--check")});
        QVERIFY(check.waitForFinished(60000));
        QVERIFY2(check.exitCode() == 0, check.readAllStandardError().constData());
    }

    // The field's own words (those of the source documents) wherever the English names the thing.
    void glossary_data()
    {
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("english");
        QTest::addColumn<QString>("term");
        const QList<std::array<const char *, 4>> terms = {
            // English pattern, Serbian Cyrillic, Serbian Latin, Russian (stems: any case ending)
            {"П-joint", "П-зглоб", "P-zglob", "П-шарнир"},
            {"Jacobian", "Јакобиј", "Jakobij", "Якоби"}, // јакобијан, Јакобијева матрица
            {"workspace", "радн", "radn", "рабоч"},
            {"four-bar", "четвороуг", "četvoroug", "четырёхзвен"},
            {"transmission angle", "угао преноса", "ugao prenosa", "угол передачи"},
            {"stepper", "корачн", "koračn", "шагов"},
            {"parallelogram", "паралелограм", "paralelogram", "параллелограмм"},
        };
        for (const auto &t : terms) {
            QTest::newRow(qPrintable(QStringLiteral("sr ") + QString::fromUtf8(t[0]))) << QStringLiteral("sr") << QString::fromUtf8(t[0]) << QString::fromUtf8(t[1]);
            QTest::newRow(qPrintable(QStringLiteral("sr_Latn ") + QString::fromUtf8(t[0]))) << QStringLiteral("sr_Latn") << QString::fromUtf8(t[0]) << QString::fromUtf8(t[2]);
            QTest::newRow(qPrintable(QStringLiteral("ru ") + QString::fromUtf8(t[0]))) << QStringLiteral("ru") << QString::fromUtf8(t[0]) << QString::fromUtf8(t[3]);
        }
    }
    void glossary()
    {
        QFETCH(QString, code);
        QFETCH(QString, english);
        QFETCH(QString, term);
        QString error;
        int uses = 0;
        for (const Message &m : readCatalogue(tsPath(code), &error)) {
            // the English word, not a command named after it ("pkm workspace")
            const QRegularExpression named(QStringLiteral("(?<!pkm )\\b") + QRegularExpression::escape(english),
                                           QRegularExpression::CaseInsensitiveOption | QRegularExpression::UseUnicodePropertiesOption);
            if (!named.match(m.source).hasMatch())
                continue;
            ++uses;
            for (const QString &form : m.forms) {
                QString plain = form.toLower();
                plain.replace(QStringLiteral("ё"), QStringLiteral("е"));
                QString wanted = term.toLower();
                wanted.replace(QStringLiteral("ё"), QStringLiteral("е"));
                QVERIFY2(plain.contains(wanted), qPrintable(code + QStringLiteral(": “") + form + QStringLiteral("” lacks “") + term
                                                            + QStringLiteral("” for ") + describe(m)));
            }
        }
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY2(uses > 0, qPrintable(QStringLiteral("no source names ") + english));
    }

    // Each catalogue loads and translates, core sentences included.
    void loads()
    {
        for (const language::Language &l : language::all()) {
            QVERIFY(language::apply(l.code));
            QCOMPARE(language::current(), l.code);
            if (l.code == QStringLiteral("en"))
                QCOMPARE(text::translate("core", "%n loop(s)", nullptr, 1), std::string("1 loop"));
            else
                QVERIFY(text::translate("core", "crank (lever) length") != "crank (lever) length");
        }
        QVERIFY(language::apply(QStringLiteral("ru")));
        QCOMPARE(text::number(1.5, 2), std::string("1,5"));
        QVERIFY(!language::apply(QStringLiteral("xx")));
        QCOMPARE(language::current(), QStringLiteral("ru"));
        QVERIFY(language::apply(QStringLiteral("en")));
        QCOMPARE(text::number(1.5, 2), std::string("1.5"));
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
