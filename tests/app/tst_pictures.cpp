// Pictures from the main window (issue 7): every plot and map of every kind of mechanism has
// the right-click "Save picture…" (and a right click changes nothing else), and File ▸ Save 2D
// View Picture… writes the linkage as PNG (size, DPI), SVG (the joints' names as text) and PDF
// (the page from the pixels and the DPI).

#include "gui/mainwindow.h"

#include "export/scenepicture.h"
#include "document/designsession.h"
#include "document/document.h"
#include "document/language.h"
#include "drawlist.h"
#include "linkageview.h"
#include "scenelayout.h"
#include "pictureexport.h"
#include "gui/viewpicture.h"
#include "workspacemapview.h"
#include "kinds/workspacepanel.h"
#include "support/app.h"
#include "support/process.h"

#include <qcustomplot.h>

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QXmlStreamReader>

#include <cmath>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {

/// The text of every <text> element of an SVG, or a null list when it is not valid XML with an
/// <svg> root.
QStringList svgTexts(const QByteArray &bytes, QString *error)
{
    QStringList texts;
    QXmlStreamReader reader(bytes);
    bool root = false;
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.isStartElement() && !root) {
            root = true;
            if (reader.name() != QLatin1String("svg")) {
                *error = QStringLiteral("root <%1>").arg(reader.name().toString());
                return {};
            }
        }
        if (reader.isStartElement() && reader.name() == QLatin1String("text"))
            texts << reader.readElementText(QXmlStreamReader::IncludeChildElements).trimmed();
    }
    if (reader.hasError()) {
        *error = reader.errorString();
        return {};
    }
    return texts;
}

} // namespace

class TestPictures : public QObject
{
    Q_OBJECT

private:
    MainWindow *m_window = nullptr;

