#include "capabilityshapes.h"

#include "text.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pkm::capability {

namespace {

using Vector2 = Eigen::Vector2d;
using Polygon = std::vector<Vector2>;
constexpr int ellipsePoints = 96;
/// Core torques are N·m and lengths mm (capability.cpp): a rotary actuator's torque acts on
/// the platform's mm as N·mm.
constexpr double perMetre = 1e3;

/// The part of `polygon` where a·v ≤ b (Sutherland–Hodgman against one half-plane).
Polygon clip(const Polygon &polygon, const Vector2 &a, double b)
{
    Polygon out;
    out.reserve(polygon.size() + 1);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vector2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double sp = a.dot(p) - b, sq = a.dot(q) - b;
        if (sp <= 0.0)
            out.push_back(p);
        if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0))
            out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    return out;
}

Polygon square(double half)
{
    return {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
}

/// Whether a vertex lies on the clip box: the slabs leave the polygon open that way.
bool touchesBox(const Polygon &polygon, double half)
{
    return std::any_of(polygon.begin(), polygon.end(), [&](const Vector2 &p) {
        return std::max(std::abs(p.x()), std::abs(p.y())) >= half * (1.0 - 1e-9);
    });
}

/// Each vertex again as the exact crossing of the two lines nearest to it (a clip from a
/// large box leaves rounding of the box's size in them, 10⁻⁹ of the polygon).
void refineVertices(Polygon &polygon, const std::vector<std::pair<Vector2, double>> &lines)
{
    for (Vector2 &v : polygon) {
        int first = -1, second = -1;
        double firstResidual = 0.0, secondResidual = 0.0;
        for (int k = 0; k < int(lines.size()); ++k) {
            const auto &[n, c] = lines[std::size_t(k)];
            const double residual = std::abs(n.dot(v) - c) / n.norm();
            if (first < 0 || residual < firstResidual) {
                second = first;
                secondResidual = firstResidual;
                first = k;
                firstResidual = residual;
            } else if (second < 0 || residual < secondResidual) {
                const Vector2 &m = lines[std::size_t(first)].first;
                if (std::abs(m.x() * n.y() - m.y() * n.x()) > 1e-9 * m.norm() * n.norm()) {
                    second = k;
                    secondResidual = residual;
                }
            }
        }
        if (first < 0 || second < 0)
            continue;
        Eigen::Matrix2d A;
        A.row(0) = lines[std::size_t(first)].first.transpose();
        A.row(1) = lines[std::size_t(second)].first.transpose();
        const double det = A.determinant();
        if (std::abs(det) <= 1e-9 * A.row(0).norm() * A.row(1).norm())
            continue; // parallel: keep the clipped point
        const Vector2 exact = A.inverse() * Vector2(lines[std::size_t(first)].second, lines[std::size_t(second)].second);
        if ((exact - v).norm() <= 1e-6 * std::max(1.0, v.norm()))
            v = exact;
    }
}

/// {v : |a_i·v| ≤ b_i} for the rows a_i of `normals` (2 columns), cut by the clip box, and its
/// inscribed ellipse Σ (a_i·v/b_i)² ≤ 1.
Shape slabShape(const Eigen::MatrixX2d &normals, const Eigen::VectorXd &limits, double half)
{
    Shape shape;
    Polygon polygon = square(half);
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    std::vector<std::pair<Vector2, double>> lines = {
        {{1.0, 0.0}, half}, {{-1.0, 0.0}, half}, {{0.0, 1.0}, half}, {{0.0, -1.0}, half}};
    for (int i = 0; i < normals.rows(); ++i) {
        const Vector2 a = normals.row(i).transpose();
        if (a.squaredNorm() == 0.0 || !(limits[i] > 0.0))
            continue; // an actuator that no longer bounds this quantity
        polygon = clip(polygon, a, limits[i]);
        polygon = clip(polygon, -a, limits[i]);
        lines.push_back({a, limits[i]});
        lines.push_back({-a, limits[i]});
        M += a * a.transpose() / (limits[i] * limits[i]);
    }
    shape.unbounded = touchesBox(polygon, half);
    refineVertices(polygon, lines);
    shape.polygon = std::move(polygon);
    // The ellipse's radius along u is 1/√(uᵀMu); where M is (nearly) singular it is cut by the
    // box, so it is traced by its radius, else by its axes (even spacing on a long ellipse).
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(M);
    const Eigen::Vector2d lambda = eigen.eigenvalues();
    const bool bounded = lambda[0] > 0.0 && 1.0 / std::sqrt(lambda[0]) <= half;
    for (int k = 0; k < ellipsePoints; ++k) {
        const double t = 2.0 * std::numbers::pi * k / ellipsePoints;
        const Vector2 u(std::cos(t), std::sin(t));
        if (bounded) {
            shape.ellipse.push_back(eigen.eigenvectors() * Vector2(u.x() / std::sqrt(lambda[0]), u.y() / std::sqrt(lambda[1])));
        } else {
            const double q = u.dot(M * u);
            const double r = q > 0.0 ? std::min(1.0 / std::sqrt(q), half) : half;
            const Vector2 p = r * u;
            shape.ellipse.push_back(p * std::min(1.0, half / std::max(std::abs(p.x()), std::abs(p.y()))));
        }
    }
    return shape;
}

/// The image {A·u : |u_i| ≤ b_i} of the actuator box under a 2×2 matrix, and its ellipse
/// A·diag(b)·(unit circle): the form that stays finite where the slab form's normals do not.
Shape imageShape(const Eigen::Matrix2d &A, const Eigen::Vector2d &limits)
{
    Shape shape;
    const Vector2 g0 = A.col(0) * limits[0], g1 = A.col(1) * limits[1];
    shape.polygon = {g0 + g1, -g0 + g1, -g0 - g1, g0 - g1};
    if ((g0.x() * g1.y() - g0.y() * g1.x()) < 0.0)
        std::reverse(shape.polygon.begin(), shape.polygon.end());
    for (int k = 0; k < ellipsePoints; ++k) {
        const double t = 2.0 * std::numbers::pi * k / ellipsePoints;
        shape.ellipse.push_back(g0 * std::cos(t) + g1 * std::sin(t));
    }
    return shape;
}

bool finite(const Matrix &m)
{
    return m.allFinite();
}

} // namespace

