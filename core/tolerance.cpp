#include "tolerance.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

namespace pkm::tolerance {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();
/// Relative step of the central differences: the truncation error is O(h²) ≈ 10⁻¹⁰ of the
/// derivative, the rounding error of solves exact to ~10⁻¹³ mm is 10⁻¹³/h ≈ 10⁻⁸ mm/mm.
constexpr double relativeStep = 1e-5;
/// Below this singularity margin the inverse kinematics is too close to its branch point for a
/// central difference of it to be trusted: the direct method takes over (tolerance.h).
constexpr double implicitMargin = 1e-3;

Failure named(std::string_view name, const char *pattern, std::initializer_list<std::string_view> more = {})
{
    std::vector<std::string_view> args{name};
    args.insert(args.end(), more.begin(), more.end());
    std::string message = text::translate("core", pattern);
    // text::format takes an initializer list: at most three arguments are used here
    const auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : std::string_view(); };
    message = text::format(message, {arg(0), arg(1), arg(2)});
    return Failure{FailureKind::InvalidParameter, std::string(name), message};
}

/// 53 random bits as a double in [0, 1): the same on every standard library (tolerance.h).
double unit(std::mt19937_64 &generator)
{
    return double(generator() >> 11) * 0x1.0p-53;
}

/// One standard normal number (Box–Muller, the cosine branch; the sine one is not kept so
/// that each parameter draws the same two words of the stream whatever the others do).
double normal(std::mt19937_64 &generator)
{
    const double u1 = 1.0 - unit(generator); // (0, 1]: the logarithm is finite
    const double u2 = unit(generator);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double normOf(const Coordinates &delta, const std::vector<int> &outputs)
{
    double sum = 0.0;
    for (const int k : outputs)
        sum += delta[k] * delta[k];
    return std::sqrt(sum);
}

} // namespace

std::string_view methodName(Method method)
{
    return method == Method::Implicit ? "implicit" : "direct";
}

std::string_view distributionName(Distribution distribution)
{
    return distribution == Distribution::Uniform ? "uniform" : "normal";
}

Result<const ParameterInfo *> checkParameter(const Mechanism &mechanism, std::string_view name)
{
    const ParameterInfo *info = mechanism.findParameter(name);
    if (!info) {
        Failure f = named(name, QT_TRANSLATE_NOOP("core", "The design has no parameter named '%1' to give a tolerance."));
        f.kind = FailureKind::UnknownName;
        return f;
    }
    if (info->group != ParameterGroup::Geometry) {
        return named(name, QT_TRANSLATE_NOOP("core", "'%1' (%2) is not a geometric parameter: tolerances apply to the "
                                                     "lengths, positions and angles of the design."),
                     {text::label(info->label)});
    }
    if (!info->stored) {
        return named(name, QT_TRANSLATE_NOOP("core", "'%1' is derived from other parameters: give the tolerances of "
                                                     "the parameters it is made of."));
    }
    if (!mechanism.parameterApplies(name))
        return named(name, QT_TRANSLATE_NOOP("core", "'%1' has no say in this design, so a tolerance on it changes nothing."));
    return info;
}

Result<double> checkTolerance(const Mechanism &mechanism, std::string_view name, double value)
{
    auto info = checkParameter(mechanism, name);
    if (!info)
        return info.failure();
    const ParameterInfo &p = **info;
    if (!std::isfinite(value) || value < 0.0)
        return named(name, QT_TRANSLATE_NOOP("core", "The tolerance of '%1' must be a finite number ≥ 0."));
    const double nominal = mechanism.parameters().at(p.name);
    for (const double sign : {-1.0, 1.0}) {
        if (!Mechanism::checkDomain(p, nominal + sign * value)) {
            return named(name, QT_TRANSLATE_NOOP("core", "The tolerance ±%2 of '%1' takes it to %3, outside its allowed values."),
                         {text::number(p.unit.toDisplay(value), p.decimals + 2),
                          text::number(p.unit.toDisplay(nominal + sign * value), p.decimals + 2)});
        }
    }
    return value;
}

