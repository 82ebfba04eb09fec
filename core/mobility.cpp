#include "mobility.h"

#include "mechanism.h"
#include "text.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <string_view>

namespace pkm {

namespace {

using Twist = Eigen::Matrix<double, 6, 1>;

/// A rigid displacement x ↦ R·x + p.
struct Displacement {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

Displacement operator*(const Displacement &a, const Displacement &b)
{
    return {a.R * b.R, a.R * b.p + a.p};
}

Displacement inverse(const Displacement &g)
{
    const Eigen::Matrix3d Rt = g.R.transpose();
    return {Rt, -Rt * g.p};
}

/// Ad_g·ξ: the twist ξ carried by the displacement g.
Twist adjoint(const Displacement &g, const Twist &xi)
{
    Twist out;
    out.head<3>() = g.R * xi.head<3>();
    out.tail<3>() = g.R * xi.tail<3>() + g.p.cross(out.head<3>());
    return out;
}

/// exp(ξ̂·q) for a unit twist (|ω| = 1) or a translation (ω = 0):
/// R = e^{ω̂q}, p = (I − R)(ω × v) + ω·(ω·v)·q.
Displacement exponential(const Twist &xi, double q)
{
    const Eigen::Vector3d w = xi.head<3>(), v = xi.tail<3>();
    if (w.squaredNorm() == 0.0)
        return {Eigen::Matrix3d::Identity(), v * q};
    const Eigen::Matrix3d R = Eigen::AngleAxisd(q, w).toRotationMatrix();
    return {R, (Eigen::Matrix3d::Identity() - R) * w.cross(v) + w * w.dot(v) * q};
}

Twist revoluteTwist(const Eigen::Vector3d &axis, const Eigen::Vector3d &point)
{
    Twist xi;
    xi << axis, point.cross(axis);
    return xi;
}

Twist prismaticTwist(const Eigen::Vector3d &axis)
{
    Twist xi;
    xi << Eigen::Vector3d::Zero(), axis;
    return xi;
}

bool needsAxis(PairType type)
{
    return type != PairType::Spherical;
}

bool planarCapable(PairType type)
{
    return type == PairType::Revolute || type == PairType::Prismatic || type == PairType::CamPlanar;
}

/// Why the chain cannot be analysed, or empty.
std::string chainProblem(const KinematicChain &chain)
{
    const int links = static_cast<int>(chain.links.size());
    if (links == 0)
        return text::translate("core", "no kinematic chain is described for this mechanism");
    constexpr double along = 1e-9;
    for (const KinematicPair &pair : chain.pairs) {
        if (pair.link1 < 0 || pair.link1 >= links || pair.link2 < 0 || pair.link2 >= links || pair.link1 == pair.link2)
            return text::format(text::translate("core", "pair '%1' does not join two different links of the chain"),
                                {pair.name});
        if (!pair.point.allFinite() || !pair.axis.allFinite() || !std::isfinite(pair.pitch))
            return text::format(text::translate("core", "pair '%1' has a point or an axis that is not finite"),
                                {pair.name});
        if (needsAxis(pair.type) && pair.axis.norm() < along)
            return text::format(text::translate("core", "pair '%1' has no axis"), {pair.name});
        if (!chain.planar)
            continue;
        const Eigen::Vector3d axis = pair.axis.normalized();
        const bool rotates = pair.type == PairType::Revolute;
        const bool inPlane = pair.type == PairType::Prismatic || pair.type == PairType::CamPlanar;
        if ((rotates && axis.head<2>().norm() > along) || (inPlane && std::abs(axis.z()) > along)
            || std::abs(pair.point.z()) > along * std::max(1.0, pair.point.norm()))
            return text::format(
                text::translate("core", "the chain is marked planar (the plane z = 0) but pair '%1' is not"),
                {pair.name});
    }
    return {};
}

/// The spanning tree of the link graph, from the ground (link 0) and then from any link not
/// reached (a floating part); the pairs left out are the chords, one loop each.
struct Tree {
    std::vector<int> order; ///< links, parents before children
    std::vector<int> parentPair; ///< per link, −1 for a root
    std::vector<std::vector<int>> path; ///< per link, the tree pairs from its root to it
    std::vector<int> chords;
    int components = 0;
};

Tree spanningTree(const KinematicChain &chain)
{
    const std::size_t links = chain.links.size();
    std::vector<std::vector<int>> adjacent(links);
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) {
        adjacent[std::size_t(chain.pairs[k].link1)].push_back(int(k));
        adjacent[std::size_t(chain.pairs[k].link2)].push_back(int(k));
    }
    Tree tree;
    tree.parentPair.assign(links, -1);
    tree.path.assign(links, {});
    std::vector<bool> reached(links, false), inTree(chain.pairs.size(), false);
    for (std::size_t root = 0; root < links; ++root) {
        if (reached[root])
            continue;
        ++tree.components;
        reached[root] = true;
        std::deque<int> queue {int(root)};
        while (!queue.empty()) {
            const int link = queue.front();
            queue.pop_front();
            tree.order.push_back(link);
            for (int k : adjacent[std::size_t(link)]) {
                const KinematicPair &pair = chain.pairs[std::size_t(k)];
                const int other = pair.link1 == link ? pair.link2 : pair.link1;
                if (reached[std::size_t(other)])
                    continue;
                reached[std::size_t(other)] = true;
                inTree[std::size_t(k)] = true;
                tree.parentPair[std::size_t(other)] = k;
                tree.path[std::size_t(other)] = tree.path[std::size_t(link)];
                tree.path[std::size_t(other)].push_back(k);
                queue.push_back(other);
            }
        }
    }
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) {
        if (!inTree[k])
            tree.chords.push_back(int(k));
    }
    return tree;
}

/// The unit twists of every freedom at the pose, in the scaled frame: origin at the centroid
/// c of the pair points, lengths divided by ℓ.
struct Freedoms {
    std::vector<Twist> twists;
    std::vector<int> pairOf; ///< per column
    std::vector<int> first; ///< per pair its first column; first[pairs] = F
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double size = 1.0;

