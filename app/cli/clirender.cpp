#include "cli/clirender.h"

#include "camera3d.h"
#include "cli/cli.h"
#include "document/savefile.h"
#include "export/scenepicture.h"
#include "export/workspacepictures.h"
#include "labels3d.h"
#include "linkageview.h"
#include "mesh3d.h"
#include "renderer3d.h"
#include "report/texttable.h"
#include "scenepainter.h"
#include "text.h"

#include <QBuffer>
#include <QByteArray>
#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QImage>
#include <QMarginsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRectF>
#include <QStandardPaths>
#include <QSvgGenerator>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace pkm::cli {

using namespace report;

namespace {

/// The longer side of a PDF page, mm: A4's, so a picture prints on A4 at full width.
constexpr double pdfLongerSideMillimetres = 297.0;
/// The PDF device's resolution, device units per inch.
constexpr int pdfResolution = 300;
/// The SVG's resolution: a style pixel is a CSS pixel.
constexpr int svgResolution = 96;
/// The virtual screen of Xvfb; the picture is drawn offscreen, so its size does not matter.
constexpr const char *xvfbServerArguments = "-screen 0 1280x1024x24";

/// The command to run again under Xvfb, set by enableXvfbRerun().
struct XvfbRerun {
    QString program;
    QStringList arguments;
};
std::optional<XvfbRerun> &xvfbRerun()
{
    static std::optional<XvfbRerun> rerun;
    return rerun;
}

bool underXvfb()
{
    return qEnvironmentVariableIsSet(underXvfbVariable);
}

// -- names -----------------------------------------------------------------------------------

Camera3D::StandardView standardView(const std::string &camera)
{
    if (camera == "front")
        return Camera3D::StandardView::Front;
    if (camera == "top")
        return Camera3D::StandardView::Top;
    if (camera == "side")
        return Camera3D::StandardView::Side;
    return Camera3D::StandardView::Isometric;
}

std::string cameraTitle(const std::string &camera)
{
    return camera == "iso" ? std::string("isometric") : camera;
}

/// "1600 × 1200 pixels, 3D isometric view, perspective"
std::string pictureDescription(const Invocation &invocation, const std::string &extension)
{
    std::string text;
    const std::string size = std::to_string(invocation.width) + " × " + std::to_string(invocation.height);
    const bool is3d = invocation.view.value_or("2d") == "3d";
    if (extension == "pdf") {
        const double longer = std::max(invocation.width, invocation.height);
        text.append(fixedText(pdfLongerSideMillimetres * invocation.width / longer, 1))
            .append(" × ")
            .append(fixedText(pdfLongerSideMillimetres * invocation.height / longer, 1))
            .append(" mm page, ");
        text.append(is3d ? "a " + size + "-pixel picture, " : std::string("vector, "));
    } else if (extension == "svg") {
        text.append(size).append(is3d ? "-pixel picture embedded, " : ", vector, ");
    } else {
        text.append(size).append(" pixels, ");
    }
    if (is3d) {
        text.append("3D ").append(cameraTitle(invocation.camera.value_or("iso"))).append(" view, ");
        text.append(invocation.orthographic ? "orthographic" : "perspective");
    } else {
        text.append("2D view");
    }
    return text;
}

// -- drawing -------------------------------------------------------------------------------

/// The 3D picture: a standard camera fitted to the model above a band of `band` pixels at the
/// bottom (for the caption). A null image with `error` when OpenGL 3.3 is not to be had.
QImage render3d(const PreparedDesign &prepared, const Invocation &invocation, double band, QString &error)
{
    const Scene3D scene = prepared.mechanism->scene3d(prepared.pose);
    const int height = invocation.height;
    band = std::clamp(band, 0.0, 0.25 * height);
    Camera3D camera;
    camera.setProjection(
        invocation.orthographic ? Camera3D::Projection::Orthographic : Camera3D::Projection::Perspective);
    camera.setStandardView(standardView(invocation.camera.value_or("iso")));
    const int fitted = std::max(1, static_cast<int>(std::lround(height - band)));
    camera.setViewport(invocation.width, fitted);
    // A still picture: fitted to the parts in this pose, not to the extent over the whole
    // motion that keeps the interactive view steady.
    Eigen::AlignedBox3d parts;
    for (const Solid &solid : scene.solids)
        parts.extend(solidBounds(solid));
    camera.fit(parts.isEmpty() ? modelBounds(scene) : parts);
    if (fitted < height) {
        // The full height at the same scale, with the fitted part at the top.
        const double toRadians = std::numbers::pi / 180.0;
        const double tangent = std::tan(0.5 * camera.fieldOfViewDegrees() * toRadians) * height / fitted;
        camera.setFieldOfViewDegrees(2.0 * std::atan(tangent) / toRadians);
        camera.setViewport(invocation.width, height);
        camera.pan(0.0, -0.5 * (height - fitted));
    }
    QImage image = Renderer3D::renderOffscreen(scene, camera, QSize(invocation.width, invocation.height), &error);
    if (!image.isNull()) {
        // The points' names, as the 3D view draws them, at the caption's size.
        QPainter painter(&image);
        paintLabels3D(painter, scene.labels, camera, pictures::captionFont(SceneStyle()));
    }
    if (image.isNull()) {
        // The probe tells why a context cannot be had; renderOffscreen() why it failed later.
        const QString problem = Renderer3D::probeOpenGL();
        if (!problem.isEmpty())
            error = problem;
        if (error.isEmpty())
            error = QStringLiteral("The OpenGL renderer returned no picture.");
    }
    return image;
}

/// An image as a page of a PDF or an SVG: vector output holding the raster picture, or the
/// 2D drawing itself when `image` is null.
QByteArray vectorFile(const std::string &extension, const Invocation &invocation, const QString &title,
    const QImage &image, const Scene &scene, const QString &caption)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    const QString description = QStringLiteral("Drawn by pkm render (PKM Studio %1)").arg(QStringLiteral(PKM_VERSION));
    SceneStyle style;
    if (extension == "pdf") {
        const double longer = std::max(invocation.width, invocation.height);
        const QSizeF page(pdfLongerSideMillimetres * invocation.width / longer,
            pdfLongerSideMillimetres * invocation.height / longer);
        QPdfWriter pdf(&buffer);
        pdf.setResolution(pdfResolution);
        // A custom QPageSize is taken as given in portrait: Landscape would swap its sides.
        pdf.setPageLayout(QPageLayout(QPageSize(page, QPageSize::Millimeter, QString(), QPageSize::ExactMatch),
            QPageLayout::Portrait, QMarginsF()));
        pdf.setTitle(title);
        pdf.setCreator(description);
        QPainter painter(&pdf);
        if (!painter.isActive())
            return {};
        const QRectF area(0.0, 0.0, pdf.width(), pdf.height());
        if (!image.isNull()) {
            painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
            painter.drawImage(area, image);
        } else {
            style.pixelSize = area.width() / invocation.width; // the PNG's proportions
            pictures::paintScenePicture(painter, area, scene, style, caption);
        }
        painter.end();
    } else {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(QSize(invocation.width, invocation.height));
        svg.setViewBox(QRectF(0.0, 0.0, invocation.width, invocation.height));
        svg.setResolution(svgResolution);
        svg.setTitle(title);
        svg.setDescription(description);
        QPainter painter(&svg);
        if (!painter.isActive())
            return {};
        const QRectF area(0.0, 0.0, invocation.width, invocation.height);
        if (!image.isNull())
            painter.drawImage(area, image);
        else
            pictures::paintScenePicture(painter, area, scene, style, caption);
        painter.end();
    }
    return bytes;
}

