// The map rows of the planar parallel mechanism. A 2-DOF platform's row is worked out a block
// of cells at a time: every leg's inverse kinematics in closed form over the block, written
// without branches so that the compiler vectorises it (as MOMA's and the five-bar's rows are),
// then J_q, J_x and the quantity from the distal links. A cell within round-off of one of the
// legs' limits is solved again as a single pose (mapCell), so the map reaches exactly the cells
// solveInverse() reaches and every cell equals evaluate() at its pose. A 3-DOF platform's det J
// row (the slice at φ = phi_map) is worked out alike (ppmaprow3.cpp); its other rows are
// solved cell by cell.
#include "ppmaprow.h"

#include "capabilitycell.h"
#include "mapclones.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pkm {

namespace {

using namespace maprow;

struct RowConstants {
    LegConstants a, b;
    double assembly = 1;
};

/// What the row knows of one cell, for the quantity it maps.
struct Cell {
    double jqa, jqb;                 ///< J_q = diag(jqa, jqb)
    double j00, j01, j10, j11;       ///< J_x
    double rowA, rowB;               ///< |J_x rows|
    double inverseMargin, directMargin;
};

/// The block: both legs, then per cell the assembly check, J_q and J_x, the margins and
/// `value(cell)`. `uncertain[i]` is set where a limit is within round-off: the caller solves
/// that cell as a pose.
template <class Value>
[[gnu::always_inline]] inline void twoLegBlock(const RowConstants &k, double y, double x0, double dx, float *values,
                                               float *margins, int *uncertain, int count, const Value &value)
{
    LegBlock a, b;
    legBlock(k.a, y, x0, dx, count, a);
    legBlock(k.b, y, x0, dx, count, b);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double assembly = k.assembly, bax = k.a.bx, bay = k.a.by, bbx = k.b.bx, bby = k.b.by;
    for (int i = 0; i < count; ++i) {
        // planarparallel.cpp's inverseCheck(): P on the assembly's side of the line C₁→C₂
        // between the circle centres, each taken at its platform point's reference
        const double ox = (b.cx[i] - bbx) - (a.cx[i] - bax), oy = (b.cy[i] - bby) - (a.cy[i] - bay);
        const double radii = a.radius[i] * b.radius[i];
        const double inverseRadii = a.inverseRadius[i] * b.inverseRadius[i];
        const double side = (assembly * (ox * a.ey[i] - oy * a.ex[i]) + 1e-9 * radii) * inverseRadii;
        const double slack = std::min(std::min(a.slack[i], b.slack[i]), side);
        // NaN (which no limit should give) is left to the pose solver too
        uncertain[i] = !(std::abs(slack) >= band);
        const bool ok = slack >= 0.0;
        const double crossLinks = a.ex[i] * b.ey[i] - a.ey[i] * b.ex[i];
        // N's rows are the unit distal links, whose lengths are ρ_i (legs.cpp's e.norm())
        const double direct = std::abs(crossLinks) * inverseRadii * std::min(a.pjoint[i], b.pjoint[i]);
        const Cell cell{a.jq[i],
                        b.jq[i],
                        -a.rate[i] * a.ex[i],
                        -a.rate[i] * a.ey[i],
                        -b.rate[i] * b.ex[i],
                        -b.rate[i] * b.ey[i],
                        std::abs(a.rate[i]) * a.radius[i],
                        std::abs(b.rate[i]) * b.radius[i],
                        std::min(a.inverse[i], b.inverse[i]),
                        radii > 0.0 ? direct : 0.0};
        values[i] = ok ? static_cast<float>(value(cell)) : nan;
        margins[i] = ok ? static_cast<float>(std::min(cell.inverseMargin, cell.directMargin)) : nan;
    }
}

struct Determinant {
    double operator()(const Cell &c) const { return (c.j00 * c.j11 - c.j01 * c.j10) / (c.jqa * c.jqb); }
};

/// planaranalysis.cpp's κ(J) of a 2 × 2 J = J_q⁻¹·J_x: (‖J‖²_F + √(‖J‖⁴_F − 4 det²))/(2|det J|),
/// +∞ where J_q or J_x is singular.
struct Condition {
    double operator()(const Cell &c) const
    {
        const double detJq = c.jqa * c.jqb;
        const double sa = 1.0 / (c.jqa != 0.0 ? c.jqa : 1.0), sb = 1.0 / (c.jqb != 0.0 ? c.jqb : 1.0);
        const double j00 = c.j00 * sa, j01 = c.j01 * sa, j10 = c.j10 * sb, j11 = c.j11 * sb;
        const double f = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
        const double d = std::abs(j00 * j11 - j01 * j10);
        const double spread = std::sqrt(std::max(0.0, f * f - 4.0 * d * d));
        const bool regular = (detJq != 0.0) & (d > 0.0);
        return regular ? (f + spread) / (2.0 * (regular ? d : 1.0)) : std::numeric_limits<double>::infinity();
    }
};

/// What the actuators deliver (capabilitycell.h) with the class of planaranalysis.cpp.
template <MapQuantity Q>
struct Delivered {
    capability::CellLimits limits; // a copy: loads the loop may hoist
    double operator()(const Cell &c) const
    {
        const double value = capability::cell2<Q>(limits, c.jqa, c.jqb, c.j00, c.j01, c.j10, c.j11, c.rowA, c.rowB,
                                                  c.inverseMargin < PlanarParallel::singularTolerance,
                                                  c.directMargin < PlanarParallel::singularTolerance);
        // capability::cellValue(): undefined reads as unbounded
        return std::isnan(value) ? std::numeric_limits<double>::infinity() : value;
    }
};

// The variants, each built for AVX-512 and AVX2 as well as the baseline (mapclones.h).
using BlockFunction = void (*)(const RowConstants &, const capability::CellLimits &, double, double, double, float *,
                               float *, int *, int);
#define PKM_PP_BLOCK(name, functor)                                                                                 \
    PKM_MAP_CLONES void name(const RowConstants &k, const capability::CellLimits &l, double y, double x0, double dx, \
                             float *v, float *m, int *u, int n)                                          \
    {                                                                                                               \
        (void)l;                                                                                                    \
        twoLegBlock(k, y, x0, dx, v, m, u, n, functor);                                                             \
    }
PKM_PP_BLOCK(determinantBlock, Determinant{})
PKM_PP_BLOCK(conditionBlock, Condition{})
PKM_PP_BLOCK(forceBlock, Delivered<MapQuantity::ForceWorst>{l})
PKM_PP_BLOCK(speedBlock, Delivered<MapQuantity::SpeedWorst>{l})
PKM_PP_BLOCK(resolutionBlock, Delivered<MapQuantity::ResolutionWorst>{l})
PKM_PP_BLOCK(stiffnessBlock, Delivered<MapQuantity::StiffnessWorst>{l})
#undef PKM_PP_BLOCK

BlockFunction blockFunction(MapQuantity quantity)
{
    switch (quantity) {
    case MapQuantity::Determinant:
        return determinantBlock;
    case MapQuantity::Condition:
        return conditionBlock;
    case MapQuantity::ForceWorst:
        return forceBlock;
    case MapQuantity::SpeedWorst:
        return speedBlock;
    case MapQuantity::ResolutionWorst:
        return resolutionBlock;
    case MapQuantity::StiffnessWorst:
        return stiffnessBlock;
    default:
        return nullptr;
    }
}

} // namespace