    int count() const { return static_cast<int>(twists.size()); }
};

Freedoms freedomsOf(const KinematicChain &chain)
{
    Freedoms f;
    if (!chain.pairs.empty()) {
        for (const KinematicPair &pair : chain.pairs)
            f.centre += pair.point;
        f.centre /= double(chain.pairs.size());
        double size = 0.0;
        for (const KinematicPair &pair : chain.pairs)
            size = std::max(size, (pair.point - f.centre).norm());
        if (size > 0.0)
            f.size = size;
    }
    for (std::size_t k = 0; k < chain.pairs.size(); ++k) {
        const KinematicPair &pair = chain.pairs[k];
        f.first.push_back(f.count());
        const Eigen::Vector3d p = (pair.point - f.centre) / f.size;
        const Eigen::Vector3d a = needsAxis(pair.type) ? pair.axis.normalized() : Eigen::Vector3d::UnitZ();
        switch (pair.type) {
        case PairType::Revolute:
            f.twists.push_back(revoluteTwist(a, p));
            break;
        case PairType::Prismatic:
            f.twists.push_back(prismaticTwist(a));
            break;
        case PairType::Screw: {
            Twist xi = revoluteTwist(a, p);
            xi.tail<3>() += pair.pitch / f.size * a;
            f.twists.push_back(xi);
            break;
        }
        case PairType::Cylindrical:
            f.twists.push_back(revoluteTwist(a, p));
            f.twists.push_back(prismaticTwist(a));
            break;
        case PairType::Spherical:
            for (int i = 0; i < 3; ++i)
                f.twists.push_back(revoluteTwist(Eigen::Vector3d::Unit(i), p));
            break;
        case PairType::CamPlanar:
            f.twists.push_back(revoluteTwist(Eigen::Vector3d::UnitZ(), p));
            f.twists.push_back(prismaticTwist(Eigen::Vector3d::UnitZ().cross(a).normalized()));
            break;
        }
        while (int(f.pairOf.size()) < f.count())
            f.pairOf.push_back(int(k));
    }
    f.first.push_back(f.count());
    return f;
}

/// The loop equations at the joint displacements q from the pose (q = 0: the pose itself):
/// the 6L × F Jacobian and, per loop, the closure error of the chord (rotation vector, then
/// translation), zero on the closed chain.
struct Loops {
    Eigen::MatrixXd jacobian;
    Eigen::VectorXd residual;
};

Loops loopsAt(const KinematicChain &chain, const Tree &tree, const Freedoms &f, const Eigen::VectorXd &q)
{
    const int F = f.count();
    const int L = static_cast<int>(tree.chords.size());
    std::vector<Displacement> placement(chain.links.size());
    Eigen::MatrixXd current(6, F); // the twists carried to the displaced chain
    // the tree: each link displaced by the product of exponentials from its root
    for (int link : tree.order) {
        const int k = tree.parentPair[std::size_t(link)];
        if (k < 0)
            continue;
        const KinematicPair &pair = chain.pairs[std::size_t(k)];
        const int parent = pair.link2 == link ? pair.link1 : pair.link2;
        const double sign = pair.link2 == link ? 1.0 : -1.0; // a twist is link2's motion on link1
        Displacement g = placement[std::size_t(parent)];
        for (int col = f.first[std::size_t(k)]; col < f.first[std::size_t(k) + 1]; ++col) {
            const Twist xi = sign * f.twists[std::size_t(col)];
            current.col(col) = adjoint(g, xi);
            g = g * exponential(xi, q[col]);
        }
        placement[std::size_t(link)] = g;
    }
    Loops loops {Eigen::MatrixXd::Zero(6 * L, F), Eigen::VectorXd::Zero(6 * L)};
    for (int i = 0; i < L; ++i) {
        const int k = tree.chords[std::size_t(i)];
        const KinematicPair &pair = chain.pairs[std::size_t(k)];
        auto block = loops.jacobian.middleRows(6 * i, 6);
        Displacement g = placement[std::size_t(pair.link1)];
        for (int col = f.first[std::size_t(k)]; col < f.first[std::size_t(k) + 1]; ++col) {
            block.col(col) += adjoint(g, f.twists[std::size_t(col)]);
            g = g * exponential(f.twists[std::size_t(col)], q[col]);
        }
        const auto addPath = [&](int link, double sign) {
            for (int j : tree.path[std::size_t(link)]) {
                for (int col = f.first[std::size_t(j)]; col < f.first[std::size_t(j) + 1]; ++col)
                    block.col(col) += sign * current.col(col);
            }
        };
        addPath(pair.link1, 1.0);
        addPath(pair.link2, -1.0);
        const Displacement error = g * inverse(placement[std::size_t(pair.link2)]);
        const Eigen::AngleAxisd rotation(error.R);
        loops.residual.segment<3>(6 * i) = rotation.angle() * rotation.axis();
        loops.residual.segment<3>(6 * i + 3) = error.p;
    }
    return loops;
}

/// The rows ω_z, v_x, v_y of every loop: the planar loop equations.
Eigen::MatrixXd planarRows(const Eigen::MatrixXd &jacobian)
{
    const Eigen::Index loops = jacobian.rows() / 6;
    Eigen::MatrixXd rows(3 * loops, jacobian.cols());
    for (Eigen::Index i = 0; i < loops; ++i)
        rows.middleRows(3 * i, 3) = jacobian.middleRows(6 * i + 2, 3);
    return rows;
}

/// The columns of the freedoms that are not actuated.
Eigen::MatrixXd passiveColumns(const KinematicChain &chain, const Freedoms &f, const Eigen::MatrixXd &jacobian)
{
    std::vector<Eigen::Index> keep;
    for (int col = 0; col < f.count(); ++col) {
        if (!chain.pairs[std::size_t(f.pairOf[std::size_t(col)])].actuated)
            keep.push_back(col);
    }
    Eigen::MatrixXd out(jacobian.rows(), Eigen::Index(keep.size()));
    for (std::size_t i = 0; i < keep.size(); ++i)
        out.col(Eigen::Index(i)) = jacobian.col(keep[i]);
    return out;
}

/// The number of singular values above tolerance·σ_max (sorted, largest first).
int rankOf(const Eigen::VectorXd &sigma, double tolerance)
{
    if (sigma.size() == 0 || sigma[0] == 0.0)
        return 0;
    return static_cast<int>((sigma.array() > tolerance * sigma[0]).count());
}

/// The ranks that matter at one configuration.
struct Ranks {
    int full = 0;
    int planar = 0;
    int passive = 0;
};

Ranks ranksOf(const KinematicChain &chain, const Freedoms &f, const Eigen::MatrixXd &jacobian, double tolerance)
{
    Ranks r;
    r.full = mobility::numericalRank(jacobian, tolerance);
    if (chain.planar)
        r.planar = mobility::numericalRank(planarRows(jacobian), tolerance);
    r.passive = mobility::numericalRank(passiveColumns(chain, f, jacobian), tolerance);
    return r;
}

/// The ranks at regular configurations near the pose (see mobility.h): steps `step` (scaled
/// units: radians, or sizes ℓ) along random first-order motions, back onto the loop closures
/// by Newton's method with the least-norm correction, and keeps the largest ranks. Empty when
/// no step came back to the closed chain; `isolated` when every step fell back onto the pose
/// itself (a chain that is rigid although it has first-order motions).
struct Nearby {
    std::optional<Ranks> ranks;
    bool isolated = false;
};

Nearby exploreNearby(
    const KinematicChain &chain, const Tree &tree, const Freedoms &f, const Eigen::MatrixXd &jacobian, double tolerance)
{
    Nearby nearby;
    const int F = f.count();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullV);
    const Eigen::MatrixXd null = svd.matrixV().rightCols(F - rankOf(svd.singularValues(), tolerance));
    std::mt19937 random(20240601u); // fixed: the same answer every time
    const auto uniform = [&random] { return 2.0 * double(random()) / double(std::mt19937::max()) - 1.0; };
    bool fellBack = false;
    for (const double step : {2e-2, 5e-3}) {
        for (int trial = 0; trial < 3; ++trial) {
            Eigen::VectorXd c(null.cols());
            for (Eigen::Index i = 0; i < c.size(); ++i)
                c[i] = uniform();
            if (c.norm() == 0.0)
                continue;
            Eigen::VectorXd q = step * (null * c).normalized();
            bool closed = false;
            Loops loops;
            for (int iteration = 0; iteration < 100 && q.norm() < 1.0; ++iteration) {
                loops = loopsAt(chain, tree, f, q);
                if (loops.residual.norm() < 1e-11) { // ≈ 10⁻⁶ from a double root: still seen by the solver
                    closed = true;
                    break;
                }
                Eigen::JacobiSVD<Eigen::MatrixXd> solver(loops.jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
                solver.setThreshold(tolerance);
                q -= solver.solve(loops.residual);
            }
            if (!closed)
                continue;
            if (q.norm() < 0.25 * step) {
                fellBack = true;
                continue;
            }
            const Ranks r = ranksOf(chain, f, loops.jacobian, tolerance);
            if (!nearby.ranks)
                nearby.ranks = r;
            nearby.ranks->full = std::max(nearby.ranks->full, r.full);
            nearby.ranks->planar = std::max(nearby.ranks->planar, r.planar);
            nearby.ranks->passive = std::max(nearby.ranks->passive, r.passive);
        }
        if (nearby.ranks)
            return nearby;
    }
    nearby.isolated = fellBack;
    return nearby;
}

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

} // namespace

