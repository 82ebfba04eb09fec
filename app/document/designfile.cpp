#include "document/designfile.h"
#include "document/designfileinternal.h"

#include <algorithm>
#include <optional>
#include <cmath>

#include "quantityformat.h"
#include "registry.h"
#include "text.h"
#include "tolerance.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace pkm {

namespace designfile {

namespace {
/// The message reaches a dialog, the status bar or a terminal as it is: whatever the file (or
/// its path) put into it is escaped there (text::printable), and a quoted name is cut short by
/// quoted() before, so that the sentence around it survives.
Failure fileFailure(const QString &culprit, const QString &message)
{
    return Failure{FailureKind::InvalidParameter, text::printable(culprit.toStdString(), 200),
                   text::printable(message.toStdString(), 2000)};
}

/// A name or word from the file, for a message: control characters escaped, at most 80 characters.
QString quoted(const QString &fromFile)
{
    return QString::fromStdString(text::printable(fromFile.toStdString(), 80));
}

const ParameterInfo *findParameter(const Mechanism &mechanism, const QString &name)
{
    return mechanism.findParameter(name.toStdString());
}

QString presetPath(const QString &id)
{
    return QStringLiteral(":/presets/%1.pkm.json").arg(id);
}
} // namespace

/// A number in a message: the locale's decimal point and minus sign in the GUI, '.' in the CLI
/// (text::number's rules), `significant` digits as QString::number(v, 'g', significant).
QString detail::numberText(double value, int significant)
{
    QString text = QString::number(value, 'g', significant);
    const text::Hooks hooks = text::installed();
    if (!hooks.decimalPoint.empty())
        text.replace(QLatin1Char('.'), toQString(hooks.decimalPoint));
    if (!hooks.minusSign.empty() && text.startsWith(QLatin1Char('-')))
        text.replace(0, 1, toQString(hooks.minusSign));
    return text;
}

using detail::numberText;

namespace {
Result<Design> parseDesign(const QByteArray &json, const QString &origin);
} // namespace

Result<Design> parse(const QByteArray &json, const QString &origin)
{
    // Every failure, whichever part of the file or the kinds' checks made it, reaches the user
    // escaped (the file's path and names may hold anything).
    Result<Design> design = parseDesign(json, origin);
    if (design)
        return design;
    Failure failure = design.failure();
    failure.culprit = text::printable(failure.culprit, 200);
    failure.message = text::printable(failure.message, 2000);
    return failure;
}

namespace {
Result<Design> parseDesign(const QByteArray &json, const QString &origin)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 is not valid JSON (%2 at byte %3).")
                                       .arg(origin, error.errorString(), numberText(error.offset)));
    }
    const QJsonObject root = document.object();
    if (!document.isObject() || root.value(QStringLiteral("format")).toString() != QLatin1String(formatName))
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 is not a PKM Studio design file.").arg(origin));
    const int version = root.value(QStringLiteral("version")).toInt(-1);
    if (version > formatVersion) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 was written by a newer PKM Studio (format "
                                                          "version %2; this version reads up to %3).")
                                       .arg(origin, numberText(version), numberText(formatVersion)));
    }
    if (version < 1)
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 has no valid format version.").arg(origin));
    // Older versions are read by the same code: see formatVersion for what each one changed.

    const QString kindId = root.value(QStringLiteral("mechanism")).toString();
    if (!findMechanismKind(kindId.toStdString()))
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 names an unknown mechanism kind '%2'.").arg(origin, quoted(kindId)));
    auto defaults = createMechanism(kindId.toStdString(), {});
    if (!defaults)
        return defaults.failure();

    ParameterSet values;
    const QJsonObject parameters = root.value(QStringLiteral("parameters")).toObject();
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        const ParameterInfo *info = findParameter(**defaults, it.key());
        if (!info)
            return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: unknown parameter '%2'.").arg(origin, quoted(it.key())));
        if (it.value().isString()) {
            // a mode given by its name ("mode": "X")
            const std::string word = it.value().toString().toStdString();
            const auto choice = std::find_if(info->choices.begin(), info->choices.end(),
                                             [&](const auto &c) { return c.first == word; });
            if (choice == info->choices.end()) {
                QStringList names;
                for (const auto &c : info->choices)
                    names << QString::fromStdString(c.first);
                return fileFailure(origin, names.isEmpty()
                                               ? QCoreApplication::translate("pkm::designfile", "%1: parameter '%2' is not a number.").arg(origin, quoted(it.key()))
                                               : QCoreApplication::translate("pkm::designfile", "%1: parameter '%2' must be a number or one of %3, not '%4'.")
                                                     .arg(origin, quoted(it.key()), names.join(QStringLiteral(", ")),
                                                          quoted(it.value().toString())));
            }
            values[info->name] = choice->second;
            continue;
        }
        if (!it.value().isDouble())
            return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: parameter '%2' is not a number.").arg(origin, quoted(it.key())));
        values[info->name] = info->unit.fromDisplay(it.value().toDouble());
    }
    auto mechanism = createMechanism(kindId.toStdString(), values);
    if (!mechanism) {
        Failure f = mechanism.failure();
        f.message = origin.toStdString() + ": " + f.message;
        return f;
    }

    Design design;
    design.id = root.value(QStringLiteral("id")).toString();
    design.title = root.value(QStringLiteral("title")).toString();
    design.description = root.value(QStringLiteral("description")).toString();
    if (design.title.size() > maxTextLength) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: the title is longer than %2 "
                                                                                 "characters, the most a design keeps.")
                                       .arg(origin, numberText(maxTextLength)));
    }
    if (design.description.size() > maxTextLength) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: the description is longer than %2 "
                                                                                 "characters, the most a design keeps.")
                                       .arg(origin, numberText(maxTextLength)));
    }
    design.mechanism = *mechanism;
    design.pose = design.mechanism->homePose();

    QList<QPair<QString, double>> pose;
    const QJsonObject poseObject = root.value(QStringLiteral("pose")).toObject();
    for (auto it = poseObject.begin(); it != poseObject.end(); ++it) {
        if (!it.value().isDouble())
            return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: pose value '%2' is not a number.").arg(origin, quoted(it.key())));
        pose.append({it.key(), it.value().toDouble()});
    }
    if (!pose.isEmpty()) {
        auto solved = solveSavedPose(*design.mechanism, design.pose, pose);
        if (!solved) {
            Failure f = solved.failure();
            f.message = origin.toStdString() + ": " + f.message;
            return f;
        }
        design.pose = *solved;
    }
    // Bookmarks are read as they are: one that no longer solves (the file was edited by hand)
    // says so when it is chosen, rather than refusing the whole design.
    const QJsonValue bookmarks = root.value(QStringLiteral("bookmarks"));
    if (!bookmarks.isUndefined() && !bookmarks.isArray())
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: “bookmarks” is not a list.").arg(origin));
    if (bookmarks.toArray().size() > maxBookmarks) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 has more than %2 bookmarks.")
                                       .arg(origin, numberText(maxBookmarks)));
    }
    for (const QJsonValue &entry : bookmarks.toArray()) {
        const QJsonObject object = entry.toObject();
        Bookmark bookmark;
        bookmark.name = object.value(QStringLiteral("name")).toString();
        if (bookmark.name.size() > maxBookmarkName) {
            return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: a bookmark's name is longer than %2 characters.")
                                           .arg(origin, numberText(maxBookmarkName)));
        }
        const QJsonObject values = object.value(QStringLiteral("pose")).toObject();
        for (auto it = values.begin(); it != values.end(); ++it) {
            if (!it.value().isDouble() || design.mechanism->variableIndex(it.key().toStdString()) < 0) {
                return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: bookmark “%2” has an invalid pose value '%3'.")
                                               .arg(origin, quoted(bookmark.name), quoted(it.key())));
            }
            bookmark.pose.append({it.key(), it.value().toDouble()});
        }
        design.bookmarks.append(bookmark);
    }
    auto tolerances = parseTolerances(*design.mechanism, root.value(QStringLiteral("tolerances")), origin);
    if (!tolerances)
        return tolerances.failure();
    design.tolerances = *tolerances;
    auto requirements = parseRequirements(*design.mechanism, root.value(QStringLiteral("requirements")), origin);
    if (!requirements)
        return requirements.failure();
    design.requirements = std::move(*requirements);
    return design;
}
} // namespace

