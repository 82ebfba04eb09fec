#pragma once
/// The 2D linkage view: shows one Scene on a mm grid, zooms and pans, and turns a drag of a
/// scene handle into handleDragged() requests. It never changes the pose itself: its owner
/// answers handleDragged() by solving the mechanism and calling setScene() with the result.
///
/// A handle that edits the design (an attachment point, SceneHandle::editsDesign) is dragged the
/// same way; the owner turns its handleDragged() into a design change instead of a pose.
///
/// Ghost scenes — the pose in the mechanism's other modes — go faded under the real one; a
/// hovered ghost is highlighted and named, and a click on one emits ghostClicked(). Switching
/// is the owner's business too.

#include "scene.h"
#include "scenepainter.h"

#include <Eigen/Core>

#include <QList>
#include <QMetaType>
#include <QStringList>
#include <QWidget>

// Here, not in core: core stays free of Qt (docs/architecture.md).
Q_DECLARE_METATYPE(Eigen::Vector2d)

namespace pkm {

class LinkageView : public QWidget
{
    Q_OBJECT

public:
    explicit LinkageView(QWidget *parent = nullptr);

    /// Cheap: stores the scene and schedules a repaint. Only the first scene is fitted; later
    /// ones keep the mapping so the drawing does not jump while the user drags — unless the
    /// view is fitted to a pose (Scene::poseExtent) and the mechanism leaves it: then it widens
    /// by steps towards the whole range of motion, and stays there until the next Fit.
    void setScene(const Scene &scene);
    const Scene &scene() const { return m_scene; }

    /// One line at the bottom-left ("θ stops at its upper limit 60°"); empty hides it.
    void setMessage(const QString &message);
    QString message() const { return m_message; }

    /// Ghosts drawn under the scene, faded and without labels, with what a click on each
    /// switches to ("other assembly mode (same slider positions)"). Empty lists clear them.
    /// Not drawn by renderTo() and renderScene(). fitToView() takes in the ghosts' joints;
    /// the first ghosts are fitted unless the user has zoomed or panned.
    void setGhostScenes(const QList<Scene> &ghosts, const QStringList &labels);
    const QList<Scene> &ghostScenes() const { return m_ghosts; }
    /// The ghost within the hit radius of `position` (widget) — of one of its members'
    /// segments or of one of its joints — or −1. The real scene's handles take precedence.
    int ghostAt(const QPointF &position) const;
    /// The hovered ghost, or −1.
    int hoveredGhost() const { return m_hoverGhost; }
    /// Shows ghost `index` in front of the others as if hovered (−1: none), for the pointer on
    /// its mode's button: among a 3-RP̲R's five ghosts the one a button means is found at once.
    void highlightGhost(int index);
    /// How strongly a ghost that is not hovered is drawn, of SceneStyle::ghostOpacity: fainter
    /// where there are more than two, whose dashes had hidden the linkage.
    double ghostShare() const;
    /// The message line as drawn: the hovered ghost's "Click to switch to: …", else message().
    QString shownMessage() const;

    void setSceneStyle(const SceneStyle &style);
    const SceneStyle &sceneStyle() const { return m_style; }

    ViewMapping mapping() const { return m_mapping; }
    /// Device (widget) position of handle `handle`'s joint; a null point for a bad index.
    QPointF handlePosition(int handle) const;
    /// The handle whose joint is within the hit radius of `position` (widget), or −1.
    int handleAt(const QPointF &position) const;
    /// The hovered or dragged handle, or −1.
    int activeHandle() const { return m_dragHandle >= 0 ? m_dragHandle : m_hoverHandle; }
    /// Whether the user has zoomed or panned since the last fit.
    bool userMoved() const { return m_userMoved; }
    /// `area` without the top the scene's legend takes (ScenePainter::legendHeight()), for a fit.
    static QRectF belowLegend(const QRectF &area, const Scene &scene, const SceneStyle &style);

