#include "gui/animationdialog.h"

#include <malloc.h>

#include "export/animationplot.h"
#include "export/videowriter.h"
#include "gui/backgroundtask.h"
#include "kinds/kindpanel.h"
#include "pictureexport.h"
#include "quantityformat.h"
#include "symboltext.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSaveFile>
#include <QSettings>
#include <QSpinBox>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

namespace pkm {

namespace {
const QList<QSize> pictureSizes {{640, 480}, {960, 720}, {1280, 960}, {1600, 1200}};
constexpr int defaultSize = 1; // 960 × 720: sharp on a projector, a few MB for a minute of frames
// A projector's 720p (the default) and full HD.
const QList<QSize> videoSizes {defaultVideoSize, fullHdVideoSize};
const QStringList formatExtensions {QStringLiteral("gif"), QStringLiteral("mp4"), QStringLiteral("webm")};
} // namespace

AnimationDialog::AnimationDialog(const Mechanism &mechanism, int variable, QWidget *parent)
    : QDialog(parent)
    , m_mechanism(mechanism)
{
    auto *form = new QFormLayout(this);
    m_form = form;
    // the labels get their texts in retranslate()
    auto addRow = [this, form](QWidget *field) {
        auto *label = new QLabel(this);
        label->setBuddy(field);
        form->addRow(label, field);
    };

    m_format = new QComboBox(this);
    for (const QString &extension : formatExtensions)
        m_format->addItem(QString(), extension);
    addRow(m_format);

    m_variable = new SymbolComboBox(this);
    const auto &variables = mechanism.variableInfo();
    for (std::size_t i = 0; i < variables.size(); ++i)
        m_variable->addItem(QString());
    addRow(m_variable);

    m_from = new NumberSpinBox(this);
    m_to = new NumberSpinBox(this);
    addRow(m_from);
    addRow(m_to);

    m_frames = new QSpinBox(this);
    m_frames->setRange(minAnimationFrames, maxAnimationFrames);
    m_frames->setValue(60);
    addRow(m_frames);

    m_frameTime = new QSpinBox(this);
    m_frameTime->setRange(20, 2000);
    m_frameTime->setSingleStep(10);
    m_frameTime->setValue(50);
    addRow(m_frameTime);

    m_size = new QComboBox(this);
    addRow(m_size);
    showSizes();

    m_bounce = new QCheckBox(this);
    m_bounce->setChecked(true);
    form->addRow(QString(), m_bounce);

    m_beside = new SymbolComboBox(this);
    m_beside->setObjectName(QStringLiteral("besideBox"));
    m_beside->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    addRow(m_beside);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons = buttons;
    retranslate();
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);

    connect(m_format, &QComboBox::currentIndexChanged, this, &AnimationDialog::selectFormat);
    connect(m_variable, &QComboBox::currentIndexChanged, this, &AnimationDialog::selectVariable);
    m_variable->setCurrentIndex(std::clamp(variable, 0, static_cast<int>(variables.size()) - 1));
    selectVariable(m_variable->currentIndex());
}

void AnimationDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void AnimationDialog::setRowLabel(QWidget *field, const QString &text)
{
    if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(field)))
        label->setText(text);
}

