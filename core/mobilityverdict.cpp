// The words of a mobility report's verdict: the counts of links, pairs and loops, whether the
// structural formulas give the numerical mobility and why not, and how the chain is actuated
// (docs/mathematics.md, section 7).

#include "mobilityinternal.h"

#include "mechanism.h"
#include "text.h"

#include <string>
#include <string_view>

namespace pkm {

namespace {
/// A phrase with a count: `translated`, the catalogue's plural form of a "%n …(s)" source, when a
/// program installed one (text::install); else English, `one` for n = 1 and `many` otherwise with
/// "%n" replaced by n, so that the CLI and the tests read "1 loop", "3 loops".
std::string counted(std::string translated, int n, std::string_view one, std::string_view many)
{
    // a catalogue leaves "%n" for n < 0 (no plural form): filled here, as in English
    std::string phrase = text::installed().translate ? std::move(translated) : std::string(n == 1 ? one : many);
    const std::string number = std::to_string(n);
    for (std::size_t at = phrase.find("%n"); at != std::string::npos; at = phrase.find("%n", at + number.size()))
        phrase.replace(at, 2, number);
    return phrase;
}

/// An integer as printed for people: a true minus sign.
std::string integerText(int n)
{
    return n < 0 ? joinText({"−", std::to_string(-n)}) : std::to_string(n);
}

} // namespace

namespace mobility {

std::string verdictOf(const MobilityReport &r)
{
    const int M = r.mobility;
    const std::string links = counted(text::translate("core", "%n moving link(s)", nullptr, r.movingLinks),
        r.movingLinks, "%n moving link", "%n moving links");
    const std::string pairs
        = counted(text::translate("core", "%n pair(s)", nullptr, r.pairs), r.pairs, "%n pair", "%n pairs");
    const std::string loops
        = counted(text::translate("core", "%n loop(s)", nullptr, r.loops), r.loops, "%n loop", "%n loops");
    std::string verdict = text::format(r.planar
            ? text::translate("core",
                "Planar chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4")
            : text::translate("core",
                "Spatial chain of %1, %2 and %3: the rank of its constraint Jacobian gives mobility %4"),
        {links, pairs, loops, integerText(M)});
    const auto add = [&verdict](const std::string &clause) { verdict.append("; ").append(clause); };
    if (r.chebyshev) {
        if (r.chebyshevFails) {
            const int n = r.planarRedundantConstraints.value_or(0);
            add(text::format(counted(text::translate("core",
                                         "Chebyshev's W = %1 is wrong: %n planar loop equation(s) is/are redundant (an "
                                         "overconstrained planar chain)",
                                         nullptr, n),
                                 n,
                                 "Chebyshev's W = %1 is wrong: %n planar loop equation is redundant (an overconstrained "
                                 "planar chain)",
                                 "Chebyshev's W = %1 is wrong: %n planar loop equations are redundant (an "
                                 "overconstrained planar chain)"),
                {integerText(*r.chebyshev)}));
        } else {
            add(text::format(text::translate("core", "Chebyshev's W = %1 is right"), {integerText(*r.chebyshev)}));
        }
    }
    if (!r.somovMalyshevFails) {
        add(text::format(
            text::translate("core", "Somov–Malyshev's W = %1 is right"), {integerText(r.somovMalyshev)}));
    } else {
        const std::string why = r.planar ? text::translate("core", "(parallel axes: a planar loop imposes only 3)")
            : M > 0 && r.somovMalyshev <= 0
            ? text::translate("core", "(an overconstrained, \"paradoxical\" chain: it moves)")
            : text::translate("core", "(an overconstrained chain)");
        const int n = r.redundantConstraints;
        add(text::format(counted(text::translate("core",
                                     "Somov–Malyshev's W = %1 is wrong: it counts 6 equations per loop and %n is/are "
                                     "redundant %2",
                                     nullptr, n),
                             n,
                             "Somov–Malyshev's W = %1 is wrong: it counts 6 equations per loop and %n is redundant "
                             "%2",
                             "Somov–Malyshev's W = %1 is wrong: it counts 6 equations per loop and %n are redundant "
                             "%2"),
            {integerText(r.somovMalyshev), why}));
    }
    if (r.singular) {
        add(text::format(
            text::translate("core", "at this pose the rank drops: the instantaneous mobility is %1, a singular pose"),
            {integerText(r.numerical)}));
    }
    const int useful = M - r.idleFreedoms;
    const int uncontrolled = r.lockedMobilityNearby - r.idleFreedoms;
    const int actuators = r.actuators;
    if (actuators == 0) {
        add(text::translate("core", "no pair is actuated"));
    } else if (uncontrolled > 0) {
        const std::string left = counted(text::translate("core", "%n freedom(s)", nullptr, uncontrolled), uncontrolled,
            "%n freedom", "%n freedoms");
        add(text::format(
            counted(text::translate("core", "%n actuated freedom(s) leave(s) %1 uncontrolled (under-actuated)", nullptr,
                        actuators),
                actuators, "%n actuated freedom leaves %1 uncontrolled (under-actuated)",
                "%n actuated freedoms leave %1 uncontrolled (under-actuated)"),
            {left}));
    } else if (actuators > useful) {
        add(text::format(
            counted(text::translate("core", "%n actuated freedom(s) for mobility %1: redundantly actuated", nullptr,
                        actuators),
                actuators, "%n actuated freedom for mobility %1: redundantly actuated",
                "%n actuated freedoms for mobility %1: redundantly actuated"),
            {integerText(useful)}));
    } else {
        add(counted(text::translate("core", "%n actuated freedom(s): fully actuated", nullptr, actuators), actuators,
            "%n actuated freedom: fully actuated", "%n actuated freedoms: fully actuated"));
    }
    if (r.lockedMobility > r.lockedMobilityNearby)
        add(text::translate(
            "core", "with the actuators locked it can still move instantaneously here (a direct singularity)"));
    if (r.idleFreedoms > 0) {
        add(counted(text::translate("core", "%n idle freedom(s) is/are included", nullptr, r.idleFreedoms),
            r.idleFreedoms, "%n idle freedom is included", "%n idle freedoms are included"));
    }
    verdict += '.';
    return verdict;
}

} // namespace mobility

} // namespace pkm
