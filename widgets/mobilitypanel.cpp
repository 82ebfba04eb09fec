// The mobility panel (docs/mathematics.md, section 7): its subject — this mechanism or a
// classroom example —, the analysis run off the GUI thread, and the display kept in step with
// it; the display's words are made in mobilitydisplay.cpp.

#include "mobilitypanel.h"
#include "mobilitypanelinternal.h"

#include "quantityformat.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QScrollBar>
#include <QTextBrowser>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <array>
#include <numbers>

namespace pkm {

namespace {

constexpr double degree = std::numbers::pi / 180.0;

using mobilitypanel::quietColour;

/// The classroom examples (docs/mathematics.md): the П-joint prototype's parallelogram (a = 170 mm,
/// b = 68 mm) taken as a spatial chain, a Bennett linkage and four general revolute axes.
KinematicChain exampleChain(MobilityPanel::Subject subject)
{
    switch (subject) {
    case MobilityPanel::Subject::SpatialParallelogram:
        return mobility::spatialParallelogram(170.0, 68.0, 35.0 * degree);
    case MobilityPanel::Subject::BennettLinkage:
        return mobility::bennettLinkage(100.0, 30.0 * degree, 70.0 * degree, 100.0 * degree);
    case MobilityPanel::Subject::SpatialFourR:
        return mobility::randomSpatial4R(1);
    case MobilityPanel::Subject::ThisMechanism:
        break;
    }
    return {};
}

} // namespace

MobilityPanel::MobilityPanel(QWidget *parent)
    : QWidget(parent)
{
    m_pool.setMaxThreadCount(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto *row = new QHBoxLayout;
    m_subjectLabel = new QLabel(this);
    m_subjectBox = new QComboBox(this);
    for (int i = 0; i < 4; ++i) // one per Subject; their texts: retranslate()
        m_subjectBox->addItem(QString());
    m_subjectLabel->setBuddy(m_subjectBox);
    row->addWidget(m_subjectLabel);
    row->addWidget(m_subjectBox, 1);
    layout->addLayout(row);
    m_browser = new QTextBrowser(this);
    m_browser->setOpenLinks(false);
    m_browser->setFrameShape(QFrame::NoFrame);
    m_browser->setFocusPolicy(Qt::NoFocus);
    layout->addWidget(m_browser, 1);

    connect(m_subjectBox, &QComboBox::currentIndexChanged, this, [this] {
        ++m_context;
        request();
    });
    connect(&m_watcher, &QFutureWatcher<Analysis>::finished, this, &MobilityPanel::onFinished);
    retranslate();
}

void MobilityPanel::retranslate()
{
    m_subjectLabel->setText(tr("Analyse:"));
    m_subjectBox->setItemText(int(Subject::ThisMechanism), tr("This mechanism"));
    m_subjectBox->setItemText(int(Subject::SpatialParallelogram), tr("Example: spatial parallelogram"));
    m_subjectBox->setItemText(int(Subject::BennettLinkage), tr("Example: Bennett linkage"));
    m_subjectBox->setItemText(int(Subject::SpatialFourR), tr("Example: general spatial 4R (rigid)"));
    m_subjectBox->setToolTip(tr("Classroom examples: chains where the structural formulas fail, and one where "
                                "the counts predict the truth"));
}

void MobilityPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        // The analysis on display speaks the old language (core made its chain and verdict):
        // run it again, now or when the panel is seen.
        if (m_html.isEmpty() && isBusy())
            showPlaceholder(tr("Analysing…"));
        request();
    }
    QWidget::changeEvent(event);
}

MobilityPanel::~MobilityPanel()
{
    m_watcher.disconnect(this);
}

void MobilityPanel::setMechanism(const MechanismPtr &mechanism)
{
    if (!m_mechanism || !mechanism || m_mechanism->kind() != mechanism->kind() || m_chain)
        ++m_context;
    m_mechanism = mechanism;
    m_chain.reset();
    m_pose.reset(); // the old pose may not fit the new design: wait for setPose()
}

void MobilityPanel::setMechanism(const MechanismPtr &mechanism, const Pose &pose)
{
    setMechanism(mechanism);
    setPose(pose);
}

void MobilityPanel::setPose(const Pose &pose)
{
    m_pose = pose;
    if (subject() == Subject::ThisMechanism)
        request();
}

void MobilityPanel::setChain(const KinematicChain &chain)
{
    ++m_context;
    m_mechanism.reset();
    m_pose.reset();
    m_chain = chain;
    if (subject() == Subject::ThisMechanism)
        request();
}

