#include "valuestable.h"

#include "quantityformat.h"
#include "symboltext.h"

#include <QEvent>
#include <QFontMetrics>
#include <QHeaderView>
#include <QLabel>
#include <QResizeEvent>
#include <QStyle>

#include <algorithm>
#include <cmath>
#include <optional>

namespace pkm {

namespace {
QString groupTitle(ReportGroup group)
{
    switch (group) {
    case ReportGroup::Pose: return ValuesTable::tr("Pose");
    case ReportGroup::Jacobian: return ValuesTable::tr("Jacobian");
    case ReportGroup::Derived: return ValuesTable::tr("Derived");
    }
    return {};
}

QString singularityText(SingularityType type)
{
    switch (type) {
    case SingularityType::None: return ValuesTable::tr("none");
    case SingularityType::Inverse: return ValuesTable::tr("inverse");
    case SingularityType::Direct: return ValuesTable::tr("direct");
    case SingularityType::Combined: return ValuesTable::tr("combined");
    }
    return {};
}

/// The class a hair from a singular pose, where the values are shown as at it.
QString nearSingularityText(SingularityType type)
{
    switch (type) {
    case SingularityType::Inverse: return ValuesTable::tr("near inverse");
    case SingularityType::Direct: return ValuesTable::tr("near direct");
    default: return ValuesTable::tr("near combined");
    }
}

} // namespace

ValuesTable::ValuesTable(QWidget *parent)
    : QTreeWidget(parent)
{
    setColumnCount(3);
    setHeaderLabels({tr("Quantity"), tr("Value"), tr("Meaning")});
    setRootIsDecorated(false);
    setItemDelegateForColumn(0, new SymbolDelegate(this));
    setItemDelegateForColumn(2, new SymbolDelegate(this)); // "J_d = 2a·cos θ", lowered alike
    setUniformRowHeights(true);
    setSelectionMode(QAbstractItemView::NoSelection);
    setFocusPolicy(Qt::NoFocus);
    // Not ResizeToContents: that re-measures every row on every slider move. The columns are
    // sized when the values first appear and widen only when a longer text comes.
    header()->setSectionResizeMode(QHeaderView::Interactive);
    header()->setStretchLastSection(true);
    setMouseTracking(true); // itemEntered: the strip follows the pointer
    connect(this, &QTreeWidget::itemEntered, this, [this](QTreeWidgetItem *item) { updateMeaningStrip(item); });
    connect(header(), &QHeaderView::sectionResized, this, [this] { updateMeaningStrip(m_meaningShown); });
}

QLabel *ValuesTable::meaningStrip()
{
    if (!m_meaningStrip) {
        m_meaningStrip = new QLabel; // the caller's layout takes it
        m_meaningStrip->setObjectName(QStringLiteral("meaningStrip"));
        m_meaningStrip->setWordWrap(true);
        m_meaningStrip->setTextFormat(Qt::RichText);
        m_meaningStrip->setContentsMargins(6, 3, 6, 3);
        m_meaningStrip->setBackgroundRole(QPalette::AlternateBase);
        m_meaningStrip->setAutoFillBackground(true);
        updateMeaningStrip();
    }
    return m_meaningStrip;
}

void ValuesTable::updateMeaningStrip(const QTreeWidgetItem *item)
{
    if (!m_meaningStrip)
        return;
    // What the "Meaning" column shows of its widest text, as its cells elide it.
    int widest = 0;
    for (int i = 0; i < topLevelItemCount(); ++i)
        widest = std::max(widest, fontMetrics().horizontalAdvance(topLevelItem(i)->text(2)));
    const int margin = 2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1);
    const int shown = viewport()->width() - header()->sectionViewportPosition(2);
    const bool cut = topLevelItemCount() > 0 && shown < widest + margin;
    m_meaningStrip->setVisible(cut);
    if (item && !item->text(2).isEmpty())
        m_meaningShown = item; // a group's title has none: the last row's stays
    if (!cut)
        return;
    if (m_meaningShown) {
        m_meaningStrip->setText(QStringLiteral("<b>%1</b> — %2").arg(symbolHtml(m_meaningShown->text(0)),
                                                                     symbolHtml(m_meaningShown->text(2))));
    } else {
        m_meaningStrip->setText(QStringLiteral("<span style=\"color:%1\">%2</span>")
                                    .arg(palette().color(QPalette::Disabled, QPalette::Text).name(),
                                         tr("Point at a row to read its meaning in full.").toHtmlEscaped()));
    }
}