std::vector<int> normOutputs(const Mechanism &mechanism)
{
    std::vector<int> outputs;
    const auto &variables = mechanism.variableInfo();
    const int first = mechanism.inputCount();
    for (int k = 0; first + k < static_cast<int>(variables.size()); ++k) {
        if (variables[std::size_t(first + k)].unit.symbol == units::millimetre.symbol)
            outputs.push_back(k);
    }
    if (outputs.empty()) {
        for (int k = 0; k < mechanism.outputCount(); ++k)
            outputs.push_back(k);
    }
    return outputs;
}

Unit normUnit(const Mechanism &mechanism)
{
    const std::vector<int> outputs = normOutputs(mechanism);
    return mechanism.variableInfo()[std::size_t(mechanism.inputCount() + outputs.front())].unit;
}

Result<Analysis> Analysis::make(MechanismPtr mechanism, const ParameterSet &tolerances)
{
    if (static_cast<int>(tolerances.size()) > maxTolerances) {
        return Failure{FailureKind::InvalidParameter, {},
                       text::format(text::translate("core", "At most %1 tolerances can be given."),
                                    {std::to_string(maxTolerances)})};
    }
    Analysis a;
    a.m_mechanism = std::move(mechanism);
    const ParameterSet values = a.m_mechanism->parameters();
    for (const auto &[name, tol] : tolerances) {
        auto checked = checkTolerance(*a.m_mechanism, name, tol);
        if (!checked)
            return checked.failure();
        a.m_tolerances.emplace(name, tol);
        Perturbed p{name, tol, relativeStep * std::max(1.0, std::abs(values.at(name))), nullptr, nullptr};
        if (auto minus = a.m_mechanism->withParameter(name, values.at(name) - p.step))
            p.minus = *minus;
        if (auto plus = a.m_mechanism->withParameter(name, values.at(name) + p.step))
            p.plus = *plus;
        a.m_perturbed.push_back(std::move(p));
    }
    const auto &variables = a.m_mechanism->variableInfo();
    for (int v = 0; v < a.m_mechanism->inputCount(); ++v) {
        if (!variables[std::size_t(v)].independent)
            a.m_rows.push_back(v);
    }
    return a;
}

std::optional<Coordinates> Analysis::directDerivative(const Pose &pose, std::size_t parameter) const
{
    const Perturbed &p = m_perturbed[parameter];
    const auto solve = [&](const MechanismPtr &m) -> std::optional<Coordinates> {
        if (!m)
            return std::nullopt;
        auto solved = m->solveDirect(pose.inputs, &pose);
        if (!solved)
            return std::nullopt;
        return solved->outputs;
    };
    const auto plus = solve(p.plus), minus = solve(p.minus);
    if (plus && minus)
        return Coordinates((*plus - *minus) / (2.0 * p.step));
    if (plus) // a one-sided difference at the edge of the domain: O(h) instead of O(h²)
        return Coordinates((*plus - pose.outputs) / p.step);
    if (minus)
        return Coordinates((pose.outputs - *minus) / p.step);
    return std::nullopt;
}

