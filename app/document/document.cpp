#include "document/document.h"

#include "document/commands.h"
#include "quantityformat.h"
#include "text.h"
#include "tolerance.h"

#include <QCoreApplication>
#include <QEvent>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
/// Below this singularity margin the status bar warns that the pose is nearly singular.
constexpr double statusNearSingularMargin = 0.02;
} // namespace

Document::Document(QObject *parent)
    : QObject(parent)
{
    auto initial = designfile::load(QStringLiteral("pjoint-prototype"));
    Q_ASSERT(initial.ok());
    m_design = *initial;
    m_modeNeighbours = m_design.mechanism->modeNeighbours();
    if (QCoreApplication *application = QCoreApplication::instance())
        application->installEventFilter(this);
}

bool Document::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && watched == QCoreApplication::instance()) {
        for (int i = 0; i < m_undoStack.count(); ++i) {
            // the stack hands out const commands; their texts are ours to set
            if (auto *command = dynamic_cast<TranslatableCommand *>(const_cast<QUndoCommand *>(m_undoStack.command(i))))
                command->retranslate();
        }
    }
    return QObject::eventFilter(watched, event);
}

Result<bool> Document::open(const QString &presetOrPath)
{
    auto loaded = designfile::load(presetOrPath);
    if (!loaded)
        return loaded.failure();
    const QString title = loaded->title.isEmpty() ? presetOrPath : loaded->title;
    m_undoStack.push(new ReplaceDesignCommand(this, m_design, *loaded,
                                              [title] { return tr("Open %1").arg(designfile::presetText(title)); }));
    return true;
}

Result<bool> Document::openTemplate(const QString &presetId)
{
    auto loaded = designfile::load(presetId);
    if (!loaded)
        return loaded.failure();
    loaded->id.clear(); // the user's design from now on, not the preset
    const QString title = loaded->title;
    m_undoStack.push(new ReplaceDesignCommand(this, m_design, *loaded, [title] {
        return tr("New design from template %1").arg(designfile::presetText(title));
    }));
    return true;
}

Result<bool> Document::setParameters(const ParameterSet &changes, const QString &mergeKey, bool continuous,
                                     std::function<QString()> text)
{
    auto changed = m_design.mechanism->withParameters(changes);
    if (!changed)
        return changed.failure();
    Design next = m_design;
    next.mechanism = *changed;
    next.pose = carryPose(*next.mechanism, m_design.pose);
    if (next.mechanism->parameters() == m_design.mechanism->parameters())
        return true;
    auto *command = new SetParameterCommand(this, mergeKey, m_design, next, continuous);
    command->setTextMaker(std::move(text));
    m_undoStack.push(command);
    return true;
}

Result<bool> Document::setParameter(const QString &name, double displayValue, bool continuous)
{
    auto changed = designfile::setDisplayParameter(m_design.mechanism, name, displayValue);
    if (!changed)
        return changed.failure();
    Design next = m_design;
    next.mechanism = *changed;
    next.pose = carryPose(*next.mechanism, m_design.pose);
    if (next.mechanism->parameters() == m_design.mechanism->parameters())
        return true;
    m_undoStack.push(new SetParameterCommand(this, name, m_design, next, continuous));
    return true;
}

template <class Solve>
Result<Pose> Document::moveTowards(const Solve &solveAt)
{
    m_lastMoveWasPartial = false;
    auto solved = solveAt(1.0);
    if (solved) {
        applyPose(*solved);
        return solved;
    }
    // Stop at the last reachable pose on the way rather than short of it: bisect the move.
    double reachable = 0.0, unreachable = 1.0;
    Result<Pose> best = Failure{FailureKind::Unreachable, {}, {}};
    for (int i = 0; i < 30; ++i) {
        const double t = 0.5 * (reachable + unreachable);
        if (auto at = solveAt(t)) {
            reachable = t;
            best = at;
        } else {
            unreachable = t;
        }
    }
    if (best) {
        m_lastMoveWasPartial = true;
        applyPose(*best);
    }
    return solved;
}

Result<Pose> Document::setVariable(int variable, double value)
{
    const Mechanism &m = *m_design.mechanism;
    const Interval range = m.variableRange(variable);
    m_drivenVariable = variable;
    if (!std::isfinite(value))
        return m.solveWith(m_design.pose, variable, value);
    const Pose start = m_design.pose;
    const double from = m.variableValue(start, variable);
    const double to = range.clamp(value);
    return moveTowards([&](double t) { return m.solveWith(start, variable, from + t * (to - from)); });
}