void ValuesTable::fitColumns()
{
    resizeColumnToContents(0);
    resizeColumnToContents(1);
    const int room = viewport()->width() - columnWidth(0) - 4 * fontMetrics().averageCharWidth();
    const int least = fontMetrics().horizontalAdvance(QStringLiteral("−0000.00 mm²"));
    if (columnWidth(1) > room)
        setColumnWidth(1, std::max(room, least));
}

void ValuesTable::resizeEvent(QResizeEvent *event)
{
    QTreeWidget::resizeEvent(event);
    if (m_widestValue > 0)
        fitColumns();
    updateMeaningStrip(m_meaningShown);
}

void ValuesTable::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange)
        updateMeaningStrip(m_meaningShown); // the texts' widths change with the text size
    if (event->type() == QEvent::LanguageChange) {
        setHeaderLabels({tr("Quantity"), tr("Value"), tr("Meaning")});
        // The rows again, in the new language, and the values of the pose shown in its locale.
        if (m_mechanism) {
            rebuild();
            if (m_pose)
                setPose(*m_pose);
        }
    }
    QTreeWidget::changeEvent(event);
}

void ValuesTable::setMechanism(const MechanismPtr &mechanism)
{
    // A design of the same kind may report other quantities (a leg library's third leg adds φ
    // and a 3 × 3 J): the rows follow the report's layout, not only the kind.
    bool rebuildNeeded = !m_mechanism || m_mechanism->kind() != mechanism->kind()
        || m_mechanism->reportLayout().size != mechanism->reportLayout().size
        || m_mechanism->reportLayout().entries.size() != mechanism->reportLayout().entries.size();
    for (std::size_t i = 0; !rebuildNeeded && i < mechanism->reportLayout().entries.size(); ++i) {
        const ReportEntry &was = m_mechanism->reportLayout().entries[i], &is = mechanism->reportLayout().entries[i];
        rebuildNeeded = was.name != is.name || was.unit.symbol != is.unit.symbol || was.rows != is.rows
            || was.cols != is.cols || was.label != is.label || was.symbol != is.symbol;
    }
    m_mechanism = mechanism;
    m_actuators = capability::actuatorsOf(*mechanism);
    const ReportLayout *capabilityLayout = capability::layoutFor(m_actuators);
    rebuildNeeded = rebuildNeeded || capabilityLayout != m_capabilityLayout;
    m_capabilityLayout = capabilityLayout;
    if (rebuildNeeded) {
        m_pose.reset(); // a pose of another kind of mechanism
        rebuild();
    }
}

void ValuesTable::rebuild()
{
    m_meaningShown = nullptr; // its row goes
    clear();
    m_items.clear();
    const ReportLayout &layout = m_mechanism->reportLayout();
    m_values.assign(layout.size, 0.0);
    m_widestValue = 0;
    QFont groupFont = font();
    groupFont.setBold(true);
    std::optional<ReportGroup> current;
    auto addGroup = [&](const QString &title) {
        auto *item = new QTreeWidgetItem(this, {title});
        item->setFirstColumnSpanned(true);
        item->setFont(0, groupFont);
        item->setBackground(0, QColor(0xe8, 0xee, 0xf4));
        return item;
    };
    const auto addItem = [&](const ReportEntry &entry) {
        const QString label = coreLabel(entry.label);
        auto *item = new QTreeWidgetItem(this, {toQString(entry.symbol), QString(), label});
        item->setTextAlignment(1, Qt::AlignRight | Qt::AlignVCenter);
        item->setData(0, Qt::UserRole, toQString(entry.name));
        item->setToolTip(2, label); // the column may be too narrow for it
        item->setToolTip(0, label); // or off the dock's edge: the symbol tells what it is
        return item;
    };
    for (const ReportEntry &entry : layout.entries) {
        if (!current || *current != entry.group) {
            current = entry.group;
            addGroup(groupTitle(entry.group));
        }
        m_items.push_back(addItem(entry));
    }
    m_capabilityItems.clear();
    m_capabilityValues.clear();
    m_capabilityGroup = nullptr;
    if (m_capabilityLayout) {
        m_capabilityGroup = addGroup(tr("Capability"));
        m_capabilityValues.assign(std::size_t(m_capabilityLayout->size), 0.0);
        for (const ReportEntry &entry : m_capabilityLayout->entries)
            m_capabilityItems.push_back(addItem(entry));
    }
    addGroup(tr("Singularity"));
    m_singularity = new QTreeWidgetItem(this, {tr("class"), QString(), tr("none, inverse, direct or combined")});
    m_singularity->setTextAlignment(1, Qt::AlignRight | Qt::AlignVCenter);
    updateMeaningStrip();
}

