#include "gui/player.h"

#include "document/document.h"
#include "quantityformat.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pkm {

namespace {

Singularity singularityAt(const Mechanism &mechanism, const Pose &pose)
{
    std::vector<double> values(mechanism.reportLayout().size);
    return mechanism.evaluate(pose, values);
}

QString singularName(SingularityType type)
{
    switch (type) {
    case SingularityType::Inverse:
        return Player::tr("inverse");
    case SingularityType::Direct:
        return Player::tr("direct");
    case SingularityType::Combined:
        return Player::tr("combined");
    case SingularityType::None:
        break;
    }
    return {};
}

} // namespace

Player::Player(Document *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
{
    m_timer.setInterval(1000 / framesPerSecond);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &Player::onTimer);
    // A new design (another preset, an undo) is a new lesson: Play does not carry on in it.
    connect(m_document, &Document::designChanged, this, &Player::stop);
}

double Player::stopMargin()
{
    // Where the status bar begins to warn of a nearby singular pose (document.cpp): Play stops
    // as the warning would appear, never on the singular pose itself.
    return 0.02;
}

bool Player::start(const PlaySettings &settings)
{
    const Mechanism &m = *m_document->mechanism();
    if (settings.variable < 0 || settings.variable >= static_cast<int>(m.variableInfo().size()))
        return false;
    const Interval range = m.variableRange(settings.variable);
    m_settings = settings;
    m_settings.from = range.clamp(std::min(settings.from, settings.to));
    m_settings.to = range.clamp(std::max(settings.from, settings.to));
    if (!(m_settings.to > m_settings.from) || !(settings.speed > 0.0) || !std::isfinite(settings.speed)) {
        const VariableInfo &info = m.variableInfo()[std::size_t(settings.variable)];
        emit stopped(tr("Play needs a range: “from” must be below “to” for %1, and the speed above 0.")
                         .arg(toQString(info.symbol)));
        return false;
    }
    // Outside its range the variable first goes to the range's nearer end.
    const double value = m.variableValue(m_document->pose(), settings.variable);
    if (value < m_settings.from - 1e-12 || value > m_settings.to + 1e-12) {
        const double entry = value < m_settings.from ? m_settings.from : m_settings.to;
        if (auto moved = m_document->setVariable(settings.variable, entry); !moved) {
            emit stopped(QString::fromStdString(moved.failure().message));
            return false;
        }
    }
    m_direction = value >= m_settings.to - 1e-12 ? -1.0 : 1.0;
    m_blockedLastStep = false;
    m_clock.start();
    m_timer.start();
    return true;
}

void Player::stop()
{
    m_timer.stop();
}

void Player::onTimer()
{
    // Real time: a slow repaint makes larger steps, not a slower mechanism. A stall (a dialog,
    // a suspended machine) does not make one huge jump.
    const double seconds = std::min(m_clock.restart() / 1000.0, 0.1);
    advance(seconds);
}