// -- formulas ------------------------------------------------------------------------------

namespace mobility {

int pairClass(PairType type)
{
    return 6 - pairFreedoms(type);
}

int pairFreedoms(PairType type)
{
    switch (type) {
    case PairType::Revolute:
    case PairType::Prismatic:
    case PairType::Screw:
        return 1;
    case PairType::Cylindrical:
    case PairType::CamPlanar:
        return 2;
    case PairType::Spherical:
        return 3;
    }
    return 1;
}

PairClassCounts countPairs(const KinematicChain &chain)
{
    PairClassCounts counts {};
    for (const KinematicPair &pair : chain.pairs)
        ++counts[std::size_t(pairClass(pair.type))];
    return counts;
}

int chebyshev(int movingLinks, int lowerPairs, int higherPairs)
{
    return 3 * movingLinks - 2 * lowerPairs - higherPairs;
}

std::optional<int> chebyshev(const KinematicChain &chain)
{
    if (!chain.planar || chain.links.empty())
        return std::nullopt;
    int lower = 0, higher = 0;
    for (const KinematicPair &pair : chain.pairs) {
        if (!planarCapable(pair.type))
            return std::nullopt;
        ++(pair.type == PairType::CamPlanar ? higher : lower);
    }
    return chebyshev(chain.movingLinks(), lower, higher);
}

int somovMalyshev(int movingLinks, const PairClassCounts &p)
{
    return 6 * movingLinks - 5 * p[5] - 4 * p[4] - 3 * p[3] - 2 * p[2] - p[1];
}

int documentSomovMalyshev(int movingLinks, const PairClassCounts &p)
{
    return 6 * movingLinks - 5 * p[5] - 4 * p[4] - 3 * p[3] - 2 * p[2] + p[1];
}

// -- the constraint Jacobian ---------------------------------------------------------------

ConstraintJacobian constraintJacobian(const KinematicChain &chain)
{
    ConstraintJacobian out;
    if (!chainProblem(chain).empty())
        return out;
    const Tree tree = spanningTree(chain);
    const Freedoms f = freedomsOf(chain);
    out.matrix = loopsAt(chain, tree, f, Eigen::VectorXd::Zero(f.count())).jacobian;
    out.columnPair = f.pairOf;
    out.loops = static_cast<int>(tree.chords.size());
    out.centre = f.centre;
    out.size = f.size;
    return out;
}

int numericalRank(const Eigen::MatrixXd &matrix, double tolerance)
{
    return matrix.size() == 0 ? 0 : rankOf(Eigen::JacobiSVD<Eigen::MatrixXd>(matrix).singularValues(), tolerance);
}

// -- classroom chains ----------------------------------------------------------------------

KinematicPair makePair(PairType type, std::string name, int link1, int link2, const Eigen::Vector3d &point,
    const Eigen::Vector3d &axis, bool actuated)
{
    KinematicPair pair;
    pair.name = std::move(name);
    pair.type = type;
    pair.link1 = link1;
    pair.link2 = link2;
    pair.point = point;
    pair.axis = axis.normalized();
    pair.actuated = actuated;
    return pair;
}

KinematicPair planarRevolute(std::string name, int link1, int link2, const Eigen::Vector2d &point, bool actuated)
{
    return makePair(PairType::Revolute, std::move(name), link1, link2, Eigen::Vector3d(point.x(), point.y(), 0.0),
        Eigen::Vector3d::UnitZ(), actuated);
}

KinematicPair planarPrismatic(std::string name, int link1, int link2, const Eigen::Vector2d &point,
    const Eigen::Vector2d &direction, bool actuated)
{
    return makePair(PairType::Prismatic, std::move(name), link1, link2, Eigen::Vector3d(point.x(), point.y(), 0.0),
        Eigen::Vector3d(direction.x(), direction.y(), 0.0), actuated);
}

namespace {
/// Four revolute pairs closing ground → 1 → 2 → 3 → ground, at the given axes.
KinematicChain fourRevoluteLoop(
    const std::array<Eigen::Vector3d, 4> &points, const std::array<Eigen::Vector3d, 4> &axes)
{
    KinematicChain chain;
    chain.links = {text::translate("core", "ground")};
    for (int i = 1; i < 4; ++i)
        chain.links.push_back(text::format(text::translate("core", "link %1"), {std::to_string(i)}));
    for (int i = 0; i < 4; ++i)
        chain.pairs.push_back(makePair(
            PairType::Revolute, std::to_string(i + 1), i, (i + 1) % 4, points[std::size_t(i)], axes[std::size_t(i)]));
    chain.pairs[0].actuated = true;
    chain.planar = false;
    return chain;
}
} // namespace

KinematicChain spatialParallelogram(double a, double b, double theta)
{
    const Eigen::Vector3d crank = a * Eigen::Vector3d(std::sin(theta), std::cos(theta), 0.0);
    const Eigen::Vector3d O = Eigen::Vector3d::Zero(), B(b, 0.0, 0.0), A = B + crank, C = O + crank;
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    KinematicChain chain = fourRevoluteLoop({O, C, A, B}, {z, z, z, z});
    chain.links = {text::translate("core", "ground OB"), text::translate("core", "crank OC"),
        text::translate("core", "coupler CA"), text::translate("core", "crank AB")};
    const char *names[] = {"O", "C", "A", "B"};
    for (std::size_t i = 0; i < 4; ++i)
        chain.pairs[i].name = names[i];
    chain.description
        = text::translate("core", "spatial parallelogram: four parallel revolute axes taken as a spatial chain");
    return chain;
}

Eigen::Isometry3d denavitHartenberg(double theta, double d, double a, double alpha)
{
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.rotate(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
    T.translate(Eigen::Vector3d(a, 0.0, d));
    T.rotate(Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()));
    return T;
}

std::array<double, 4> bennettAngles(double alpha, double beta, double theta1)
{
    // tan(θ₂/2) = K / tan(θ₁/2), K = sin((β + α)/2) / sin((β − α)/2); the atan2 form holds at
    // θ₁ = 0 too (θ₂ = π there).
    const double K = std::sin(0.5 * (beta + alpha)) / std::sin(0.5 * (beta - alpha));
    const double theta2 = 2.0 * std::atan2(K * std::cos(0.5 * theta1), std::sin(0.5 * theta1));
    return {theta1, theta2, -theta1, -theta2};
}

KinematicChain bennettLinkage(double a, double alpha, double beta, double theta1)
{
    const double b = a * std::sin(beta) / std::sin(alpha);
    const std::array<double, 4> theta = bennettAngles(alpha, beta, theta1);
    const std::array<double, 3> lengths = {a, b, a}, twists = {alpha, beta, alpha};
    std::array<Eigen::Vector3d, 4> points, axes;
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
    for (std::size_t i = 0; i < 4; ++i) {
        points[i] = frame.translation();
        axes[i] = frame.linear().col(2);
        if (i < 3)
            frame = frame * denavitHartenberg(theta[i], 0.0, lengths[i], twists[i]);
    }
    KinematicChain chain = fourRevoluteLoop(points, axes);
    chain.description
        = text::translate("core", "Bennett linkage: four revolute axes, opposite links equal, a/sin α = b/sin β");
    return chain;
}

KinematicChain randomSpatial4R(unsigned seed, double size)
{
    std::mt19937 random(seed);
    const auto uniform = [&random] { return double(random()) / double(std::mt19937::max()); };
    std::array<Eigen::Vector3d, 4> points, axes;
    for (std::size_t i = 0; i < 4; ++i) {
        points[i] = size * Eigen::Vector3d(uniform(), uniform(), uniform());
        do {
            axes[i] = Eigen::Vector3d(uniform(), uniform(), uniform()) * 2.0 - Eigen::Vector3d::Ones();
        } while (axes[i].norm() < 0.1 || axes[i].norm() > 1.0);
    }
    KinematicChain chain = fourRevoluteLoop(points, axes);
    chain.pairs[0].actuated = false; // a structure: nothing to drive
    chain.description = text::translate("core", "spatial 4R loop with random axes (not a Bennett linkage)");
    return chain;
}

KinematicChain planarFiveBar(const std::array<Eigen::Vector2d, 5> &joints)
{
    KinematicChain chain;
    chain.links = {text::translate("core", "ground AE"), text::translate("core", "crank AB"),
        text::translate("core", "link BC"), text::translate("core", "link DC"), text::translate("core", "crank ED")};
    const char *names[] = {"A", "B", "C", "D", "E"};
    for (int i = 0; i < 5; ++i)
        chain.pairs.push_back(planarRevolute(names[i], i, (i + 1) % 5, joints[std::size_t(i)], i == 0 || i == 4));
    chain.description = text::translate("core", "planar five-bar: ground, two driven cranks, two distal links");
    return chain;
}

} // namespace mobility

