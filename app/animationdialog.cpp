#include "animationdialog.h"

#include "backgroundtask.h"
#include "quantityformat.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFileInfo>
#include <QPushButton>
#include <QSaveFile>
#include <QSpinBox>

namespace pkm {

namespace {
const QList<QSize> pictureSizes {{640, 480}, {960, 720}, {1280, 960}, {1600, 1200}};
constexpr int defaultSize = 1; // 960 × 720: sharp on a projector, a few MB for a minute of frames
} // namespace

AnimationDialog::AnimationDialog(const Mechanism &mechanism, int variable, QWidget *parent)
    : QDialog(parent)
    , m_mechanism(mechanism)
{
    setWindowTitle(tr("Export Animation"));
    auto *form = new QFormLayout(this);

    m_variable = new QComboBox(this);
    const auto &variables = mechanism.variableInfo();
    for (const VariableInfo &info : variables) {
        m_variable->addItem(QStringLiteral("%1 — %2").arg(toQString(info.symbol), toQString(info.label)));
    }
    form->addRow(tr("Move"), m_variable);

    m_from = new QDoubleSpinBox(this);
    m_to = new QDoubleSpinBox(this);
    form->addRow(tr("From"), m_from);
    form->addRow(tr("To"), m_to);

    m_frames = new QSpinBox(this);
    m_frames->setRange(minAnimationFrames, maxAnimationFrames);
    m_frames->setValue(60);
    form->addRow(tr("Frames"), m_frames);

    m_frameTime = new QSpinBox(this);
    m_frameTime->setRange(20, 2000);
    m_frameTime->setSingleStep(10);
    m_frameTime->setValue(50);
    m_frameTime->setSuffix(tr(" ms per frame"));
    form->addRow(tr("Speed"), m_frameTime);

    m_size = new QComboBox(this);
    for (const QSize &size : pictureSizes)
        m_size->addItem(tr("%1 × %2 pixels").arg(size.width()).arg(size.height()), size);
    m_size->setCurrentIndex(defaultSize);
    form->addRow(tr("Size"), m_size);

    m_bounce = new QCheckBox(tr("Play back to the start (a smooth loop)"), this);
    m_bounce->setChecked(true);
    form->addRow(QString(), m_bounce);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export…"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);

    connect(m_variable, &QComboBox::currentIndexChanged, this, &AnimationDialog::selectVariable);
    m_variable->setCurrentIndex(std::clamp(variable, 0, static_cast<int>(variables.size()) - 1));
    selectVariable(m_variable->currentIndex());
}

void AnimationDialog::selectVariable(int variable)
{
    if (variable < 0)
        return;
    const VariableInfo &info = m_mechanism.variableInfo()[variable];
    const Interval range = m_mechanism.variableRange(variable);
    const double lo = info.unit.toDisplay(range.min), hi = info.unit.toDisplay(range.max);
    const QString symbol = toQString(info.unit.symbol);
    const QString suffix = symbol.isEmpty() || symbol == QStringLiteral("°") ? symbol : QStringLiteral(" ") + symbol;
    for (QDoubleSpinBox *box : {m_from, m_to}) {
        box->setDecimals(info.decimals);
        box->setRange(lo, hi);
        box->setSuffix(suffix);
    }
    m_from->setValue(lo);
    m_to->setValue(hi);
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

void exportAnimation(QWidget *parent, MechanismPtr mechanism, const Pose &pose, const AnimationSettings &settings,
                     const QString &path, const std::function<void(const QString &, bool)> &done)
{
    runInBackground(
        parent, QObject::tr("Export Animation"), QObject::tr("Drawing %1 frames…").arg(settings.frames),
        [mechanism = std::move(mechanism), pose, settings, path](const std::atomic<bool> &cancel) -> TaskFailure {
            const Result<QByteArray> gif = renderAnimation(*mechanism, pose, settings, &cancel);
            if (cancel)
                return std::nullopt;
            if (!gif)
                return QString::fromStdString(gif.failure().message);
            QSaveFile file(path);
            if (!file.open(QIODevice::WriteOnly) || file.write(*gif) != gif->size() || !file.commit())
                return QObject::tr("Cannot write %1: %2.").arg(path, file.errorString());
            return std::nullopt;
        },
        [path, done](const TaskFailure &failure, bool cancelled) {
            if (cancelled)
                done(QObject::tr("Animation export cancelled."), false);
            else if (failure)
                done(*failure, true);
            else
                done(QObject::tr("Wrote %1 (%2 kB)").arg(path).arg((QFileInfo(path).size() + 512) / 1024), false);
        });
}

} // namespace pkm