Result<Pose> Document::dragHandle(int handle, const Eigen::Vector2d &target)
{
    const Mechanism &m = *m_design.mechanism;
    m_drivenVariable = m.inputCount(); // a drag moves the outputs
    const Pose start = m_design.pose;
    const Scene scene = m.scene(start);
    if (handle < 0 || handle >= static_cast<int>(scene.handles.size()))
        return m.dragHandle(start, handle, target);
    if (const SceneHandle &point = scene.handles[std::size_t(handle)]; point.editsDesign()) {
        const Eigen::Vector2d p = point.designPoint(target);
        const QString name = toQString(scene.joints[std::size_t(point.joint)].label);
        auto moved = setParameters({{point.xParameter, p.x()}, {point.yParameter, p.y()}},
                                   toQString(point.xParameter) + QLatin1Char('+') + toQString(point.yParameter),
                                   !m_dragStarts, [name] { return tr("Move %1").arg(name); });
        if (!moved)
            return moved.failure();
        m_dragStarts = false;
        return m_design.pose;
    }
    const Eigen::Vector2d from = scene.joints[scene.handles[handle].joint].position.head<2>();
    return moveTowards([&](double t) { return m.dragHandle(start, handle, from + t * (target - from)); });
}

Result<Pose> Document::moveOutputsTo(const Coordinates &outputs)
{
    const Mechanism &m = *m_design.mechanism;
    m_drivenVariable = m.inputCount();
    const Pose start = m_design.pose;
    return moveTowards([&](double t) {
        const Coordinates x = start.outputs + t * (outputs - start.outputs);
        return m.solveInverse(x, &start);
    });
}

std::vector<ModeAlternative> Document::modeAlternatives() const
{
    return Mechanism::solveAlternatives(m_modeNeighbours, m_design.pose, m_design.mechanism.get());
}

Result<bool> Document::switchMode(const ModeAlternative &alternative)
{
    if (!alternative.mechanism || alternative.pose.inputs.size() != m_design.pose.inputs.size())
        return Failure{FailureKind::InvalidParameter, {}, tr("That mode is not available at this pose.").toStdString()};
    Design next = m_design;
    next.mechanism = alternative.mechanism;
    next.pose = alternative.pose;
    m_undoStack.push(new ReplaceDesignCommand(this, m_design, next, [label = alternative.label] {
        return tr("Switch to %1").arg(coreLabel(label));
    }));
    return true;
}

QString Document::limitNote() const
{
    const Mechanism &m = *m_design.mechanism;
    const auto &variables = m.variableInfo();
    const int count = static_cast<int>(variables.size());
    // Name the variable the user drives first: moving θ to its limit is about θ, not d.
    for (int n = 0; n < count; ++n) {
        const int i = (m_drivenVariable + n) % count;
        const VariableInfo &info = variables[i];
        const Interval range = m.variableRange(i);
        const double value = m.variableValue(m_design.pose, i);
        const double tolerance = 1e-9 * std::max({1.0, std::abs(range.min), std::abs(range.max)});
        // at a limit, not beyond it: an output's range may be an estimate that a pose passes
        // (the 3-RP̲R's x at another orientation), and it stops at nothing there
        const double beyond = 1e-6 * std::max({1.0, std::abs(range.min), std::abs(range.max)});
        const bool atMin = value <= range.min + tolerance && value >= range.min - beyond;
        const bool atMax = value >= range.max - tolerance && value <= range.max + beyond;
        // a crank that turns fully has no limit: 360° is 0° (the four-bar opened at α = 0°
        // said "α stops at its lower limit" although nothing had moved)
        if ((!atMin && !atMax) || turnsFully(m, i))
            continue;
        const QString symbol = toQString(info.symbol);
        const QString limit = formatQuantity(atMax ? range.max : range.min, info.unit, info.decimals);
        if (const std::string reason = m.rangeLimitReason(i, atMax); !reason.empty()) {
            return atMax ? tr("%1 stops at its upper limit %2: %3.").arg(symbol, limit, QString::fromStdString(reason))
                         : tr("%1 stops at its lower limit %2: %3.").arg(symbol, limit, QString::fromStdString(reason));
        }
        return atMax ? tr("%1 stops at its upper limit %2 (design range).").arg(symbol, limit)
                     : tr("%1 stops at its lower limit %2 (design range).").arg(symbol, limit);
    }
    std::vector<double> values(m.reportLayout().size);
    const Singularity singularity = m.evaluate(m_design.pose, values);
    switch (singularity.type) {
    case SingularityType::None:
        break;
    case SingularityType::Inverse:
        return tr("Singular pose (inverse): the mechanism cannot be driven here.");
    case SingularityType::Direct:
        return tr("Singular pose (direct): the mechanism cannot be driven here.");
    case SingularityType::Combined:
        return tr("Singular pose (combined): the mechanism cannot be driven here.");
    }
    if (singularity.margin < statusNearSingularMargin)
        return tr("Close to a singular pose: small input steps make large output jumps.");
    return {};
}

void Document::applyDesign(const Design &design)
{
    if (design.mechanism != m_design.mechanism)
        m_modeNeighbours = design.mechanism->modeNeighbours();
    m_design = design;
    emit designChanged();
}

