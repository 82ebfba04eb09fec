// The structural mobility formulas — the pair classes, Chebyshev's and Somov–Malyshev's counts
// (the four-bar and mobility document; docs/mathematics.md, section 7) — and the classroom
// chains they are taught and tested on: the spatial parallelogram, Bennett's linkage, random
// spatial 4R loops and the planar five-bar.

#include "mobility.h"

#include "text.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace pkm {

namespace {
bool planarCapable(PairType type)
{
    return type == PairType::Revolute || type == PairType::Prismatic || type == PairType::CamPlanar;
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

} // namespace pkm