    QAction *saveViewAction() const
    {
        QMenu *file = m_window->menuBar()->actions().value(0)->menu();
        for (QAction *action : file->actions()) {
            if (action->objectName() == QLatin1String("saveViewPictureAction"))
                return action;
        }
        return nullptr;
    }

private slots:
    void initTestCase()
    {
        m_window = freshMainWindow({1800, 1000});
        QVERIFY(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void cleanup() { setPictureAsker({}); }

    void everyPlotHasTheMenu_data()
    {
        addPresetPerKindRows(); // every kind of mechanism, as it comes with the program
    }

    void everyPlotHasTheMenu()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(m_window->openDesign(preset));
        QCoreApplication::processEvents();
        // the generic panel's map, or the one inside the kind's own panel (the leg library's)
        WorkspaceMapView *map = m_window->workspacePanel()->mapView();
        for (WorkspaceMapView *shown : m_window->findChildren<WorkspaceMapView *>()) {
            if (shown->isVisible())
                map = shown;
        }
        if (map->isVisible()) { // its picture is to show the map, not "computing…"
            QSignalSpy ready(map, &WorkspaceMapView::mapReady);
            QVERIFY(!map->busy() || ready.wait(20000));
        }
        const QList<QCustomPlot *> plots = m_window->findChildren<QCustomPlot *>();
        QVERIFY(plots.size() >= 8 + 5 + 3); // П-joint, four-bar, maps and the O-X glide's views
        int visible = 0;
        for (QCustomPlot *plot : plots) {
            QVERIFY2(hasPictureExport(plot), qPrintable(plotPictureName(plot)));
            QCOMPARE(plot->contextMenuPolicy(), Qt::CustomContextMenu);
            if (!plot->isVisible() || plot->width() < 50 || plot->height() < 50)
                continue;
            ++visible;
            // A right click opens the menu and changes nothing: no pose, no undo step.
            const Pose before = m_window->document()->pose();
            const int steps = m_window->document()->undoStack()->count();
            const QPoint centre = plot->mapTo(m_window, plot->rect().center());
            QTest::mouseClick(m_window->windowHandle(), Qt::RightButton, Qt::NoModifier, centre);
            QTRY_VERIFY2(openMenu(plot), qPrintable(plotPictureName(plot)));
            QMenu *menu = openMenu(plot);
            QAction *save = menu->findChild<QAction *>(QStringLiteral("savePictureAction"));
            QVERIFY(save);
            QCOMPARE(save->text(), QStringLiteral("Save picture…"));
            menu->close();
            QCoreApplication::processEvents();
            QVERIFY(m_window->document()->pose().inputs.isApprox(before.inputs));
            QVERIFY(m_window->document()->pose().outputs.isApprox(before.outputs));
            QCOMPARE(m_window->document()->undoStack()->count(), steps);

            // and its picture has the size asked for, the plot on screen left as it was
            plot->replot();
            const QCPRange x = plot->xAxis->range(), y = plot->yAxis->range();
            const QRect axisRect = plot->axisRect()->rect();
            PictureOptions options;
            options.size = QSize(1920, 1080);
            options.dpi = 300;
            QString error;
            QImage image;
            QVERIFY(image.loadFromData(plotPicture(plot, QStringLiteral("png"), options, &error), "PNG"));
            QCOMPARE(image.size(), QSize(1920, 1080));
            QVERIFY(std::abs(image.dotsPerMeterX() - 300 / 0.0254) <= 1.0);
            QCoreApplication::processEvents(); // the plot's queued replot
            QCOMPARE(plot->axisRect()->rect(), axisRect);
            const double tolerance = 1e-6 * x.size();
            QVERIFY(std::abs(plot->xAxis->range().lower - x.lower) < tolerance);
            QVERIFY(std::abs(plot->xAxis->range().upper - x.upper) < tolerance);
            QVERIFY(std::abs(plot->yAxis->range().lower - y.lower) < 1e-6 * y.size());
            QVERIFY(std::abs(plot->yAxis->range().upper - y.upper) < 1e-6 * y.size());
            if (plot == map->plot()) { // the coloured cells are in the picture
                int coloured = 0;
                for (int y = 0; y < image.height(); y += 4) {
                    for (int x = 0; x < image.width(); x += 4)
                        coloured += QColor(image.pixel(x, y)).hsvSaturation() > 120;
                }
                QVERIFY2(coloured > 2000, qPrintable(QString::number(coloured)));
            }
        }
        QVERIFY2(visible >= 1, qPrintable(preset));
    }

    void saveViewPictureFromTheMenu()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        QAction *action = saveViewAction();
        QVERIFY(action);
        QVERIFY(action->text().contains(QStringLiteral("Save 2D &View Picture")));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("linkage.png"));
        QString offered;
        QSize shown;
        setPictureAsker([&](QWidget *, const QString &, const QString &name, const QSize &size) {
            offered = name;
            shown = size;
            PictureOptions options;
            options.size = QSize(1600, 900);
            options.dpi = 150;
            return std::optional<PictureRequest>(PictureRequest {path, QStringLiteral("png"), options});
        });
        action->trigger();
        QVERIFY(QFileInfo::exists(path));
        QCOMPARE(offered, QStringLiteral("fourbar-example-2d"));
        QCOMPARE(shown, m_window->linkageView()->size());
        QVERIFY2(
            m_window->lastStatus().contains(QStringLiteral("Wrote the 2D view")), qPrintable(m_window->lastStatus()));
        const QImage image(path);
        QCOMPARE(image.size(), QSize(1600, 900));
        QVERIFY(std::abs(image.dotsPerMeterX() - 150 / 0.0254) <= 1.0);
        QVERIFY(std::abs(image.dotsPerMeterY() - 150 / 0.0254) <= 1.0);
        QVERIFY2(image.text(QStringLiteral("Title")).startsWith(m_window->session()->displayName()),
            qPrintable(image.text(QStringLiteral("Title"))));

