#pragma once
/// Pictures of the plots and maps (issue 7): PNG at a chosen size and DPI, SVG and PDF as
/// vector drawings. A right click on a plot offers "Save picture…" (enablePictureExport());
/// the same dialogs and drawing serve the 2D linkage view (app/viewpicture.h). The 3D view
/// has its own PNG export (View3DPanel::savePictureAs()).
///
/// Size and scale: a picture of W × H pixels is laid out at W/s × H/s screen pixels and drawn
/// s times larger, s = max(1, min(W / shown width, H / shown height)) for the size the plot has
/// on screen. A 3840 × 2160 picture of an 800 × 600 plot is the plot enlarged — its text,
/// lines and margins keep their proportions — rather than a small-print plot with a huge
/// axis rect; a picture no larger than the plot is laid out at its own size.
///
/// DPI: written into the PNG (its physical size, QImage::setDotsPerMeterX/Y) and giving the
/// PDF its page: W / dpi × 25.4 mm wide. An SVG is W × H CSS pixels. The plots' text is set in
/// points: the pictures are drawn at the screen's logical DPI so that a point is as large,
/// against the layout, as it is on screen, whatever DPI the file declares.
///
/// Files are written completely or not at all (QSaveFile): a failure leaves what was there.

#include <QDialog>
#include <QSize>
#include <QString>

#include <functional>
#include <optional>

class QByteArray;
class QComboBox;
class QCPPainter;
class QFormLayout;
class QCustomPlot;
class QLabel;
class QMenu;
class QRectF;
class QSpinBox;

