#pragma once
/// The controls of Play: which joint variable moves, over which range, how fast, and whether it
/// loops, goes forth and back or plays once. The bar only holds the choice; the main window's
/// player moves the document (it stops at a limit or before a singular pose and says why).

#include "mechanism.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace pkm {

enum class PlayMode { Loop, ForthAndBack, Once };

struct PlaySettings {
    int variable = 0;   ///< index into variableInfo()
    double from = 0.0;  ///< core units
    double to = 0.0;    ///< core units, > from
    double speed = 1.0; ///< core units per second, > 0
    PlayMode mode = PlayMode::ForthAndBack;
};

class PlayBar : public QWidget
{
    Q_OBJECT

public:
    explicit PlayBar(QWidget *parent = nullptr);

    /// Lists the mechanism's joint variables; a new kind starts on its first input with its
    /// whole range, a changed design of the same kind keeps the choice where it still fits.
    void setMechanism(const MechanismPtr &mechanism);
    PlaySettings settings() const;
    /// Chooses the variable to play (index into variableInfo()) with its whole range.
    void setVariable(int variable);
    void setRange(double from, double to);
    void setSpeed(double coreUnitsPerSecond);
    void setMode(PlayMode mode);
    /// Shows the button as Pause (playing) or Play.
    void setPlaying(bool playing);
    /// Without the range's fields (from, to), which keep their values: presentation mode,
    /// where at a large text size the whole bar in a longer language is wider than a
    /// 1280×720 projector and its combo boxes would be cut.
    void setCompact(bool compact);
    bool isPlaying() const { return m_playing; }

    QToolButton *playButton() const { return m_play; }
    QComboBox *variableBox() const { return m_variable; }
    QDoubleSpinBox *speedBox() const { return m_speed; }
    QComboBox *modeBox() const { return m_mode; }

signals:
    /// The user pressed Play (true) or Pause (false).
    void playRequested(bool play);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    /// Spin boxes' units, decimals and limits for the variable chosen now.
    void describeVariable();
    void resetRange();
    /// Whether the variable chosen now is a crank that turns fully (Loop suits it).
    bool suitsLoop() const;

    MechanismPtr m_mechanism;
    QToolButton *m_play = nullptr;
    QComboBox *m_variable = nullptr;
    QLabel *m_fromLabel = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QLabel *m_toLabel = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QLabel *m_speedLabel = nullptr;
    QDoubleSpinBox *m_speed = nullptr;
    QComboBox *m_mode = nullptr;
    bool m_playing = false;
};

} // namespace pkm
