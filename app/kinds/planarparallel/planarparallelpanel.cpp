#include "kinds/planarparallel/planarparallelpanel.h"

#include "document/document.h"
#include "kinds/workspacepanel.h"
#include "quantityformat.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace pkm {

namespace {
QString legName(int leg)
{
    return QString::number(leg + 1);
}
} // namespace

PlanarParallelPanel::PlanarParallelPanel(Document *document, QWidget *parent)
    : KindPanel(parent)
    , m_document(document)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_box = new QGroupBox(this);
    m_box->setObjectName(QStringLiteral("legsEditor"));
    auto *grid = new QGridLayout(m_box);
    m_platformLabel = new QLabel(m_box);
    m_platform = new QComboBox(m_box);
    m_platform->setObjectName(QStringLiteral("platformBox"));
    m_platformLabel->setBuddy(m_platform);
    m_add = new QPushButton(m_box);
    m_add->setObjectName(QStringLiteral("addLegButton"));
    m_remove = new QPushButton(m_box);
    m_remove->setObjectName(QStringLiteral("removeLegButton"));
    grid->addWidget(m_platformLabel, 0, 0);
    // over the legs' type and working mode both: in its own column "постоянная ориентация"
    // made every leg's type as wide, and the panel 420 px, past a 1024×768 projector
    grid->addWidget(m_platform, 0, 1, 1, 2, Qt::AlignLeft);
    // Below the legs, not beside the platform: a column of its own would widen the panel
    // past what a 1024-pixel screen leaves it.
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    grid->addLayout(buttons, 4, 0, 1, 4);
    for (int i = 0; i < 3; ++i) {
        const std::size_t k = std::size_t(i);
        m_legLabels[k] = new QLabel(m_box);
        m_types[k] = new QComboBox(m_box);
        m_types[k]->setObjectName(QStringLiteral("legType%1").arg(i + 1));
        m_working[k] = new QComboBox(m_box);
        m_working[k]->setObjectName(QStringLiteral("working%1").arg(i + 1));
        m_legLabels[k]->setBuddy(m_types[k]);
        grid->addWidget(m_legLabels[k], i + 1, 0);
        grid->addWidget(m_types[k], i + 1, 1);
        grid->addWidget(m_working[k], i + 1, 2, Qt::AlignLeft);
        connect(m_types[k], &QComboBox::activated, this, [this, k](int index) {
            std::array<LegType, 3> chosen = types();
            chosen[k] = LegType(m_types[k]->itemData(index).toInt());
            restructure(m_mechanism->design().platform, chosen);
        });
        connect(m_working[k], &QComboBox::activated, this,
                [this, i](int index) { setWorking(i, m_working[std::size_t(i)]->itemData(index).toInt()); });
    }
    // The choosers show their whole text (none is cut on a projector); the panel's width is
    // checked against 1024×768 in every language (tst_classroom).
    for (QComboBox *box : {m_platform, m_types[0], m_types[1], m_types[2], m_working[0], m_working[1], m_working[2]})
        box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    grid->setColumnStretch(3, 1);
    layout->addWidget(m_box);
    connect(m_platform, &QComboBox::activated, this,
            [this](int index) { restructure(PlatformType(m_platform->itemData(index).toInt()), types()); });
    connect(m_add, &QPushButton::clicked, this, [this] { restructure(PlatformType::Free, types()); });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        // two legs that can carry a platform of constant orientation keep it; others meet at a point
        const auto t = types();
        const auto parallelogram = [](LegType type) { return type == LegType::PRR || type == LegType::PiRR; };
        restructure(parallelogram(t[0]) && parallelogram(t[1]) ? PlatformType::Translating : PlatformType::Point, t);
    });

    m_map = new WorkspacePanel(this);
    layout->addWidget(m_map, 1);
    connect(m_map, &KindPanel::pointClicked, this, &KindPanel::pointClicked);
    connect(m_map, &KindPanel::statusMessage, this, &KindPanel::statusMessage);
    retranslate();
}

void PlanarParallelPanel::setDesign(const MechanismPtr &mechanism, const QString &title)
{
    m_mechanism = std::dynamic_pointer_cast<const PlanarParallel>(mechanism);
    m_map->setDesign(mechanism, title);
    showDesign();
}

void PlanarParallelPanel::setPresenting(bool on)
{
    m_box->setVisible(!on);
    m_map->setPresenting(on);
}

void PlanarParallelPanel::setPose(const Pose &pose)
{
    m_pose = pose;
    m_map->setPose(pose);
}

std::array<LegType, 3> PlanarParallelPanel::types() const
{
    std::array<LegType, 3> t {};
    for (std::size_t k = 0; k < 3; ++k)
        t[k] = m_mechanism->design().legs[k].type;
    return t;
}