namespace pkm {

/// What a picture is to be: its size in pixels and its DPI.
struct PictureOptions {
    QSize size {1600, 1200}; ///< pixels: the PNG, the SVG's width and height, the PDF's page with `dpi`
    int dpi = 96; ///< PNG metadata; the PDF page is size / dpi inches
    /// Picture pixels per layout pixel; 0: automatic, from the size shown (pictureScale()).
    double scale = 0.0;
    QString title; ///< the file's title (PNG text "Title", SVG <title>, PDF title); may be empty
};

/// The sizes and resolutions a picture may have.
inline constexpr int minimumPictureSide = 16;
inline constexpr int maximumPictureSide = 8000;
inline constexpr int minimumPictureDpi = 36;
inline constexpr int maximumPictureDpi = 2400;

/// "png", "svg" or "pdf" for a file name's suffix (any case); empty for any other suffix.
QString pictureFormatOf(const QString &path);

/// The layout scale of a picture of `pixels` for something `shown` that large on screen (see
/// above): at least 1.
double pictureScale(const QSize &pixels, const QSize &shown);

/// Draws a picture in `format` ("png", "svg", "pdf") of options.size pixels: `paint` gets the
/// painter (a QCPPainter, so that plots can draw into it) and the area to fill, device units
/// (the PDF's are not pixels). Text set in points is as large as on a screen of `fontDpi`. The
/// encoded file, or empty bytes with `error` set. For the 2D view and the plots.
QByteArray paintPicture(const QString &format, const PictureOptions &options, int fontDpi,
    const std::function<void(QCPPainter &painter, const QRectF &area)> &paint, QString *error);

/// `plot` as a picture: PNG (raster, with the DPI), SVG or PDF (vector, via
/// QCustomPlot::toPainter()). Lays the plot out at the picture's size for the drawing only:
/// the plot on screen keeps its size, its axis ranges and its layout. Empty bytes with `error`
/// set on failure.
QByteArray plotPicture(QCustomPlot *plot, const QString &format, const PictureOptions &options, QString *error);
/// `plot` laid out at `layout` and drawn `scale` times as large (a video's frame), the plot on
/// screen left as it was: its ranges, and its layout at the next repaint. A null image for none.
QImage plotImage(QCustomPlot *plot, const QSize &layout, double scale);

/// Writes `bytes` to `path` atomically (QSaveFile): false with a sentence naming the file in
/// `error` when it cannot be written (a missing folder, no permission, a full disk).
bool savePictureFile(const QString &path, const QByteArray &bytes, QString *error);

/// The name a picture of `plot` is offered under, without a suffix: from the plot's title
/// ("Fig. 8 — diagonal length d(θ), (2)" → "fig-8-diagonal-length-d-θ"), else its objectName,
/// else "plot".
QString plotPictureName(const QCustomPlot *plot);

/// Gives `plot` a context menu (right click) with "Save picture…": asks for the file and the
/// size and DPI, writes the picture, and says what failed in a message box. The left button
/// keeps whatever it did. `suggestedName` (no suffix) names the file offered; empty: the
/// plot's title at the time (plotPictureName()). Calling it again only changes the name.
void enablePictureExport(QCustomPlot *plot, const QString &suggestedName = QString());
/// Whether enablePictureExport() was called on `plot`.
bool hasPictureExport(const QCustomPlot *plot);
/// The context menu enablePictureExport() shows, parented to `plot` (the caller deletes it):
/// its action "Save picture…" (objectName "savePictureAction") runs savePlotPictureAs().
QMenu *createPictureMenu(QCustomPlot *plot);
/// What "Save picture…" does: asks (askForPicture()), draws and writes. The path written, or
/// empty when cancelled or failed (the failure shown in a message box).
QString savePlotPictureAs(QCustomPlot *plot);

/// What the user chose for a picture.
struct PictureRequest {
    QString path; ///< with a suffix .png, .svg or .pdf
    QString format; ///< "png", "svg" or "pdf"
    PictureOptions options;
};

/// Asks for a picture file — a file dialog with PNG, SVG and PDF filters (a name without one
/// of these suffixes gets the chosen filter's), then the PictureDialog for its size and DPI.
/// `suggestedName` has no suffix; the last folder and format used are offered again.
/// Nothing when cancelled.
std::optional<PictureRequest> askForPicture(
    QWidget *parent, const QString &title, const QString &suggestedName, const QSize &shown);
/// Replaces askForPicture()'s dialogs (tests answer without them); an empty function restores them.
using PictureAsker = std::function<std::optional<PictureRequest>(
    QWidget *parent, const QString &title, const QString &suggestedName, const QSize &shown)>;
void setPictureAsker(PictureAsker asker);

/// The size and DPI of a picture: presets (as shown, twice as shown, 1920 × 1080,
/// 3840 × 2160) or a custom width and height, and 72 … 600 dpi, with the size it prints at
/// (PNG) or the PDF's page size.
class PictureDialog : public QDialog
{
    Q_OBJECT

public:
    /// `shown`: the size on screen; `format`: "png", "svg" or "pdf" (what the size means).
    PictureDialog(const QSize &shown, const QString &format, QWidget *parent = nullptr);

    PictureOptions options() const;
    /// The presets' sizes, in the size box's order; the last entry of the box is "Custom".
    QList<QSize> presetSizes() const { return m_presets; }
    static QList<int> dpiChoices() { return {72, 96, 150, 300, 600}; }

    QComboBox *sizeBox() const { return m_sizeBox; }
    QSpinBox *widthBox() const { return m_width; }
    QSpinBox *heightBox() const { return m_height; }
    QComboBox *dpiBox() const { return m_dpiBox; }
    /// "Prints at 203.2 × 152.4 mm at 96 dpi." and the like.
    QString physicalText() const;

    void accept() override;

protected:
    void changeEvent(QEvent *event) override;

private:
    void presetChosen();
    void updateNote();
    /// Every text of the dialog in the current language (the choices stay as they are).
    void retranslate();

    QString m_format;
    QList<QSize> m_presets;
    QComboBox *m_sizeBox = nullptr;
    QSpinBox *m_width = nullptr;
    QSpinBox *m_height = nullptr;
    QComboBox *m_dpiBox = nullptr;
    QLabel *m_note = nullptr;
    QFormLayout *m_form = nullptr;
};

} // namespace pkm
