#include "textscale.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QSet>
#include <QWidget>

#include <algorithm>

namespace pkm::textscale {

namespace {
double g_factor = 1.0;

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

} // namespace pkm::textscale