Result<bool> Document::addBookmark(const QString &name)
{
    if (m_design.bookmarks.size() >= designfile::maxBookmarks) {
        return Failure{FailureKind::InvalidParameter, {},
                       tr("A design keeps at most %1 bookmarks: remove one first.").arg(designfile::maxBookmarks).toStdString()};
    }
    QList<Bookmark> after = m_design.bookmarks;
    after.append(designfile::bookmarkOf(*m_design.mechanism, m_design.pose, name.left(designfile::maxBookmarkName)));
    m_undoStack.push(new SetBookmarksCommand(this, m_design.bookmarks, after,
                                             [name] { return tr("Add bookmark “%1”").arg(name); }));
    return true;
}

Result<bool> Document::removeBookmark(int index)
{
    if (index < 0 || index >= m_design.bookmarks.size())
        return Failure{FailureKind::InvalidParameter, {}, tr("There is no bookmark %1.").arg(index + 1).toStdString()};
    QList<Bookmark> after = m_design.bookmarks;
    const QString name = after.takeAt(index).name;
    m_undoStack.push(new SetBookmarksCommand(this, m_design.bookmarks, after,
                                             [name] { return tr("Remove bookmark “%1”").arg(name); }));
    return true;
}

Result<Pose> Document::goToBookmark(int index)
{
    if (index < 0 || index >= m_design.bookmarks.size())
        return Failure{FailureKind::InvalidParameter, {}, tr("There is no bookmark %1.").arg(index + 1).toStdString()};
    const Bookmark &bookmark = m_design.bookmarks[index];
    // The inputs decide, the outputs must agree (as in a design file): a bookmark of another
    // assembly mode, or one the design has changed under, is refused rather than reached in
    // a pose it does not show.
    auto solved = designfile::solveSavedPose(*m_design.mechanism, m_design.pose, bookmark.pose);
    if (!solved) {
        Failure failure = solved.failure();
        failure.message = tr("Bookmark “%1”: %2").arg(bookmark.name, QString::fromStdString(failure.message)).toStdString();
        return failure;
    }
    m_drivenVariable = 0;
    applyPose(*solved);
    return solved;
}

Result<bool> Document::setTolerance(const QString &name, double value)
{
    const std::string key = name.toStdString();
    if (value != 0.0) {
        auto checked = tolerance::checkTolerance(*m_design.mechanism, key, value);
        if (!checked)
            return checked.failure();
    }
    ParameterSet after = m_design.tolerances;
    if (value == 0.0)
        after.erase(key);
    else
        after[key] = value;
    if (after == m_design.tolerances)
        return true;
    if (static_cast<int>(after.size()) > tolerance::maxTolerances) {
        return Failure{FailureKind::InvalidParameter, key,
                       tr("A design keeps at most %1 tolerances.").arg(tolerance::maxTolerances).toStdString()};
    }
    m_undoStack.push(new SetTolerancesCommand(this, m_design.tolerances, after,
                                              [name] { return tr("Change tolerance of %1").arg(name); }));
    return true;
}

void Document::clearTolerances()
{
    if (m_design.tolerances.empty())
        return;
    m_undoStack.push(new SetTolerancesCommand(this, m_design.tolerances, {}, [] { return tr("Clear tolerances"); }));
}

void Document::applyTolerances(const ParameterSet &tolerances)
{
    m_design.tolerances = tolerances;
    emit tolerancesChanged();
}

void Document::setRequirements(std::vector<capability::Requirement> requirements)
{
    if (requirements == m_design.requirements)
        return;
    m_undoStack.push(new SetRequirementsCommand(this, m_design.requirements, std::move(requirements),
                                                [] { return tr("Change requirements"); }));
}

void Document::applyRequirements(const std::vector<capability::Requirement> &requirements)
{
    m_design.requirements = requirements;
    emit requirementsChanged();
}

void Document::applyBookmarks(const QList<Bookmark> &bookmarks)
{
    m_design.bookmarks = bookmarks;
    emit bookmarksChanged();
}

void Document::applyPose(const Pose &pose)
{
    m_design.pose = pose;
    emit poseChanged();
}

Pose Document::carryPose(const Mechanism &mechanism, const Pose &old)
{
    // Keep the outputs (what the user looks at: θ, the platform) and let the inputs follow;
    // past a narrowed range, stop at the limit.
    // A design that gains or loses an output (a third leg and the platform's angle) keeps the
    // ones both have; a new one starts at 0.
    const int inputs = mechanism.inputCount();
    Coordinates outputs = Coordinates::Zero(mechanism.outputCount());
    for (int i = 0; i < std::min<int>(outputs.size(), old.outputs.size()); ++i)
        outputs[i] = old.outputs[i];
    for (int i = 0; i < outputs.size(); ++i)
        outputs[i] = mechanism.variableRange(inputs + i).clamp(outputs[i]);
    if (auto kept = mechanism.solveInverse(outputs, &old))
        return *kept;
    // Out of the new workspace: keep the actuators where they are, if the design allows.
    Coordinates actuators = old.inputs;
    if (actuators.size() != inputs)
        return mechanism.homePose();
    for (int i = 0; i < actuators.size(); ++i)
        actuators[i] = mechanism.variableRange(i).clamp(actuators[i]);
    if (auto kept = mechanism.solveDirect(actuators, &old))
        return *kept;
    return mechanism.homePose();
}

} // namespace pkm