        // a folder that does not exist: a message box says so, and no file is left
        const QString missing = dir.filePath(QStringLiteral("gone/linkage.svg"));
        setPictureAsker([&](QWidget *, const QString &, const QString &, const QSize &) {
            return std::optional<PictureRequest>(PictureRequest {missing, QStringLiteral("svg"), PictureOptions()});
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
        action->trigger();
        closer.stop();
        QVERIFY2(message.contains(QStringLiteral("linkage.svg")), qPrintable(message));
        QVERIFY(!QFileInfo::exists(missing));
    }

    /// A still picture's labels are whole: the drawing is fitted smaller where a label would
    /// be cut at the edge (MOMA's γ₁ and γ₂ beside the guides, the O-X glide's "B · 2a"), as Fit
    /// does on the screen; an animation's frames keep the motion range's scale.
    void stillPicturesKeepLabelsWhole()
    {
        int cutByMotionRange = 0;
        for (const char *preset : {"moma-3a", "oxglide-prototype", "fivebar-example", "pjoint-prototype", "fourbar-example"}) {
            QVERIFY(m_window->openDesign(QString::fromLatin1(preset)));
            const Scene scene = m_window->document()->mechanism()->scene(m_window->document()->pose());
            SceneStyle style;
            style.showHandles = false;
            for (const QSize size : {QSize(372, 500), QSize(640, 480)}) {
                QImage image(size, QImage::Format_RGB32);
                const QRectF area(image.rect());
                for (const auto fit : {pictures::PictureFit::LabelsWhole, pictures::PictureFit::MotionRange}) {
                    const ViewMapping mapping = pictures::pictureMapping(area, scene, style, fit, &image);
                    QStringList cut;
                    for (const drawing::Primitive &item : drawing::layoutScene(scene, mapping, style).items) {
                        const auto *text = std::get_if<drawing::Text>(&item.shape);
                        if (!text || !drawing::shownOnScreen(item.medium))
                            continue;
                        drawing::DrawList one;
                        one.add(*text, item.layer, item.medium);
                        // half in, half out; a far point's label (an instant centre) is wholly out
                        const QRectF box = drawing::bounds(one, false);
                        if (box.intersects(area) && !area.contains(box))
                            cut << text->text;
                    }
                    if (fit == pictures::PictureFit::MotionRange) {
                        cutByMotionRange += int(cut.size());
                        continue;
                    }
                    QVERIFY2(cut.isEmpty(), qPrintable(QStringLiteral("%1 at %2×%3: %4 cut")
                        .arg(QLatin1String(preset)).arg(size.width()).arg(size.height()).arg(cut.join(QStringLiteral(", ")))));
                }
            }
        }
        QCOMPARE_GT(cutByMotionRange, 0); // the motion range alone cuts some: the check sees it
    }

    void viewPictures()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        const Mechanism &mechanism = *m_window->document()->mechanism();
        const Pose &pose = m_window->document()->pose();
        const QString name = m_window->session()->displayName();
        const QString caption = pictures::poseCaption(mechanism, pose, name);
        const SceneStyle style = m_window->linkageView()->sceneStyle();
        const QSize shown = m_window->linkageView()->size();
        PictureOptions options;
        options.size = QSize(1920, 1080);
        options.dpi = 300;
        QString error;

        const QByteArray png
            = viewpicture::posePicture(mechanism, pose, name, style, QStringLiteral("png"), options, shown, &error);
        QImage image;
        QVERIFY2(image.loadFromData(png, "PNG"), qPrintable(error));
        QCOMPARE(image.size(), QSize(1920, 1080));
        QVERIFY(std::abs(image.dotsPerMeterX() - 300 / 0.0254) <= 1.0);
        QCOMPARE(image.text(QStringLiteral("Title")), caption);

        const QByteArray svg
            = viewpicture::posePicture(mechanism, pose, name, style, QStringLiteral("svg"), options, shown, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));
        QString xmlError;
        const QStringList texts = svgTexts(svg, &xmlError);
        QVERIFY2(xmlError.isEmpty(), qPrintable(xmlError));
        QVERIFY2(texts.contains(QStringLiteral("A")) && texts.contains(QStringLiteral("D")),
            qPrintable(texts.join(QStringLiteral(" | "))));
        QVERIFY(svg.contains("viewBox=\"0 0 1920 1080\""));
        QVERIFY(!svg.contains("<image")); // vector