void AnimationDialog::retranslate()
{
    setWindowTitle(tr("Export Animation"));
    m_format->setItemText(0, tr("Animated GIF"));
    m_format->setItemText(1, tr("MP4 video (H.264, 30 frames/s)"));
    m_format->setItemText(2, tr("WebM video (VP9, 30 frames/s)"));
    setRowLabel(m_format, tr("Format"));
    const auto &variables = m_mechanism.variableInfo();
    for (int i = 0; i < m_variable->count() && i < static_cast<int>(variables.size()); ++i) {
        const VariableInfo &info = variables[i];
        m_variable->setItemText(i, QStringLiteral("%1 — %2").arg(toQString(info.symbol), coreLabel(info.label)));
    }
    setRowLabel(m_variable, tr("Move"));
    setRowLabel(m_from, tr("From"));
    setRowLabel(m_to, tr("To"));
    setRowLabel(m_frames, tr("Frames"));
    m_frameTime->setSuffix(tr(" ms per frame"));
    m_frameTime->setToolTip(tr("A GIF's speed; a video plays 30 frames per second."));
    setRowLabel(m_frameTime, tr("Speed"));
    for (int i = 0; i < m_size->count(); ++i) {
        const QSize size = m_size->itemData(i).toSize();
        m_size->setItemText(i, tr("%1 × %2 pixels").arg(QLocale().toString(size.width()), QLocale().toString(size.height())));
    }
    setRowLabel(m_size, tr("Size"));
    m_bounce->setText(tr("Play back to the start (a smooth loop)"));
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Export…"));
    setRowLabel(m_beside, tr("Beside the view"));
    m_beside->setToolTip(tr("Each frame shows the mechanism at the left and this plot at the right, its cursor "
                            "following the pose."));
    showRangeUnit();
    fillBeside();
}

void AnimationDialog::setShownPlot(const QString &title)
{
    m_shownPlot = title;
    fillBeside();
}

QString AnimationDialog::besideChoice() const
{
    return m_beside->currentData().toString();
}

void AnimationDialog::fillBeside()
{
    if (!m_beside || m_variable->currentIndex() < 0)
        return;
    const QString chosen = m_beside->currentData().toString();
    const QSignalBlocker blocker(m_beside);
    m_beside->clear();
    m_beside->addItem(tr("Nothing"), QString());
    if (!m_shownPlot.isEmpty())
        m_beside->addItem(tr("The plot on screen: %1").arg(m_shownPlot), shownPlotChoice());
    const VariableInfo &moved = m_mechanism.variableInfo()[m_variable->currentIndex()];
    for (const ReportEntry *entry : animationPlotQuantities(m_mechanism, m_variable->currentIndex())) {
        m_beside->addItem(tr("%1 against %2 — %3")
                              .arg(toQString(entry->symbol), toQString(moved.symbol), coreLabel(entry->label)),
                          toQString(entry->name));
    }
    m_beside->setCurrentIndex(std::max(0, m_beside->findData(chosen)));
}

QString AnimationDialog::fileExtension() const
{
    return m_format->currentData().toString();
}

void AnimationDialog::showSizes()
{
    const bool video = fileExtension() != QLatin1String("gif");
    const QSize chosen = m_size->currentData().toSize();
    const QList<QSize> &sizes = video ? videoSizes : pictureSizes;
    {
        const QSignalBlocker blocker(m_size);
        m_size->clear();
        for (const QSize &size : sizes)
            m_size->addItem(tr("%1 × %2 pixels").arg(QLocale().toString(size.width()), QLocale().toString(size.height())),
                            size);
    }
    const int kept = static_cast<int>(sizes.indexOf(chosen));
    m_size->setCurrentIndex(kept >= 0 ? kept : video ? 0 : defaultSize);
    m_frameTime->setEnabled(!video); // a video's frame rate is fixed
}

void AnimationDialog::selectFormat()
{
    showSizes();
}

void AnimationDialog::showRangeUnit()
{
    const int variable = m_variable->currentIndex();
    if (variable < 0)
        return;
    const QString symbol = unitText(m_mechanism.variableInfo()[variable].unit);
    const QString suffix = symbol.isEmpty() || symbol.startsWith(QChar(0x00B0)) ? symbol : QLatin1Char(' ') + symbol;
    for (QDoubleSpinBox *box : {m_from, m_to})
        box->setSuffix(suffix);
}

void AnimationDialog::selectVariable(int variable)
{
    if (variable < 0)
        return;
    const VariableInfo &info = m_mechanism.variableInfo()[variable];
    const Interval range = m_mechanism.variableRange(variable);
    const double lo = info.unit.toDisplay(range.min), hi = info.unit.toDisplay(range.max);
    for (QDoubleSpinBox *box : {m_from, m_to}) {
        box->setDecimals(info.decimals);
        box->setRange(lo, hi);
    }
    showRangeUnit();
    // What the mechanism sweeps from its pose, inwards to the decimals shown: the default
    // export then runs to its end (a five-bar's whole −180…180° stopped at a stretched leg).
    Interval offered = m_start ? animationRange(m_mechanism, *m_start, variable) : range;
    const double scale = std::pow(10.0, info.decimals);
    m_from->setValue(std::ceil(info.unit.toDisplay(offered.min) * scale - 1e-9) / scale);
    m_to->setValue(std::floor(info.unit.toDisplay(offered.max) * scale + 1e-9) / scale);
    fillBeside();
}

