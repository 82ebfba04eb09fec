// Pictures of plots (issue 7): PNG at the chosen size and DPI, SVG and PDF as vector drawings
// with the plot's text, atomic writing, the picture dialog, and the right-click menu that
// leaves the left button alone.

#include "pictureexport.h"
#include "support/process.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QXmlStreamReader>

#include <cmath>
#include <memory>

using namespace pkm;
using namespace pkm::test;

namespace {

const QString xLabel = QStringLiteral("Crank angle (deg)");
const QString yLabel = QStringLiteral("Stroke length (mm)");
const QString title = QStringLiteral("Fig. 8 — diagonal length d(θ), (2)");

/// A plot like the application's: a title above the axis rect, two labelled axes, a curve.
std::unique_ptr<QCustomPlot> makePlot()
{
    auto plot = std::make_unique<QCustomPlot>();
    plot->setBackground(Qt::white);
    plot->plotLayout()->insertRow(0);
    plot->plotLayout()->addElement(0, 0, new QCPTextElement(plot.get(), title));
    plot->xAxis->setLabel(xLabel);
    plot->yAxis->setLabel(yLabel);
    QVector<double> x, y;
    for (int i = 0; i <= 120; ++i) {
        x << -60.0 + i;
        y << 180.0 + 40.0 * std::sin((-60.0 + i) * 3.14159 / 180.0);
    }
    plot->addGraph()->setData(x, y);
    plot->xAxis->setRange(-60.0, 60.0);
    plot->yAxis->setRange(130.0, 230.0);
    plot->resize(640, 480);
    plot->replot();
    return plot;
}

struct Svg {
    QString error;
    QString root;
    QString text; ///< all character data
    QString viewBox;
};

Svg readSvg(const QByteArray &bytes)
{
    Svg svg;
    QXmlStreamReader reader(bytes);
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.isStartElement() && svg.root.isEmpty()) {
            svg.root = reader.name().toString();
            svg.viewBox = reader.attributes().value(QStringLiteral("viewBox")).toString();
        }
        if (reader.isCharacters())
            svg.text += reader.text().toString() + QLatin1Char('\n');
    }
    if (reader.hasError())
        svg.error = reader.errorString();
    return svg;
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

/// Shows `plot` and lays it out for the screen; false if it never appeared.
bool shownAndLaidOut(QCustomPlot *plot)
{
    plot->show();
    if (!QTest::qWaitForWindowExposed(plot))
        return false;
    plot->replot();
    return true;
}

/// The menu a context menu request opened on `plot`, if any.
QMenu *openMenu(QCustomPlot *plot)
{
    for (QMenu *menu : plot->findChildren<QMenu *>()) {
        if (menu->isVisible())
            return menu;
    }
    return nullptr;
}

} // namespace

