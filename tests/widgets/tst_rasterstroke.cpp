// The raster outlines of rasterstroke.h against Qt's own stroker: every shape the views draw
// (a closed polygon, a zigzag with sharp corners, a traced ellipse, a lone segment) with every
// cap, join and dash pattern the drawing pipeline uses, painted both ways on white, must ink the
// same pixels — the same total ink within a few per cent and hardly a pixel that one paints
// dark and the other leaves light — and the fast path is taken only where it is exact enough.
#include "drawlistpainter.h"
#include "rasterstroke.h"

#include <QImage>
#include <QPicture>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace pkm::drawing;

namespace {

QImage blank()
{
    QImage image(420, 320, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    return image;
}

/// How dark a pixel is, 0 (white) … 1 (the pen's full colour, black here).
double ink(QRgb pixel)
{
    return 1.0 - qGray(pixel) / 255.0;
}

struct Comparison {
    double qtInk = 0.0, ownInk = 0.0;
    int disagreeing = 0; ///< pixels at least half inked by one and not by the other
    int inked = 0;       ///< pixels at least half inked by Qt
};

Comparison compare(const QPolygonF &points, bool closed, const Pen &pen)
{
    QImage byQt = blank(), byUs = blank();
    {
        QPainter painter(&byQt);
        painter.setRenderHint(QPainter::Antialiasing);
        QPen qpen(pen.colour, pen.width, Qt::SolidLine, pen.cap, pen.join);
        if (const QVector<qreal> pattern = dashPattern(pen.dash); !pattern.isEmpty())
            qpen.setDashPattern(pattern);
        painter.setPen(qpen);
        if (closed)
            painter.drawPolygon(points);
        else
            painter.drawPolyline(points);
    }
    {
        QPainter painter(&byUs);
        painter.setRenderHint(QPainter::Antialiasing);
        if (!strokesOnRaster(painter, pen))
            qFatal("the fast path was not taken");
        strokeOnRaster(painter, points, closed, pen);
    }
    Comparison c;
    for (int y = 0; y < byQt.height(); ++y) {
        for (int x = 0; x < byQt.width(); ++x) {
            const double a = ink(byQt.pixel(x, y)), b = ink(byUs.pixel(x, y));
            c.qtInk += a;
            c.ownInk += b;
            c.inked += a >= 0.5;
            c.disagreeing += (a >= 0.5) != (b >= 0.5) && std::abs(a - b) > 0.35;
        }
    }
    return c;
}

QPolygonF hexagon()
{
    QPolygonF p;
    for (int k = 0; k < 6; ++k)
        p << QPointF(210 + 170 * std::cos(k * std::numbers::pi / 3), 160 + 120 * std::sin(k * std::numbers::pi / 3));
    return p;
}

QPolygonF ellipse()
{
    QPolygonF p;
    for (int k = 0; k < 96; ++k) {
        const double t = 2.0 * std::numbers::pi * k / 96;
        p << QPointF(210 + 180 * std::cos(t) * 0.92 - 90 * std::sin(t) * 0.39,
                     160 + 180 * std::cos(t) * 0.39 + 90 * std::sin(t) * 0.92);
    }
    return p;
}

QPolygonF zigzag()
{
    return QPolygonF{{20, 280}, {90, 40}, {150, 270}, {260, 60}, {300, 250}, {400, 200}};
}

} // namespace

class TestRasterStroke : public QObject
{
    Q_OBJECT

private slots:
    void sameInkAsQt_data()
    {
        QTest::addColumn<QPolygonF>("points");
        QTest::addColumn<bool>("closed");
        QTest::addColumn<double>("width");
        QTest::addColumn<int>("cap");
        QTest::addColumn<int>("join");
        QTest::addColumn<int>("dash");
        const std::pair<const char *, QPolygonF> shapes[] = {{"hexagon", hexagon()}, {"ellipse", ellipse()},
                                                             {"zigzag", zigzag()}, {"segment", QPolygonF{{30, 30}, {380, 290}}}};
        for (const auto &[name, points] : shapes) {
            const bool closed = QByteArray(name) == "hexagon" || QByteArray(name) == "ellipse";
            for (const double width : {1.6, 2.0, 6.0}) {
                for (const Qt::PenCapStyle cap : {Qt::FlatCap, Qt::RoundCap, Qt::SquareCap}) {
                    for (const Qt::PenJoinStyle join : {Qt::RoundJoin, Qt::BevelJoin, Qt::MiterJoin}) {
                        for (const Dash dash : {Dash::Solid, Dash::Dashed, Dash::Centre, Dash::Ghost}) {
                            QTest::addRow("%s w%.1f cap%d join%d dash%d", name, width, int(cap), int(join), int(dash))
                                << points << closed << width << int(cap) << int(join) << int(dash);
                        }
                    }
                }
            }
        }
    }