MobilityPanel::Subject MobilityPanel::subject() const
{
    return static_cast<Subject>(std::max(0, m_subjectBox->currentIndex()));
}

void MobilityPanel::setSubject(Subject subject)
{
    m_subjectBox->setCurrentIndex(static_cast<int>(subject));
}

bool MobilityPanel::isBusy() const
{
    return m_running != 0 || m_waiting.has_value();
}

QString MobilityPanel::partText(Part part) const
{
    const auto found = m_parts.find(part);
    return found == m_parts.end() ? QString() : found->second;
}

QString MobilityPanel::plainText() const
{
    return m_browser->toPlainText();
}

void MobilityPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // Later: a dock shown as a tab behind another says so (visibilityChanged) after this.
    QTimer::singleShot(0, this, [this] {
        if (m_stale && isSeen())
            request();
    });
}

bool MobilityPanel::event(QEvent *event)
{
    if (event->type() == QEvent::ParentChange)
        findDock();
    return QWidget::event(event);
}

void MobilityPanel::findDock()
{
    QDockWidget *dock = nullptr;
    for (QWidget *w = parentWidget(); w && !dock; w = w->parentWidget())
        dock = qobject_cast<QDockWidget *>(w);
    if (dock == m_dock)
        return;
    if (m_dock)
        m_dock->disconnect(this);
    m_dock = dock;
    m_dockInFront = true;
    if (dock) {
        connect(dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
            m_dockInFront = visible;
            if (m_stale && isSeen())
                request();
        });
    }
}

bool MobilityPanel::isSeen() const
{
    return isVisible() && m_dockInFront;
}

void MobilityPanel::request()
{
    if (!isSeen()) {
        m_stale = true;
        return;
    }
    m_stale = false;
    Analysis analysis;
    analysis.subject = subject();
    if (analysis.subject != Subject::ThisMechanism) {
        analysis.chain = exampleChain(analysis.subject);
    } else if (m_chain) {
        analysis.chain = *m_chain;
    } else if (m_mechanism && m_pose) {
        analysis.chain = m_mechanism->kinematicChain(*m_pose);
        analysis.kind = std::string(m_mechanism->kind());
    } else {
        m_waiting.reset();
        m_shown = Analysis {};
        m_shown.request = ++m_requests; // whatever is running is older
        showPlaceholder(tr("No mechanism to analyse."));
        return;
    }
    analysis.request = ++m_requests;
    analysis.context = m_context;
    if (m_running != 0)
        m_waiting = std::move(analysis);
    else
        start(std::move(analysis));
}

void MobilityPanel::start(Analysis analysis)
{
    m_running = analysis.request;
    if (m_html.isEmpty())
        showPlaceholder(tr("Analysing…"));
    m_watcher.setFuture(QtConcurrent::run(&m_pool, [analysis = std::move(analysis)]() mutable {
        analysis.report = analyseMobility(analysis.chain);
        return analysis;
    }));
}

void MobilityPanel::onFinished()
{
    Analysis done = m_watcher.result();
    m_running = 0;
    // A result older than the one shown, or of another subject or kind of mechanism, is
    // dropped; one of the same subject is shown even when a newer pose waits, so that the
    // display follows a drag.
    if (done.request > m_shown.request && done.context == m_context)
        display(done);
    if (m_waiting) {
        Analysis next = std::move(*m_waiting);
        m_waiting.reset();
        start(std::move(next));
    }
}

void MobilityPanel::display(const Analysis &analysis)
{
    m_shown = analysis;
    const std::map<Part, QString> parts
        = mobilitypanel::displayParts(analysis.chain, analysis.report, analysis.subject);
    QString html;
    m_parts.clear();
    for (const auto &[part, fragment] : parts) {
        html += fragment;
        m_parts[part] = QTextDocumentFragment::fromHtml(fragment).toPlainText().replace(QChar::Nbsp, QLatin1Char(' '));
    }
    if (html != m_html) {
        // the text follows the pose while the reader keeps their place in it
        const int scrolled = m_browser->verticalScrollBar()->value();
        m_html = html;
        m_browser->setHtml(html);
        m_browser->verticalScrollBar()->setValue(scrolled);
    }
    emit analysisShown();
}

void MobilityPanel::showPlaceholder(const QString &text)
{
    m_parts.clear();
    m_html.clear();
    m_browser->setHtml(
        QStringLiteral("<p style=\"color:%1\">%2</p>").arg(QLatin1String(quietColour), text.toHtmlEscaped()));
}

} // namespace pkm
