#include "playbar.h"

#include "quantityformat.h"
#include "symboltext.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace pkm {

PlayBar::PlayBar(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("playButton"));
    m_play->setCheckable(true);
    m_play->setToolButtonStyle(Qt::ToolButtonTextOnly);
    connect(m_play, &QToolButton::clicked, this, [this](bool checked) { emit playRequested(checked); });
    m_variable = new SymbolComboBox(this);
    m_variable->setObjectName(QStringLiteral("playVariable"));
    m_variable->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    connect(m_variable, &QComboBox::currentIndexChanged, this, [this] {
        describeVariable();
        resetRange();
    });
    const auto spinBox = [this](const char *name) {
        auto *box = new NumberSpinBox(this);
        box->setObjectName(QLatin1String(name));
        box->setKeyboardTracking(false);
        box->setAlignment(Qt::AlignRight);
        return box;
    };
    m_fromLabel = new QLabel(this);
    m_from = spinBox("playFrom");
    m_toLabel = new QLabel(this);
    m_to = spinBox("playTo");
    m_speedLabel = new QLabel(this);
    m_speed = spinBox("playSpeed");
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("playMode"));
    m_mode->setSizeAdjustPolicy(QComboBox::AdjustToContents); // the new language's words fit
    m_mode->addItems({QString(), QString(), QString()});
    m_mode->setCurrentIndex(static_cast<int>(PlayMode::ForthAndBack));
    for (QWidget *widget : std::initializer_list<QWidget *> {m_play, m_variable, m_fromLabel, m_from,
                                                              m_toLabel, m_to, m_speedLabel, m_speed, m_mode})
        layout->addWidget(widget);
    layout->addStretch(1);
    retranslate();
}

void PlayBar::setCompact(bool compact)
{
    for (QWidget *widget : std::initializer_list<QWidget *> {m_fromLabel, m_from, m_toLabel, m_to})
        widget->setVisible(!compact);
}

void PlayBar::setMechanism(const MechanismPtr &mechanism)
{
    const bool sameKind = m_mechanism && mechanism && m_mechanism->kind() == mechanism->kind();
    const int previous = m_variable->currentIndex();
    m_mechanism = mechanism;
    const QSignalBlocker blocker(m_variable);
    m_variable->clear();
    const auto &variables = mechanism->variableInfo();
    for (const VariableInfo &info : variables)
        m_variable->addItem(toQString(info.symbol));
    // A new kind starts on its first input: what a teacher would move first.
    const int chosen = sameKind && previous >= 0 && previous < m_variable->count() ? previous : 0;
    m_variable->setCurrentIndex(chosen);
    const PlaySettings kept = settings();
    describeVariable();
    // A design edit keeps the range the teacher chose, cut to what the new design can move
    // through. Where almost nothing of it is left (another preset of the kind, a 1 m study
    // after the 170 mm prototype) the bar starts afresh: the whole range and its speed, not a
    // range of one point.
    const Interval now = sameKind ? mechanism->variableRange(chosen) : Interval{};
    const double lo = std::max(std::min(kept.from, kept.to), now.min);
    const double hi = std::min(std::max(kept.from, kept.to), now.max);
    if (!sameKind || !(hi - lo > 0.01 * (now.max - now.min)))
        resetRange();
    else
        setRange(kept.from < kept.to ? lo : hi, kept.from < kept.to ? hi : lo);
    // An edit that stops the crank turning fully (a crank-rocker made a double rocker) ends
    // its loop; otherwise the teacher's mode stays.
    if (kept.mode == PlayMode::Loop && !suitsLoop())
        m_mode->setCurrentIndex(static_cast<int>(PlayMode::ForthAndBack));
}

PlaySettings PlayBar::settings() const
{
    PlaySettings settings;
    settings.variable = std::max(0, m_variable->currentIndex());
    settings.mode = static_cast<PlayMode>(m_mode->currentIndex());
    if (!m_mechanism)
        return settings;
    const Unit &unit = m_mechanism->variableInfo()[std::size_t(settings.variable)].unit;
    settings.from = unit.fromDisplay(m_from->value());
    settings.to = unit.fromDisplay(m_to->value());
    settings.speed = unit.fromDisplay(m_speed->value());
    return settings;
}

void PlayBar::setVariable(int variable)
{
    m_variable->setCurrentIndex(variable); // describes it and resets its range
}

void PlayBar::setRange(double from, double to)
{
    if (!m_mechanism)
        return;
    const Unit &unit = m_mechanism->variableInfo()[std::size_t(std::max(0, m_variable->currentIndex()))].unit;
    m_from->setValue(unit.toDisplay(from));
    m_to->setValue(unit.toDisplay(to));
}

void PlayBar::setSpeed(double coreUnitsPerSecond)
{
    if (!m_mechanism)
        return;
    const Unit &unit = m_mechanism->variableInfo()[std::size_t(std::max(0, m_variable->currentIndex()))].unit;
    m_speed->setValue(unit.toDisplay(coreUnitsPerSecond));
}