bool PlanarParallelPanel::restructure(PlatformType platform, const std::array<LegType, 3> &chosen)
{
    if (!m_mechanism)
        return false;
    const Pose pose = m_pose.outputs.size() == m_mechanism->outputCount() ? m_pose : m_document->pose();
    const ParameterSet changes = m_mechanism->restructure(pose, platform, chosen);
    if (changes.empty())
        return true;
    const int before = m_mechanism->design().legCount(), after = platform == PlatformType::Free ? 3 : 2;
    int retyped = -1;
    for (int i = 0; i < after; ++i) {
        if (chosen[std::size_t(i)] != m_mechanism->design().legs[std::size_t(i)].type)
            retyped = i;
    }
    std::function<QString()> text;
    if (after > before)
        text = [] { return tr("Add leg 3"); };
    else if (after < before)
        text = [] { return tr("Remove leg 3"); };
    else if (platform != m_mechanism->design().platform)
        text = [] { return tr("Change the platform"); };
    else
        text = [retyped] { return tr("Change the type of leg %1").arg(legName(retyped)); };
    return answer(m_document->setParameters(changes, QStringLiteral("legs"), false, text));
}

bool PlanarParallelPanel::setWorking(int leg, int working)
{
    if (!m_mechanism)
        return false;
    const std::string name = "working" + std::to_string(leg + 1);
    return answer(m_document->setParameters({{name, double(working)}}, QString::fromStdString(name), false,
                                            [leg] { return tr("Change the working mode of leg %1").arg(legName(leg)); }));
}

bool PlanarParallelPanel::answer(const Result<bool> &result)
{
    if (result)
        return true;
    emit statusMessage(QString::fromStdString(result.failure().message), true);
    showDesign(); // the choosers go back to the design that stays
    return false;
}

void PlanarParallelPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void PlanarParallelPanel::retranslate()
{
    m_box->setTitle(tr("Legs"));
    m_platformLabel->setText(tr("&Platform:"));
    m_add->setText(tr("Add leg"));
    m_add->setToolTip(tr("A third leg, a strut opposite the other two: the platform becomes a free body (3 DOF)."));
    m_remove->setText(tr("Remove leg 3"));
    m_remove->setToolTip(tr("Two legs: the platform becomes a point, or keeps a constant orientation if both legs are P̲RR or П̲RR."));
    {
        const QSignalBlocker blocker(m_platform);
        m_platform->clear();
        // Short names in the box, the whole sentence as the item's tooltip: the panel keeps
        // the width of the map beside it on a 1024×768 projector in every language.
        const auto add = [](QComboBox *box, const QString &name, const QString &description, int data) {
            box->addItem(name, data);
            box->setItemData(box->count() - 1, description, Qt::ToolTipRole);
        };
        add(m_platform, tr("point"), tr("a point (2 legs, x and y)"), int(PlatformType::Point));
        add(m_platform, tr("constant orientation"), tr("constant orientation (2 legs, x and y)"), int(PlatformType::Translating));
        add(m_platform, tr("free body"), tr("free body (3 legs, x, y and φ)"), int(PlatformType::Free));
        for (int i = 0; i < 3; ++i) {
            const std::size_t k = std::size_t(i);
            m_legLabels[k]->setText(tr("Leg %1:").arg(legName(i)));
            const QSignalBlocker types(m_types[k]), working(m_working[k]);
            m_types[k]->clear();
            // the underlined joint is the actuated one; the codes are the same in every language
            add(m_types[k], QStringLiteral("R̲RR"), tr("R̲RR: driven crank and link"), int(LegType::RRR));
            add(m_types[k], QStringLiteral("P̲RR"), tr("P̲RR: driven slider and link"), int(LegType::PRR));
            add(m_types[k], QStringLiteral("RP̲R"), tr("RP̲R: telescopic strut"), int(LegType::RPR));
            add(m_types[k], QStringLiteral("П̲RR"), tr("П̲RR: active П-joint and link"), int(LegType::PiRR));
            m_types[k]->setToolTip(tr("The leg's joints from the base, the actuated one underlined."));
            m_working[k]->clear();
            // the words of the Design panel and the modes line ("w₁ = left"), not "mode +1"
            add(m_working[k], coreLabel("left"), tr("working mode +1"), 1);
            add(m_working[k], coreLabel("right"), tr("working mode −1"), -1);
            m_working[k]->setToolTip(tr("+1: the elbow left of the line from A to the platform point (P̲RR: the slider beyond the foot of the perpendicular)."));
        }
    }
    if (m_mechanism)
        showDesign();
}

void PlanarParallelPanel::showDesign()
{
    if (!m_mechanism)
        return;
    const PlanarParallelDesign &d = m_mechanism->design();
    const int n = d.legCount();
    const QSignalBlocker blocker(m_platform);
    m_platform->setCurrentIndex(m_platform->findData(int(d.platform)));
    for (int i = 0; i < 3; ++i) {
        const std::size_t k = std::size_t(i);
        const QSignalBlocker types(m_types[k]), working(m_working[k]);
        m_types[k]->setCurrentIndex(m_types[k]->findData(int(d.legs[k].type)));
        m_working[k]->setCurrentIndex(m_working[k]->findData(d.legs[k].working > 0 ? 1 : -1));
        m_legLabels[k]->setVisible(i < n);
        m_types[k]->setVisible(i < n);
        m_working[k]->setVisible(i < n && d.legs[k].type != LegType::RPR); // a strut has one working mode
    }
    // Only the one that applies: a greyed "Remove leg 3" under two legs read as if there were
    // a third to remove.
    m_add->setVisible(n == 2);
    m_remove->setVisible(n == 3);
}

} // namespace pkm
