#pragma once
/// One plot at a time, for a projector: the curve plots that a panel lays out side by side on
/// the pages of its tabs (the П-joint's figs. 8–10 on one page, the four-bar's ω₃ and ε₃ on
/// another) are unreadable at 1280×720 in presentation mode's large text. These functions show
/// one plot per page, filling it, and give the page back as it was. Plots that are not laid
/// out directly on a tab's page (a map's own parts) are left alone.

#include <QList>
#include <QString>

class QCustomPlot;
class QWidget;

namespace pkm::plotfocus {

/// The plots on the tab pages under `root`, page by page in tab order, each page's in the
/// order it lays them out.
QList<QCustomPlot *> plots(const QWidget *root);
/// The plot's title as shown, on one line ("Fig. 8 — diagonal length d(θ), (2)"); its object
/// name when it has no title.
QString title(const QCustomPlot *plot);
/// Every page under `root` with one plot shown: `chosen` on its page (which becomes the current
/// tab), the first plot on the others. A null or foreign `chosen` picks the current page's first.
void showOnePerPage(QWidget *root, QCustomPlot *chosen);
/// The tab holding `plot` made the current one.
void bringToFront(QCustomPlot *plot);
/// Every plot under `root` shown again.
void showAll(QWidget *root);
/// The plot shown alone on the current page under `root`, or null when none is.
QCustomPlot *shownAlone(const QWidget *root);
/// The plot a viewer is looking at under `root`: the one shown alone, else the first visible
/// one in tab order (the current page's first), else any visible plot or map; null when none
/// is on screen.
QCustomPlot *active(const QWidget *root);

} // namespace pkm::plotfocus
