#pragma once
/// The workspaces of a mechanism's forms drawn over each other, as in the O-X glide
/// document's fig. 5: each form's region filled (the larger, lighter one first), the union
/// outlined, the singular curves where the forms meet, and the current pose. A click inside
/// the plot asks to move the platform there. Regions are computed on one grid over all forms,
/// so the areas of the forms and of their union are comparable.

#include "linkageview.h" // Q_DECLARE_METATYPE(Eigen::Vector2d)
#include "mechanism.h"
#include "planarworkspace.h"

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

class QCustomPlot;
class QCPCurve;
class QCPGraph;
class QCPItemPixmap;
class QCPItemTracer;
class QCPTextElement;
class QMouseEvent;

namespace pkm {

struct FormRegion {
    QString title;          ///< "X — crossed"
    MechanismPtr mechanism; ///< the design in this form; must have a planar workspace
    QColor fill;
    double exactArea = 0.0; ///< mm², shown when > 0 (a closed form), else the grid's area
};

class FormWorkspaceView : public QWidget
{
    Q_OBJECT

public:
    explicit FormWorkspaceView(QWidget *parent = nullptr);

    /// Regions are painted in order (later ones over earlier ones); `singular` are drawn over
    /// them as dashed red lines, `singularLabel` names them in the legend.
    void setForms(const QString &title, const std::vector<FormRegion> &forms, const std::vector<SingularCurve> &singular,
                  const QString &singularLabel);
    void setPose(const Eigen::Vector2d &platform);

    /// Areas on the common grid (mm²): of form i, and of the union of all forms.
    double gridArea(int form) const;
    double unionArea() const { return m_unionArea; }
    /// The form regions that contain the point (indices into the forms given).
    std::vector<int> formsAt(const Eigen::Vector2d &point) const;
    QCustomPlot *plot() const { return m_plot; }
    QString legendText() const;

signals:
    void pointClicked(const Eigen::Vector2d &point);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    /// On a change of language: the axes, the legend's own words and the tooltip again (the
    /// titles given to setForms() are the caller's to translate: it calls setForms() again).
    void changeEvent(QEvent *event) override;

private:
    void fitView();
    void retranslate();
    /// The title and the legend broken and laid out for the plot's width.
    void fitTexts();
    void mouseReleased(QMouseEvent *event);

    QCustomPlot *m_plot = nullptr;
    QCPTextElement *m_title = nullptr;
    QCPItemPixmap *m_regions = nullptr;
    QCPCurve *m_outline = nullptr;
    QCPCurve *m_singularHalo = nullptr;
    QCPCurve *m_singular = nullptr;
    QCPItemTracer *m_pose = nullptr;
    MapGrid m_grid;
    std::vector<std::vector<char>> m_reached; ///< per form, per cell (row-major from the bottom)
    std::vector<double> m_areas;
    double m_unionArea = 0.0;
    // what the legend and the tooltip are made of, to make them again in another language
    std::vector<QCPGraph *> m_swatches; ///< one per form, in order
    std::vector<QString> m_formTitles;
    std::vector<double> m_shownAreas; ///< exact where known, else on the grid, mm²
    double m_unionShown = 0.0;        ///< mm²
    bool m_exactAreas = false;
    Eigen::AlignedBox2d m_bounds;
    int m_refits = 0; ///< relayouts in a row asked by fitView(), to stop a ping-pong of margins
    QString m_fittedFor; ///< the width and fonts the title and legend were last broken for
    QPoint m_pressPosition;
};

} // namespace pkm
