#include "capabilitycell.h"

#include <limits>

namespace pkm::capability {

namespace {
/// Core torques are N·m, lengths mm (capability.cpp): a rotary actuator's torque and
/// stiffness enter the Jacobian products in N·mm and N·mm/rad.
constexpr double perMetre = 1e3;
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
        // as capability::deliveryClass(): no upper bound where the home pose gives no scale
        const double home = actuators.transmission[k];
        l.negligible[k] = home / nearSingular;
        l.excessive[k] = home > 0.0 ? home * nearSingular : std::numeric_limits<double>::infinity();
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
    // the same formulas as the map loops' (capabilitycell.h), so that a pose and its map cell
    // agree to the last bit of the arithmetic they share
    const double qs[3] = {q[0], q[1], q[2]};
    const double j[3][3] = {{jx(0, 0), jx(0, 1), jx(0, 2)}, {jx(1, 0), jx(1, 1), jx(1, 2)}, {jx(2, 0), jx(2, 1), jx(2, 2)}};
    switch (l.quantity) {
    case MapQuantity::ForceWorst:
        return cell3<MapQuantity::ForceWorst>(l, qs, j, inverse, direct);
    case MapQuantity::SpeedWorst:
        return cell3<MapQuantity::SpeedWorst>(l, qs, j, inverse, direct);
    case MapQuantity::ResolutionWorst:
        return cell3<MapQuantity::ResolutionWorst>(l, qs, j, inverse, direct);
    default:
        return cell3<MapQuantity::StiffnessWorst>(l, qs, j, inverse, direct);
    }
}

} // namespace pkm::capability
