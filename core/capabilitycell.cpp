#include "capabilitycell.h"

#include <Eigen/LU>

namespace pkm::capability {

namespace {
/// Core torques are N·m, lengths mm (capability.cpp): a rotary actuator's torque and
/// stiffness enter the Jacobian products in N·mm and N·mm/rad.
constexpr double perMetre = 1e3;
constexpr double infinity = std::numeric_limits<double>::infinity();
} // namespace

CellLimits cellLimits(const Actuators &actuators, MapQuantity quantity)
{
    CellLimits l;
    l.quantity = quantity;
    l.count = actuators.count;
    for (int i = 0; i < actuators.count; ++i) {
        const std::size_t k = std::size_t(i);
        const Actuator &a = actuators.items[k];
        const double toMillimetre = a.rotary ? perMetre : 1.0;
        switch (quantity) {
        case MapQuantity::ForceWorst:
            l.limit[k] = a.force * toMillimetre;
            break;
        case MapQuantity::SpeedWorst:
            l.limit[k] = a.speed;
            break;
        case MapQuantity::ResolutionWorst:
            l.limit[k] = 0.5 * a.step;
            break;
        default:
            l.limit[k] = 1.0 / (a.stiffness * toMillimetre);
            break;
        }
        l.negligible[k] = 1e-6 * actuators.transmission[k];
    }
    return l;
}

double cell2(const CellLimits &l, double q1, double q2, double a, double b, double c, double d, double r1,
             double r2, bool inverse, bool direct)
{
    switch (l.quantity) {
    case MapQuantity::ForceWorst:
        return cell2<MapQuantity::ForceWorst>(l, q1, q2, a, b, c, d, r1, r2, inverse, direct);
    case MapQuantity::SpeedWorst:
        return cell2<MapQuantity::SpeedWorst>(l, q1, q2, a, b, c, d, r1, r2, inverse, direct);
    case MapQuantity::ResolutionWorst:
        return cell2<MapQuantity::ResolutionWorst>(l, q1, q2, a, b, c, d, r1, r2, inverse, direct);
    default:
        return cell2<MapQuantity::StiffnessWorst>(l, q1, q2, a, b, c, d, r1, r2, inverse, direct);
    }
}

double cell3(const CellLimits &l, const Eigen::Vector3d &q, const Eigen::Matrix3d &jx, bool inverse, bool direct)
{
    // the exact values of a singular pose first (capability.cpp's marks)
    switch (l.quantity) {
    case MapQuantity::ForceWorst:
    case MapQuantity::StiffnessWorst:
        if (direct)
            return 0.0;
        break;
    case MapQuantity::SpeedWorst:
        if (inverse)
            return 0.0;
        break;
    default:
        if (direct)
            return infinity;
        break;
    }
    const Eigen::Vector3d limit(l.limit[0], l.limit[1], l.limit[2]);
    if (l.quantity == MapQuantity::SpeedWorst) {
        // J's rows J_x,i/q_i on the translation: min v_i·|q_i|/|J_x,i(x, y)|
        double radius = infinity;
        for (int i = 0; i < 3; ++i) {
            const double norm = jx.row(i).head<2>().norm() / std::abs(q[i]);
            if (norm > 0.0)
                radius = std::min(radius, limit[i] / norm);
        }
        return radius;
    }
    // J_x⁻¹ by cofactors (Eigen's closed form for 3×3), scaled column by column: G = J_x⁻¹·J_q
    Eigen::Matrix3d G = jx.inverse() * q.asDiagonal();
    for (int i = 0; i < 3; ++i) {
        if (inverse && G.col(i).norm() <= l.negligible[std::size_t(i)])
            G.col(i).setZero();
    }
    if (l.quantity == MapQuantity::ForceWorst) {
        // a pure force: the slabs |(Gᵀ·F)_i| ≤ F_i over (F_x, F_y, 0)
        double radius = infinity;
        for (int i = 0; i < 3; ++i) {
            const double norm = G.col(i).head<2>().norm();
            if (norm > 0.0)
                radius = std::min(radius, limit[i] / norm);
        }
        return radius;
    }
    if (l.quantity == MapQuantity::ResolutionWorst) {
        double farthest = 0.0; // the translational part of G·u over the vertices u of the box
        for (int signs = 0; signs < 8; ++signs) {
            Eigen::Vector3d u;
            for (int j = 0; j < 3; ++j)
                u[j] = (signs >> j & 1) ? limit[j] : -limit[j];
            farthest = std::max(farthest, (G.topRows<2>() * u).norm());
        }
        return farthest;
    }
    // the translational block of the compliance C = G·diag(1/k)·Gᵀ, its largest eigenvalue
    const Eigen::Matrix<double, 2, 3> top = G.topRows<2>();
    const Eigen::Matrix2d C = top * limit.asDiagonal() * top.transpose();
    const double half = 0.5 * (C(0, 0) - C(1, 1));
    return 1.0 / (0.5 * (C(0, 0) + C(1, 1)) + std::hypot(half, C(0, 1)));
}

} // namespace pkm::capability