// -- Xvfb ----------------------------------------------------------------------------------

/// "No OpenGL context …." → "no OpenGL context …" for the middle of a sentence.
std::string inSentence(const QString &reason)
{
    std::string text = reason.trimmed().toStdString();
    while (!text.empty() && (text.back() == '.' || text.back() == ' '))
        text.pop_back();
    if (text.size() > 1 && text[0] >= 'A' && text[0] <= 'Z' && text[1] >= 'a' && text[1] <= 'z')
        text[0] = static_cast<char>(text[0] - 'A' + 'a');
    return text;
}

/// Runs the command again under xvfb-run; `noGl` says why this process cannot render (empty:
/// there is no display at all).
int rerunUnderXvfb(const XvfbRerun &rerun, const QString &noGl, std::FILE *out, std::FILE *err)
{
    const QString xvfbRun = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
    if (xvfbRun.isEmpty()) {
        if (noGl.isEmpty()) {
            printError(err,
                "3D pictures need OpenGL: there is no display and xvfb-run is missing (install the Debian "
                "package xvfb).");
        } else {
            printError(err,
                "3D pictures need OpenGL 3.3: " + inSentence(noGl)
                    + ", and xvfb-run, for a virtual display, is missing (install the Debian package xvfb).");
        }
        return CliNoSolution;
    }
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QString::fromLatin1(underXvfbVariable), QStringLiteral("1"));
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
    QProcess process;
    process.setProcessEnvironment(environment);
    process.setProcessChannelMode(QProcess::ForwardedOutputChannel); // stdout goes straight through
    process.setInputChannelMode(QProcess::ForwardedInputChannel);
    QStringList arguments {
        QStringLiteral("-a"), QStringLiteral("-s"), QString::fromLatin1(xvfbServerArguments), rerun.program};
    arguments += rerun.arguments;
    std::fflush(out);
    process.start(xvfbRun, arguments);
    if (!process.waitForStarted(-1)) {
        printError(
            err, "3D pictures need OpenGL: xvfb-run could not be started (" + inSentence(process.errorString()) + ").");
        return CliNoSolution;
    }
    process.waitForFinished(-1);
    const QByteArray messages = process.readAllStandardError();
    if (process.exitStatus() != QProcess::NormalExit) {
        printError(err, "3D pictures need OpenGL: the renderer under xvfb-run stopped unexpectedly.");
        return CliNoSolution;
    }
    const int status = process.exitCode();
    if (const qsizetype at = messages.indexOf("xvfb-run: error: "); at >= 0) {
        const QString why = QString::fromUtf8(messages.mid(at + 17)).section(QLatin1Char('\n'), 0, 0);
        printError(
            err, "3D pictures need OpenGL: xvfb-run could not start a virtual display (" + inSentence(why) + ").");
        return CliNoSolution;
    }
    std::fwrite(messages.constData(), 1, static_cast<std::size_t>(messages.size()), err);
    std::fflush(err);
    if (status >= CliSuccess && status <= CliNoSolution)
        return status;
    printError(err,
        "3D pictures need OpenGL: the renderer under xvfb-run stopped with status " + std::to_string(status) + ".");
    return CliNoSolution;
}