class TestPictureExport : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void cleanup() { setPictureAsker({}); }

    void formatsAndScale()
    {
        QCOMPARE(pictureFormatOf(QStringLiteral("/tmp/a.PNG")), QStringLiteral("png"));
        QCOMPARE(pictureFormatOf(QStringLiteral("b.svg")), QStringLiteral("svg"));
        QCOMPARE(pictureFormatOf(QStringLiteral("c.d.pdf")), QStringLiteral("pdf"));
        QCOMPARE(pictureFormatOf(QStringLiteral("c.jpg")), QString());
        QCOMPARE(pictureFormatOf(QStringLiteral("plot")), QString());

        QCOMPARE(pictureScale(QSize(800, 600), QSize(800, 600)), 1.0);
        QCOMPARE(pictureScale(QSize(400, 300), QSize(800, 600)), 1.0); // never smaller than shown
        QCOMPARE(pictureScale(QSize(1600, 1200), QSize(800, 600)), 2.0);
        QCOMPARE(pictureScale(QSize(1920, 1080), QSize(800, 600)), 1.8); // the tighter side
    }

    void names()
    {
        auto plot = makePlot();
        QCOMPARE(plotPictureName(plot.get()), QStringLiteral("fig-8-diagonal-length-d-θ"));
        QCustomPlot bare;
        bare.setObjectName(QStringLiteral("fourbarPlot0"));
        QCOMPARE(plotPictureName(&bare), QStringLiteral("fourbarplot0"));
        QCustomPlot nameless;
        QCOMPARE(plotPictureName(&nameless), QStringLiteral("plot"));
    }

    void png_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<int>("dpi");
        QTest::newRow("as shown, 96 dpi") << QSize(640, 480) << 96;
        QTest::newRow("full HD, 300 dpi") << QSize(1920, 1080) << 300;
        QTest::newRow("4K, 600 dpi") << QSize(3840, 2160) << 600;
        QTest::newRow("small, 72 dpi") << QSize(300, 200) << 72;
        QTest::newRow("custom, 150 dpi") << QSize(1000, 1500) << 150;
    }

    void png()
    {
        QFETCH(QSize, size);
        QFETCH(int, dpi);
        auto plot = makePlot();
        PictureOptions options;
        options.size = size;
        options.dpi = dpi;
        QString error;
        const QByteArray bytes = plotPicture(plot.get(), QStringLiteral("png"), options, &error);
        QVERIFY2(!bytes.isEmpty(), qPrintable(error));
        QVERIFY(bytes.startsWith("\x89PNG"));
        QImage image;
        QVERIFY(image.loadFromData(bytes, "PNG"));
        QCOMPARE(image.size(), size);
        QVERIFY(std::abs(image.dotsPerMeterX() - dpi / 0.0254) <= 1.0);
        QVERIFY(std::abs(image.dotsPerMeterY() - dpi / 0.0254) <= 1.0);
        QCOMPARE(image.text(QStringLiteral("Title")), title);
        // a drawing, not a blank: the curve and the axes put dark pixels in it
        int dark = 0;
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2)
                dark += qGray(image.pixel(x, y)) < 128;
        }
        QVERIFY(dark > 100);
    }

    void pngScalesLikeTheScreen()
    {
        // Twice the size shown is the plot drawn twice as large: its dark pixels (text, axes,
        // curve) are about four times as many, not the same lines over a larger area.
        auto plot = makePlot();
        auto darkPixels = [&](const QSize &size) {
            PictureOptions options;
            options.size = size;
            QImage image;
            image.loadFromData(plotPicture(plot.get(), QStringLiteral("png"), options, nullptr), "PNG");
            int dark = 0;
            for (int y = 0; y < image.height(); ++y) {
                for (int x = 0; x < image.width(); ++x)
                    dark += qGray(image.pixel(x, y)) < 160;
            }
            return dark;
        };
        const double ratio = double(darkPixels(QSize(1280, 960))) / darkPixels(QSize(640, 480));
        QVERIFY2(ratio > 2.8 && ratio < 5.5, qPrintable(QString::number(ratio)));
    }

    void screenPlotUnchanged()
    {
        // The picture lays the plot out at its own size for the drawing only.
        auto plot = makePlot();
        QVERIFY(shownAndLaidOut(plot.get()));
        const QRect axisRect = plot->axisRect()->rect();
        const QCPRange x = plot->xAxis->range(), y = plot->yAxis->range();
        const QSize size = plot->size();
        const double clicked = plot->xAxis->pixelToCoord(axisRect.center().x());
        PictureOptions options;
        options.size = QSize(1900, 700);
        for (const QString &format : {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")})
            QVERIFY(!plotPicture(plot.get(), format, options, nullptr).isEmpty());
        QCoreApplication::processEvents(); // the queued replot
        QCOMPARE(plot->size(), size);
        QCOMPARE(plot->viewport(), QRect(QPoint(0, 0), size));
        QCOMPARE(plot->axisRect()->rect(), axisRect);
        QCOMPARE(plot->xAxis->range(), x);
        QCOMPARE(plot->yAxis->range(), y);
        // and a click still maps to the same coordinate
        QCOMPARE(plot->xAxis->pixelToCoord(axisRect.center().x()), clicked);
    }

    void videoFrameLeavesTheScreenPlot()
    {
        // A video's frame lays the plot out at the frame's size; a cursor moved afterwards
        // redraws its layer alone, with the layout it finds, so the layout must be the
        // screen's again or the cursor stands away from the pose.
        auto plot = makePlot();
        QVERIFY(shownAndLaidOut(plot.get()));
        const QRect axisRect = plot->axisRect()->rect();
        const QCPRange x = plot->xAxis->range(), y = plot->yAxis->range();
        const QImage frame = plotImage(plot.get(), QSize(640, 720), 1.5);
        QCOMPARE(frame.size(), QSize(960, 1080));
        QCoreApplication::processEvents(); // the queued replot
        QCOMPARE(plot->viewport(), plot->rect());
        QCOMPARE(plot->axisRect()->rect(), axisRect);
        QCOMPARE(plot->xAxis->range(), x);
        QCOMPARE(plot->yAxis->range(), y);
        QVERIFY(plotImage(nullptr, QSize(640, 720), 1.0).isNull());
    }

    void svg()
    {
        auto plot = makePlot();
        PictureOptions options;
        options.size = QSize(1200, 900);
        options.dpi = 300; // no meaning for an SVG
        QString error;
        const QByteArray bytes = plotPicture(plot.get(), QStringLiteral("svg"), options, &error);
        QVERIFY2(!bytes.isEmpty(), qPrintable(error));
        const Svg svg = readSvg(bytes);
        QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
        QCOMPARE(svg.root, QStringLiteral("svg"));
        QCOMPARE(svg.viewBox, QStringLiteral("0 0 1200 900"));
        QVERIFY2(svg.text.contains(xLabel), qPrintable(svg.text.left(400)));
        QVERIFY(svg.text.contains(yLabel));
        QVERIFY(svg.text.contains(title)); // also its <title>
        QVERIFY(!bytes.contains("<image")); // vector: no embedded raster
    }

    void pdf_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<int>("dpi");
        QTest::newRow("as shown, 96 dpi") << QSize(640, 480) << 96;
        QTest::newRow("full HD, 300 dpi") << QSize(1920, 1080) << 300;
        QTest::newRow("portrait, 150 dpi") << QSize(900, 1400) << 150;
    }

    void pdf()
    {
        QFETCH(QSize, size);
        QFETCH(int, dpi);
        auto plot = makePlot();
        PictureOptions options;
        options.size = size;
        options.dpi = dpi;
        QString error;
        const QByteArray bytes = plotPicture(plot.get(), QStringLiteral("pdf"), options, &error);
        QVERIFY2(!bytes.isEmpty(), qPrintable(error));
        QVERIFY(bytes.startsWith("%PDF"));
        QVERIFY(!bytes.contains("/Subtype /Image")); // vector: no embedded raster
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("plot.pdf"));
        QVERIFY(writeFile(path, bytes));
        const QString info = poppler(QStringLiteral("pdfinfo"), {path});
        if (info.isNull())
            QSKIP("pdfinfo (poppler-utils) is not installed");
        const QSizeF page = pdfPageSize(info);
        const QSizeF expected(size.width() * 72.0 / dpi, size.height() * 72.0 / dpi); // points
        QVERIFY2(std::abs(page.width() - expected.width()) <= 1.0 && std::abs(page.height() - expected.height()) <= 1.0,
            qPrintable(info));
        const QString text = poppler(QStringLiteral("pdftotext"), {path, QStringLiteral("-")});
        QVERIFY2(text.contains(xLabel), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("diagonal length")));
    }

    void refusals()
    {
        auto plot = makePlot();
        QString error;
        PictureOptions options;
        QVERIFY(plotPicture(plot.get(), QStringLiteral("jpg"), options, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral(".png, .svg or .pdf")), qPrintable(error));
        options.size = QSize(9000, 100);
        QVERIFY(plotPicture(plot.get(), QStringLiteral("png"), options, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("9000 × 100")), qPrintable(error));
        options.size = QSize(800, 600);
        options.dpi = 0;
        QVERIFY(plotPicture(plot.get(), QStringLiteral("pdf"), options, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("dpi")), qPrintable(error));
    }

    void atomicWriting()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("no such folder/plot.png"));
        QString error;
        QVERIFY(!savePictureFile(missing, QByteArray("picture"), &error));
        QVERIFY2(error.contains(QStringLiteral("plot.png")) && error.contains(QStringLiteral("could not")),
            qPrintable(error));
        QVERIFY(!QFileInfo::exists(missing));
        QVERIFY(!QFileInfo::exists(QFileInfo(missing).absolutePath()));

        const QString path = dir.filePath(QStringLiteral("plot.svg"));
        QVERIFY(writeFile(path, "old"));
        QVERIFY(savePictureFile(path, QByteArray("new picture"), &error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("new picture"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList {QStringLiteral("plot.svg")}); // no leftovers
    }

    void dialog()
    {
        PictureDialog dialog(QSize(700, 500), QStringLiteral("pdf"));
        QCOMPARE(dialog.presetSizes(),
            (QList<QSize> {QSize(700, 500), QSize(1400, 1000), QSize(1920, 1080), QSize(3840, 2160)}));
        QCOMPARE(dialog.sizeBox()->count(), 5);
        QCOMPARE(dialog.dpiBox()->count(), 5);
        QVERIFY(dialog.sizeBox()->itemText(0).contains(QStringLiteral("700 × 500")));

        dialog.sizeBox()->setCurrentIndex(2);
        dialog.dpiBox()->setCurrentIndex(dialog.dpiBox()->findData(300));
        QCOMPARE(dialog.options().size, QSize(1920, 1080));
        QCOMPARE(dialog.options().dpi, 300);
        QVERIFY(!dialog.widthBox()->isEnabled());
        QVERIFY2(dialog.physicalText().contains(QStringLiteral("162.6 × 91.4 mm")), qPrintable(dialog.physicalText()));

        dialog.sizeBox()->setCurrentIndex(4); // custom: the spin boxes, starting from the preset
        QVERIFY(dialog.widthBox()->isEnabled());
        dialog.widthBox()->setValue(1000);
        dialog.heightBox()->setValue(2000);
        QCOMPARE(dialog.options().size, QSize(1000, 2000));
        dialog.accept();

        PictureDialog next(QSize(700, 500), QStringLiteral("svg")); // remembers the last choice
        QCOMPARE(next.sizeBox()->currentIndex(), 4);
        QCOMPARE(next.options().size, QSize(1000, 2000));
        QCOMPARE(next.options().dpi, 300);
        QVERIFY(!next.dpiBox()->isEnabled()); // an SVG has no DPI
        next.sizeBox()->setCurrentIndex(0);
        next.accept();
    }

    void contextMenu()
    {
        auto plot = makePlot();
        int leftPresses = 0;
        connect(plot.get(), &QCustomPlot::mousePress, this,
            [&](QMouseEvent *event) { leftPresses += event->button() == Qt::LeftButton; });
        enablePictureExport(plot.get());
        QVERIFY(hasPictureExport(plot.get()));
        QCOMPARE(plot->contextMenuPolicy(), Qt::CustomContextMenu);
        plot->show();
        QVERIFY(QTest::qWaitForWindowExposed(plot.get()));
        QWindow *window = plot->windowHandle();
        QVERIFY(window);

        // the left button: the plot's own, no menu
        QTest::mouseClick(window, Qt::LeftButton, Qt::NoModifier, QPoint(300, 200));
        QCOMPARE(leftPresses, 1);
        QCoreApplication::processEvents();
        QVERIFY(!openMenu(plot.get()));

        // the right button: the menu with Save picture…
        QTest::mouseClick(window, Qt::RightButton, Qt::NoModifier, QPoint(300, 200));
        QTRY_VERIFY(openMenu(plot.get()));
        QMenu *menu = openMenu(plot.get());
        auto *save = menu->findChild<QAction *>(QStringLiteral("savePictureAction"));
        QVERIFY(save);
        QCOMPARE(save->text(), QStringLiteral("Save picture…"));
        QCOMPARE(leftPresses, 1);

        // Save picture…: the asker answers; the file is written
        QTemporaryDir dir;
        QString offered;
        QSize shown;
        const QString path = dir.filePath(QStringLiteral("plot.png"));
        setPictureAsker([&](QWidget *, const QString &, const QString &name, const QSize &size) {
            offered = name;
            shown = size;
            PictureOptions options;
            options.size = QSize(1280, 960);
            options.dpi = 150;
            return std::optional<PictureRequest>(PictureRequest {path, QStringLiteral("png"), options});
        });
        menu->close();
        save->trigger();
        QTRY_VERIFY(QFileInfo::exists(path));
        QCOMPARE(offered, QStringLiteral("fig-8-diagonal-length-d-θ"));
        QCOMPARE(shown, QSize(640, 480));
        QImage image(path);
        QCOMPARE(image.size(), QSize(1280, 960));
        QVERIFY(std::abs(image.dotsPerMeterX() - 150 / 0.0254) <= 1.0);

        // a name given; a file that cannot be written: said in a message box, nothing left
        enablePictureExport(plot.get(), QStringLiteral("stroke"));
        const QString missing = dir.filePath(QStringLiteral("gone/plot.pdf"));
        setPictureAsker([&](QWidget *, const QString &, const QString &name, const QSize &) {
            offered = name;
            return std::optional<PictureRequest>(PictureRequest {missing, QStringLiteral("pdf"), PictureOptions()});
        });
        QString message;
        QTimer closer;
        connect(&closer, &QTimer::timeout, this, [&] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
                message = box->text();
                box->close();
            }
        });
        closer.start(20);
        QCOMPARE(savePlotPictureAs(plot.get()), QString());
        QCOMPARE(offered, QStringLiteral("stroke"));
        QVERIFY2(message.contains(QStringLiteral("plot.pdf")), qPrintable(message));
        QVERIFY(!QFileInfo::exists(missing));
    }
};

QTEST_MAIN(TestPictureExport)
#include "tst_pictureexport.moc"