void PlayBar::setMode(PlayMode mode)
{
    m_mode->setCurrentIndex(static_cast<int>(mode));
}

void PlayBar::setPlaying(bool playing)
{
    m_playing = playing;
    m_play->setChecked(playing);
    // The symbols say it in every language; the word helps a first-time user. The button
    // keeps the width of the longer of its two texts, so that the bar does not shift as it
    // turns from Play to Pause under the teacher's pointer.
    const QString play = QStringLiteral("▶ ") + tr("Play"), pause = QStringLiteral("❚❚ ") + tr("Pause");
    m_play->setMinimumWidth(0);
    int width = 0;
    for (const QString &text : {play, pause}) {
        m_play->setText(text);
        width = std::max(width, m_play->sizeHint().width());
    }
    m_play->setMinimumWidth(width);
    m_play->setText(playing ? pause : play);
}

void PlayBar::describeVariable()
{
    if (!m_mechanism || m_variable->currentIndex() < 0)
        return;
    const int i = m_variable->currentIndex();
    const VariableInfo &info = m_mechanism->variableInfo()[std::size_t(i)];
    const Interval range = m_mechanism->variableRange(i);
    const QString unit = unitText(info.unit);
    const QString suffix = unit.startsWith(QChar(0x00B0)) ? unit : QLatin1Char(' ') + unit;
    const double lo = info.unit.toDisplay(range.min), hi = info.unit.toDisplay(range.max);
    const double scale = std::pow(10.0, info.decimals);
    for (QDoubleSpinBox *box : {m_from, m_to}) {
        box->setDecimals(info.decimals);
        // outwards to the decimals shown, so that the exact limit stays reachable
        box->setRange(std::floor(lo * scale) / scale, std::ceil(hi * scale) / scale);
        box->setSuffix(suffix);
        box->setSingleStep(std::pow(10.0, std::floor(std::log10(std::max(hi - lo, 1e-9))) - 1));
    }
    m_speed->setDecimals(info.decimals);
    m_speed->setRange(std::pow(10.0, -info.decimals), std::max(1.0, 10.0 * (hi - lo)));
    m_speed->setSuffix(suffix + tr("/s"));
    m_speed->setSingleStep(std::pow(10.0, std::floor(std::log10(std::max(hi - lo, 1e-9))) - 1));
    m_variable->setToolTip(coreLabel(info.label));
}

void PlayBar::resetRange()
{
    if (!m_mechanism || m_variable->currentIndex() < 0)
        return;
    const int i = m_variable->currentIndex();
    const Interval range = m_mechanism->variableRange(i);
    setRange(range.min, range.max);
    // The whole range in about five seconds: slow enough to follow on a projector.
    setSpeed((range.max - range.min) / 5.0);
    // A crank that turns fully loops, as its motor turns it; anything else goes forth and back.
    // Once stays as the teacher chose it.
    if (m_mode->currentIndex() != static_cast<int>(PlayMode::Once))
        m_mode->setCurrentIndex(static_cast<int>(suitsLoop() ? PlayMode::Loop : PlayMode::ForthAndBack));
}

bool PlayBar::suitsLoop() const
{
    // The only input, over a whole turn: a crank-rocker's crank. A loop of anything else would
    // jump from the end of a stroke back to its start, and a 2-DOF mechanism's crank that may
    // turn on its own meets the other leg's limits on the way.
    if (!m_mechanism || m_variable->currentIndex() < 0)
        return false;
    const auto &variables = m_mechanism->variableInfo();
    const auto inputs = std::count_if(variables.begin(), variables.end(),
                                      [](const VariableInfo &info) { return info.actuated; });
    const int i = m_variable->currentIndex();
    return inputs == 1 && variables[std::size_t(i)].actuated && pkm::turnsFully(*m_mechanism, i);
}

void PlayBar::retranslate()
{
    setPlaying(m_playing);
    m_play->setToolTip(tr("Play: move the chosen joint variable by itself (stops at a limit or before a singular pose)"));
    m_fromLabel->setText(tr("from"));
    m_toLabel->setText(tr("to"));
    m_speedLabel->setText(tr("speed"));
    m_mode->setItemText(static_cast<int>(PlayMode::Loop), tr("Loop"));
    m_mode->setItemText(static_cast<int>(PlayMode::ForthAndBack), tr("Forth and back"));
    m_mode->setItemText(static_cast<int>(PlayMode::Once), tr("Once"));
    m_mode->setToolTip(tr("At the end of the range: start again, turn back, or stop"));
    if (m_mechanism)
        describeVariable();
}

void PlayBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::FontChange) // the text size of presentation mode
        setPlaying(m_playing);
    QWidget::changeEvent(event);
}

} // namespace pkm
