// The mobility analysis (docs/mathematics.md, section 7): the chain's loop equations from the
// twists of its pairs, their ranks at the pose and near it, and the report built on them; the
// structural formulas and the classroom chains are in mobilityformulas.cpp, the verdict's
// words in mobilityverdict.cpp.

#include "mobility.h"
#include "mobilityinternal.h"

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
using mobility::verdictOf;

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

} // namespace

namespace mobility {

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