Result<ParameterSet> parseTolerances(const Mechanism &mechanism, const QJsonValue &value, const QString &origin)
{
    ParameterSet tolerances;
    if (value.isUndefined())
        return tolerances;
    if (!value.isObject())
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1: “tolerances” is not an object.").arg(origin));
    const QJsonObject object = value.toObject();
    if (object.size() > tolerance::maxTolerances) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "%1 has more than %2 tolerances.")
                                       .arg(origin, numberText(tolerance::maxTolerances)));
    }
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string name = it.key().toStdString();
        const ParameterInfo *info = mechanism.findParameter(name);
        if (!it.value().isDouble() || !info) {
            auto checked = tolerance::checkParameter(mechanism, name);
            const QString why = checked ? QCoreApplication::translate("pkm::designfile", "it is not a number")
                                        : QString::fromStdString(checked.failure().message);
            return fileFailure(it.key(), QCoreApplication::translate("pkm::designfile", "%1: the tolerance of '%2' is refused: %3")
                                             .arg(origin, quoted(it.key()), why));
        }
        auto checked = tolerance::checkTolerance(mechanism, name, info->unit.fromDisplay(it.value().toDouble()));
        if (!checked) {
            return fileFailure(it.key(), QCoreApplication::translate("pkm::designfile", "%1: the tolerance of '%2' is refused: %3")
                                             .arg(origin, quoted(it.key()), QString::fromStdString(checked.failure().message)));
        }
        tolerances[name] = *checked;
    }
    return tolerances;
}