Shapes shapesOf(const Actuators &actuators, const Matrix &jq, const Matrix &jx, SingularityType type,
                double velocityClip, double forceClip)
{
    Shapes shapes;
    const int n = actuators.count;
    if (n < 2 || actuators.outputs < 2 || actuators.rotaryOutput)
        return shapes;
    Eigen::VectorXd speed(n), effort(n);
    for (int i = 0; i < n; ++i) {
        const Actuator &a = actuators.items[std::size_t(i)];
        speed[i] = a.speed;
        effort[i] = a.force * (a.rotary ? perMetre : 1.0);
    }
    const Matrix J = jq.partialPivLu().solve(jx);
    Matrix G = jx.partialPivLu().solve(jq);
    // as capability::evaluate(): a (nearly) stretched leg's actuator moves the platform no more
    type = deliveryClass(actuators, G, type);
    const bool inverse = type == SingularityType::Inverse || type == SingularityType::Combined;
    const bool direct = type == SingularityType::Direct || type == SingularityType::Combined;
    // velocity: slabs |J_i·ẋ| ≤ q̇_max,i over the translations (the first two columns of J)
    if (!inverse && finite(J))
        shapes.velocity = slabShape(J.leftCols(2), speed, velocityClip);
    else if (n == 2 && finite(G) && !direct)
        shapes.velocity = imageShape(G, speed.head<2>());
    // force: slabs |(Gᵀ·F)_i| ≤ τ_max,i over pure forces (the first two rows of G)
    if (!direct && finite(G))
        shapes.force = slabShape(G.topRows(2).transpose(), effort, forceClip);
    else if (n == 2 && finite(J) && !inverse)
        shapes.force = imageShape(J.transpose(), effort.head<2>());
    return shapes;
}

namespace {

/// The smallest 1/2/5·10ⁿ not below `value`.
double niceAbove(double value)
{
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        if (step * decade >= value * (1.0 - 1e-12))
            return step * decade;
    }
    return 10.0 * decade;
}

Matrix selected(const Eigen::MatrixXd &m, const Actuators &actuators, bool rowsOnly)
{
    const int n = actuators.count;
    Matrix out(n, n);
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c)
            out(r, c) = m(actuators.inputs[std::size_t(r)], rowsOnly ? c : actuators.inputs[std::size_t(c)]);
    }
    return out;
}

/// The largest distance of a shape's polygon from the origin.
double reach(const Shape &shape)
{
    double r = 0.0;
    for (const Vector2 &p : shape.polygon)
        r = std::max(r, p.norm());
    return r;
}

} // namespace

ShapeScales scalesFor(const Mechanism &mechanism, const Actuators &actuators)
{
    ShapeScales scales;
    if (actuators.count < 2 || actuators.outputs < 2 || actuators.rotaryOutput)
        return scales;
    const Pose home = mechanism.homePose();
    const Jacobians j = mechanism.jacobians(home);
    const Scene scene = mechanism.scene(home);
    const double size = scene.extent.isEmpty() ? 0.0 : scene.extent.sizes().head<2>().maxCoeff();
    if (!(size > 0.0) || !j.inputs.allFinite() || !j.outputs.allFinite())
        return scales;
    const Matrix jq = selected(j.inputs, actuators, false), jx = selected(j.outputs, actuators, true);
    // an unbounded shape at home is measured inside a box much larger than any sane drawing
    constexpr double huge = 1e12;
    const Shapes home0 = shapesOf(actuators, jq, jx, SingularityType::None, huge, huge);
    const double v = reach(home0.velocity), f = reach(home0.force);
    if (!(v > 0.0) || !(f > 0.0) || v >= huge * 0.5 || f >= huge * 0.5)
        return scales;
    const double target = 0.3 * size; // mm of drawing for the home pose's strongest direction
    scales.velocityUnits = niceAbove(v / target);
    scales.forceUnits = niceAbove(f / target);
    scales.velocity = 1.0 / scales.velocityUnits;
    scales.force = 1.0 / scales.forceUnits;
    scales.clip = 0.6 * size;
    return scales;
}