    /// Draws the current scene, fitted to its extent, into `target` of any painter (PNG, SVG
    /// and PDF export): background, grid, scene and scale bar; no handle rings, no message.
    void renderTo(QPainter &painter, const QRectF &target) const;
    /// The same for any scene, without a view.
    static void renderScene(QPainter &painter, const QRectF &target, const Scene &scene, const SceneStyle &style);
    /// The mapping renderScene() uses for `target`.
    static ViewMapping fittedMapping(const Scene &scene, const QRectF &target, const SceneStyle &style);
    /// The mapping Fit gives the view on the screen: `extent` (the scene's and its ghosts')
    /// above the scale bar and below the legend, with every label whole where the area allows
    /// (ScenePainter::fitWithLabels()). Pictures and animation frames keep fittedMapping(), so
    /// that a frame's labels never change its scale.
    static ViewMapping screenMapping(
        const Scene &scene, const Eigen::AlignedBox3d &extent, const QRectF &area, const SceneStyle &style);

    int paintCount() const { return m_paintCount; }
    double lastPaintMilliseconds() const { return m_lastPaintMilliseconds; }

    QSize sizeHint() const override { return {800, 600}; }
    QSize minimumSizeHint() const override { return {200, 150}; }

    static constexpr double hitRadius = 12.0; ///< device px around a handle's joint
    static constexpr double zoomStep = 1.25; ///< per wheel notch and per zoomIn()

    /// After a design edit: Fit if the mechanism (its pose's box where the scene gives one,
    /// else its range of motion) has left the view or shrunk to a small part of it.
    void keepInSight();
    /// What the last fit framed, in scene mm: the pose and its ghosts, or more once widened.
    const Eigen::AlignedBox3d &fittedBox() const { return m_fitBox; }

public slots:
    /// Fits the pose (Scene::poseExtent) where the scene gives one, else the whole range of
    /// motion; the ghosts' joints are taken in.
    void fitToView();
    void zoomIn();
    void zoomOut();

signals:
    void dragStarted(int handle);
    /// The pointer dragging `handle` is at `targetMm` (scene plane, mm).
    void handleDragged(int handle, const Eigen::Vector2d &targetMm);
    void dragFinished();
    /// Ghost `index` (into the list given to setGhostScenes()) was clicked: pressed and
    /// released without a drag.
    void ghostClicked(int index);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void leaveEvent(QEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    /// Fits m_fitBox to the view as it is now (its size, the labels).
    void fit();
    /// Widens m_fitBox when the mechanism has moved out of sight (see setScene()).
    void followMechanism();
    /// Whether Fit frames the pose (Scene::poseExtent) rather than the whole range of motion.
    bool fitsPose() const;
    /// The pose's box where Fit frames it, else the range of motion.
    Eigen::AlignedBox3d inSightBox() const;
    Eigen::AlignedBox3d withGhostJoints(Eigen::AlignedBox3d box) const;
    /// Scales by `factor` keeping the scene point under `anchor` (widget) where it is.
    void zoomAbout(const QPointF &anchor, double factor);
    void setHoverHandle(int handle);
    void setHoverGhost(int ghost);
    /// Hover state for the pointer at `position`: a handle first, else a ghost.
    void updateHover(const QPointF &position);
    void updateToolTip();
    void updateCursor();

    Scene m_scene;
    bool m_hasScene = false;
    SceneStyle m_style;
    ViewMapping m_mapping;
    bool m_userMoved = false; ///< zoomed or panned since the last fit: resizing keeps the mapping
    Eigen::AlignedBox3d m_fitBox; ///< what fit() frames: set by fitToView(), widened by followMechanism()
    /// Fitted while hidden, without the labels: the whole fit, which lays the labels out a few
    /// times, waits for the first paint at the size the view is shown at.
    bool m_fitPending = false;
    QString m_message;

    int m_hoverHandle = -1;
    int m_dragHandle = -1;
    bool m_panning = false;
    QPointF m_lastPanPosition;

    QList<Scene> m_ghosts;
    /// Where the labels stood in the last repaint: a moving drawing keeps each on its side.
    std::vector<std::pair<QString, QPointF>> m_labelPlaces;
    QStringList m_ghostLabels;
    int m_hoverGhost = -1;
    int m_pressGhost = -1; ///< the ghost a left press began on, until it becomes a drag
    bool m_ghostsFitted = false; ///< the first ghosts have been seen
    QPointF m_pressPosition;

    int m_paintCount = 0;
    double m_lastPaintMilliseconds = 0.0;
};

} // namespace pkm
