#pragma once
/// Play: moves one joint variable by itself through the document, in real time (the speed is
/// per second of the clock, whatever a repaint costs), so that the plots' cursors, the map's
/// marker and the 3D view follow as they follow a slider. Like the O-X glide's crossing
/// animation it never runs into trouble: it stops (or, forth and back, turns) at a limit the
/// pose cannot pass and *before* a singular pose, and says why.

#include "playbar.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

namespace pkm {

class Document;

class Player : public QObject
{
    Q_OBJECT

public:
    explicit Player(Document *document, QObject *parent = nullptr);

    /// Starts from the current pose; false (and `message` says why) if the settings cannot play.
    bool start(const PlaySettings &settings);
    /// Stops without a message (the user's Pause, a new design).
    void stop();
    bool isPlaying() const { return m_timer.isActive(); }
    /// One step of `seconds` of play (the timer calls it with the time since the last frame;
    /// tests call it directly).
    void advance(double seconds);

    /// Frames per second the timer asks for.
    static constexpr int framesPerSecond = 30;
    /// A step whose pose has a singularity margin below this (and falling) is not taken.
    static double stopMargin();

signals:
    /// Play stopped by itself (a limit, a singular pose ahead, the end of a single run): why.
    void stopped(const QString &reason);
    /// Forth and back turned at a limit or before a singular pose: why.
    void turned(const QString &reason);

private:
    void onTimer();
    /// The pose ahead cannot be taken: stop, saying `reason`, or, playing forth and back, turn,
    /// saying `turnedBack` (by default "Play turned back: `reason`").
    void blocked(const QString &reason, const QString &turnedBack = {});

    Document *m_document;
    PlaySettings m_settings;
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_direction = 1.0;
    bool m_blockedLastStep = false; ///< turned without moving since: a second block stops
};

} // namespace pkm
