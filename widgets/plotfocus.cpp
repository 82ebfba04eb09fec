#include "plotfocus.h"

#include <qcustomplot.h>

#include <QGridLayout>
#include <QStackedWidget>
#include <QTabWidget>

namespace pkm::plotfocus {

namespace {

/// The tab widget whose page `plot` sits on directly, or null.
QTabWidget *tabsOf(const QCustomPlot *plot)
{
    QWidget *page = plot->parentWidget();
    QWidget *stack = page ? page->parentWidget() : nullptr;
    if (!qobject_cast<QStackedWidget *>(stack))
        return nullptr;
    auto *tabs = qobject_cast<QTabWidget *>(stack->parentWidget());
    return tabs && tabs->indexOf(page) >= 0 ? tabs : nullptr;
}

/// The plots on one page, in the order of its layout (its children's order otherwise).
QList<QCustomPlot *> plotsOn(const QWidget *page)
{
    QList<QCustomPlot *> found;
    if (QLayout *layout = page->layout()) {
        for (int i = 0; i < layout->count(); ++i) {
            if (auto *plot = qobject_cast<QCustomPlot *>(layout->itemAt(i)->widget()))
                found.append(plot);
        }
    }
    for (QCustomPlot *plot : page->findChildren<QCustomPlot *>(Qt::FindDirectChildrenOnly)) {
        if (!found.contains(plot))
            found.append(plot);
    }
    return found;
}

/// The tab widgets under `root` that hold plots on their pages.
QList<QTabWidget *> tabWidgets(const QWidget *root)
{
    QList<QTabWidget *> found;
    for (QCustomPlot *plot : root->findChildren<QCustomPlot *>()) {
        if (QTabWidget *tabs = tabsOf(plot); tabs && !found.contains(tabs))
            found.append(tabs);
    }
    return found;
}

const char *stretchProperty = "pkmColumnStretch"; ///< a grid's column stretches while one plot is alone

/// A page laid out in a grid shares its columns by stretch (the П-joint's halves): while
/// `alone` is the one plot shown, its columns take the stretch and the others none, or an
/// empty column keeps its share; with `alone` null, the stretches the page had come back.
void stretchFor(QWidget *page, QCustomPlot *alone)
{
    auto *grid = qobject_cast<QGridLayout *>(page->layout());
    if (!grid)
        return;
    QVariantList kept = grid->property(stretchProperty).toList();
    if (kept.isEmpty()) {
        if (!alone)
            return;
        for (int c = 0; c < grid->columnCount(); ++c)
            kept.append(grid->columnStretch(c));
        grid->setProperty(stretchProperty, kept);
    }
    int row = 0, column = 0, rows = 1, columns = 1;
    if (alone && grid->indexOf(alone) >= 0)
        grid->getItemPosition(grid->indexOf(alone), &row, &column, &rows, &columns);
    for (int c = 0; c < int(kept.size()) && c < grid->columnCount(); ++c)
        grid->setColumnStretch(c, !alone ? kept[c].toInt() : c >= column && c < column + columns ? 1 : 0);
    if (!alone)
        grid->setProperty(stretchProperty, QVariant());
}

} // namespace

QList<QCustomPlot *> plots(const QWidget *root)
{
    QList<QCustomPlot *> found;
    for (QTabWidget *tabs : tabWidgets(root)) {
        for (int i = 0; i < tabs->count(); ++i)
            found += plotsOn(tabs->widget(i));
    }
    return found;
}

QString title(const QCustomPlot *plot)
{
    for (QCPLayoutElement *element : plot->plotLayout()->elements(true)) {
        if (auto *text = qobject_cast<QCPTextElement *>(element); text && !text->text().isEmpty())
            return text->text().simplified(); // a fitted title is broken into lines
    }
    return plot->objectName();
}

void showOnePerPage(QWidget *root, QCustomPlot *chosen)
{
    for (QTabWidget *tabs : tabWidgets(root)) {
        for (int i = 0; i < tabs->count(); ++i) {
            const QList<QCustomPlot *> onPage = plotsOn(tabs->widget(i));
            if (onPage.isEmpty())
                continue;
            const bool hasChosen = chosen && onPage.contains(chosen);
            QCustomPlot *shown = hasChosen ? chosen : onPage.first();
            // Shown first, then the others hidden: the page never has none to lay out.
            shown->show();
            for (QCustomPlot *plot : onPage) {
                if (plot != shown)
                    plot->hide();
            }
            stretchFor(tabs->widget(i), shown);
            if (hasChosen)
                bringToFront(chosen);
        }
    }
}

void bringToFront(QCustomPlot *plot)
{
    if (QTabWidget *tabs = tabsOf(plot))
        tabs->setCurrentWidget(plot->parentWidget());
}

void showAll(QWidget *root)
{
    for (QCustomPlot *plot : plots(root))
        plot->show();
    for (QTabWidget *tabs : tabWidgets(root)) {
        for (int i = 0; i < tabs->count(); ++i)
            stretchFor(tabs->widget(i), nullptr);
    }
}

QCustomPlot *shownAlone(const QWidget *root)
{
    for (QTabWidget *tabs : tabWidgets(root)) {
        const QList<QCustomPlot *> onPage = plotsOn(tabs->currentWidget());
        QCustomPlot *shown = nullptr;
        int count = 0;
        for (QCustomPlot *plot : onPage) {
            if (!plot->isHidden()) {
                shown = plot;
                ++count;
            }
        }
        if (count == 1 && onPage.size() > 1)
            return shown;
    }
    return nullptr;
}

QCustomPlot *active(const QWidget *root)
{
    if (QCustomPlot *alone = shownAlone(root); alone && alone->isVisible())
        return alone;
    for (QCustomPlot *plot : plots(root)) {
        if (plot->isVisible())
            return plot;
    }
    for (QCustomPlot *plot : root->findChildren<QCustomPlot *>()) {
        if (plot->isVisible())
            return plot; // a plot or map that is not on a tab's page
    }
    return nullptr;
}

} // namespace pkm::plotfocus
