// Pictures of the plots and views (docs/architecture.md, drawing): PNG, SVG or PDF at a size and
// resolution the user picks, the plots' context menus and the file names suggested from their
// titles; the dialog that asks is in picturedialog.cpp.

#include "pictureexport.h"
#include "pictureexportinternal.h"

#include <qcustomplot.h>

#include <QBuffer>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QMarginsF>
#include <QMenu>
#include <QMessageBox>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QPointer>
#include <QSaveFile>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSvgGenerator>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace pkm {

namespace pictureexport {

QString count(int value)
{
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale.toString(value);
}

DialogMemory &memory()
{
    static DialogMemory remembered;
    return remembered;
}

} // namespace pictureexport

namespace {

/// Laying a plot out at another size moves its layout there and may move its ranges (a map
/// keeps equal scales on both axes when laid out): both go back for the screen once the
/// picture is drawn, or the plot on screen kept the picture's margins and its cursor stood
/// away from the pose.
class ScreenLayoutKept
{
public:
    explicit ScreenLayoutKept(QCustomPlot *plot)
        : m_plot(plot)
    {
        for (QCPAxisRect *rect : plot->axisRects()) {
            for (QCPAxis *axis : rect->axes())
                m_ranges.emplace_back(axis, axis->range());
        }
    }
    ~ScreenLayoutKept()
    {
        for (const auto &[axis, range] : m_ranges) {
            if (axis && (axis->range().lower != range.lower || axis->range().upper != range.upper))
                axis->setRange(range);
        }
        if (m_plot)
            m_plot->replot(QCustomPlot::rpQueuedReplot);
    }
    ScreenLayoutKept(const ScreenLayoutKept &) = delete;
    ScreenLayoutKept &operator=(const ScreenLayoutKept &) = delete;

private:
    QPointer<QCustomPlot> m_plot;
    std::vector<std::pair<QPointer<QCPAxis>, QCPRange>> m_ranges;
};

using pictureexport::count;
using pictureexport::DialogMemory;
using pictureexport::memory;

constexpr const char *exportProperty = "pkmPictureExport";
constexpr const char *nameProperty = "pkmPictureName";
constexpr double metresPerInch = 0.0254;
constexpr int longestName = 60; ///< characters of a suggested file name

bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}


int dotsPerMetre(int dpi)
{
    return static_cast<int>(std::lround(dpi / metresPerInch));
}

/// The size a plot is seen at: its own once laid out, never below its minimum.
QSize shownSize(const QCustomPlot *plot)
{
    return plot->size().expandedTo(plot->minimumSize()).expandedTo(QSize(minimumPictureSide, minimumPictureSide));
}

/// The first title of the plot's layout, or empty.
QString plotTitle(const QCustomPlot *plot)
{
    for (QCPLayoutElement *element : plot->plotLayout()->elements(true)) {
        if (const auto *text = qobject_cast<QCPTextElement *>(element); text && !text->text().trimmed().isEmpty())
            return text->text().trimmed();
    }
    return {};
}

/// "Fig. 8 — diagonal length d(θ)" → "fig-8-diagonal-length-d-θ": letters and digits of any
/// script, everything else one hyphen.
QString slug(const QString &text)
{
    QString result;
    for (const QChar c : text.toLower()) {
        if (c.isLetterOrNumber())
            result.append(c);
        else if (!result.isEmpty() && !result.endsWith(QLatin1Char('-')))
            result.append(QLatin1Char('-'));
    }
    if (result.size() > longestName) {
        result.truncate(longestName);
        const qsizetype cut = result.lastIndexOf(QLatin1Char('-'));
        if (cut > longestName / 2)
            result.truncate(cut);
    }
    while (result.endsWith(QLatin1Char('-')))
        result.chop(1);
    return result;
}

struct AskerHolder {
    PictureAsker asker;
    QString lastDirectory;
    QString lastFormat = QStringLiteral("png");
};
AskerHolder &asking()
{
    static AskerHolder holder;
    return holder;
}