Shapes polygonsAt(const Mechanism &mechanism, const Actuators &actuators, const Pose &pose, SingularityType type)
{
    Shapes shapes;
    if (actuators.count < 2 || actuators.outputs < 2 || actuators.rotaryOutput)
        return shapes;
    const Jacobians j = mechanism.jacobians(pose);
    if (j.inputs.rows() < actuators.count || j.outputs.cols() < actuators.outputs)
        return shapes;
    const Matrix jq = selected(j.inputs, actuators, false), jx = selected(j.outputs, actuators, true);
    // a report gives no cut polygon: one that reaches this far is unbounded (its inscribed
    // radius, the worst direction, may still be finite)
    constexpr double huge = 1e12;
    shapes = shapesOf(actuators, jq, jx, type, huge, huge);
    // the slabs are cut from the clip box, whose size sets the rounding error of the vertices:
    // cut again from a box just larger than the polygon
    const auto clipFor = [](const Shape &shape) {
        const double r = reach(shape);
        return shape.unbounded || !(r > 0.0) ? huge : 2.0 * r;
    };
    shapes = shapesOf(actuators, jq, jx, type, clipFor(shapes.velocity), clipFor(shapes.force));
    for (Shape *shape : {&shapes.velocity, &shapes.force}) {
        shape->ellipse.clear();
        if (shape->unbounded)
            shape->polygon.clear();
    }
    return shapes;
}

void addShapes(Scene &scene, const Mechanism &mechanism, const Actuators &actuators, const ShapeScales &scales,
               const Pose &pose, SingularityType type)
{
    if (!scales.valid() || pose.outputs.size() < 2 || !pose.outputs.head<2>().allFinite())
        return;
    const Jacobians j = mechanism.jacobians(pose);
    if (j.inputs.rows() < actuators.count || j.outputs.cols() < actuators.outputs)
        return;
    const Matrix jq = selected(j.inputs, actuators, false), jx = selected(j.outputs, actuators, true);
    const Shapes shapes = shapesOf(actuators, jq, jx, type, scales.clip / scales.velocity, scales.clip / scales.force);
    const Vector2 at = pose.outputs.head<2>();
    const auto add = [&](const std::vector<Vector2> &points, double scale, PathKind kind) {
        if (points.size() < 2)
            return;
        ScenePolyline line;
        line.closed = true;
        line.kind = kind;
        for (const Vector2 &p : points)
            line.points.emplace_back(at.x() + p.x() * scale, at.y() + p.y() * scale, 0.0);
        scene.polylines.push_back(std::move(line));
    };
    add(shapes.velocity.polygon, scales.velocity, PathKind::VelocityPolygon);
    add(shapes.velocity.ellipse, scales.velocity, PathKind::VelocityEllipse);
    add(shapes.force.polygon, scales.force, PathKind::ForcePolygon);
    add(shapes.force.ellipse, scales.force, PathKind::ForceEllipse);

    const bool inverse = type == SingularityType::Inverse || type == SingularityType::Combined;
    const bool direct = type == SingularityType::Direct || type == SingularityType::Combined;
    // what a cut shape means: at the singular pose that opens it, the truth; elsewhere only
    // that it reaches past the drawing
    const auto legend = [&](const Shape &shape, PathKind kind, std::string scaleText, bool singular,
                            const char *singularText, double units) {
        std::string text = text::format(scaleText, {text::number(units, 6)});
        if (shape.polygon.empty())
            text += " — " + text::translate("core", "undefined at this singular pose");
        else if (shape.unbounded)
            text += " — " + text::translate("core", singular ? singularText : QT_TRANSLATE_NOOP("core", "cut at the edge of the drawing"));
        scene.legend.push_back({kind, std::move(text)});
    };
    legend(shapes.velocity, PathKind::VelocityPolygon, text::translate("core", "velocity: 1 mm ≙ %1 mm/s"), direct,
           QT_TRANSLATE_NOOP("core", "unbounded: the locked actuators do not hold the platform (direct singularity)"),
           scales.velocityUnits);
    legend(shapes.force, PathKind::ForcePolygon, text::translate("core", "force: 1 mm ≙ %1 N"), inverse,
           QT_TRANSLATE_NOOP("core", "unbounded: a stretched leg holds any force along it (inverse singularity)"),
           scales.forceUnits);
}

} // namespace pkm::capability
