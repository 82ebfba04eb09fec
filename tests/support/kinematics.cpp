#include "support/kinematics.h"

#include "kinds/fivebar/fivebar.h"
#include "kinds/fourbar/fourbar.h"
#include "kinds/moma/moma.h"
#include "kinds/oxglide/oxglide.h"
#include "kinds/pjoint/pjoint.h"
#include "registry.h"

#include <QTest>

#include <limits>
#include <string>

namespace pkm::test {

namespace {

/// The design a test built is part of the test's set-up, not under test: stop at once.
MechanismPtr valid(Result<MechanismPtr> made)
{
    if (!made)
        qFatal("%s", made.failure().message.c_str());
    return *made;
}

template<class Kind> std::shared_ptr<const Kind> validKind(Result<MechanismPtr> made)
{
    return std::static_pointer_cast<const Kind>(valid(std::move(made)));
}

/// The step ±h of `values` in `column`, solved by `solve`; its change per unit, or empty.
template<class Solve>
std::optional<Eigen::VectorXd> centralDifference(
    const Coordinates &values, int column, double h, Solve solve, bool wantInputs)
{
    Coordinates up = values, down = values;
    up[column] += h;
    down[column] -= h;
    const Result<Pose> a = solve(up), b = solve(down);
    if (!a || !b)
        return std::nullopt;
    const Coordinates &high = wantInputs ? a->inputs : a->outputs;
    const Coordinates &low = wantInputs ? b->inputs : b->outputs;
    return Eigen::VectorXd((high - low) / (2 * h));
}

/// The columns of `column(c)` for every c of `values`, or empty when one is.
template<class Column> std::optional<Eigen::MatrixXd> columns(const Coordinates &values, Column column)
{
    Eigen::MatrixXd matrix;
    for (int c = 0; c < values.size(); ++c) {
        const std::optional<Eigen::VectorXd> difference = column(c);
        if (!difference)
            return std::nullopt;
        if (c == 0)
            matrix.resize(difference->size(), values.size());
        matrix.col(c) = *difference;
    }
    return matrix;
}

} // namespace

std::shared_ptr<const PJoint> make(const PJointDesign &design)
{
    return validKind<PJoint>(PJoint::create(design));
}

std::shared_ptr<const FourBar> make(const FourBarDesign &design)
{
    return validKind<FourBar>(FourBar::create(design));
}

std::shared_ptr<const FiveBar> make(const FiveBarDesign &design)
{
    return validKind<FiveBar>(FiveBar::create(design));
}

std::shared_ptr<const Moma> make(const MomaDesign &design)
{
    return validKind<Moma>(Moma::create(design));
}

std::shared_ptr<const OxGlide> make(const OxGlideDesign &design)
{
    return validKind<OxGlide>(OxGlide::create(design));
}

MechanismPtr makeKind(std::string_view kind, const ParameterSet &parameters)
{
    return valid(createMechanism(kind, parameters));
}

void addKindRows()
{
    QTest::addColumn<QString>("kind");
    for (const MechanismKind &kind : mechanismKinds()) {
        const std::string id(kind.id);
        QTest::newRow(id.c_str()) << QString::fromStdString(id);
    }
}

FourBarDesign tripleRockerFourBar()
{
    FourBarDesign d;
    d.crank = 100;
    d.coupler = 60;
    d.rocker = 80;
    d.ground = 70;
    return d;
}

Coordinates one(double v)
{
    return Coordinates::Constant(1, v);
}

Coordinates pair(double a, double b)
{
    Coordinates c(2);
    c << a, b;
    return c;
}

Coordinates triple(double a, double b, double c)
{
    Coordinates t(3);
    t << a, b, c;
    return t;
}

std::vector<double> evaluated(const Mechanism &m, const Pose &pose, Singularity *singularity)
{
    std::vector<double> values(std::size_t(m.reportLayout().size), std::numeric_limits<double>::quiet_NaN());
    const Singularity s = m.evaluate(pose, values);
    if (singularity)
        *singularity = s;
    return values;
}

double entry(const Mechanism &m, const std::vector<double> &values, const char *name)
{
    const ReportEntry *e = m.reportLayout().find(name);
    if (!e)
        qFatal("no report entry %s", name);
    return values[std::size_t(e->offset)];
}

Eigen::Matrix2d matrixEntry(const Mechanism &m, const std::vector<double> &values, const char *name)
{
    const ReportEntry *e = m.reportLayout().find(name);
    if (!e || e->rows != 2 || e->cols != 2)
        qFatal("no 2x2 report entry %s", name);
    return Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(&values[std::size_t(e->offset)]);
}

double reportValue(const Mechanism &m, const Pose &pose, const char *name)
{
    return entry(m, evaluated(m, pose), name);
}

double uniform(std::mt19937 &generator, double lo, double hi)
{
    return lo + (hi - lo) * (generator() / 4294967296.0);
}

std::optional<Eigen::VectorXd> inverseDifference(
    const Mechanism &m, const Coordinates &outputs, int column, double h, const Pose *near)
{
    return centralDifference(
        outputs, column, h, [&](const Coordinates &x) { return m.solveInverse(x, near); }, true);
}

std::optional<Eigen::MatrixXd> inverseDifferences(
    const Mechanism &m, const Coordinates &outputs, double h, const Pose *near)
{
    return columns(outputs, [&](int c) { return inverseDifference(m, outputs, c, h, near); });
}

std::optional<Eigen::VectorXd> directDifference(
    const Mechanism &m, const Coordinates &inputs, int column, double h, const Pose *near)
{
    return centralDifference(
        inputs, column, h, [&](const Coordinates &q) { return m.solveDirect(q, near); }, false);
}

std::optional<Eigen::MatrixXd> directDifferences(
    const Mechanism &m, const Coordinates &inputs, double h, const Pose *near)
{
    return columns(inputs, [&](int c) { return directDifference(m, inputs, c, h, near); });
}

} // namespace pkm::test