bool isPresetId(const QString &presetOrPath)
{
    return !presetOrPath.contains(QLatin1Char('/')) && !presetOrPath.endsWith(QLatin1String(".json"));
}

Result<Design> load(const QString &presetOrPath)
{
    QString path = presetOrPath;
    if (isPresetId(presetOrPath)) {
        path = presetPath(presetOrPath);
        if (!QFile::exists(path)) {
            return fileFailure(presetOrPath,
                               QCoreApplication::translate("pkm::designfile", "'%1' is neither a preset id (see 'pkm list') nor a design file.")
                                   .arg(presetOrPath));
        }
    }
    const auto bytes = readFile(path, presetOrPath);
    if (!bytes)
        return bytes.failure();
    return parse(*bytes, presetOrPath);
}

Result<QByteArray> readFile(const QString &path, const QString &origin)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile", "Cannot open %1: %2.").arg(origin, file.errorString()));
    // one byte past the limit tells a file that is too large, whatever size() says (0 for
    // /dev/zero and pipes)
    QByteArray bytes = file.read(maxFileBytes + 1);
    if (bytes.size() > maxFileBytes) {
        return fileFailure(origin, QCoreApplication::translate("pkm::designfile",
                                                               "%1 is larger than %2 MiB, the most a design file may be.")
                                       .arg(origin, numberText(double(maxFileBytes) / double(1 << 20))));
    }
    return bytes;
}

