#pragma once
/// Designs, poses and reports of the mechanisms as the tests need them: the kinds made from a
/// design (a design a test builds must be valid, so a failure stops the test with its message),
/// joint coordinates, the values of a pose's report by name, reproducible random numbers and
/// central finite differences of the kinematics, which every kind's Jacobians are checked
/// against.

#include "mechanism.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

namespace pkm {
struct PJointDesign;
class PJoint;
struct FourBarDesign;
class FourBar;
struct FiveBarDesign;
class FiveBar;
struct MomaDesign;
class Moma;
struct OxGlideDesign;
class OxGlide;
} // namespace pkm

namespace pkm::test {

// -- designs ---------------------------------------------------------------------------------

/// The mechanism of a design that must be valid (qFatal with the failure's message if not).
std::shared_ptr<const PJoint> make(const PJointDesign &design);
std::shared_ptr<const FourBar> make(const FourBarDesign &design);
std::shared_ptr<const FiveBar> make(const FiveBarDesign &design);
std::shared_ptr<const Moma> make(const MomaDesign &design);
std::shared_ptr<const OxGlide> make(const OxGlideDesign &design);
/// A registered kind from named values (the registry's createMechanism), likewise.
MechanismPtr makeKind(std::string_view kind, const ParameterSet &parameters = {});

/// The column "kind" (QString) and one row per registered kind (mechanismKinds()), named by its
/// id: a test over every kind then covers a new kind without a list to edit.
void addKindRows();

/// A triple-rocker four-bar (AB 100, BC 60, CD 80, AD 70): the crank's range ends where
/// coupler and rocker lie in line, a dead point (direct singularity) the mobility tests use.
FourBarDesign tripleRockerFourBar();

// -- coordinates -----------------------------------------------------------------------------

Coordinates one(double v);
Coordinates pair(double a, double b);
Coordinates triple(double a, double b, double c);

// -- reports ---------------------------------------------------------------------------------

/// The report of `pose` (Mechanism::evaluate) into a buffer first filled with NaN, so that a
/// value the mechanism leaves unset shows; its singularity goes to `singularity`.
std::vector<double> evaluated(const Mechanism &m, const Pose &pose, Singularity *singularity = nullptr);
/// The (first) value of the report entry `name` (qFatal when the layout has none).
double entry(const Mechanism &m, const std::vector<double> &values, const char *name);
/// A 2×2 report entry, stored row-major (qFatal when the layout has no such entry).
Eigen::Matrix2d matrixEntry(const Mechanism &m, const std::vector<double> &values, const char *name);
/// The report entry `name` of `pose`.
double reportValue(const Mechanism &m, const Pose &pose, const char *name);

// -- random designs --------------------------------------------------------------------------

/// A reproducible uniform number in [lo, hi): std::uniform_real_distribution's algorithm differs
/// between standard libraries, the engine's output does not.
double uniform(std::mt19937 &generator, double lo, double hi);

// -- finite differences ----------------------------------------------------------------------

/// Central difference of f at x with step h.
template<class F> double derivative(F f, double x, double h = 1e-6)
{
    return (f(x + h) - f(x - h)) / (2 * h);
}

/// How the inputs change per unit of output `column`: the inverse kinematics of the outputs
/// moved by ±h, (q(x + h·e) − q(x − h·e)) / 2h, solved near `near`. Empty when either side
/// cannot be solved (outside the workspace, or a step across a singularity).
std::optional<Eigen::VectorXd> inverseDifference(
    const Mechanism &m, const Coordinates &outputs, int column, double h, const Pose *near = nullptr);
/// All columns of it: the matrix ∂q/∂x that Jacobians::full must be.
std::optional<Eigen::MatrixXd> inverseDifferences(
    const Mechanism &m, const Coordinates &outputs, double h, const Pose *near = nullptr);
/// How the outputs change per unit of input `column`, from the direct kinematics likewise.
std::optional<Eigen::VectorXd> directDifference(
    const Mechanism &m, const Coordinates &inputs, int column, double h, const Pose *near = nullptr);
/// All columns of it: ∂x/∂q, which undoes Jacobians::full (∂x/∂q · ∂q/∂x = I).
std::optional<Eigen::MatrixXd> directDifferences(
    const Mechanism &m, const Coordinates &inputs, double h, const Pose *near = nullptr);

} // namespace pkm::test
