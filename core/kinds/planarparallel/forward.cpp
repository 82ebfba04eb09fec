// The direct kinematics of a 3-DOF platform on three circle constraints |P_i(X) − C_i| = ρ_i:
// the planar 3-RPR forward problem. Following C. Gosselin, J. Sefrioui and M. J. Richard
// ("Solutions polynomiales au problème de la cinématique directe des manipulateurs parallèles
// plans à trois degrés de liberté", Mechanism and Machine Theory 27, 1992):
//
//   with w = P₁ − C₁, c_i = B_i − B₁, D_i = C_i − C₁ and v_i = R(φ)c_i − D_i, legs 2 and 3
//   minus leg 1 are linear in w:  w·v_i = h_i,  h_i = ½(ρ_i² − ρ₁² − |v_i|²)  (i = 2, 3);
//   Cramer's rule gives w = N/Δ, and leg 1, |w|² = ρ₁², becomes
//       f(φ) = N_x² + N_y² − ρ₁²Δ² = 0,
//   a quartic in (cos φ, sin φ). With t = tan(φ/2) it is (1 + t²)⁻⁴ times a polynomial of
//   degree 8 whose quartic part vanishes at the circular points (cos, sin) ∝ (1, ±i), so that
//   (1 + t²) divides it: the quotient is the sextic of the forward problem (at most six
//   assembly modes; M. Husty, "An algorithm for solving the direct kinematics of general
//   Stewart–Gough platforms", Mechanism and Machine Theory 31, 1996, the planar case).
//
// Every root is kept: the sextic's roots are the eigenvalues of its companion matrix, those
// with a small imaginary part (a nearly double real root splits into a complex pair under
// rounding) are candidates too, φ = π (t = ∞, where the sextic loses its degree) is tried
// apart, and every candidate is polished by Newton's method on the three original equations
// and kept only when they hold. Lengths are divided by the design's size first, so that the
// coefficients are of order one.
#include "planarparallel.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm::planar {

namespace {
constexpr double pi = std::numbers::pi;

/// a₀ + a_c·cos φ + a_s·sin φ, times (1 + t²): a quadratic in t (coefficients of t⁰, t¹, t²).
std::array<double, 3> trig(double a0, double ac, double as)
{
    return {a0 + ac, 2.0 * as, a0 - ac};
}

template <std::size_t N, std::size_t M>
std::array<double, N + M - 1> multiply(const std::array<double, N> &p, const std::array<double, M> &q)
{
    std::array<double, N + M - 1> r{};
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = 0; j < M; ++j)
            r[i + j] += p[i] * q[j];
    }
    return r;
}

template <std::size_t N>
std::array<double, N> minus(const std::array<double, N> &p, const std::array<double, N> &q)
{
    std::array<double, N> r{};
    for (std::size_t i = 0; i < N; ++i)
        r[i] = p[i] - q[i];
    return r;
}

struct Problem {
    std::array<Eigen::Vector2d, 3> b;  ///< B_i / L
    std::array<Eigen::Vector2d, 3> C;  ///< C_i / L
    std::array<double, 3> rho{};       ///< ρ_i / L
};

/// w = P₁ − C₁ at angle φ from legs 2 and 3 (Cramer), or from leg 2 and leg 1 where the
/// system is singular; false when neither gives a point.
bool pointAt(const Problem &p, double phi, Eigen::Vector2d &w)
{
    const Eigen::Rotation2Dd R(phi);
    std::array<Eigen::Vector2d, 3> v;
    std::array<double, 3> h{};
    for (int i = 1; i < 3; ++i) {
        v[i] = R * (p.b[i] - p.b[0]) - (p.C[i] - p.C[0]);
        h[i] = 0.5 * (p.rho[i] * p.rho[i] - p.rho[0] * p.rho[0] - v[i].squaredNorm());
    }
    const double delta = cross(v[1], v[2]);
    if (std::abs(delta) > 1e-9 * std::max(1e-300, v[1].norm() * v[2].norm())) {
        w = Eigen::Vector2d(h[1] * v[2].y() - h[2] * v[1].y(), v[1].x() * h[2] - v[2].x() * h[1]) / delta;
        return true;
    }
    // v₂ ∥ v₃: the circle |w| = ρ₁ and the line w·v_i = h_i of the longer v_i, the point that
    // satisfies the other leg best
    const int i = v[1].norm() >= v[2].norm() ? 1 : 2;
    const double n = v[i].norm();
    if (n < 1e-12)
        return false;
    const Eigen::Vector2d u = v[i] / n;
    const double along = h[i] / n, across2 = p.rho[0] * p.rho[0] - along * along;
    if (across2 < -1e-9)
        return false;
    const double across = std::sqrt(std::max(0.0, across2));
    const Eigen::Vector2d w1 = along * u + across * Eigen::Vector2d(-u.y(), u.x());
    const Eigen::Vector2d w2 = along * u - across * Eigen::Vector2d(-u.y(), u.x());
    const int j = 3 - i;
    const double r1 = std::abs(w1.dot(v[j]) - h[j]), r2 = std::abs(w2.dot(v[j]) - h[j]);
    w = r1 <= r2 ? w1 : w2;
    return true;
}