/// The drawings' numbers while a picture is drawn: the typographic minus (U+2212), as the
/// application's drawings print it ("γ₁ = −5°"), not the hyphen that the command line's text
/// and JSON keep for scripts; and English numbers and units in the caption whatever the
/// system's locale, as everything else the command line writes. What was installed comes back
/// at the end: runCli() also runs inside other programs (the tests).
class PictureNumbers
{
public:
    PictureNumbers()
        : m_previous(text::installed())
    {
        text::Hooks hooks = m_previous;
        hooks.minusSign = "\u2212";
        text::install(std::move(hooks));
        QLocale english(QLocale::English, QLocale::UnitedStates);
        english.setNumberOptions(QLocale::OmitGroupSeparator);
        QLocale::setDefault(english);
    }
    ~PictureNumbers()
    {
        text::install(m_previous);
        QLocale::setDefault(m_locale);
    }
    PictureNumbers(const PictureNumbers &) = delete;
    PictureNumbers &operator=(const PictureNumbers &) = delete;

private:
    text::Hooks m_previous;
    QLocale m_locale; ///< the default before
};

} // namespace

// -- pictures ------------------------------------------------------------------------------

QString renderCaption(const PreparedDesign &prepared)
{
    return pictures::poseCaption(*prepared.mechanism, prepared.pose,
                       QFileInfo(QString::fromStdString(prepared.origin)).fileName());
}

// -- the command ---------------------------------------------------------------------------

void enableXvfbRerun(const QString &program, const QStringList &arguments)
{
    xvfbRerun() = XvfbRerun {program, arguments};
}

RenderSetup prepareRenderPlatform(const std::vector<std::string> &arguments)
{
    RenderSetup setup;
    const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM").trimmed();
    if (!arguments.empty() && arguments.front() == "dxf") {
        // The DXF drawing is laid out by the screen's label layout, which measures text with
        // QtGui's fonts: a QGuiApplication on the offscreen platform, no display.
        if (platform.isEmpty())
            qputenv("QT_QPA_PLATFORM", "offscreen");
        setup.quietQt = true;
        setup.guiApplication = true;
        return setup;
    }
    if (arguments.empty() || (arguments.front() != "render" && arguments.front() != "sheet"))
        return setup;
    const auto parsed = parseArguments(arguments);
    if (!parsed || parsed->help || (parsed->command != Command::Render && parsed->command != Command::Sheet))
        return setup; // the usage error or the help, from a QCoreApplication
    setup.quietQt = true;
    if (parsed->command == Command::Sheet || parsed->view.value_or("2d") != "3d") {
        // A picture needs fonts and QPainter, never a display: the same pixels everywhere.
        if (platform.isEmpty())
            qputenv("QT_QPA_PLATFORM", "offscreen");
        setup.guiApplication = true;
        return setup;
    }
    if (underXvfb()) { // the parent set xcb and Xvfb the display
        setup.guiApplication = true;
        return setup;
    }
    setup.xvfbRerun = true;
    const bool x11 = !qEnvironmentVariableIsEmpty("DISPLAY");
    const bool wayland = !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    if (!platform.isEmpty()) {
        // "xcb", "wayland;xcb", "offscreen:option=…": the first platform decides.
        const QString first = platform.section(QLatin1Char(';'), 0, 0).section(QLatin1Char(':'), 0, 0).trimmed();
        const bool noOpenGl = first == QLatin1String("offscreen") || first == QLatin1String("minimal")
            || first == QLatin1String("vnc") || first == QLatin1String("linuxfb");
        const bool noServer
            = (first == QLatin1String("xcb") && !x11) || (first.startsWith(QLatin1String("wayland")) && !wayland);
        setup.guiApplication = !noOpenGl && !noServer; // else: validate here, render under Xvfb
        return setup;
    }
    if (!x11 && !wayland)
        return setup; // no display: validate here, render under Xvfb
    if (!wayland) // an X server that does not answer: offscreen, which has no OpenGL, then Xvfb
        qputenv("QT_QPA_PLATFORM", "xcb;offscreen");
    setup.guiApplication = true;
    return setup;
}

int runRenderCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err)
{
    const bool is3d = invocation.view.value_or("2d") == "3d";
    const bool gui = qobject_cast<QGuiApplication *>(QCoreApplication::instance()) != nullptr;
    const std::optional<XvfbRerun> rerun = underXvfb() ? std::nullopt : xvfbRerun();
    if (is3d && !gui && rerun)
        return rerunUnderXvfb(*rerun, {}, out, err); // it prints the note, if any
    if (!gui) {
        printError(err,
            is3d ? "3D pictures need OpenGL: there is no display (run 'pkm render', which uses xvfb-run without "
                   "one)."
                 : "'pkm render' draws with Qt's GUI module: it needs a QGuiApplication, which 'pkm' makes.");
        return is3d ? CliNoSolution : CliOutputError;
    }

    const PictureNumbers numbers; // in the scene's labels and the caption
    const std::string &path = *invocation.output;
    const std::string extension = fileExtension(path);
    if (extension == "gif" || extension == "mp4" || extension == "webm")
        return runRenderAnimation(prepared, invocation, out, err);
    const QString caption = invocation.caption ? renderCaption(prepared) : QString();
    const QString title = renderCaption(prepared);

    QImage image; // the 3D picture, or the 2D one for PNG
    Scene scene;
    if (is3d) {
        QString error;
        const double band = caption.isEmpty() ? 0.0 : pictures::captionBand(SceneStyle());
        image = render3d(prepared, invocation, band, error);
        if (image.isNull() && rerun)
            return rerunUnderXvfb(*rerun, error, out, err); // another chance on a virtual display
        if (!prepared.note.empty())
            printError(err, "note: " + prepared.note);
        if (image.isNull()) {
            printError(err, "3D pictures need OpenGL 3.3: " + inSentence(error) + ".");
            return CliNoSolution;
        }
        if (!caption.isEmpty()) {
            QPainter painter(&image);
            pictures::paintCaption(painter, QRectF(image.rect()), caption, SceneStyle(), 0.0);
        }
    } else {
        if (!prepared.note.empty())
            printError(err, "note: " + prepared.note);
        scene = prepared.mechanism->scene(prepared.pose);
        if (extension == "png") {
            image = QImage(invocation.width, invocation.height, QImage::Format_RGB32);
            image.fill(SceneStyle().background);
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing, true);
            pictures::paintScenePicture(painter, QRectF(image.rect()), scene, SceneStyle(), caption);
        }
    }

    std::optional<std::string> failure;
    if (extension == "png") {
        image.setText(QStringLiteral("Title"), title);
        image.setText(QStringLiteral("Software"), QStringLiteral("PKM Studio " PKM_VERSION " (pkm render)"));
        failure = pictures::savePng(path, image);
    } else {
        const QByteArray bytes = vectorFile(extension, invocation, title, is3d ? image : QImage(), scene, caption);
        failure = bytes.isEmpty() ? std::optional<std::string>(
                      "Cannot write '" + path + "': the ." + extension + " picture could not be drawn.")
                                  : files::saveBytes(path, bytes);
    }
    if (failure) {
        printError(err, *failure);
        return CliOutputError;
    }
    std::string line("Wrote ");
    line.append(path).append(" (").append(pictureDescription(invocation, extension)).append(")\n");
    return printOutput(out, err, line);
}

} // namespace pkm::cli
