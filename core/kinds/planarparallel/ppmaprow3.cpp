// The det J and capability map rows of a 3-DOF platform: the slice at φ = phi_map, where each platform point
// is the cell's point plus R(φ)·B_i, so every leg is worked out over a block of cells as a
// 2-DOF platform's legs are (ppmaprow.h), then J_x with its third column (R(φ)·B_i) × e_i,
// det J = det J_x / det J_q and the margins of planaranalysis.cpp's singularity(). A cell
// within round-off of a limit is solved again as a pose (mapCell), so the slice reaches
// exactly the cells solveInverse() reaches at that angle.
#include "ppmaprow.h"

#include "capabilitycell.h"
#include "mapclones.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pkm {

namespace {

using namespace maprow;

struct ThreeLegs {
    LegConstants legs[3];
    double inverseSize = 1; ///< 1/(the platform's size): the rotation column as a length
};

/// One cell's parts, for a value other than det J: J_q's diagonal, J_x's rows and the margins.
struct Cell3 {
    double jq[3];
    double jx[3][3];
    double inverseMargin, directMargin;
};

/// det J = det J_x / det J_q, with det J_x from the rows' shared factors (vectorised).
struct Determinant {
    static constexpr bool needsCell = false;
    double operator()(const Cell3 &) const { return 0.0; }
};

/// What the actuators deliver (capabilitycell.h), with the class the margins give, as mapCell()
/// works it out from a solved pose.
template <MapQuantity Q>
struct Delivered {
    static constexpr bool needsCell = true;
    capability::CellLimits limits; // a copy: loads the loop may hoist
    double operator()(const Cell3 &c) const
    {
        const double value = capability::cell3<Q>(limits, c.jq, c.jx, c.inverseMargin < PlanarParallel::singularTolerance,
                                                  c.directMargin < PlanarParallel::singularTolerance);
        return std::isnan(value) ? std::numeric_limits<double>::infinity() : value; // capability::cellValue()
    }
};

template <class Value>
[[gnu::always_inline]] inline void threeLegBlock(const ThreeLegs &k, double y, double x0, double dx, float *values,
                                                 float *margins, int *uncertain, int count, const Value &valueOf)
{
    LegBlock a, b, c;
    legBlock(k.legs[0], y, x0, dx, count, a);
    legBlock(k.legs[1], y, x0, dx, count, b);
    legBlock(k.legs[2], y, x0, dx, count, c);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // the constants as locals: a store into the map cannot then be taken for a change of them
    const double bax = k.legs[0].bx, bay = k.legs[0].by, bbx = k.legs[1].bx, bby = k.legs[1].by;
    const double bcx = k.legs[2].bx, bcy = k.legs[2].by, inverseSize = k.inverseSize;
    for (int i = 0; i < count; ++i) {
        const double slack = std::min(std::min(a.slack[i], b.slack[i]), c.slack[i]);
        uncertain[i] = !(std::abs(slack) >= band);
        const bool ok = slack >= 0.0;
        // J_x rows −rate_i·(e_i, (R(φ)·B_i) × e_i) (planaranalysis.cpp's jacobianParts())
        const double ta = bax * a.ey[i] - bay * a.ex[i], tb = bbx * b.ey[i] - bby * b.ex[i];
        const double tc = bcx * c.ey[i] - bcy * c.ex[i];
        const double detE = a.ex[i] * (b.ey[i] * tc - tb * c.ey[i]) - a.ey[i] * (b.ex[i] * tc - tb * c.ex[i])
            + ta * (b.ex[i] * c.ey[i] - b.ey[i] * c.ex[i]);
        // the margins: the smallest leg's inverse one; the direct one |det N|/Π|N_i| with N's
        // rows (u_i, (R(φ)·B_i) × u_i / size), u_i the unit distal link (|e_i| = ρ_i)
        const double inverseRadii = a.inverseRadius[i] * b.inverseRadius[i] * c.inverseRadius[i];
        const bool lengths = (a.radius[i] > 0.0) & (b.radius[i] > 0.0) & (c.radius[i] > 0.0);
        const double na = ta * a.inverseRadius[i] * inverseSize, nb = tb * b.inverseRadius[i] * inverseSize;
        const double nc = tc * c.inverseRadius[i] * inverseSize;
        const double product = std::sqrt((1.0 + na * na) * (1.0 + nb * nb) * (1.0 + nc * nc));
        const double direct = std::abs(detE) * inverseRadii * inverseSize / product
            * std::min(std::min(a.pjoint[i], b.pjoint[i]), c.pjoint[i]);
        const double inverse = std::min(std::min(a.inverse[i], b.inverse[i]), c.inverse[i]);
        const double margin = std::min(inverse, lengths ? direct : 0.0);
        double value;
        if constexpr (Value::needsCell) {
            const Cell3 cell{{a.jq[i], b.jq[i], c.jq[i]},
                             {{-a.rate[i] * a.ex[i], -a.rate[i] * a.ey[i], -a.rate[i] * ta},
                              {-b.rate[i] * b.ex[i], -b.rate[i] * b.ey[i], -b.rate[i] * tb},
                              {-c.rate[i] * c.ex[i], -c.rate[i] * c.ey[i], -c.rate[i] * tc}},
                             inverse,
                             lengths ? direct : 0.0};
            value = ok ? valueOf(cell) : 0.0;
        } else {
            value = -(a.rate[i] * b.rate[i] * c.rate[i]) * detE / (a.jq[i] * b.jq[i] * c.jq[i]);
        }
        values[i] = ok ? static_cast<float>(value) : nan;
        margins[i] = ok ? static_cast<float>(margin) : nan;
    }
}

PKM_MAP_CLONES void determinantBlock(const ThreeLegs &k, double y, double x0, double dx, float *values, float *margins,
                                     int *uncertain, int count)
{
    threeLegBlock(k, y, x0, dx, values, margins, uncertain, count, Determinant{});
}

// What the actuators deliver: each quantity's loop built for AVX-512 and AVX2 as well
// (mapclones.h; as plain functions, since the clones are made per function, not per template).
#define PKM_PP3_BLOCK(name, quantity)                                                                           \
    PKM_MAP_CLONES void name(const ThreeLegs &k, const capability::CellLimits &limits, double y, double x0,    \
                             double dx, float *values, float *margins, int *uncertain, int count)               \
    {                                                                                                           \
        threeLegBlock(k, y, x0, dx, values, margins, uncertain, count, Delivered<quantity>{limits});            \
    }
PKM_PP3_BLOCK(forceBlock, MapQuantity::ForceWorst)
PKM_PP3_BLOCK(speedBlock, MapQuantity::SpeedWorst)
PKM_PP3_BLOCK(resolutionBlock, MapQuantity::ResolutionWorst)
PKM_PP3_BLOCK(stiffnessBlock, MapQuantity::StiffnessWorst)
#undef PKM_PP3_BLOCK

void capabilityBlock(const ThreeLegs &k, const capability::CellLimits &limits, double y, double x0, double dx,
                     float *values, float *margins, int *uncertain, int count)
{
    switch (limits.quantity) {
    case MapQuantity::ForceWorst:
        return forceBlock(k, limits, y, x0, dx, values, margins, uncertain, count);
    case MapQuantity::SpeedWorst:
        return speedBlock(k, limits, y, x0, dx, values, margins, uncertain, count);
    case MapQuantity::ResolutionWorst:
        return resolutionBlock(k, limits, y, x0, dx, values, margins, uncertain, count);
    default:
        return stiffnessBlock(k, limits, y, x0, dx, values, margins, uncertain, count);
    }
}

} // namespace

