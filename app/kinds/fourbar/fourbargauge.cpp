// The four-bar panel's transmission gauge: |γ| on a bar 0°…180° with the poor bands below 40°
// and above 140° shaded, the range over the motion and the current value as a needle
// (docs/mathematics.md, section 4), and the group that shows it with the value in words.

#include "kinds/fourbar/fourbarpanel.h"

#include "kinds/fourbar/fourbar.h"
#include "plotfont.h"

#include <QEvent>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace pkm {

namespace {
constexpr QRgb poorRgb = 0xb3261e;
} // namespace

TransmissionGauge::TransmissionGauge(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("transmissionGauge"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void TransmissionGauge::setValues(double gamma, double minimum, double maximum)
{
    m_value = gamma;
    m_minimum = minimum;
    m_maximum = maximum;
    update();
}

void TransmissionGauge::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        update();
    QWidget::changeEvent(event);
}

void TransmissionGauge::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont small = fontOf(font(), 10.0);
    painter.setFont(small);
    const QFontMetrics metrics(small);
    const double margin = metrics.horizontalAdvance(QStringLiteral("180°")) / 2.0 + 2.0;
    const QRectF bar(margin, 10.0, width() - 2.0 * margin, 14.0);
    auto xOf = [&](double degrees) { return bar.left() + bar.width() * std::clamp(degrees, 0.0, 180.0) / 180.0; };
    const double poor = FourBar::poorTransmission;

    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0xf3c7c7));
    painter.drawRect(QRectF(QPointF(xOf(0), bar.top()), QPointF(xOf(poor), bar.bottom())));
    painter.drawRect(QRectF(QPointF(xOf(180 - poor), bar.top()), QPointF(xOf(180), bar.bottom())));
    painter.setBrush(QColor(0xdcefd8));
    painter.drawRect(QRectF(QPointF(xOf(poor), bar.top()), QPointF(xOf(180 - poor), bar.bottom())));
    // the range over the motion
    painter.setBrush(QColor(0x7a99c2));
    painter.drawRect(QRectF(QPointF(xOf(m_minimum), bar.top() + 4),
        QPointF(std::max(xOf(m_maximum), xOf(m_minimum) + 2), bar.bottom() - 4)));
    painter.setPen(QPen(QColor(0x606060), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(bar);

    // ticks
    painter.setPen(QColor(0x303030));
    for (double tick : {0.0, poor, 90.0, 180.0 - poor, 180.0}) {
        const double x = xOf(tick);
        painter.drawLine(QPointF(x, bar.bottom()), QPointF(x, bar.bottom() + 4));
        const QString text = QLocale().toString(tick, 'f', 0) + QChar(0x00B0);
        const double w = metrics.horizontalAdvance(text);
        painter.drawText(QPointF(x - w / 2.0, bar.bottom() + 5 + metrics.ascent()), text);
    }

    // the needle
    const bool warn = std::min(m_value, 180.0 - m_value) < poor;
    const QColor needle = warn ? QColor(poorRgb) : QColor(0x202020);
    const double x = xOf(m_value);
    painter.setPen(QPen(needle, 2.5));
    painter.drawLine(QPointF(x, bar.top() - 2), QPointF(x, bar.bottom() + 2));
    QPainterPath triangle;
    triangle.moveTo(x - 6, 1);
    triangle.lineTo(x + 6, 1);
    triangle.lineTo(x, bar.top() - 1);
    triangle.closeSubpath();
    painter.setPen(Qt::NoPen);
    painter.setBrush(needle);
    painter.drawPath(triangle);
}

QGroupBox *FourBarPanel::createTransmissionGroup(const QFont &labelFont)
{
    auto *transmission = new QGroupBox(this);
    m_transmissionGroup = transmission;
    transmission->setFont(labelFont);
    auto *column = new QVBoxLayout(transmission);
    column->setContentsMargins(8, 2, 8, 4);
    column->setSpacing(2);
    m_transmission = new QLabel(transmission);
    m_transmission->setObjectName(QStringLiteral("transmissionLabel"));
    m_transmission->setFont(fontOf(font(), 14.0, true));
    m_transmission->setWordWrap(true); // "— poor: below 40°" under the value where narrow
    m_gauge = new TransmissionGauge(transmission);
    m_transmissionRange = new QLabel(transmission);
    m_transmissionRange->setFont(labelFont);
    m_transmissionRange->setWordWrap(true);
    column->addWidget(m_transmission);
    column->addWidget(m_gauge);
    column->addWidget(m_transmissionRange);
    return transmission;
}

} // namespace pkm