/// The sextic's coefficients (t⁰ … t⁶) of the forward problem, or of degree 8 if (1 + t²)
/// does not divide up to rounding (it always does in exact arithmetic).
std::vector<double> forwardPolynomial(const Problem &p)
{
    std::array<std::array<double, 3>, 3> vx{}, vy{}, h{};
    for (int i = 1; i < 3; ++i) {
        const Eigen::Vector2d c = p.b[i] - p.b[0], D = p.C[i] - p.C[0];
        // v_i = R c_i − D_i
        vx[i] = trig(-D.x(), c.x(), -c.y());
        vy[i] = trig(-D.y(), c.y(), c.x());
        // h_i = ½(ρ_i² − ρ₁² − |c_i|² − |D_i|²) + D_i·R c_i
        h[i] = trig(0.5 * (p.rho[i] * p.rho[i] - p.rho[0] * p.rho[0] - c.squaredNorm() - D.squaredNorm()),
                    D.dot(c), cross(c, D));
    }
    const auto Nx = minus(multiply(h[1], vy[2]), multiply(h[2], vy[1]));
    const auto Ny = minus(multiply(vx[1], h[2]), multiply(vx[2], h[1]));
    const auto Delta = minus(multiply(vx[1], vy[2]), multiply(vy[1], vx[2]));
    const auto nx2 = multiply(Nx, Nx), ny2 = multiply(Ny, Ny), delta2 = multiply(Delta, Delta);
    const double rho2 = p.rho[0] * p.rho[0];
    std::array<double, 9> f{};
    for (std::size_t k = 0; k < f.size(); ++k)
        f[k] = nx2[k] + ny2[k] - rho2 * delta2[k];
    // divide by t² + 1
    std::array<double, 9> r = f;
    std::vector<double> q(7, 0.0);
    for (int k = 8; k >= 2; --k) {
        q[std::size_t(k - 2)] = r[std::size_t(k)];
        r[std::size_t(k - 2)] -= r[std::size_t(k)];
        r[std::size_t(k)] = 0.0;
    }
    double size = 0.0;
    for (double c : f)
        size = std::max(size, std::abs(c));
    if (std::abs(r[0]) + std::abs(r[1]) > 1e-10 * size)
        return {f.begin(), f.end()};
    return q;
}

/// The real and nearly real roots of a polynomial (coefficients t⁰ … tⁿ).
std::vector<double> realRoots(std::vector<double> a)
{
    double size = 0.0;
    for (double c : a)
        size = std::max(size, std::abs(c));
    if (size == 0.0)
        return {};
    while (a.size() > 1 && std::abs(a.back()) <= 1e-13 * size)
        a.pop_back(); // a root at t = ∞ (φ = π): tried apart
    const int n = int(a.size()) - 1;
    if (n < 1)
        return {};
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (int i = 1; i < n; ++i)
        companion(i, i - 1) = 1.0;
    for (int i = 0; i < n; ++i)
        companion(i, n - 1) = -a[std::size_t(i)] / a[std::size_t(n)];
    Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
    std::vector<double> roots;
    for (const std::complex<double> &z : solver.eigenvalues()) {
        if (std::abs(z.imag()) <= 1e-4 * (1.0 + std::abs(z)))
            roots.push_back(z.real());
    }
    return roots;
}
} // namespace