FirstOrder Analysis::firstOrder(const Pose &pose) const
{
    const Mechanism &m = *m_mechanism;
    FirstOrder r;
    const int n = m.outputCount();
    r.worst = Coordinates::Zero(n);
    r.sigmaUniform = Coordinates::Zero(n);
    r.sigmaNormal = Coordinates::Zero(n);
    std::vector<double> values(std::size_t(m.reportLayout().size));
    const Singularity s = m.evaluate(pose, values);
    r.singularity = s.type;
    const auto give = [&](double value, const char *reason) {
        r.finite = false;
        r.worst.setConstant(value);
        r.sigmaUniform.setConstant(value);
        r.sigmaNormal.setConstant(value);
        r.worstNorm = value;
        r.reason = text::translate("core", reason);
        for (Contribution &c : r.parameters) {
            c.derivative.setConstant(value);
            c.contribution = value;
            c.share = nan;
        }
        return r;
    };
    for (const Perturbed &p : m_perturbed)
        r.parameters.push_back({p.name, p.tolerance, Coordinates::Zero(n), 0.0, 0.0});
    if (s.type == SingularityType::Direct)
        return give(infinity, QT_TRANSLATE_NOOP("core", "At a direct singularity the actuators do not hold the platform: "
                                                        "the error from the tolerances is unbounded."));
    if (s.type == SingularityType::Combined)
        return give(nan, QT_TRANSLATE_NOOP("core", "At a combined singularity the error from the tolerances is undefined."));

    // (T2) the implicit method, where it holds (tolerance.h)
    std::vector<Coordinates> derivatives;
    const int rows = static_cast<int>(m_rows.size());
    bool implicit = rows == n && s.type == SingularityType::None && s.margin >= implicitMargin;
    if (implicit) {
        const Jacobians j = m.jacobians(pose);
        Eigen::MatrixXd jq(rows, rows), jx(rows, n);
        for (int a = 0; a < rows; ++a) {
            for (int b = 0; b < rows; ++b)
                jq(a, b) = j.inputs(m_rows[std::size_t(a)], m_rows[std::size_t(b)]);
            jx.row(a) = j.outputs.row(m_rows[std::size_t(a)]).head(n);
        }
        const Eigen::PartialPivLU<Eigen::MatrixXd> lu(jx);
        for (const Perturbed &p : m_perturbed) {
            auto plus = p.plus ? p.plus->solveInverse(pose.outputs, &pose) : Result<Pose>(Failure{});
            auto minus = p.minus ? p.minus->solveInverse(pose.outputs, &pose) : Result<Pose>(Failure{});
            if (!plus || !minus) {
                implicit = false;
                break;
            }
            Eigen::VectorXd dq(rows);
            for (int a = 0; a < rows; ++a) {
                const int v = m_rows[std::size_t(a)];
                dq[a] = (plus->inputs[v] - minus->inputs[v]) / (2.0 * p.step);
            }
            const Eigen::VectorXd dx = -lu.solve(jq * dq);
            if (!dx.allFinite()) {
                implicit = false;
                break;
            }
            derivatives.emplace_back(dx);
        }
    }
    if (!implicit) {
        r.method = Method::Direct;
        derivatives.clear();
        for (std::size_t i = 0; i < m_perturbed.size(); ++i) {
            auto d = directDerivative(pose, i);
            if (!d || !d->allFinite())
                return give(nan, QT_TRANSLATE_NOOP("core", "The perturbed designs do not assemble at these inputs: the "
                                                           "error from the tolerances is undefined here."));
            derivatives.push_back(*d);
        }
    }

    // (T3), (T4)
    const std::vector<int> norm = normOutputs(m);
    Coordinates varUniform = Coordinates::Zero(n), varNormal = Coordinates::Zero(n);
    for (std::size_t i = 0; i < derivatives.size(); ++i) {
        Contribution &c = r.parameters[i];
        c.derivative = derivatives[i];
        c.contribution = normOf(c.derivative, norm) * c.tolerance;
        r.worst += c.derivative.cwiseAbs() * c.tolerance;
        r.worstNorm += c.contribution;
        varUniform += c.derivative.cwiseAbs2() * (c.tolerance * c.tolerance / 3.0);
        varNormal += c.derivative.cwiseAbs2() * (c.tolerance * c.tolerance / 9.0);
    }
    for (Contribution &c : r.parameters)
        c.share = r.worstNorm > 0.0 ? c.contribution / r.worstNorm : 0.0;
    r.sigmaUniform = varUniform.cwiseSqrt();
    r.sigmaNormal = varNormal.cwiseSqrt();
    r.finite = true;
    return r;
}