// -- the analysis --------------------------------------------------------------------------

MobilityReport analyseMobility(const KinematicChain &chain, double tolerance)
{
    MobilityReport r;
    r.planar = chain.planar;
    if (const std::string problem = chainProblem(chain); !problem.empty()) {
        r.verdict = text::format(text::translate("core", "Cannot analyse the mobility: %1."), {problem});
        return r;
    }
    r.valid = true;
    r.movingLinks = chain.movingLinks();
    r.pairsByClass = mobility::countPairs(chain);
    r.pairs = static_cast<int>(chain.pairs.size());
    r.chebyshev = mobility::chebyshev(chain);
    r.somovMalyshev = mobility::somovMalyshev(r.movingLinks, r.pairsByClass);
    r.idleFreedoms = chain.idleFreedoms;

    const Tree tree = spanningTree(chain);
    const Freedoms f = freedomsOf(chain);
    r.loops = static_cast<int>(tree.chords.size());
    r.freedoms = f.count();
    for (const KinematicPair &pair : chain.pairs)
        r.actuators += pair.actuated ? mobility::pairFreedoms(pair.type) : 0;
    const int passiveFreedoms = r.freedoms - r.actuators;

    const Eigen::MatrixXd jacobian = loopsAt(chain, tree, f, Eigen::VectorXd::Zero(r.freedoms)).jacobian;
    const Ranks here = ranksOf(chain, f, jacobian, tolerance);
    r.rank = here.full;
    r.numerical = r.freedoms - here.full;
    r.lockedMobility = passiveFreedoms - here.passive;

    Ranks near = here;
    if (r.numerical > 0 && r.loops > 0) { // an open chain (a tree) has no loop to close
        const Nearby nearby = exploreNearby(chain, tree, f, jacobian, tolerance);
        if (nearby.ranks) {
            near = *nearby.ranks;
        } else if (nearby.isolated) { // rigid: only first-order motions
            near.full = r.freedoms;
            near.passive = passiveFreedoms;
            near.planar = near.full; // a planar chain's loop equations are its planar rows
        }
    }
    r.mobility = r.freedoms - near.full;
    r.singular = r.numerical > r.mobility;
    r.lockedMobilityNearby = passiveFreedoms - near.passive;
    r.redundantConstraints = 6 * r.loops - near.full;
    if (r.chebyshev)
        r.planarRedundantConstraints = 3 * r.loops - near.planar;

    r.chebyshevFails = r.chebyshev && *r.chebyshev != r.mobility;
    r.somovMalyshevFails = r.somovMalyshev != r.mobility;
    r.formulaFails = r.chebyshevFails || r.somovMalyshevFails;
    r.fullyActuated
        = r.actuators > 0 && r.mobility - r.idleFreedoms == r.actuators && r.lockedMobilityNearby == r.idleFreedoms;
    r.verdict = verdictOf(r);
    return r;
}

} // namespace pkm