        const QByteArray pdf
            = viewpicture::posePicture(mechanism, pose, name, style, QStringLiteral("pdf"), options, shown, &error);
        QVERIFY2(pdf.startsWith("%PDF"), qPrintable(error));
        QVERIFY(!pdf.contains("/Subtype /Image"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("linkage.pdf"));
        QVERIFY(savePictureFile(path, pdf, &error));
        const QString info = poppler(QStringLiteral("pdfinfo"), {path});
        if (info.isNull())
            QSKIP("pdfinfo (poppler-utils) is not installed");
        const QSizeF page = pdfPageSize(info);
        QVERIFY2(
            std::abs(page.width() - 1920 * 72.0 / 300) <= 1.0 && std::abs(page.height() - 1080 * 72.0 / 300) <= 1.0,
            qPrintable(info));
        const QString text = poppler(QStringLiteral("pdftotext"), {path, QStringLiteral("-")});
        QVERIFY2(text.contains(name), qPrintable(text)); // the caption
        QVERIFY2(QRegularExpression(QStringLiteral("(^|\\s)A(\\s|$)")).match(text).hasMatch(), qPrintable(text));
    }

    /// A picture's or a video's caption writes the pose as the window's read-out does: in the
    /// language's decimal sign and units, with the typographic minus. A Russian video read
    /// "q₁ = 21.95 mm" and an English one "θ = -7.40°".
    void captionSpeaksTheLanguage()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        const Mechanism &mechanism = *m_window->document()->mechanism();
        QVERIFY(m_window->document()->setVariable(mechanism.variableIndex("theta"), -7.4 * std::numbers::pi / 180.0));
        const Pose &pose = m_window->document()->pose();
        const QString english = pictures::poseCaption(mechanism, pose, QString());
        QCOMPARE(english, QStringLiteral("d = 174.77 mm, θ = −7.40°")); // d = 170·√(1.16 + 0.8·sin(−7.4°))
        language::apply(QStringLiteral("ru"));
        const QString russian = pictures::poseCaption(mechanism, pose, QStringLiteral("урок"));
        language::apply(QStringLiteral("en"));
        QCOMPARE(russian, QStringLiteral("урок — d = 174,77 мм, θ = −7,40°"));
    }

    /// The five-bar's caption in a video's half frame ended "y = 1…": it goes on two lines,
    /// broken after a comma, and is cut short only where two lines are not enough.
    void longCaptionTakesTwoLines()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fivebar-example")));
        const Mechanism &mechanism = *m_window->document()->mechanism();
        const QString caption = pictures::poseCaption(mechanism, m_window->document()->pose(), QString());
        const QFontMetricsF metrics(pictures::captionFont(SceneStyle()));
        const double width = metrics.horizontalAdvance(caption);
        const QStringList whole = pictures::captionLines(caption, metrics, width + 1.0);
        QCOMPARE(whole, QStringList {caption});
        const QStringList two = pictures::captionLines(caption, metrics, 0.75 * width);
        QCOMPARE(two.size(), 2);
        QVERIFY2(two[0].endsWith(QLatin1Char(',')) && !two.join(QString()).contains(QChar(0x2026)), qPrintable(two.join(QLatin1Char('|'))));
        QCOMPARE(two[0] + QLatin1Char(' ') + two[1], caption);
        for (const QString &line : two)
            QVERIFY(metrics.horizontalAdvance(line) <= 0.75 * width);
        const QStringList cut = pictures::captionLines(caption, metrics, 0.2 * width);
        QVERIFY(cut.join(QString()).contains(QChar(0x2026)));
    }

    void suggestedNames()
    {
        QCOMPARE(viewpicture::suggestedName(QString(), QStringLiteral("moma-3a")), QStringLiteral("moma-3a-2d"));
        QCOMPARE(viewpicture::suggestedName(QStringLiteral("/home/u/my design.pkm.json"), QString()),
            QStringLiteral("my design-2d"));
        QCOMPARE(viewpicture::suggestedName(QString(), QString()), QStringLiteral("linkage-2d"));
    }
};

QTEST_MAIN(TestPictures)
#include "tst_pictures.moc"
