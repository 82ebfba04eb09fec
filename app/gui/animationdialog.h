#pragma once
/// File → Export Animation: an animated GIF, an MP4 (H.264) or a WebM video; which pose
/// variable to sweep, over what range, in how many frames and at what size. The file is drawn
/// (and a video encoded, frame by frame) off the GUI thread, with a progress bar and Cancel.

#include "export/animation.h"

#include <QDialog>

#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QFormLayout;
class QSpinBox;
class QCustomPlot;

namespace pkm {

class KindPanel;

class AnimationDialog : public QDialog
{
    Q_OBJECT

public:
    /// Offers `mechanism`'s pose variables, starting with `variable` over its whole range.
    AnimationDialog(const Mechanism &mechanism, int variable, QWidget *parent = nullptr);

    /// The choices, in core units.
    AnimationSettings settings() const;

    QComboBox *variableBox() const { return m_variable; }
    QDoubleSpinBox *fromBox() const { return m_from; }
    QDoubleSpinBox *toBox() const { return m_to; }
    QSpinBox *framesBox() const { return m_frames; }
    QComboBox *formatBox() const { return m_format; }
    QComboBox *sizeBox() const { return m_size; }

    /// The chosen format's file extension: "gif", "mp4" or "webm".
    QString fileExtension() const;

    /// The pose the animation starts from: the range offered is then what the mechanism sweeps
    /// from it (animationRange), not the variable's whole range.
    void setStart(const Pose &pose);
    /// The format, frames, frame time, size and forth-and-back of the last export, kept
    /// between runs (the range belongs to the design and is offered afresh).
    void restoreChoices();
    void rememberChoices() const;
    /// Offers the plot on screen, titled `title`, beside the view (none when empty).
    void setShownPlot(const QString &title);
    QComboBox *besideBox() const { return m_beside; }
    /// What goes beside the view: nothing (empty), the plot on screen (shownPlotChoice()) or
    /// the name of a quantity plotted against the moved variable (animationplot.h).
    QString besideChoice() const;
    static QString shownPlotChoice() { return QStringLiteral("@shown"); }

protected:
    /// A new language: labels, lists and units again, the choices kept.
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void selectVariable(int variable);
    /// The unit after the range's values, in the current language.
    void showRangeUnit();
    void setRowLabel(QWidget *field, const QString &text);
    /// The sizes the format offers (a video's are even, 720p and 1080p); the speed is a GIF's.
    void selectFormat();
    void showSizes();
    /// The choices beside the view for the moved variable, the one chosen kept where it can be.
    void fillBeside();

    const Mechanism &m_mechanism;
    std::optional<Pose> m_start;
    QFormLayout *m_form = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QComboBox *m_format = nullptr;
    QComboBox *m_variable = nullptr;
    QDoubleSpinBox *m_from = nullptr;
    QDoubleSpinBox *m_to = nullptr;
    QSpinBox *m_frames = nullptr;
    QComboBox *m_size = nullptr;
    QSpinBox *m_frameTime = nullptr;
    QCheckBox *m_bounce = nullptr;
    QComboBox *m_beside = nullptr;
    QString m_shownPlot;
};

/// Asks where to write the animation: a file name ending in .gif, .mp4 or .webm (`extension`
/// added when the name has none of them); empty when the user cancels.
QString chooseAnimationPath(QWidget *parent, const QString &baseName, const QString &extension);

/// Draws the animation off the GUI thread (a progress dialog offers to cancel) and writes it to
/// `path` atomically — an animated GIF, or a video when `path` ends in .mp4 or .webm, encoded
/// one frame at a time; cancelling leaves no file. `done` gets the message for the status bar
/// and whether it is an error.
void exportAnimation(QWidget *parent, MechanismPtr mechanism, const Pose &pose, const AnimationSettings &settings,
                     const QString &path, const std::function<void(const QString &, bool)> &done);

/// The pictures of `plot`, a plot or map on screen, for the frames beside the view
/// (AnimationSettings::beside): called from the thread that draws the frames, each is made on
/// the GUI thread, `panel` given the frame's pose first so that its cursors and markers follow.
/// The panel is given its pose back by the caller when the export ends. A plot closed meanwhile
/// leaves the frames' right half blank.
std::function<QImage(const Pose &, const QSize &)> shownPlotPictures(KindPanel *panel, QCustomPlot *plot);

} // namespace pkm