std::optional<PictureRequest> askWithDialogs(
    QWidget *parent, const QString &title, const QString &suggestedName, const QSize &shown)
{
    AskerHolder &state = asking();
    const QStringList formats {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")};
    const QStringList filters {PictureDialog::tr("PNG pictures (*.png)"), PictureDialog::tr("SVG drawings (*.svg)"),
        PictureDialog::tr("PDF documents (*.pdf)")};
    QString directory = state.lastDirectory;
    if (directory.isEmpty())
        directory = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const qsizetype last = std::max<qsizetype>(0, formats.indexOf(state.lastFormat));
    QString filter = filters[last];
    const QString name
        = (suggestedName.isEmpty() ? QStringLiteral("picture") : suggestedName) + QLatin1Char('.') + formats[last];
    QString path = QFileDialog::getSaveFileName(parent, title,
        directory.isEmpty() ? name : QDir(directory).filePath(name), filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty())
        return std::nullopt;
    QString format = pictureFormatOf(path);
    if (format.isEmpty()) { // no suffix, or one of another kind: the filter's
        format = formats[std::max<qsizetype>(0, filters.indexOf(filter))];
        path += QLatin1Char('.') + format;
    }
    state.lastDirectory = QFileInfo(path).absolutePath();
    state.lastFormat = format;
    PictureDialog dialog(shown, format, parent);
    dialog.setWindowTitle(title);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return PictureRequest {path, format, dialog.options()};
}

} // namespace

QString pictureFormatOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("png") || suffix == QLatin1String("svg") || suffix == QLatin1String("pdf"))
        return suffix;
    return {};
}

double pictureScale(const QSize &pixels, const QSize &shown)
{
    if (pixels.isEmpty() || shown.isEmpty())
        return 1.0;
    const double scale = std::min(double(pixels.width()) / shown.width(), double(pixels.height()) / shown.height());
    return std::max(1.0, scale);
}

QByteArray paintPicture(const QString &format, const PictureOptions &options, int fontDpi,
    const std::function<void(QCPPainter &painter, const QRectF &area)> &paint, QString *error)
{
    const QSize size = options.size;
    if (size.width() < minimumPictureSide || size.height() < minimumPictureSide || size.width() > maximumPictureSide
        || size.height() > maximumPictureSide) {
        fail(error,
            PictureDialog::tr("%1 × %2 pixels is not a picture size: each side must be from %3 to %4.")
                .arg(count(size.width()), count(size.height()), count(minimumPictureSide),
                    count(maximumPictureSide)));
        return {};
    }
    if (options.dpi < minimumPictureDpi || options.dpi > maximumPictureDpi) {
        fail(error,
            PictureDialog::tr("%1 dpi is not a resolution: it must be from %2 to %3 dpi.")
                .arg(count(options.dpi), count(minimumPictureDpi), count(maximumPictureDpi)));
        return {};
    }
    if (fontDpi <= 0)
        fontDpi = 96;
    const QString software = QStringLiteral("PKM Studio");
    const auto notDrawn = [&] {
        fail(error, PictureDialog::tr("The %1 picture could not be drawn.").arg(format.toUpper()));
        return QByteArray();
    };

    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (format == QLatin1String("png")) {
        QImage image(size, QImage::Format_RGB32);
        if (image.isNull()) {
            fail(error,
                PictureDialog::tr("There is not enough memory for a picture of %1 × %2 pixels.")
                    .arg(count(size.width()), count(size.height())));
            return {};
        }
        // Drawn at the screen's DPI (text in points as on screen), then labelled with the chosen one.
        image.setDotsPerMeterX(dotsPerMetre(fontDpi));
        image.setDotsPerMeterY(dotsPerMetre(fontDpi));
        image.fill(Qt::white);
        QCPPainter painter;
        if (!painter.begin(&image))
            return notDrawn();
        painter.setRenderHint(QPainter::Antialiasing, true);
        paint(painter, QRectF(image.rect()));
        painter.end();
        image.setDotsPerMeterX(dotsPerMetre(options.dpi));
        image.setDotsPerMeterY(dotsPerMetre(options.dpi));
        if (!options.title.isEmpty())
            image.setText(QStringLiteral("Title"), options.title);
        image.setText(QStringLiteral("Software"), software);
        if (!image.save(&buffer, "PNG"))
            return notDrawn();
    } else if (format == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setResolution(fontDpi);
        svg.setTitle(options.title);
        svg.setDescription(PictureDialog::tr("Drawn by %1").arg(software));
        QCPPainter painter;
        if (!painter.begin(&svg))
            return notDrawn();
        painter.setRenderHint(QPainter::Antialiasing, true);
        paint(painter, QRectF(QPointF(0.0, 0.0), QSizeF(size)));
        painter.end();
    } else if (format == QLatin1String("pdf")) {
        // The page: the pixels at the chosen DPI. A custom QPageSize is taken as given in
        // portrait; Landscape would swap its sides.
        const QSizeF page(size.width() * 25.4 / options.dpi, size.height() * 25.4 / options.dpi);
        QPdfWriter pdf(&buffer);
        pdf.setResolution(fontDpi);
        if (!pdf.setPageLayout(QPageLayout(QPageSize(page, QPageSize::Millimeter, QString(), QPageSize::ExactMatch),
                QPageLayout::Portrait, QMarginsF())))
            return notDrawn();
        pdf.setTitle(options.title);
        pdf.setCreator(software);
        QCPPainter painter;
        if (!painter.begin(&pdf))
            return notDrawn();
        painter.setRenderHint(QPainter::Antialiasing, true);
        paint(painter, QRectF(0.0, 0.0, pdf.width(), pdf.height()));
        painter.end();
    } else {
        fail(error,
            PictureDialog::tr("“%1” is not a picture format: the file name must end in .png, .svg or .pdf.")
                .arg(format));
        return {};
    }
    buffer.close();
    if (bytes.isEmpty())
        return notDrawn();
    return bytes;
}

