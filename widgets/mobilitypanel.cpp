#include "mobilitypanel.h"

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

// The house colours (designpanel.cpp): right, wrong, alarm, notes.
constexpr const char *okColour = "#1e6b34";
constexpr const char *warningColour = "#8a5a00";
constexpr const char *alarmColour = "#b3261e";
constexpr const char *alarmBackground = "#fde7e5";
constexpr const char *noteBackground = "#eef3f8";
constexpr const char *noteBorder = "#c5d3e0";
constexpr const char *quietColour = "#555555";

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

/// The rotation axes of all pairs are parallel and the slides perpendicular to them (no
/// spherical pair): every loop moves in a plane.
bool axesParallel(const KinematicChain &chain)
{
    std::optional<Eigen::Vector3d> axis;
    for (const KinematicPair &pair : chain.pairs) {
        Eigen::Vector3d rotation;
        switch (pair.type) {
        case PairType::Spherical:
            return false;
        case PairType::Prismatic:
            continue;
        case PairType::CamPlanar:
            rotation = Eigen::Vector3d::UnitZ();
            break;
        case PairType::Revolute:
        case PairType::Screw:
        case PairType::Cylindrical:
            rotation = pair.axis.normalized();
            break;
        }
        if (!axis)
            axis = rotation;
        else if (axis->cross(rotation).norm() > 1e-9)
            return false;
    }
    if (!axis)
        return false;
    for (const KinematicPair &pair : chain.pairs) {
        if (pair.type == PairType::Prismatic && std::abs(pair.axis.normalized().dot(*axis)) > 1e-9)
            return false;
    }
    return true;
}

/// The texts of the display: one HTML fragment per part.
class Display
{
    Q_DECLARE_TR_FUNCTIONS(pkm::MobilityPanel)

public:
    using Subject = MobilityPanel::Subject;
    using Part = MobilityPanel::Part;

    Display(const KinematicChain &chain, const MobilityReport &report, Subject subject)
        : c(chain)
        , r(report)
        , subject(subject)
    {
    }

    std::map<Part, QString> parts() const
    {
        std::map<Part, QString> out;
        if (subject != Subject::ThisMechanism)
            out[Part::Example] = example();
        out[Part::Chain] = chainInWords();
        if (r.valid) {
            if (const QString s = singularity(); !s.isEmpty())
                out[Part::Singularity] = s;
            out[Part::Chebyshev] = chebyshev();
            out[Part::SomovMalyshev] = somovMalyshev();
            out[Part::Note] = note();
            out[Part::Rank] = rank();
            if (subject == Subject::ThisMechanism)
                out[Part::Actuation] = actuation();
        }
        out[Part::Verdict] = verdict();
        return out;
    }

private:
    // -- words and numbers ------------------------------------------------------------------

    /// An integer as printed for people: a true minus sign.
    static QString integer(int n)
    {
        const QString digits = QLocale().toString(std::abs(n));
        return n < 0 ? QStringLiteral("−") + digits : digits;
    }

    /// English plurals of "%n link(s)" until the English catalogue supplies them
    /// (translations/README.md).
    static QString plural(QString text, int n)
    {
        return text.replace(QStringLiteral("(s)"), n == 1 ? QString() : QStringLiteral("s"));
    }

    static QString html(std::string_view text) { return toQString(text).toHtmlEscaped(); }

    static QString coloured(const QString &text, const char *colour)
    {
        return QStringLiteral("<span style=\"color:%1; font-weight:600\">%2</span>").arg(QLatin1String(colour), text);
    }

    /// An equation kept on one line.
    static QString equation(QString text) { return text.replace(QLatin1Char(' '), QStringLiteral("&nbsp;")); }

    /// A sign and its word, kept on one line.
    static QString marker(QString text, const char *colour)
    {
        return coloured(text.replace(QLatin1Char(' '), QStringLiteral("&nbsp;")), colour);
    }

    static QString heading(const QString &title, const QString &marker = {})
    {
        return QStringLiteral("<p style=\"margin-top:14px; margin-bottom:4px\"><span style=\"font-size:large; "
                              "font-weight:600\">%1</span>%2</p>")
            .arg(title,
                marker.isEmpty() ? QString()
                                 : QStringLiteral("&nbsp;&nbsp;<span style=\"font-size:large\">%1</span>").arg(marker));
    }

