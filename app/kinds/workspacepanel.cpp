#include "kinds/workspacepanel.h"

#include "document/designfile.h"
#include "flowlayout.h"
#include "quantityformat.h"
#include "workspacemapview.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace pkm {

namespace {
/// Item data of the comparison list: a preset id, "" for none, or this marker for the pin.
const QString pinnedItem = QStringLiteral("#pinned");
} // namespace

WorkspacePanel::WorkspacePanel(QWidget *parent)
    : KindPanel(parent)
    , m_map(new WorkspaceMapView(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // In a row that wraps: the Russian "Сравнить рабочее пространство с:", its list and
    // "Запомнить эту конструкцию" side by side asked for 592 px, past a 1024×768 projector.
    auto *row = new FlowLayout;
    row->setContentsMargins(8, 4, 8, 0);
    auto *label = new QLabel(this);
    m_label = label;
    m_compare = new QComboBox(this);
    m_compare->setObjectName(QStringLiteral("comparisonBox"));
    // as wide as a short name closed (its list shows the long ones whole): a list as wide as
    // its longest design's name pushed the rest of the row onto lines of their own
    m_compare->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_compare->setMinimumContentsLength(18);
    label->setBuddy(m_compare);
    m_pin = new QPushButton(this);
    m_pin->setObjectName(QStringLiteral("pinButton"));
    row->addWidget(label);
    row->addWidget(m_compare);
    row->addWidget(m_pin);
    layout->addLayout(row);
    layout->addWidget(m_map, 1);
    // A click on the map moves the platform there (the main window asks the document).
    connect(m_map, &WorkspaceMapView::pointClicked, this, &WorkspacePanel::pointClicked);

    connect(m_compare, &QComboBox::activated, this, &WorkspacePanel::compareWith);
    connect(m_pin, &QPushButton::clicked, this, &WorkspacePanel::pinCurrent);
    retranslate();
}

void WorkspacePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void WorkspacePanel::retranslate()
{
    m_label->setText(tr("Compare workspace with:"));
    m_pin->setText(tr("Pin this design"));
    m_pin->setToolTip(tr("Keep the current design's workspace as the comparison, then change the design "
                         "and see both outlines."));
    if (m_kind.isEmpty())
        return;
    const QString current = m_compare->currentData().toString();
    fillComparisons(current);
    if (current == pinnedItem && m_pinned)
        m_map->setComparison(m_pinned, tr("pinned")); // the legend names it in the new language
}

void WorkspacePanel::setDesign(const MechanismPtr &mechanism, const QString &title)
{
    m_mechanism = mechanism;
    m_title = title;
    m_map->setMechanism(mechanism);
    const QString kind = toQString(mechanism->kind());
    if (kind != m_kind) {
        m_kind = kind;
        m_pinned.reset();
        fillComparisons();
        m_map->clearComparison();
    }
}

void WorkspacePanel::setPresenting(bool on)
{
    for (QWidget *widget : {static_cast<QWidget *>(m_label), static_cast<QWidget *>(m_compare), static_cast<QWidget *>(m_pin)})
        widget->setVisible(!on);
    m_map->setBrief(on);
    // Now, not when the page is next shown: a hidden page's layout waits, and a tab behind
    // (the O-X glide's map) held its stack, and presentation mode's linkage beside it, to the
    // width of the row just hidden.
    layout()->activate();
    updateGeometry();
}

void WorkspacePanel::setPose(const Pose &pose)
{
    m_map->setPose(pose);
}

void WorkspacePanel::fillComparisons(const QString &keep)
{
    m_compare->clear();
    m_compare->addItem(tr("nothing"), QString());
    for (const PresetInfo &preset : designfile::presets()) {
        if (preset.kind == m_kind)
            m_compare->addItem(designfile::presetText(preset.title), preset.id);
    }
    if (m_pinned)
        m_compare->addItem(tr("pinned: %1").arg(designfile::presetText(m_pinnedTitle)), pinnedItem);
    m_compare->setCurrentIndex(std::max(0, m_compare->findData(keep)));
    // the list open shows every name whole, however narrow the box closed
    m_compare->view()->setMinimumWidth(m_compare->view()->sizeHintForColumn(0) + 2 * m_compare->view()->frameWidth() + 16);
}

void WorkspacePanel::compareWith(int index)
{
    const QString id = m_compare->itemData(index).toString();
    if (id.isEmpty()) {
        m_map->clearComparison();
        return;
    }
    if (id == pinnedItem) {
        m_map->setComparison(m_pinned, tr("pinned"));
        return;
    }
    auto design = designfile::load(id);
    if (!design) {
        m_map->clearComparison();
        return;
    }
    // the short name of the preset ("moma-3d" → "3d") labels the dashed outline
    m_map->setComparison(design->mechanism, id.section(QLatin1Char('-'), -1));
}

void WorkspacePanel::pinCurrent()
{
    if (!m_mechanism)
        return;
    m_pinned = m_mechanism;
    m_pinnedTitle = m_title;
    fillComparisons();
    m_compare->setCurrentIndex(m_compare->count() - 1);
    m_map->setComparison(m_pinned, tr("pinned"));
}

} // namespace pkm