MonteCarlo Analysis::monteCarlo(const Pose &pose, const MonteCarloOptions &options, const std::atomic<bool> *cancel,
                                const Progress &progress) const
{
    const Mechanism &m = *m_mechanism;
    MonteCarlo r;
    const int n = m.outputCount();
    const int samples = std::clamp(options.samples, 1, maxSamples);
    const std::vector<int> norm = normOutputs(m);
    const ParameterSet nominal = m.parameters();
    std::mt19937_64 generator(options.seed);
    Coordinates sum = Coordinates::Zero(n), sumSquares = Coordinates::Zero(n), maxAbs = Coordinates::Zero(n);
    double normSum = 0.0, normSquares = 0.0, normMax = 0.0;
    r.norms.reserve(std::size_t(samples));
    int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // Samples are drawn in blocks, in order from the one stream, then solved in parallel (a
    // design costs a few solves to build) and summed in order: the result does not depend on
    // the number of threads.
    constexpr int block = 128;
    const std::size_t count = m_perturbed.size();
    std::vector<double> offsets(std::size_t(block) * count);
    std::vector<std::optional<Coordinates>> errors(static_cast<std::size_t>(block));
    for (int first = 0; first < samples; first += block) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            r.cancelled = true;
            break;
        }
        if (progress)
            progress(first, samples);
        const int size = std::min(block, samples - first);
        for (int s = 0; s < size; ++s) {
            for (std::size_t i = 0; i < count; ++i) {
                // two words of the stream per parameter in either distribution, so that the
                // uniform and the normal run of one seed use the same words
                const double u = unit(generator);
                const double z = normal(generator);
                const double tol = m_perturbed[i].tolerance;
                offsets[std::size_t(s) * count + i] =
                    options.distribution == Distribution::Uniform ? tol * (2.0 * u - 1.0) : tol / 3.0 * z;
            }
        }
        std::atomic<int> next{0};
        const auto work = [&] {
            ParameterSet changes;
            for (int s = next++; s < size; s = next++) {
                changes.clear();
                for (std::size_t i = 0; i < count; ++i) {
                    const std::string &name = m_perturbed[i].name;
                    changes[name] = nominal.at(name) + offsets[std::size_t(s) * count + i];
                }
                errors[std::size_t(s)].reset();
                auto design = changes.empty() ? Result<MechanismPtr>(m_mechanism) : m.withParameters(changes);
                if (!design)
                    continue; // no valid design: a failed sample
                auto solved = (*design)->solveDirect(pose.inputs, &pose);
                if (solved && solved->outputs.allFinite())
                    errors[std::size_t(s)] = solved->outputs - pose.outputs;
            }
        };
        {
            std::vector<std::jthread> pool;
            for (int t = 1; t < std::min(threads, size); ++t)
                pool.emplace_back(work);
            work();
        }
        for (int s = 0; s < size; ++s) {
            ++r.samples;
            const auto &delta = errors[std::size_t(s)];
            if (!delta) {
                ++r.failed;
                continue;
            }
            sum += *delta;
            sumSquares += delta->cwiseAbs2();
            maxAbs = maxAbs.cwiseMax(delta->cwiseAbs());
            const double e = normOf(*delta, norm);
            normSum += e;
            normSquares += e * e;
            normMax = std::max(normMax, e);
            r.norms.push_back(e);
        }
    }
    if (progress)
        progress(r.samples, samples);
    const int k = r.assembled();
    if (k == 0) {
        r.mean = r.deviation = r.maxAbs = Coordinates::Constant(n, nan);
        r.normMean = r.normDeviation = r.normMax = nan;
        return r;
    }
    // the sample standard deviation (n − 1), from the sums: errors are ≪ 1 and their mean
    // small, so the cancellation in Σx² − (Σx)²/n costs no digits that matter here
    const double denominator = k > 1 ? double(k - 1) : 1.0;
    r.mean = sum / k;
    r.deviation = ((sumSquares - sum.cwiseAbs2() / k) / denominator).cwiseMax(0.0).cwiseSqrt();
    r.maxAbs = maxAbs;
    r.normMean = normSum / k;
    r.normDeviation = std::sqrt(std::max(0.0, (normSquares - normSum * normSum / k) / denominator));
    r.normMax = normMax;
    return r;
}

} // namespace pkm::tolerance