    void sameInkAsQt()
    {
        QFETCH(QPolygonF, points);
        QFETCH(bool, closed);
        QFETCH(double, width);
        QFETCH(int, cap);
        QFETCH(int, join);
        QFETCH(int, dash);
        const Pen pen{QColor(Qt::black), width, Qt::PenCapStyle(cap), Dash(dash), Qt::PenJoinStyle(join)};
        const Comparison c = compare(points, closed, pen);
        QVERIFY(c.qtInk > 100.0);
        const double ratio = c.ownInk / c.qtInk;
        QVERIFY2(ratio > 0.95 && ratio < 1.05, qPrintable(QStringLiteral("ink %1 against Qt's %2").arg(c.ownInk).arg(c.qtInk)));
        QVERIFY2(c.disagreeing <= std::max(12, c.inked / 50),
                 qPrintable(QStringLiteral("%1 of %2 pixels disagree").arg(c.disagreeing).arg(c.inked)));
    }

    /// Qt's stroker where the pieces would show: a vector device (a picture, a PDF, SVG), no
    /// antialiasing, a translucent pen (overlaps would darken) or a hairline (already fast).
    void onlyWhereExact()
    {
        const Pen wide{QColor(Qt::black), 2.0, Qt::RoundCap, Dash::Solid, Qt::RoundJoin};
        QImage image = blank();
        QPainter painter(&image);
        QVERIFY(!strokesOnRaster(painter, wide)); // no antialiasing yet
        painter.setRenderHint(QPainter::Antialiasing);
        QVERIFY(strokesOnRaster(painter, wide));
        QVERIFY(!strokesOnRaster(painter, Pen{QColor(0, 0, 0, 128), 2.0, Qt::RoundCap, Dash::Solid, Qt::RoundJoin}));
        QVERIFY(!strokesOnRaster(painter, Pen{QColor(Qt::black), 1.0, Qt::RoundCap, Dash::Solid, Qt::RoundJoin}));
        painter.end();
        QPicture picture;
        QPainter recorder(&picture);
        recorder.setRenderHint(QPainter::Antialiasing);
        QVERIFY(!strokesOnRaster(recorder, wide));
    }

    /// A polyline of one point, or of points that coincide, draws what Qt draws, and nothing
    /// breaks on an empty one.
    void degeneratePolylines()
    {
        const Pen pen{QColor(Qt::black), 6.0, Qt::RoundCap, Dash::Solid, Qt::RoundJoin};
        const QPolygonF twice{{100, 100}, {100, 100}}, once{{200, 100}};
        QImage byQt = blank(), byUs = blank();
        {
            QPainter painter(&byQt);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(QPen(pen.colour, pen.width, Qt::SolidLine, pen.cap, pen.join));
            painter.drawPolyline(twice);
            painter.drawPolygon(once);
        }
        {
            QPainter painter(&byUs);
            painter.setRenderHint(QPainter::Antialiasing);
            strokeOnRaster(painter, twice, false, pen);
            strokeOnRaster(painter, once, true, pen);
            strokeOnRaster(painter, QPolygonF{}, false, pen);
        }
        QCOMPARE(byUs, byQt);
    }

    /// A dash that ends exactly on a corner leaves a side of no length in its run: no join
    /// there. Its direction was NaN, and a join polygon with a NaN corner sent Qt's rasterizer
    /// into an endless loop (the GUI hung dragging MOMA with the velocity shapes shown).
    void dashEndingOnACorner()
    {
        for (const Qt::PenJoinStyle join : {Qt::BevelJoin, Qt::MiterJoin, Qt::RoundJoin}) {
            const Pen pen{QColor(Qt::black), 2.0, Qt::FlatCap, Dash::Dashed, join};
            for (double side : {20.0, 32.0, 40.0, 60.0}) { // the pattern is 12 px on, 8 off
                const QPolygonF square{{50, 50}, {50 + side, 50}, {50 + side, 50 + side}, {50, 50 + side}};
                QImage image = blank();
                QPainter painter(&image);
                painter.setRenderHint(QPainter::Antialiasing);
                strokeOnRaster(painter, square, true, pen);
                painter.end();
                QVERIFY(image.pixelColor(56, 50) != image.pixelColor(5, 5)); // the first dash is drawn
            }
        }
    }
};

QTEST_MAIN(TestRasterStroke)
#include "tst_rasterstroke.moc"