void AnimationDialog::setStart(const Pose &pose)
{
    m_start = pose;
    selectVariable(m_variable->currentIndex());
}

void AnimationDialog::restoreChoices()
{
    const QSettings settings;
    m_format->setCurrentIndex(std::clamp(settings.value(QStringLiteral("animation/format"), 0).toInt(), 0, m_format->count() - 1));
    m_frames->setValue(settings.value(QStringLiteral("animation/frames"), m_frames->value()).toInt());
    m_frameTime->setValue(settings.value(QStringLiteral("animation/frameMilliseconds"), m_frameTime->value()).toInt());
    m_bounce->setChecked(settings.value(QStringLiteral("animation/bounce"), m_bounce->isChecked()).toBool());
    const int size = m_size->findData(settings.value(QStringLiteral("animation/size")).toSize());
    if (size >= 0)
        m_size->setCurrentIndex(size);
}

void AnimationDialog::rememberChoices() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("animation/format"), m_format->currentIndex());
    settings.setValue(QStringLiteral("animation/frames"), m_frames->value());
    settings.setValue(QStringLiteral("animation/frameMilliseconds"), m_frameTime->value());
    settings.setValue(QStringLiteral("animation/bounce"), m_bounce->isChecked());
    settings.setValue(QStringLiteral("animation/size"), m_size->currentData().toSize());
}

AnimationSettings AnimationDialog::settings() const
{
    AnimationSettings settings;
    settings.variable = m_variable->currentIndex();
    const Unit &unit = m_mechanism.variableInfo()[settings.variable].unit;
    settings.from = unit.fromDisplay(m_from->value());
    settings.to = unit.fromDisplay(m_to->value());
    settings.frames = m_frames->value();
    settings.bounce = m_bounce->isChecked();
    settings.size = m_size->currentData().toSize();
    settings.frameMilliseconds = m_frameTime->value();
    return settings;
}

QString chooseAnimationPath(QWidget *parent, const QString &baseName, const QString &extension)
{
    const QString filters = AnimationDialog::tr("Animated GIF (*.gif)") + QStringLiteral(";;")
        + AnimationDialog::tr("MP4 video (*.mp4)") + QStringLiteral(";;") + AnimationDialog::tr("WebM video (*.webm)");
    const QStringList filterList = filters.split(QStringLiteral(";;"));
    QString filter = filterList.value(std::max<qsizetype>(0, formatExtensions.indexOf(extension)));
    QString path = QFileDialog::getSaveFileName(parent, AnimationDialog::tr("Export Animation"),
                                                baseName.isEmpty() ? QString() : baseName + QLatin1Char('.') + extension,
                                                filters, &filter);
    if (path.isEmpty())
        return {};
    // The name's own extension decides (the user may type "lecture.mp4" with GIF chosen).
    if (!formatExtensions.contains(QFileInfo(path).suffix().toLower())) {
        const qsizetype chosen = filterList.indexOf(filter);
        path += QLatin1Char('.') + formatExtensions.value(chosen >= 0 ? chosen : formatExtensions.indexOf(extension));
    }
    return path;
}

namespace {
/// The GIF: every frame drawn, then encoded at once (giflib takes the frames together).
TaskFailure writeGif(const Mechanism &mechanism, const Pose &pose, const AnimationSettings &settings,
                     const QString &path, const std::atomic<bool> &cancel)
{
    const Result<QByteArray> gif = renderAnimation(mechanism, pose, settings, &cancel);
    if (cancel)
        return std::nullopt;
    if (!gif)
        return QString::fromStdString(gif.failure().message);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(*gif) != gif->size() || !file.commit())
        return AnimationDialog::tr("Cannot write %1: %2.").arg(path, file.errorString());
    return std::nullopt;
}