QByteArray serialize(const Design &design)
{
    QJsonObject root;
    root.insert(QStringLiteral("format"), QLatin1String(formatName));
    root.insert(QStringLiteral("version"), formatVersion);
    if (!design.id.isEmpty())
        root.insert(QStringLiteral("id"), design.id);
    root.insert(QStringLiteral("title"), design.title);
    if (!design.description.isEmpty())
        root.insert(QStringLiteral("description"), design.description);
    root.insert(QStringLiteral("mechanism"), toQString(design.mechanism->kind()));

    // Display values at 15 significant digits: 60° kept in radians comes back as
    // 59.99999999999999, which a person reading the file should see as the 60 they typed. The
    // value read back differs from the one saved by less than 10⁻¹⁵ of it.
    auto shown = [](double display) { return std::isfinite(display) ? QString::number(display, 'g', 15).toDouble() : display; };
    QJsonObject parameters;
    const ParameterSet values = design.mechanism->parameters();
    for (const ParameterInfo &info : design.mechanism->parameterInfo()) {
        if (info.stored)
            parameters.insert(toQString(info.name), shown(info.unit.toDisplay(values.at(info.name))));
    }
    root.insert(QStringLiteral("parameters"), parameters);

    // Every joint variable: the inputs fix the pose (direct kinematics is unique once the
    // design's modes are given), the outputs are there for the reader and are checked on load.
    QJsonObject pose;
    const auto &variables = design.mechanism->variableInfo();
    for (int i = 0; i < static_cast<int>(variables.size()); ++i) {
        pose.insert(toQString(variables[i].name),
                    shown(variables[i].unit.toDisplay(design.mechanism->variableValue(design.pose, i))));
    }
    root.insert(QStringLiteral("pose"), pose);
    if (!design.bookmarks.isEmpty()) {
        QJsonArray bookmarks;
        for (const Bookmark &bookmark : design.bookmarks) {
            QJsonObject values;
            for (const auto &[name, value] : bookmark.pose)
                values.insert(name, shown(value));
            bookmarks.append(QJsonObject {{QStringLiteral("name"), bookmark.name}, {QStringLiteral("pose"), values}});
        }
        root.insert(QStringLiteral("bookmarks"), bookmarks);
    }
    if (!design.tolerances.empty()) {
        QJsonObject tolerances;
        for (const auto &[name, value] : design.tolerances) {
            if (const ParameterInfo *info = design.mechanism->findParameter(name))
                tolerances.insert(toQString(name), shown(info->unit.toDisplay(value)));
        }
        root.insert(QStringLiteral("tolerances"), tolerances);
    }
    if (!design.requirements.empty()) {
        QJsonArray requirements;
        for (const capability::Requirement &requirement : design.requirements)
            requirements.append(requirementText(*design.mechanism, requirement));
        root.insert(QStringLiteral("requirements"), requirements);
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Result<bool> save(const Design &design, const QString &path)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fileFailure(path, QCoreApplication::translate("pkm::designfile", "Cannot write %1: %2.").arg(path, file.errorString()));
    file.write(serialize(design));
    if (!file.commit())
        return fileFailure(path, QCoreApplication::translate("pkm::designfile", "Cannot write %1: %2.").arg(path, file.errorString()));
    return true;
}

QList<PresetInfo> presets()
{
    QList<PresetInfo> list;
    const QStringList files = QDir(QStringLiteral(":/presets")).entryList({QStringLiteral("*.pkm.json")}, QDir::Files,
                                                                           QDir::Name);
    for (const QString &name : files) {
        QFile file(QStringLiteral(":/presets/") + name);
        if (!file.open(QIODevice::ReadOnly))
            continue;
        const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
        list.append({root.value(QStringLiteral("id")).toString(), root.value(QStringLiteral("mechanism")).toString(),
                     root.value(QStringLiteral("title")).toString(), root.value(QStringLiteral("description")).toString()});
    }
    return list;
}

QString presetText(const QString &english)
{
    if (english.isEmpty())
        return english;
    const QByteArray source = english.toUtf8();
    return QCoreApplication::translate("presets", source.constData());
}

Result<MechanismPtr> setDisplayParameter(const MechanismPtr &mechanism, const QString &name, double displayValue)
{
    const ParameterInfo *info = findParameter(*mechanism, name);
    if (!info) {
        return Failure{FailureKind::UnknownName, name.toStdString(),
                       QCoreApplication::translate("pkm::designfile", "Unknown parameter '%1' (see 'pkm show').")
                           .arg(name)
                           .toStdString()};
    }
    return mechanism->withParameter(info->name, info->unit.fromDisplay(displayValue));
}

} // namespace designfile
} // namespace pkm
