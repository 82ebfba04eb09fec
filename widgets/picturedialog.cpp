// The picture dialog: the size as a preset or in pixels, the resolution, and what the picture
// will be on paper, remembered for the next picture (pictureexport.cpp asks through it).

#include "pictureexport.h"
#include "pictureexportinternal.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

namespace pkm {

namespace {
using pictureexport::count;
using pictureexport::DialogMemory;
using pictureexport::memory;
} // namespace

// -- the dialog ------------------------------------------------------------------------------

PictureDialog::PictureDialog(const QSize &shown, const QString &format, QWidget *parent)
    : QDialog(parent)
    , m_format(format)
    , m_sizeBox(new QComboBox(this))
    , m_width(new QSpinBox(this))
    , m_height(new QSpinBox(this))
    , m_dpiBox(new QComboBox(this))
    , m_note(new QLabel(this))
{
    const QSize base = shown.isEmpty() ? QSize(800, 600)
                                       : shown.boundedTo(QSize(maximumPictureSide, maximumPictureSide))
                                             .expandedTo(QSize(minimumPictureSide, minimumPictureSide));
    m_presets = {base, (2 * base).boundedTo(QSize(maximumPictureSide, maximumPictureSide)), QSize(1920, 1080),
        QSize(3840, 2160)};
    m_sizeBox->setObjectName(QStringLiteral("sizeBox"));
    for (int i = 0; i <= int(m_presets.size()); ++i) // the presets and "Custom": retranslate()
        m_sizeBox->addItem(QString());
    for (QSpinBox *box : {m_width, m_height}) {
        box->setRange(minimumPictureSide, maximumPictureSide);
        box->setAccelerated(true);
    }
    m_width->setObjectName(QStringLiteral("widthBox"));
    m_height->setObjectName(QStringLiteral("heightBox"));
    m_dpiBox->setObjectName(QStringLiteral("dpiBox"));
    for (const int dpi : dpiChoices())
        m_dpiBox->addItem(QString(), dpi);
    m_note->setObjectName(QStringLiteral("pictureNote"));
    m_note->setWordWrap(true);
    m_note->setMinimumWidth(320);

    const DialogMemory &remembered = memory();
    m_width->setValue(remembered.custom.width());
    m_height->setValue(remembered.custom.height());
    m_sizeBox->setCurrentIndex(std::clamp(remembered.preset, 0, int(m_sizeBox->count()) - 1));
    m_dpiBox->setCurrentIndex(std::max(0, m_dpiBox->findData(remembered.dpi)));
    if (format == QLatin1String("svg"))
        m_dpiBox->setEnabled(false); // an SVG has no pixels to spread over an inch

    auto *form = new QFormLayout;
    m_form = form;
    for (QWidget *field : std::initializer_list<QWidget *> {m_sizeBox, m_width, m_height, m_dpiBox})
        form->addRow(new QLabel(this), field); // the labels' texts and buddies: retranslate()
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_note);
    layout->addWidget(buttons);

    connect(m_sizeBox, &QComboBox::currentIndexChanged, this, &PictureDialog::presetChosen);
    connect(m_width, &QSpinBox::valueChanged, this, &PictureDialog::updateNote);
    connect(m_height, &QSpinBox::valueChanged, this, &PictureDialog::updateNote);
    connect(m_dpiBox, &QComboBox::currentIndexChanged, this, &PictureDialog::updateNote);
    retranslate();
    presetChosen();
}

void PictureDialog::retranslate()
{
    setWindowTitle(tr("Picture Size"));
    const auto size = [](const QSize &s) { return tr("%1 × %2").arg(count(s.width()), count(s.height())); };
    m_sizeBox->setItemText(0, tr("As shown — %1").arg(size(m_presets[0])));
    m_sizeBox->setItemText(1, tr("Twice as shown — %1").arg(size(m_presets[1])));
    m_sizeBox->setItemText(2, tr("Full HD — %1").arg(size(m_presets[2])));
    m_sizeBox->setItemText(3, tr("4K UHD — %1").arg(size(m_presets[3])));
    m_sizeBox->setItemText(4, tr("Custom"));
    for (QSpinBox *box : {m_width, m_height})
        box->setSuffix(tr(" px"));
    const QList<int> dpis = dpiChoices();
    for (int i = 0; i < int(dpis.size()); ++i)
        m_dpiBox->setItemText(i, tr("%1 dpi").arg(count(dpis[i])));
    if (m_format == QLatin1String("svg"))
        m_dpiBox->setToolTip(tr("An SVG drawing is scalable: its size is in CSS pixels."));
    else if (m_format == QLatin1String("pdf"))
        m_dpiBox->setToolTip(tr("The PDF's page is the size in pixels at this resolution."));
    else
        m_dpiBox->setToolTip(tr("Stored in the PNG: the size it prints at."));
    const std::array<std::pair<QWidget *, QString>, 4> labels {{{m_sizeBox, tr("&Size:")}, {m_width, tr("&Width:")},
        {m_height, tr("&Height:")}, {m_dpiBox, tr("&Resolution:")}}};
    for (const auto &[field, text] : labels) {
        if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(field))) {
            label->setText(text);
            label->setBuddy(field);
        }
    }
    updateNote();
}

void PictureDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

PictureOptions PictureDialog::options() const
{
    PictureOptions options;
    options.size = QSize(m_width->value(), m_height->value());
    options.dpi = m_dpiBox->currentData().toInt();
    return options;
}

QString PictureDialog::physicalText() const
{
    const PictureOptions chosen = options();
    const QLocale locale;
    const QString mm = tr("%1 × %2 mm")
                           .arg(locale.toString(chosen.size.width() * 25.4 / chosen.dpi, 'f', 1),
                               locale.toString(chosen.size.height() * 25.4 / chosen.dpi, 'f', 1));
    const QString pixels = tr("%1 × %2 pixels").arg(count(chosen.size.width()), count(chosen.size.height()));
    if (m_format == QLatin1String("svg"))
        return tr("An SVG drawing of %1 (CSS pixels), lines and text as vectors.").arg(pixels);
    if (m_format == QLatin1String("pdf"))
        return tr("A PDF page of %1: %2 at %3 dpi, lines and text as vectors.").arg(mm, pixels, count(chosen.dpi));
    return tr("A PNG picture of %1; it prints at %2 at %3 dpi.").arg(pixels, mm, count(chosen.dpi));
}

void PictureDialog::presetChosen()
{
    const int index = m_sizeBox->currentIndex();
    const bool custom = index < 0 || index >= int(m_presets.size());
    if (!custom) {
        const QSignalBlocker blockWidth(m_width), blockHeight(m_height);
        m_width->setValue(m_presets[index].width());
        m_height->setValue(m_presets[index].height());
    }
    m_width->setEnabled(custom);
    m_height->setEnabled(custom);
    updateNote();
}

void PictureDialog::updateNote()
{
    m_note->setText(physicalText());
}

void PictureDialog::accept()
{
    DialogMemory &remembered = memory();
    remembered.preset = m_sizeBox->currentIndex();
    if (remembered.preset >= int(m_presets.size()))
        remembered.custom = QSize(m_width->value(), m_height->value());
    remembered.dpi = m_dpiBox->currentData().toInt();
    QDialog::accept();
}

} // namespace pkm