void ValuesTable::setPose(const Pose &pose)
{
    if (!m_mechanism)
        return;
    m_pose = pose;
    const Singularity singularity = m_mechanism->evaluate(pose, m_values);
    const ReportLayout &layout = m_mechanism->reportLayout();
    qsizetype widest = 0;
    const auto show = [&](QTreeWidgetItem *item, const ReportEntry &entry, const std::vector<double> &values) {
        const QString text = entryText(entry, values);
        widest = std::max(widest, text.size());
        item->setText(1, text);
        if (entry.rows * entry.cols > 1)
            item->setToolTip(1, text); // the column may cut a matrix
    };
    // near a singular pose J and the capability are shown as at it (capability::settleNearSingular())
    SingularityType settled = singularity.type;
    if (m_capabilityLayout) {
        settled = capability::evaluate(*m_mechanism, m_actuators, pose, singularity.type, m_capabilityValues);
        capability::settleNearSingular(layout, m_values, settled, singularity.type);
    }
    for (std::size_t i = 0; i < layout.entries.size(); ++i)
        show(m_items[i], layout.entries[i], m_values);
    const char *reason = capability::nearSingularReason(settled, singularity.type);
    if (m_capabilityLayout) {
        for (std::size_t i = 0; i < m_capabilityLayout->entries.size(); ++i)
            show(m_capabilityItems[i], m_capabilityLayout->entries[i], m_capabilityValues);
        // the group's 0 and ∞ say so, and why, where the class does not
        m_capabilityGroup->setText(0, reason ? tr("Capability: as at a singular pose") : tr("Capability"));
        m_capabilityGroup->setToolTip(0, reason ? coreLabel(reason) : QString());
    }
    QString text = reason ? nearSingularityText(settled) : singularityText(singularity.type);
    if (singularity.type == SingularityType::None)
        text = tr("%1 (margin %2)").arg(text, QLocale().toString(singularity.margin, 'f', 3));
    m_singularity->setText(1, text);
    m_singularity->setToolTip(1, reason ? coreLabel(reason) : QString());
    widest = std::max(widest, text.size());
    if (widest > m_widestValue) {
        m_widestValue = widest;
        fitColumns();
    }
    m_singularity->setForeground(1, settled == SingularityType::None ? palette().text().color()
                                                                            : QColor(0xb3, 0x26, 0x1e));
}

QString ValuesTable::entryText(const ReportEntry &entry, const std::vector<double> &values) const
{
    const auto first = values.begin() + entry.offset;
    const bool unbounded = std::all_of(first, first + entry.rows * entry.cols, [](double v) { return std::isinf(v); });
    if (entry.rows * entry.cols == 1 || unbounded) {
        // a matrix that does not exist at a singular pose (J at an inverse one) is ∞ as a whole
        return formatQuantity(values[std::size_t(entry.offset)], entry.unit, entry.decimals);
    }
    // a matrix row by row, "[a, b; c, d] mm": the unit once, so it fits the dock; where the
    // comma is the decimal point the elements part with ";" and the rows with "|",
    // "[80,0; 138,6 | −80,0; 138,6]"
    const bool comma = QLocale().decimalPoint() == QStringLiteral(",");
    QStringList rows;
    for (int r = 0; r < entry.rows; ++r) {
        QStringList row;
        for (int c = 0; c < entry.cols; ++c)
            row << formatQuantity(values[std::size_t(entry.offset + r * entry.cols + c)], units::none, entry.decimals);
        rows << row.join(comma ? QStringLiteral("; ") : QStringLiteral(", "));
    }
    QString text = QLatin1Char('[') + rows.join(comma ? QStringLiteral(" | ") : QStringLiteral("; ")) + QLatin1Char(']');
    if (!entry.unit.symbol.empty())
        text += QLatin1Char(' ') + unitText(entry.unit);
    return text;
}

QString ValuesTable::valueText(const QString &name) const
{
    if (name == QLatin1String("singularity"))
        return m_singularity ? m_singularity->text(1) : QString();
    if (name == QLatin1String("capability"))
        return m_capabilityGroup ? m_capabilityGroup->toolTip(0) : QString();
    for (const auto *items : {&m_items, &m_capabilityItems}) {
        for (const QTreeWidgetItem *item : *items) {
            if (item->data(0, Qt::UserRole).toString() == name)
                return item->text(1);
        }
    }
    return {};
}

} // namespace pkm
