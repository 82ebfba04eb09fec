#include "textscale.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QEvent>
#include <QSet>
#include <QStyle>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QWidget>

#include <algorithm>

namespace pkm::textscale {

namespace {
double g_factor = 1.0;

/// "δ(α)" of "δ(α) — fig. 4".
QString shortTitle(const QString &title)
{
    const qsizetype dash = title.indexOf(QStringLiteral(" — "));
    return dash > 0 ? title.left(dash) : title;
}

/// Watches a tab widget's size, font and language and picks the full or the short titles.
class TabTitleFitter : public QObject
{
public:
    explicit TabTitleFitter(QTabWidget *tabs)
        : QObject(tabs)
        , m_tabs(tabs)
    {
        tabs->installEventFilter(this);
        tabs->tabBar()->installEventFilter(this);
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        switch (event->type()) {
        case QEvent::Resize:
        case QEvent::Show:
        case QEvent::FontChange:
        case QEvent::LanguageChange:
        case QEvent::LayoutRequest:
            // after the event, and after the owner's retranslation has set the new titles
            QTimer::singleShot(0, this, [this] { fit(); });
            break;
        default: break;
        }
        return QObject::eventFilter(watched, event);
    }

private:
    void fit()
    {
        QTabBar *bar = m_tabs->tabBar();
        const QFontMetrics metrics(bar->font());
        // what a tab adds to its text, as QTabBar::tabSizeHint() reckons it
        const int frame = bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar) + 4;
        int fullWidth = 0;
        for (int i = 0; i < bar->count(); ++i) {
            // a title the owner set since (a new language) is the full one now
            const QString full = bar->tabData(i).toString(), shown = bar->tabText(i);
            if (shown != full && shown != shortTitle(full))
                bar->setTabData(i, shown);
            const QString title = bar->tabData(i).toString();
            fullWidth += frame + metrics.horizontalAdvance(title);
        }
        const bool full = fullWidth <= m_tabs->width();
        for (int i = 0; i < bar->count(); ++i) {
            const QString title = bar->tabData(i).toString(), wanted = full ? title : shortTitle(title);
            if (bar->tabText(i) != wanted)
                bar->setTabText(i, wanted);
        }
    }

    QTabWidget *m_tabs;
};

QFont scaled(QFont font, double ratio)
{
    if (font.pointSizeF() > 0)
        font.setPointSizeF(font.pointSizeF() * ratio);
    else if (font.pixelSize() > 0)
        font.setPixelSize(std::max(1, qRound(font.pixelSize() * ratio)));
    return font;
}

void rescalePlot(QCustomPlot *plot, double ratio)
{
    // Each axis once: a colour scale's axis is also among the axis rects' axes.
    QSet<QCPAxis *> axes;
    for (QCPAxisRect *rect : plot->axisRects()) {
        for (QCPAxis *axis : rect->axes())
            axes.insert(axis);
    }
    // Legends and titles may sit anywhere in the layout.
    const QList<QCPLayoutElement *> elements = plot->plotLayout()->elements(true);
    for (QCPLayoutElement *element : elements) {
        if (!element)
            continue;
        if (auto *text = qobject_cast<QCPTextElement *>(element))
            text->setFont(scaled(text->font(), ratio));
        // The legend passes its font on to every item it holds: scaling the items as well
        // would scale them twice.
        if (auto *legend = qobject_cast<QCPLegend *>(element))
            legend->setFont(scaled(legend->font(), ratio));
        if (auto *scale = qobject_cast<QCPColorScale *>(element); scale && scale->axis())
            axes.insert(scale->axis());
    }
    for (QCPAxis *axis : std::as_const(axes)) {
        if (!axis)
            continue;
        axis->setTickLabelFont(scaled(axis->tickLabelFont(), ratio));
        axis->setLabelFont(scaled(axis->labelFont(), ratio));
    }
    for (int i = 0; i < plot->itemCount(); ++i) {
        if (auto *text = qobject_cast<QCPItemText *>(plot->item(i)))
            text->setFont(scaled(text->font(), ratio));
    }
    plot->replot(QCustomPlot::rpQueuedReplot);
}
} // namespace

void applyBaseFont()
{
    QFont font = QApplication::font();
    if (font.pointSizeF() < 10.5)
        font.setPointSizeF(10.5);
    QApplication::setFont(font);
}

double factor()
{
    return g_factor;
}

double setFactor(double factor)
{
    g_factor = std::clamp(factor, minimum, maximum);
    return g_factor;
}

void rescale(QWidget *root, double ratio)
{
    if (!(ratio > 0) || ratio == 1.0)
        return;
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *widget : widgets) {
        if (widget->testAttribute(Qt::WA_SetFont))
            widget->setFont(scaled(widget->font(), ratio));
        if (auto *plot = qobject_cast<QCustomPlot *>(widget))
            rescalePlot(plot, ratio);
    }
}

void keepTabsInSight(QTabWidget *tabs)
{
    tabs->setElideMode(Qt::ElideRight);
    tabs->setUsesScrollButtons(false);
    new TabTitleFitter(tabs);
}

} // namespace pkm::textscale
