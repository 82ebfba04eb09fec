// The design file's "requirements": what the actuators must deliver, as the strings
// `pkm workspace --require` takes ("force_worst >= 50", display units).

#include "designfile.h"
#include "text.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace pkm::designfile {

namespace {
/// A requirement is one short line: a longer string is refused before it is read.
constexpr qsizetype maxRequirementLength = 200;

Failure requirementFailure(const QString &message)
{
    // the message may quote the file's text (and its path): escaped, as designfile.cpp's are
    return Failure{FailureKind::InvalidParameter, "requirements", text::printable(message.toStdString(), 2000)};
}
} // namespace

Result<std::vector<capability::Requirement>> parseRequirements(const Mechanism &mechanism, const QJsonValue &value,
                                                               const QString &origin)
{
    std::vector<capability::Requirement> requirements;
    if (value.isUndefined())
        return requirements;
    if (!value.isArray())
        return requirementFailure(
            QCoreApplication::translate("pkm::designfile", "%1: “requirements” is not a list of texts.").arg(origin));
    const QJsonArray array = value.toArray();
    if (array.size() > maxRequirements) {
        return requirementFailure(
            QCoreApplication::translate("pkm::designfile", "%1: “requirements” has more than %2 entries.")
                .arg(origin)
                .arg(maxRequirements));
    }
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    for (const QJsonValue &item : array) {
        if (!item.isString() || item.toString().size() > maxRequirementLength) {
            return requirementFailure(
                QCoreApplication::translate("pkm::designfile",
                                            "%1: “requirements” holds an entry that is not a text of at most %2 characters.")
                    .arg(origin)
                    .arg(maxRequirementLength));
        }
        auto parsed = capability::parseRequirement(item.toString().toStdString(), actuators);
        if (!parsed)
            return requirementFailure(QCoreApplication::translate("pkm::designfile", "%1: “requirements”: %2")
                                          .arg(origin, QString::fromStdString(parsed.failure().message)));
        requirements.push_back(*parsed);
    }
    return requirements;
}

QString requirementText(const Mechanism &mechanism, const capability::Requirement &requirement)
{
    const ReportLayout *layout = capability::layoutFor(capability::actuatorsOf(mechanism));
    const ReportEntry *entry = layout ? layout->find(requirement.name) : nullptr;
    const double shown = entry ? entry->unit.toDisplay(requirement.value) : requirement.value;
    // at the 15 digits a file keeps, so that it reads back as the same requirement
    return QStringLiteral("%1 %2 %3")
        .arg(QString::fromStdString(requirement.name), requirement.atLeast ? QStringLiteral(">=") : QStringLiteral("<="),
             QString::number(shown, 'g', 15));
}

} // namespace pkm::designfile