void PlanarParallel::mapCell(MapQuantity quantity, const capability::CellLimits *limits, const Eigen::Vector3d &X,
                             Pose &pose, float &value, float &margin) const
{
    const int n = m_design.legCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    int culprit = 0;
    if (inverseCheck(X, nullptr, pose.inputs, culprit) != planar::Reach::Yes) {
        value = margin = nan;
        return;
    }
    pose.outputs.resize(n);
    for (int i = 0; i < n; ++i)
        pose.outputs[i] = X[i];
    Eigen::Matrix3d jq, jx;
    jacobianParts(pose, jq, jx);
    const Singularity s = singularity(pose);
    margin = static_cast<float>(s.margin);
    if (limits) {
        // every leg's J_q is its own: diagonal, as capabilitycell.h takes it
        const bool inverse = s.type == SingularityType::Inverse || s.type == SingularityType::Combined;
        const bool direct = s.type == SingularityType::Direct || s.type == SingularityType::Combined;
        const double delivered = n == 3
            ? capability::cell3(*limits, jq.diagonal(), jx, inverse, direct)
            : capability::cell2(*limits, jq(0, 0), jq(1, 1), jx(0, 0), jx(0, 1), jx(1, 0), jx(1, 1),
                                jx.row(0).head<2>().norm(), jx.row(1).head<2>().norm(), inverse, direct);
        value = capability::cellValue(delivered);
        return;
    }
    const double detJq = jq.diagonal().head(n).prod();
    double result = 0.0;
    if (quantity == MapQuantity::Determinant) {
        result = (n == 2 ? jx.topLeftCorner<2, 2>().determinant() : jx.determinant()) / detJq;
    } else {
        result = std::numeric_limits<double>::infinity();
        if (detJq != 0.0) {
            Eigen::Matrix3d J = jx;
            for (int i = 0; i < n; ++i)
                J.row(i) /= jq(i, i);
            if (n == 2) {
                const Eigen::Matrix2d j2 = J.topLeftCorner<2, 2>();
                const double f = j2.squaredNorm(), d = std::abs(j2.determinant());
                if (d > 0.0)
                    result = (f + std::sqrt(std::max(0.0, f * f - 4.0 * d * d))) / (2.0 * d);
            } else {
                const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(J).singularValues();
                if (sv[2] > 0.0)
                    result = sv[0] / sv[2];
            }
        }
    }
    value = static_cast<float>(result);
}

