// The mobility panel's display in words (docs/mathematics.md, section 7): the chain, Chebyshev's
// and Somov–Malyshev's formulas with the numbers put in, the rank of the constraint Jacobian,
// the singular poses, the actuation and the verdict, each an HTML fragment in the house colours;
// a formula that fails is marked with a word and a sign, never by colour alone.

#include "mobilitypanel.h"
#include "mobilitypanelinternal.h"

#include "quantityformat.h"


#include <QCoreApplication>
#include <QLocale>

#include <array>
#include <cmath>
#include <map>
#include <optional>

namespace pkm {

namespace {

using mobilitypanel::quietColour;

// The house colours (designpanel.cpp): right, wrong, alarm, notes.
constexpr const char *okColour = "#1e6b34";
constexpr const char *warningColour = "#8a5a00";
constexpr const char *alarmColour = "#b3261e";
constexpr const char *alarmBackground = "#fde7e5";
constexpr const char *noteBackground = "#eef3f8";
constexpr const char *noteBorder = "#c5d3e0";

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

namespace mobilitypanel {

std::map<MobilityPanel::Part, QString> displayParts(const KinematicChain &chain, const MobilityReport &report,
    MobilityPanel::Subject subject)
{
    return Display(chain, report, subject).parts();
}

} // namespace mobilitypanel

} // namespace pkm