    /// A box with a coloured background, the width of the panel.
    static QString box(const QString &content, const char *background, const char *border)
    {
        return QStringLiteral("<table width=\"100%\" cellspacing=\"0\" cellpadding=\"7\" border=\"1\" "
                              "style=\"margin-top:8px; border-style:solid; border-color:%2; background-color:%1\">"
                              "<tr><td>%3</td></tr></table>")
            .arg(QLatin1String(background), QLatin1String(border), content);
    }

    /// W = formula, = the numbers put in, = the result, the "="s one under the other.
    static QString derivation(const QString &formula, const QString &numbers, const QString &result)
    {
        static const QString row = QStringLiteral("<tr><td>%1</td><td>%2</td></tr>");
        return QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\" style=\"font-size:large; margin-left:8px\">")
            + row.arg(QStringLiteral("W&nbsp;"), QStringLiteral("= ") + formula)
            + row.arg(QString(), QStringLiteral("= ") + numbers) + row.arg(QString(), QStringLiteral("= ") + result)
            + QStringLiteral("</table>");
    }

    QString rightMarker() const { return marker(tr("✓ right"), okColour); }
    QString wrongMarker() const { return marker(tr("⚠ wrong"), warningColour); }

    /// Why a formula that fails fails: it counts `perLoop` equations per loop and some of them
    /// are redundant.
    QString whyWrong(int w, int perLoop, int redundant) const
    {
        QString text = plural(tr("W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and "
                                 "%n of them are redundant.",
                                  nullptr, redundant),
            redundant)
                           .arg(integer(w), integer(r.mobility), integer(perLoop));
        if (w < 0 && r.mobility == 0)
            text += QLatin1Char(' ') + tr("A negative W rightly says “rigid”, but it is not the mobility: M = 0.");
        return text;
    }

    QString pairNames(bool actuatedOnly) const
    {
        QStringList names;
        for (const KinematicPair &pair : c.pairs) {
            if (!actuatedOnly || pair.actuated)
                names << html(pair.name);
        }
        return names.join(QStringLiteral(", "));
    }

    QString pairTypeText(PairType type, int count) const
    {
        switch (type) {
        case PairType::Revolute:
            return tr("%n revolute", nullptr, count);
        case PairType::Prismatic:
            return tr("%n prismatic", nullptr, count);
        case PairType::Screw:
            return tr("%n screw", nullptr, count);
        case PairType::Cylindrical:
            return tr("%n cylindrical", nullptr, count);
        case PairType::CamPlanar:
            return tr("%n planar cam", nullptr, count);
        case PairType::Spherical:
            return tr("%n spherical", nullptr, count);
        }
        return {};
    }

    // -- the parts --------------------------------------------------------------------------

    QString example() const
    {
        QString text;
        switch (subject) {
        case Subject::SpatialParallelogram:
            text = tr("<b>Classroom example: the spatial parallelogram.</b> The П-joint prototype's hinged "
                      "parallelogram (a = 170 mm, b = 68 mm): four parallel revolute axes, counted as a spatial "
                      "chain.");
            break;
        case Subject::BennettLinkage:
            text = tr("<b>Classroom example: the Bennett linkage.</b> Four skew revolute axes, opposite links "
                      "equal (a = 100 mm, b ≈ 188 mm) with twists α = 30°, β = 70° and a/sin α = b/sin β.");
            break;
        case Subject::SpatialFourR:
            text = tr("<b>Classroom example: a general spatial 4R loop.</b> Four revolute axes in general "
                      "position, without Bennett's proportions: the same counts as the Bennett linkage.");
            break;
        case Subject::ThisMechanism:
            break;
        }
        return box(text, noteBackground, noteBorder);
    }

    QString chainInWords() const
    {
        QString out;
        if (!c.description.empty()) {
            QString title = html(c.description);
            title[0] = title[0].toUpper();
            out += QStringLiteral("<p><span style=\"font-size:large; font-weight:600\">%1</span></p>").arg(title);
        }
        if (c.links.empty())
            return out;
        // core names the links in the language of the moment: "ground AD", Russian "стойка AD"
        const QString groundName = html(c.links.front());
        const bool named = groundName.startsWith(QLatin1String("ground"))
            || groundName.startsWith(QCoreApplication::translate("core", "ground").toHtmlEscaped());
        const QString ground = named ? tr("the %1").arg(groundName) : tr("the ground (%1)").arg(groundName);
        QStringList moving;
        for (std::size_t i = 1; i < c.links.size(); ++i)
            moving << html(c.links[i]);
        const int n = c.movingLinks();
        QStringList lines;
        lines << plural(tr("<b>Links</b>: %1 and %n moving link(s), n = %n: %2.", nullptr, n), n)
                     .arg(ground, moving.join(QStringLiteral(", ")));

        // pairs by class, the most constrained first: "4 revolute, 3 prismatic (P₅ = 7)"
        static constexpr std::array<PairType, 6> types = {PairType::Revolute, PairType::Prismatic, PairType::Screw,
            PairType::Cylindrical, PairType::CamPlanar, PairType::Spherical};
        static const std::array<QString, 6> classSymbols = {QString(), QStringLiteral("P₁"), QStringLiteral("P₂"),
            QStringLiteral("P₃"), QStringLiteral("P₄"), QStringLiteral("P₅")};
        QStringList classes;
        for (int k = 5; k >= 1; --k) {
            QStringList kinds;
            int inClass = 0;
            for (PairType type : types) {
                if (mobility::pairClass(type) != k)
                    continue;
                int count = 0;
                for (const KinematicPair &pair : c.pairs)
                    count += pair.type == type ? 1 : 0;
                if (count > 0)
                    kinds << pairTypeText(type, count);
                inClass += count;
            }
            if (inClass > 0)
                classes << QStringLiteral("%1 (%2 = %3)")
                               .arg(kinds.join(QStringLiteral(", ")), classSymbols[std::size_t(k)])
                               .arg(inClass);
        }
        QString pairs
            = tr("<b>Pairs</b>: %1.").arg(classes.isEmpty() ? tr("none") : classes.join(QStringLiteral("; ")));
        const QString actuated = pairNames(true);
        if (!actuated.isEmpty() && subject == Subject::ThisMechanism) // not the point of an example
            pairs += QLatin1Char(' ') + tr("Actuated: %1.").arg(actuated);
        lines << pairs;
        if (r.valid)
            lines << plural(tr("<b>Loops</b>: %n independent loop(s), L = %n.", nullptr, r.loops), r.loops);
        if (c.idleFreedoms > 0)
            lines << plural(tr("<b>Idle freedoms</b>: %n (a part spinning about its own axis), counted in every "
                               "number below.",
                                nullptr, c.idleFreedoms),
                c.idleFreedoms);
        out += QStringLiteral("<p>%1</p>").arg(lines.join(QStringLiteral("<br>")));
        return out;
    }

    QString singularity() const
    {
        QStringList texts;
        if (r.singular) {
            const int gained = r.numerical - r.mobility;
            QString text = gained == 1
                ? tr("At this pose the mechanism gains an instantaneous freedom (singularity).")
                : tr("At this pose the mechanism gains %n instantaneous freedoms (singularity).", nullptr, gained);
            text += QLatin1Char(' ')
                + tr("The rank of the loop equations drops from %1 to %2: the instantaneous mobility is %3, the "
                     "mobility next to this pose %4.")
                      .arg(r.freedoms - r.mobility)
                      .arg(r.rank)
                      .arg(integer(r.numerical), integer(r.mobility));
            texts << text;
        }
        if (r.lockedMobility > r.lockedMobilityNearby) {
            texts << tr("With the actuators locked the mechanism can still move instantaneously here: it gains a "
                        "freedom the actuators do not control (a direct singularity).");
        }
        if (texts.isEmpty())
            return {};
        const QString title = QStringLiteral("<span style=\"color:%1; font-size:large; font-weight:600\">%2</span>")
                                  .arg(QLatin1String(alarmColour),
                                      tr("⚠ Singular pose").replace(QLatin1Char(' '), QStringLiteral("&nbsp;")));
        return box(title + QStringLiteral("<br>") + texts.join(QStringLiteral("<br>")), alarmBackground, alarmColour);
    }

    QString chebyshev() const
    {
        const QString title = tr("Chebyshev (planar chains)");
        if (!r.chebyshev) {
            const QString why = r.planar ? tr("Does not apply: the chain has pairs that do not move in its plane.")
                                         : tr("Does not apply: a spatial chain.");
            return heading(title) + QStringLiteral("<p style=\"color:%1\">%2</p>").arg(QLatin1String(quietColour), why);
        }
        const int w = *r.chebyshev;
        const QString numbers
            = QStringLiteral("3·%1 − 2·%2 − %3").arg(r.movingLinks).arg(r.pairsByClass[5]).arg(r.pairsByClass[4]);
        const QString result = QStringLiteral("<b>%1</b>").arg(integer(w));
        QString out = heading(title, r.chebyshevFails ? wrongMarker() : rightMarker())
            + derivation(QStringLiteral("3n − 2P₅ − P₄"), numbers,
                r.chebyshevFails ? coloured(integer(w), warningColour) : result);
        if (r.chebyshevFails)
            out += QStringLiteral("<p>%1</p>").arg(whyWrong(w, 3, r.planarRedundantConstraints.value_or(0)));
        return out;
    }

    QString somovMalyshev() const
    {
        const QString title = tr("Somov–Malyshev (spatial chains)");
        const auto &p = r.pairsByClass;
        const QString numbers = QStringLiteral("6·%1 − 5·%2 − 4·%3 − 3·%4 − 2·%5 − %6")
                                    .arg(r.movingLinks)
                                    .arg(p[5])
                                    .arg(p[4])
                                    .arg(p[3])
                                    .arg(p[2])
                                    .arg(p[1]);
        const int w = r.somovMalyshev;
        QString out = heading(title, r.somovMalyshevFails ? wrongMarker() : rightMarker())
            + derivation(QStringLiteral("6n − 5P₅ − 4P₄ − 3P₃ − 2P₂ − P₁"), numbers,
                r.somovMalyshevFails ? coloured(integer(w), warningColour)
                                     : QStringLiteral("<b>%1</b>").arg(integer(w)));
        if (r.somovMalyshevFails)
            out += QStringLiteral("<p>%1</p>").arg(whyWrong(w, 6, r.redundantConstraints));
        return out;
    }

    /// The document's "+P₁" (docs/mathematics.md).
    QString note() const
    {
        QString text = tr("The source document prints the last term as “+ P₁”: a typo. A pair of class 1 takes "
                          "away one freedom, so − P₁.");
        const int printed = mobility::documentSomovMalyshev(r.movingLinks, r.pairsByClass);
        if (printed != r.somovMalyshev)
            text += QLatin1Char(' ')
                + coloured(tr("⚠ Here it matters: with + P₁ the formula would give W = %1.").arg(integer(printed)),
                    warningColour);
        return QStringLiteral("<p style=\"font-size:small; color:%1\">%2</p>").arg(QLatin1String(quietColour), text);
    }

    QString redundancyCause() const
    {
        const int q = r.redundantConstraints;
        if (q == 0)
            return tr("No loop equation is redundant: the structural count holds.");
        QString cause;
        if (subject == Subject::BennettLinkage)
            cause = tr("Bennett's proportions (opposite links equal, a/sin α = b/sin β) make them depend on the "
                       "others, so the linkage moves although the count says it cannot.");
        else if (axesParallel(c))
            cause = tr("the joint axes are parallel, so each loop moves in a plane and imposes only 3 of its 6 "
                       "equations.");
        else if (r.mobility == 0)
            cause = tr("%1 independent equations already hold all %1 freedoms of the pairs: a rigid chain with "
                       "constraints to spare.")
                        .arg(r.freedoms - r.mobility);
        else
            cause = tr("the pairs' axes lie in a special way (parallel, or meeting in a point), so some equations "
                       "repeat others: an overconstrained chain.");
        return plural(tr("%n redundant loop equation(s): %1", nullptr, q), q).arg(cause);
    }

    QString rank() const
    {
        QString out = heading(tr("From the rank of the constraint Jacobian"));
        QStringList lines;
        const int F = r.freedoms, equations = 6 * r.loops;
        if (r.loops == 0) {
            lines << plural(
                tr("An open chain, no loop: nothing holds the %n freedom(s) of its pairs, M = F = %n.", nullptr, F), F);
        } else {
            lines << tr("F = %1 freedoms of the pairs; 6L = %2 loop equations.").arg(F).arg(equations);
            const int nearRank = F - r.mobility;
            if (r.singular) {
                lines
                    << tr("At this pose: rank %1 of %2 → %3 (instantaneous).")
                           .arg(r.rank)
                           .arg(equations)
                           .arg(equation(
                               QStringLiteral("F − rank = %1 − %2 = %3").arg(F).arg(r.rank).arg(integer(r.numerical))));
                lines << tr("Next to it: rank %1 of %2 → %3.")
                             .arg(nearRank)
                             .arg(equations)
                             .arg(equation(QStringLiteral("M = F − rank = %1 − %2 = %3")
                                               .arg(F)
                                               .arg(nearRank)
                                               .arg(integer(r.mobility))));
            } else {
                lines << tr("rank %1 of %2 loop equations → %3")
                             .arg(nearRank)
                             .arg(equations)
                             .arg(equation(QStringLiteral("M = F − rank = %1 − %2 = %3")
                                               .arg(F)
                                               .arg(nearRank)
                                               .arg(integer(r.mobility))));
            }
        }
        out += QStringLiteral("<p style=\"margin-left:8px\">%1</p>").arg(lines.join(QStringLiteral("<br>")));
        QString headline = tr("Mobility M = %1").arg(integer(r.mobility));
        if (r.singular)
            headline += QLatin1Char(' ') + tr("(%1 at this pose)").arg(integer(r.numerical));
        out += QStringLiteral("<p style=\"font-size:x-large; font-weight:600; margin-left:8px\">%1</p>").arg(headline);
        if (r.loops > 0)
            out += QStringLiteral("<p>%1</p>").arg(redundancyCause());
        return out;
    }

    QString actuation() const
    {
        QString out = heading(tr("Actuation"));
        const int useful = r.mobility - r.idleFreedoms;
        const int uncontrolled = r.lockedMobilityNearby - r.idleFreedoms;
        const QString names = pairNames(true);
        const QString actuators = plural(tr("%n actuated freedom(s)", nullptr, r.actuators), r.actuators)
            + QStringLiteral(" (%1)").arg(names);
        QString text;
        if (r.actuators == 0) {
            text = tr("No pair is actuated.");
        } else if (uncontrolled > 0) {
            text = marker(tr("⚠ Under-actuated by %1:").arg(uncontrolled), warningColour) + QLatin1Char(' ')
                + plural(
                    tr("%1 for mobility %2; with the actuators locked, it keeps %n freedom(s).", nullptr, uncontrolled),
                    uncontrolled)
                      .arg(actuators, integer(useful));
            // What the mechanism's own model says about the freedom its actuators leave (the
            // O-X glide's tilt, docs/mathematics.md).
            if (!c.underActuation.empty())
                text += QStringLiteral("</p><p>") + html(c.underActuation);
        } else if (r.actuators > useful) {
            text = tr("Redundantly actuated: %1 for mobility %2.").arg(actuators, integer(useful));
        } else {
            text = marker(tr("✓ Fully actuated:"), okColour) + QLatin1Char(' ')
                + tr("%1 for mobility %2.").arg(actuators, integer(useful));
        }
        return out + QStringLiteral("<p>%1</p>").arg(text);
    }

    QString verdict() const { return box(tr("<b>Verdict</b>: %1").arg(html(r.verdict)), noteBackground, noteBorder); }

    const KinematicChain &c;
    const MobilityReport &r;
    Subject subject;
};

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
        = Display(analysis.chain, analysis.report, analysis.subject).parts();
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