void Player::advance(double seconds)
{
    const MechanismPtr mechanism = m_document->mechanism();
    const Mechanism &m = *mechanism;
    const int variable = m_settings.variable;
    const Pose current = m_document->pose();
    const double value = m.variableValue(current, variable);
    double next = value + m_direction * m_settings.speed * seconds;
    const bool atEnd = m_direction > 0 ? next >= m_settings.to : next <= m_settings.from;
    if (atEnd)
        next = m_direction > 0 ? m_settings.to : m_settings.from;

    const VariableInfo &info = m.variableInfo()[std::size_t(variable)];
    // The crank of a one-input mechanism that turns fully passes its inverse singular poses:
    // there the output stands still and turns back (a crank-rocker's rocker at either end), and
    // the crank goes on in the same mode. Only a direct one, where the output is no longer
    // held, stops it. With more inputs such a pose is where a leg stretches and would go on in
    // its other working mode, which is the user's switch (the five-bar's crank stops there).
    const bool passesInverse = info.actuated && m.inputCount() == 1 && turnsFully(m, variable);
    const auto singularityOf = [&](const Pose &pose) {
        Singularity s = singularityAt(m, pose);
        if (passesInverse) {
            s.type = s.type == SingularityType::Combined ? SingularityType::Direct
                   : s.type == SingularityType::Inverse  ? SingularityType::None
                                                         : s.type;
            s.margin = s.directMargin;
        }
        return s;
    };
    const auto stoppedBefore = [&](SingularityType type, double at) {
        // One sentence each way: "Play turned back: Play stopped before …" said both.
        const QString symbol = toQString(info.symbol), where = formatQuantity(at, info.unit, info.decimals);
        if (type == SingularityType::None) // within the stop margin of one, of no class yet
            blocked(tr("Play stopped close to a singular pose at %1 = %2.").arg(symbol, where),
                    tr("Play turned back close to a singular pose at %1 = %2.").arg(symbol, where));
        else
            blocked(tr("Play stopped before a singular pose (%1) at %2 = %3.").arg(singularName(type), symbol, where),
                    tr("Play turned back before a singular pose (%1) at %2 = %3.").arg(singularName(type), symbol, where));
    };
    const auto ahead = m.solveWith(current, variable, next);
    if (!ahead) {
        // The mechanism ends within this step: where a leg stretches or folds (a singular
        // pose), or at a limit. Going as far as it goes would land on that singular pose, so go
        // as far as it stays clear of one (bisection), then say why.
        const auto clear = [&](double v, SingularityType *type) {
            const auto at = m.solveWith(current, variable, v);
            if (!at)
                return false;
            const Singularity s = singularityOf(*at);
            *type = s.type;
            return s.type == SingularityType::None && s.margin >= stopMargin();
        };
        double good = value, bad = next;
        SingularityType edge = SingularityType::None;
        for (int i = 0; i < 48 && std::abs(bad - good) > 1e-9 * (1.0 + std::abs(good)); ++i) {
            const double middle = 0.5 * (good + bad);
            SingularityType type = SingularityType::None;
            if (clear(middle, &type))
                good = middle;
            else {
                bad = middle;
                edge = type;
            }
        }
        if (good != value)
            m_document->setVariable(variable, good);
        const Singularity here = singularityOf(m_document->pose());
        if (here.margin < 2.0 * stopMargin() || edge != SingularityType::None)
            stoppedBefore(edge, m.variableValue(m_document->pose(), variable));
        else
            blocked(QString::fromStdString(ahead.failure().message));
        return;
    }
    const Singularity there = singularityOf(*ahead);
    if (there.type != SingularityType::None
        || (there.margin < stopMargin() && there.margin < singularityOf(current).margin)) {
        stoppedBefore(there.type, value);
        return;
    }
    m_document->setVariable(variable, next);
    m_blockedLastStep = false;
    if (!atEnd)
        return;
    switch (m_settings.mode) {
    case PlayMode::Loop:
        // Back to the start: for a crank turning from 0° to 360° this is the same pose.
        if (auto restarted = m_document->setVariable(variable, m_direction > 0 ? m_settings.from : m_settings.to);
            !restarted) {
            stop();
            emit stopped(QString::fromStdString(restarted.failure().message));
        }
        break;
    case PlayMode::ForthAndBack:
        m_direction = -m_direction;
        break;
    case PlayMode::Once:
        stop();
        emit stopped(tr("Play reached the end of its range."));
        break;
    }
}

void Player::blocked(const QString &reason, const QString &turnedBack)
{
    // Forth and back turns at what blocks it, unless it was blocked right after turning:
    // then both ways are closed and it stops.
    if (m_settings.mode == PlayMode::ForthAndBack && !m_blockedLastStep) {
        m_direction = -m_direction;
        m_blockedLastStep = true;
        emit turned(turnedBack.isEmpty() ? tr("Play turned back: %1").arg(reason) : turnedBack);
        return;
    }
    stop();
    emit stopped(reason);
}

} // namespace pkm