double residual(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles, int count,
                const Eigen::Vector3d &X)
{
    double worst = 0.0;
    for (int i = 0; i < count; ++i) {
        const std::size_t k = std::size_t(i);
        worst = std::max(worst, std::abs((platformPoint(legs[k], X) - circles[k].centre).norm() - circles[k].radius));
    }
    return worst;
}

Eigen::Matrix3d circleJacobian(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles,
                               const Eigen::Vector3d &X, Eigen::Vector3d *F)
{
    Eigen::Matrix3d G;
    for (std::size_t i = 0; i < 3; ++i) {
        const Eigen::Vector2d P = platformPoint(legs[i], X), e = P - circles[i].centre;
        const Eigen::Vector2d arm = P - X.head<2>();
        if (F)
            (*F)[Eigen::Index(i)] = 0.5 * (e.squaredNorm() - circles[i].radius * circles[i].radius);
        G.row(Eigen::Index(i)) << e.x(), e.y(), cross(arm, e);
    }
    return G;
}

bool polish(const std::array<PlanarLeg, 3> &legs, const std::array<LegCircle, 3> &circles, Eigen::Vector3d &X)
{
    double scale = 1.0;
    for (std::size_t i = 0; i < 3; ++i)
        scale = std::max({scale, circles[i].radius, legs[i].platform.norm()});
    for (int iteration = 0; iteration < 60; ++iteration) {
        Eigen::Vector3d F;
        const Eigen::Matrix3d G = circleJacobian(legs, circles, X, &F);
        const Eigen::Vector3d step = G.fullPivLu().solve(F);
        if (!step.allFinite())
            return false;
        X -= step;
        X.z() = std::remainder(X.z(), 2.0 * pi);
        if (step.head<2>().norm() <= 1e-14 * scale && std::abs(step.z()) <= 1e-14)
            break;
    }
    return residual(legs, circles, 3, X) <= 1e-9 * scale;
}

std::vector<Eigen::Vector3d> threeCircleSolutions(const std::array<PlanarLeg, 3> &legs,
                                                  const std::array<LegCircle, 3> &circles)
{
    double L = 0.0;
    for (std::size_t i = 0; i < 3; ++i)
        L = std::max({L, circles[i].radius, (circles[i].centre - circles[0].centre).norm(),
                      (legs[i].platform - legs[0].platform).norm()});
    if (!(L > 0.0))
        return {};
    Problem p;
    for (std::size_t i = 0; i < 3; ++i) {
        p.b[i] = legs[i].platform / L;
        p.C[i] = (circles[i].centre - circles[0].centre) / L;
        p.rho[i] = circles[i].radius / L;
    }
    std::vector<double> angles;
    for (double t : realRoots(forwardPolynomial(p)))
        angles.push_back(2.0 * std::atan(t));
    angles.push_back(pi); // t = ∞
    std::vector<Eigen::Vector3d> found;
    for (double phi : angles) {
        Eigen::Vector2d w;
        if (!pointAt(p, phi, w))
            continue;
        // P₁ = (x, y) + R(φ)B₁ = C₁ + w
        const Eigen::Vector2d origin = circles[0].centre + L * w - Eigen::Rotation2Dd(phi) * legs[0].platform;
        Eigen::Vector3d X(origin.x(), origin.y(), phi);
        if (!polish(legs, circles, X))
            continue;
        const bool known = std::any_of(found.begin(), found.end(), [&](const Eigen::Vector3d &Y) {
            return (Y.head<2>() - X.head<2>()).norm() <= 1e-7 * L && std::abs(std::remainder(Y.z() - X.z(), 2 * pi)) <= 1e-7;
        });
        if (!known)
            found.push_back(X);
    }
    for (Eigen::Vector3d &X : found) {
        if (X.z() <= -pi + 1e-15)
            X.z() += 2.0 * pi; // φ ∈ (−π, π]
    }
    std::sort(found.begin(), found.end(), [](const Eigen::Vector3d &a, const Eigen::Vector3d &b) { return a.z() < b.z(); });
    return found;
}

} // namespace pkm::planar
