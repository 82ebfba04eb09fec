#pragma once
/// The document: one design and one pose, and the only writer of both. Widgets read it and ask
/// it for changes; every design change is an undoable command, pose moves are not (they are
/// the user exploring, not editing).

#include "document/designfile.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>

namespace pkm {

class Document : public QObject
{
    Q_OBJECT

public:
    explicit Document(QObject *parent = nullptr);

    const Design &design() const { return m_design; }
    const MechanismPtr &mechanism() const { return m_design.mechanism; }
    const Pose &pose() const { return m_design.pose; }
    QUndoStack *undoStack() { return &m_undoStack; }

    /// Opens a preset id or a design file as an undoable replacement of the design.
    Result<bool> open(const QString &presetOrPath);
    /// Opens a preset as the start of a new design of the user's own (File ▸ New from
    /// Template): undoable, not the preset any more (saving asks for a file).
    Result<bool> openTemplate(const QString &presetId);
    /// Changes several design parameters at once (core units) as one undo step that `text`
    /// names; the failure names the culprit and nothing changes. `continuous` merges into the
    /// previous step of the same `mergeKey` (a drag is one step).
    Result<bool> setParameters(const ParameterSet &changes, const QString &mergeKey, bool continuous,
                               std::function<QString()> text);
    /// A drag in the linkage view begins: the next move of an attachment point starts a new
    /// undo step, the later ones of the same drag merge into it.
    void beginDrag() { m_dragStarts = true; }
    /// Changes one design parameter (display units); the failure names it and nothing changes.
    /// `continuous` edits (stepping with keys or wheel) merge into the previous undo step of
    /// the same parameter.
    Result<bool> setParameter(const QString &name, double displayValue, bool continuous = false);
    /// Moves joint variable `variable` (index into variableInfo(), core units). Values past a
    /// limit stop at the limit; the failure names the variable if no pose can be reached.
    Result<Pose> setVariable(int variable, double value);
    /// Drags a scene handle to a point of the mechanism plane (mm). A handle that edits the
    /// design (an attachment point, SceneHandle::editsDesign) moves that point of the design,
    /// one undo step per drag (beginDrag()); a design that cannot be assembled is refused.
    Result<Pose> dragHandle(int handle, const Eigen::Vector2d &target);
    /// Moves the outputs (a platform position clicked on a map) by inverse kinematics.
    Result<Pose> moveOutputsTo(const Coordinates &outputs);
    /// The design's neighbours in other working/assembly modes (computed once per design).
    const std::vector<ModeAlternative> &modeNeighbours() const { return m_modeNeighbours; }
    /// The current pose in the other modes: what the view draws as ghosts.
    std::vector<ModeAlternative> modeAlternatives() const;
    /// Switches to another mode, as an undoable design change; the pose becomes the
    /// alternative's pose.
    Result<bool> switchMode(const ModeAlternative &alternative);
    /// Whether a move that failed went part of the way (see applyPartialMove).
    bool lastMoveWasPartial() const { return m_lastMoveWasPartial; }
    /// Why the pose cannot go further, when a variable sits at a limit or near a singularity;
    /// empty otherwise.
    QString limitNote() const;

    /// The design's pose bookmarks (designfile.h), kept in its file.
    const QList<Bookmark> &bookmarks() const { return m_design.bookmarks; }
    /// Keeps the current pose as a bookmark called `name` (undoable); refused past
    /// designfile::maxBookmarks.
    Result<bool> addBookmark(const QString &name);
    /// Removes bookmark `index` (undoable).
    Result<bool> removeBookmark(int index);
    /// Moves to bookmark `index` (a pose move, like a slider's); the failure names the bookmark.
    Result<Pose> goToBookmark(int index);
    /// The design's ±tolerances (core units, core/tolerance.h), kept in its file.
    const ParameterSet &tolerances() const { return m_design.tolerances; }
    /// Sets the tolerance of parameter `name` (core units; 0 removes it) as one undo step; the
    /// failure names the parameter and nothing changes.
    Result<bool> setTolerance(const QString &name, double value);
    /// Removes every tolerance (undoable).
    void clearTolerances();
    // Used by the undo commands only.
    void applyTolerances(const ParameterSet &tolerances);
    /// What the actuators must deliver (core/capabilitymap.h, core units), kept in the file.
    const std::vector<capability::Requirement> &requirements() const { return m_design.requirements; }
    /// Replaces the requirements as one undo step (nothing when they are the same).
    void setRequirements(std::vector<capability::Requirement> requirements);
    /// For SetRequirementsCommand.
    void applyRequirements(const std::vector<capability::Requirement> &requirements);
    // Used by the undo commands only.
    void applyBookmarks(const QList<Bookmark> &bookmarks);
    // Used by the undo commands only.
    void applyDesign(const Design &design);

protected:
    /// A new language (QEvent::LanguageChange to the application): the undo stack's texts
    /// are made again, before the widgets hear of it.
    bool eventFilter(QObject *watched, QEvent *event) override;

signals:
    /// The mechanism (and with it the pose) was replaced: recompute everything.
    void designChanged();
    /// Only the pose moved: the cheap path for slider drags.
    void poseChanged();
    /// A bookmark was added or removed (or the design replaced: designChanged says so too).
    void bookmarksChanged();
    /// The tolerances changed (or the design was replaced: designChanged says so too).
    void tolerancesChanged();
    /// The requirements changed (or the design was replaced: designChanged says so too).
    void requirementsChanged();

private:
    void applyPose(const Pose &pose);
    /// When a move to `target` fails, goes as far towards it as the mechanism allows (by
    /// bisection between the current pose and the target) and reports the failure all the
    /// same; `solveAt(t)` solves the move's fraction t ∈ [0, 1].
    template <class Solve>
    Result<Pose> moveTowards(const Solve &solveAt);
    /// The pose to keep when the design changes: same outputs if still valid, else clamped.
    static Pose carryPose(const Mechanism &mechanism, const Pose &old);

    Design m_design;
    QUndoStack m_undoStack;
    int m_drivenVariable = 0; ///< the variable the user moved last (index into variableInfo())
    std::vector<ModeAlternative> m_modeNeighbours;
    bool m_lastMoveWasPartial = false;
    bool m_dragStarts = true;
};

} // namespace pkm