void PlanarParallel::fillRow(MapQuantity quantity, const capability::CellLimits *limits, double y, double x0,
                             double dx, std::span<float> values, std::span<float> margins) const
{
    const int n = m_design.legCount();
    if (n == 3 && (limits || quantity == MapQuantity::Determinant)) {
        fillThreeLegDeterminantRow(y, x0, dx, values, margins, limits);
        return;
    }
    Pose pose;
    const BlockFunction rowBlock = n == 2 ? blockFunction(quantity) : nullptr;
    if (!rowBlock) {
        float unused = 0.0f;
        const double phi = n == 3 ? m_design.mapPhi : 0.0;
        for (std::size_t c = 0; c < values.size(); ++c)
            mapCell(quantity, limits, {x0 + double(c) * dx, y, phi}, pose, values[c], margins.empty() ? unused : margins[c]);
        return;
    }
    RowConstants k{constantsOf(m_design.legs[0]), constantsOf(m_design.legs[1]), double(m_design.assembly)};
    const capability::CellLimits none{};
    inBlocks(
        values, margins,
        [&](int start, int count, float *v, float *m, int *uncertain) {
            rowBlock(k, limits ? *limits : none, y, x0 + start * dx, dx, v, m, uncertain, count);
        },
        [&](int cell, float &value, float &margin) { mapCell(quantity, limits, {x0 + double(cell) * dx, y, 0.0}, pose, value, margin); });
}

void PlanarParallel::fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                                std::span<float> margins) const
{
    if (quantity != MapQuantity::OrientationRange) {
        fillRow(quantity, nullptr, y, x0, dx, values, margins);
        return;
    }
    // the total width of the reachable φ at each (x, y); 2-DOF platforms never turn
    const int n = m_design.legCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::array<Interval, 8> found;
    for (std::size_t c = 0; c < values.size(); ++c) {
        double margin = 0.0;
        const int count = n == 3 ? orientationIntervals({x0 + double(c) * dx, y}, found, &margin) : 0;
        double width = 0.0;
        for (int k = 0; k < count; ++k)
            width += found[std::size_t(k)].max - found[std::size_t(k)].min;
        values[c] = count > 0 ? static_cast<float>(width) : nan;
        if (!margins.empty())
            margins[c] = count > 0 ? static_cast<float>(margin) : nan;
    }
}

void PlanarParallel::fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                                       std::span<float> values, std::span<float> margins) const
{
    fillRow(limits.quantity, &limits, y, x0, dx, values, margins);
}

} // namespace pkm