void PlanarParallel::fillThreeLegDeterminantRow(double y, double x0, double dx, std::span<float> values,
                                                std::span<float> margins, const capability::CellLimits *limits) const
{
    const double phi = m_design.mapPhi;
    ThreeLegs k;
    for (int i = 0; i < 3; ++i)
        k.legs[i] = constantsOf(m_design.legs[std::size_t(i)], phi);
    // the platform's size as singularity() takes it: the farthest platform point from their centre
    const Eigen::Vector2d centre = (m_design.legs[0].platform + m_design.legs[1].platform + m_design.legs[2].platform) / 3.0;
    double size = 0.0;
    for (const PlanarLeg &leg : m_design.legs)
        size = std::max(size, (leg.platform - centre).norm());
    k.inverseSize = 1.0 / size;
    Pose pose;
    inBlocks(
        values, margins,
        [&](int start, int count, float *v, float *m, int *uncertain) {
            if (limits)
                capabilityBlock(k, *limits, y, x0 + start * dx, dx, v, m, uncertain, count);
            else
                determinantBlock(k, y, x0 + start * dx, dx, v, m, uncertain, count);
        },
        [&](int cell, float &value, float &margin) {
            mapCell(limits ? limits->quantity : MapQuantity::Determinant, limits, {x0 + double(cell) * dx, y, phi}, pose,
                    value, margin);
        });
}

} // namespace pkm