QByteArray plotPicture(QCustomPlot *plot, const QString &format, const PictureOptions &options, QString *error)
{
    if (!plot) {
        fail(error, PictureDialog::tr("There is no plot to draw."));
        return {};
    }
    PictureOptions picture = options;
    if (picture.title.isEmpty())
        picture.title = plotTitle(plot);
    const double scale = options.scale > 0.0 ? options.scale : pictureScale(options.size, shownSize(plot));
    // The layout the plot gets for the picture: the pixels at the scale.
    const QSize layout(std::max(1, int(std::lround(options.size.width() / scale))),
        std::max(1, int(std::lround(options.size.height() / scale))));

    const ScreenLayoutKept kept(plot);
    // A plot that sets its ranges once laid out (a map keeps equal scales) does so in the
    // drawing, after its ticks and margins were worked out for the old ranges: lay it out at
    // the picture's size until the ranges settle, so that the picture's ticks fit its ranges.
    const auto currentRanges = [plot] {
        std::vector<QCPRange> current;
        for (QCPAxisRect *rect : plot->axisRects()) {
            for (QCPAxis *axis : rect->axes())
                current.push_back(axis->range());
        }
        return current;
    };
    const auto same = [](const std::vector<QCPRange> &a, const std::vector<QCPRange> &b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
            [](const QCPRange &p, const QCPRange &q) { return p.lower == q.lower && p.upper == q.upper; });
    };
    for (int pass = 0; pass < 3; ++pass) {
        const std::vector<QCPRange> before = currentRanges();
        QImage scratch(1, 1, QImage::Format_RGB32);
        scratch.setDotsPerMeterX(dotsPerMetre(plot->logicalDpiX()));
        scratch.setDotsPerMeterY(dotsPerMetre(plot->logicalDpiY()));
        QCPPainter painter(&scratch);
        plot->toPainter(&painter, layout.width(), layout.height());
        painter.end();
        if (same(before, currentRanges()))
            break;
    }
    const bool vector = format != QLatin1String("png");
    QByteArray bytes = paintPicture(
        format, picture, plot->logicalDpiY(),
        [&](QCPPainter &painter, const QRectF &area) {
            const double sx = area.width() / layout.width(), sy = area.height() / layout.height();
            painter.translate(area.topLeft());
            painter.scale(sx, sy);
            if (vector)
                painter.setMode(QCPPainter::pmVectorized);
            if (std::max(sx, sy) > 1.0)
                painter.setMode(QCPPainter::pmNonCosmetic); // hairlines grow with the picture
            plot->toPainter(&painter, layout.width(), layout.height());
        },
        error);
    return bytes;
}

