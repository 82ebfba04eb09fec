#include "gui/requirementsdialog.h"

#include "quantityformat.h"
#include "symboltext.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace pkm {

namespace {
/// The rows: the four quantities the workspace maps show, each in the direction a designer
/// asks for it (at least so much force, at most so much error).
struct RowSpec {
    const char *name;
    bool atLeast;
};
constexpr RowSpec rowSpecs[] = {
    {"force_worst", true},
    {"speed_worst", true},
    {"resolution_worst", false},
    {"stiffness_worst", true},
};

/// `value` to two significant digits, down for a least value and up for a largest one, so
/// that the pose it came from meets the requirement; 0 where it is not finite.
double rounded(double value, bool down)
{
    if (!std::isfinite(value) || value <= 0.0)
        return 0.0;
    const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
    return (down ? std::floor(value / unit) : std::ceil(value / unit)) * unit;
}
} // namespace

RequirementsDialog::RequirementsDialog(const Mechanism &mechanism, const Pose &pose,
                                       const std::vector<capability::Requirement> &requirements, QWidget *parent)
    : QDialog(parent)
{
    const capability::Actuators actuators = capability::actuatorsOf(mechanism);
    const ReportLayout *entries = capability::layoutFor(actuators);
    std::vector<double> here(entries ? std::size_t(entries->size) : 0, std::nan(""));
    if (entries) {
        std::vector<double> report(std::size_t(mechanism.reportLayout().size));
        capability::evaluate(mechanism, actuators, pose, mechanism.evaluate(pose, report).type, here);
    }
    setWindowTitle(tr("Requirements"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("What the actuators must deliver at the platform. The workspace map “where the "
                                "requirements hold” shows, in green, where every checked one does, from the "
                                "actuators' limits in the design."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto *grid = new QGridLayout;
    layout->addLayout(grid);
    m_kept = requirements;
    for (const RowSpec &spec : rowSpecs) {
        const ReportEntry *entry = entries ? entries->find(spec.name) : nullptr;
        if (!entry)
            continue;
        Row row{spec.name, spec.atLeast, entry->unit};
        const int r = int(m_rows.size());
        row.check = new QCheckBox(QStringLiteral("%1 %2").arg(toQString(entry->symbol), spec.atLeast ? QStringLiteral("≥")
                                                                                                      : QStringLiteral("≤")),
                                  this);
        row.check->setObjectName(QString::fromLatin1(spec.name));
        row.check->setToolTip(coreLabel(entry->label));
        row.value = new NumberSpinBox(this);
        row.value->setObjectName(QString::fromLatin1(spec.name) + QStringLiteral("Value"));
        row.value->setDecimals(std::max(1, entry->decimals));
        row.value->setRange(0.0, 1e9);
        row.value->setValue(rounded(entry->unit.toDisplay(here[std::size_t(entry->offset)]), spec.atLeast));
        row.value->setEnabled(false);
        auto *meaning = new QLabel(QStringLiteral("%1 — %2").arg(unitText(entry->unit), coreLabel(entry->label)), this);
        meaning->setWordWrap(true);
        // a requirement on this entry in this direction fills the row; it is no longer "kept"
        const auto given = std::find_if(m_kept.begin(), m_kept.end(), [&](const capability::Requirement &k) {
            return k.name == spec.name && k.atLeast == spec.atLeast;
        });
        if (given != m_kept.end()) {
            row.check->setChecked(true);
            row.value->setValue(entry->unit.toDisplay(given->value));
            row.value->setEnabled(true);
            m_kept.erase(given);
        }
        connect(row.check, &QCheckBox::toggled, row.value, &QWidget::setEnabled);
        grid->addWidget(row.check, r, 0);
        grid->addWidget(row.value, r, 1);
        grid->addWidget(meaning, r, 2);
        m_rows.push_back(row);
    }
    grid->setColumnStretch(2, 1);
    if (m_rows.empty()) {
        layout->addWidget(new QLabel(tr("This design states no actuator limits: there is nothing to require."), this));
    }
    if (!m_kept.empty()) {
        QStringList lines;
        for (const capability::Requirement &k : m_kept)
            lines << QString::fromStdString(capability::requirementText(k, actuators));
        auto *kept = new QLabel(tr("Also required (from the file, kept as it is): %1").arg(lines.join(QStringLiteral("; "))), this);
        kept->setWordWrap(true);
        layout->addWidget(kept);
    }
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

std::vector<capability::Requirement> RequirementsDialog::requirements() const
{
    std::vector<capability::Requirement> out;
    for (const Row &row : m_rows) {
        if (row.check->isChecked())
            out.push_back({row.name, row.atLeast, row.unit.fromDisplay(row.value->value())});
    }
    out.insert(out.end(), m_kept.begin(), m_kept.end());
    return out;
}

QCheckBox *RequirementsDialog::checkBox(const char *name) const
{
    for (const Row &row : m_rows)
        if (std::string_view(row.name) == name)
            return row.check;
    return nullptr;
}

QDoubleSpinBox *RequirementsDialog::valueBox(const char *name) const
{
    for (const Row &row : m_rows)
        if (std::string_view(row.name) == name)
            return row.value;
    return nullptr;
}

} // namespace pkm