/// The video: poses first (they may fail, naming the frame), then frame by frame.
TaskFailure writeVideo(const Mechanism &mechanism, const Pose &pose, const AnimationSettings &settings,
                       const QString &path, const std::atomic<bool> &cancel, const TaskProgress &progress)
{
    auto poses = animationPoses(mechanism, pose, settings);
    if (!poses)
        return QString::fromStdString(poses.failure().message);
    const VideoExport written = writeAnimationVideo(mechanism, *poses, settings, path, &cancel, progress);
    if (written.cancelled || written.ok())
        return std::nullopt;
    return written.error;
}
} // namespace

void exportAnimation(QWidget *parent, MechanismPtr mechanism, const Pose &pose, const AnimationSettings &settings,
                     const QString &path, const std::function<void(const QString &, bool)> &done)
{
    const bool video = videoFormatForPath(path).has_value();
    const int frames = animationFrameCount(settings.frames, settings.bounce);
    runWithProgress(
        parent, AnimationDialog::tr("Export Animation"),
        video ? AnimationDialog::tr("Encoding %n frame(s)…", nullptr, frames)
              : AnimationDialog::tr("Drawing %n frame(s)…", nullptr, settings.frames),
        [mechanism = std::move(mechanism), pose, settings, path, video](const std::atomic<bool> &cancel,
                                                                        const TaskProgress &progress) -> TaskFailure {
            TaskFailure failure = video ? writeVideo(*mechanism, pose, settings, path, cancel, progress)
                                        : writeGif(*mechanism, pose, settings, path, cancel);
            // Here as well as below: the frames are freed by now, in this thread; on a loaded
            // machine the trim below could run before they were.
            malloc_trim(0);
            return failure;
        },
        [path, done](const TaskFailure &failure, bool cancelled) {
            // The frames were drawn and encoded in a worker thread's malloc arena; glibc keeps
            // what they freed there for that thread, so the window's memory would stay at the
            // export's peak. Hand it back to the system now that the export is over.
            malloc_trim(0);
            if (cancelled)
                done(AnimationDialog::tr("Animation export cancelled."), false);
            else if (failure)
                done(*failure, true);
            else
                done(AnimationDialog::tr("Wrote %1 (%2 kB)")
                         .arg(path, QLocale().toString((QFileInfo(path).size() + 512) / 1024)),
                    false);
        });
}

std::function<QImage(const Pose &, const QSize &)> shownPlotPictures(KindPanel *panel, QCustomPlot *plot)
{
    return [panel = QPointer<KindPanel>(panel), plot = QPointer<QCustomPlot>(plot)](const Pose &pose,
                                                                                     const QSize &size) {
        // A widget is drawn on the GUI thread only: the frame's thread asks it and waits. The
        // wait gives up when the application is closing (its thread pool waits for this one).
        auto picture = std::make_shared<std::promise<QImage>>();
        std::future<QImage> made = picture->get_future();
        QMetaObject::invokeMethod(
            qApp,
            [panel, plot, pose, size, picture] {
                QImage image;
                if (panel && plot) {
                    panel->setPose(pose);
                    // Laid out at the 720-pixel frame's scale, so a full-HD frame's plot is the
                    // same plot enlarged rather than one with small print.
                    const double scale = std::max(1.0, size.height() / 720.0);
                    image = plotImage(plot, QSize(int(size.width() / scale), int(size.height() / scale)), scale);
                }
                picture->set_value(image);
            },
            Qt::QueuedConnection);
        while (made.wait_for(std::chrono::milliseconds(20)) == std::future_status::timeout) {
            if (QCoreApplication::closingDown())
                return QImage();
        }
        QImage image = made.get();
        if (image.isNull()) {
            image = QImage(size, QImage::Format_RGB32);
            image.fill(Qt::white);
        }
        return image.size() == size ? image : image.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    };
}

} // namespace pkm