QImage plotImage(QCustomPlot *plot, const QSize &layout, double scale)
{
    if (!plot)
        return {};
    const ScreenLayoutKept kept(plot);
    // A plot with equal scales (a map) fits its ranges to the axis rect after each layout
    // (afterLayout): the first drawing at the frame's size lays it out and fits the ranges,
    // but drew its ticks for the screen's, so that a tick label stood past the axis, under
    // the colour scale. The second one draws what the first laid out.
    plot->toPixmap(layout.width(), layout.height(), scale);
    return plot->toPixmap(layout.width(), layout.height(), scale).toImage();
}

bool savePictureFile(const QString &path, const QByteArray &bytes, QString *error)
{
    const QString shown = QDir::toNativeSeparators(path);
    QSaveFile file(path); // replaces the file only once it is complete
    if (!file.open(QIODevice::WriteOnly))
        return fail(
            error, PictureDialog::tr("“%1” could not be opened for writing: %2.").arg(shown, file.errorString()));
    if (file.write(bytes) != bytes.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return fail(error, PictureDialog::tr("The picture could not be written to “%1”: %2.").arg(shown, why));
    }
    if (!file.commit())
        return fail(error, PictureDialog::tr("“%1” could not be saved: %2.").arg(shown, file.errorString()));
    return true;
}

QString plotPictureName(const QCustomPlot *plot)
{
    if (!plot)
        return QStringLiteral("plot");
    QString title = plotTitle(plot);
    // the name of the plot, not its numbers: up to a "·" or a comma
    for (const QString &end : {QStringLiteral(" · "), QStringLiteral(",")}) {
        if (const qsizetype at = title.indexOf(end); at > 0)
            title.truncate(at);
    }
    QString name = slug(title);
    if (name.isEmpty())
        name = slug(plot->objectName());
    return name.isEmpty() ? QStringLiteral("plot") : name;
}

void enablePictureExport(QCustomPlot *plot, const QString &suggestedName)
{
    if (!plot)
        return;
    plot->setProperty(nameProperty, suggestedName);
    if (hasPictureExport(plot))
        return;
    plot->setProperty(exportProperty, true);
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(plot, &QWidget::customContextMenuRequested, plot, [plot](const QPoint &at) {
        QMenu *menu = createPictureMenu(plot);
        menu->setAttribute(Qt::WA_DeleteOnClose);
        menu->popup(plot->mapToGlobal(at));
    });
}

bool hasPictureExport(const QCustomPlot *plot)
{
    return plot && plot->property(exportProperty).toBool();
}

QMenu *createPictureMenu(QCustomPlot *plot)
{
    auto *menu = new QMenu(plot);
    menu->setObjectName(QStringLiteral("pictureMenu"));
    QAction *save = menu->addAction(PictureDialog::tr("Save picture…"));
    save->setObjectName(QStringLiteral("savePictureAction"));
    save->setToolTip(PictureDialog::tr("Save this plot as a PNG picture, an SVG or a PDF drawing"));
    // Queued: the dialogs open once the menu has gone.
    QObject::connect(
        save, &QAction::triggered, plot, [plot] { savePlotPictureAs(plot); }, Qt::QueuedConnection);
    return menu;
}

QString savePlotPictureAs(QCustomPlot *plot)
{
    if (!plot)
        return {};
    QString name = plot->property(nameProperty).toString();
    if (name.isEmpty())
        name = plotPictureName(plot);
    QWidget *parent = plot->window();
    const QString title = PictureDialog::tr("Save Picture");
    const std::optional<PictureRequest> request = askForPicture(parent, title, name, shownSize(plot));
    if (!request)
        return {};
    QString error;
    const QByteArray bytes = plotPicture(plot, request->format, request->options, &error);
    if (bytes.isEmpty() || !savePictureFile(request->path, bytes, &error)) {
        QMessageBox::warning(parent, title, error);
        return {};
    }
    return request->path;
}

std::optional<PictureRequest> askForPicture(
    QWidget *parent, const QString &title, const QString &suggestedName, const QSize &shown)
{
    if (const PictureAsker &asker = asking().asker)
        return asker(parent, title, suggestedName, shown);
    return askWithDialogs(parent, title, suggestedName, shown);
}

void setPictureAsker(PictureAsker asker)
{
    asking().asker = std::move(asker);
}

} // namespace pkm
