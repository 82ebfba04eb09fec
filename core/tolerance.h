#pragma once
/// Tolerances on the design: how far the platform (or the output link) is off at a pose when
/// the geometric design parameters are off by up to ±tol_i each while the actuators hold their
/// inputs (docs/mathematics.md, "Tolerances"). One computation for every kind.
///
/// First order. The constraints F(x, q, p) = 0 (outputs x, actuated inputs q, design p) give at
/// fixed q, by implicit differentiation (T1),
///     ∂x/∂p = −F_x⁻¹·F_p.
/// The Mechanism interface exposes no residual F, but it exposes the inverse kinematics
/// q = q_IK(x; p) — the very solution of F = 0 for q — and the Jacobians J_q·q̇ = J_x·ẋ, i.e.
/// F_q = J_q, F_x = −J_x in one row scaling. Differentiating F(x, q_IK(x; p), p) ≡ 0 in p gives
/// F_p = −J_q·∂q_IK/∂p, hence (T2)
///     ∂x/∂p = −J_x⁻¹·J_q·∂q_IK/∂p = −G·∂q_IK/∂p,   G = J⁻¹ = J_x⁻¹·J_q,
/// with ∂q_IK/∂p a central difference of solveInverse() in the same working mode (the
/// implicit method). Where that is not possible — the pose is (near) an inverse singularity,
/// where q_IK has a square-root branch point and G a vanishing column, or the kind is not
/// square in its actuators — the same derivative is taken as a central difference of
/// solveDirect() at fixed q, tracked in the same assembly mode (the direct method); the tests
/// check both against each other for every kind.
///
/// Worst case (T3): Δx_k ≤ Σ_i |∂x_k/∂p_i|·tol_i per output, and for the position (the outputs
/// in mm, or the one angle of a 1-DOF output) |Δx| ≤ Σ_i ‖∂x/∂p_i‖·tol_i, parameter i
/// contributing ‖∂x/∂p_i‖·tol_i. At a direct singularity (det J_x = 0) the inputs do not hold
/// the platform: the error is unbounded (∞); at a combined one it is undefined.
///
/// Monte Carlo: N designs drawn with every toleranced parameter uniform in ±tol (or normal with
/// tol = 3σ), each solved at the nominal inputs near the nominal pose (same assembly mode).
/// The generator is std::mt19937_64 seeded with `seed` (default 19, the number); the
/// uniform and normal numbers are made from its raw output here (53-bit fractions, Box–Muller),
/// not by <random>'s distributions, whose algorithms differ between standard libraries — so a
/// seed gives the same numbers everywhere.
///
/// Units: core units inside (mm, rad); the `display` helpers convert.

#include "mechanism.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pkm::tolerance {

inline constexpr int defaultSamples = 2000;
inline constexpr int maxSamples = 100000;
inline constexpr std::uint64_t defaultSeed = 19;
/// A design's tolerances: at most this many (a file that gives more is refused).
inline constexpr int maxTolerances = 64;

enum class Distribution { Uniform, Normal };
enum class Method { Implicit, Direct };
std::string_view methodName(Method method); ///< "implicit", "direct"
std::string_view distributionName(Distribution distribution); ///< "uniform", "normal"

/// Whether `name` may carry a tolerance: a stored geometry parameter (length, position, angle,
/// ratio) that has a say in the design. The failure names it, translated (text::translate).
Result<const ParameterInfo *> checkParameter(const Mechanism &mechanism, std::string_view name);
/// checkParameter() and a finite value ≥ 0 (core units), smaller than the parameter's own size
/// where that is a length (±tol beyond the value makes no design); the failure names it.
Result<double> checkTolerance(const Mechanism &mechanism, std::string_view name, double value);

/// The outputs the error norm is taken over: those in mm (a point or a platform's x, y), or,
/// without any, all (the one angle of the П-joint or the four-bar).
std::vector<int> normOutputs(const Mechanism &mechanism);
/// The display unit of the norm (mm or °).
Unit normUnit(const Mechanism &mechanism);

/// One parameter's share of the first-order error.
struct Contribution {
    std::string name;
    double tolerance = 0.0;  ///< ±tol, core units
    Coordinates derivative;  ///< ∂x/∂p, core units of x per core unit of p
    double contribution = 0.0; ///< ‖∂x_N/∂p‖·tol over normOutputs(), core units of the norm
    double share = 0.0;      ///< contribution / Σ contributions (0 … 1)
};

struct FirstOrder {
    bool finite = false;     ///< false: `reason` says why (singular pose, no solution)
    SingularityType singularity = SingularityType::None;
    /// ∞ (direct singularity) or NaN (undefined: combined singularity, or no derivative) when
    /// not finite; `reason` is one English sentence then (text::translate).
    std::string reason;
    Method method = Method::Implicit;
    std::vector<Contribution> parameters; ///< in the order of the tolerance set (by name)
    Coordinates worst;       ///< Σ_i |∂x_k/∂p_i|·tol_i per output (T3)
    double worstNorm = 0.0;  ///< Σ_i contribution_i (T3)
    /// First-order standard deviation of each output for `distribution`:
    /// √(Σ_i (∂x_k/∂p_i)²·σ_i²), σ_i = tol_i/√3 (uniform) or tol_i/3 (normal) (T4).
    Coordinates sigmaUniform;
    Coordinates sigmaNormal;
};

struct MonteCarloOptions {
    int samples = defaultSamples;
    std::uint64_t seed = defaultSeed;
    Distribution distribution = Distribution::Uniform;
    int threads = 0; ///< 0: all cores; the result is the same for any number
};

struct MonteCarlo {
    int samples = 0;         ///< drawn
    int failed = 0;          ///< no valid design or no assembly in the mode of the pose
    bool cancelled = false;
    /// Over the assembled samples (NaN when none assembled): per output error Δx = x − x₀.
    Coordinates mean, deviation, maxAbs;
    double normMean = 0.0, normDeviation = 0.0, normMax = 0.0;
    std::vector<double> norms; ///< |Δx_N| of each assembled sample, core units (histogram)
    int assembled() const { return samples - failed; }
    double failedFraction() const { return samples > 0 ? double(failed) / samples : 0.0; }
};

/// Called from the computing thread with (done, total) now and then.
using Progress = std::function<void(int done, int total)>;

/// The toleranced design: validated once, with the perturbed designs p_i ± h_i of the
/// derivatives built once, so that a pose (or a map's cell) costs only solves. Immutable and
/// safe to use from many threads.
class Analysis
{
public:
    /// Fails naming the first parameter that may not carry a tolerance (checkTolerance()).
    static Result<Analysis> make(MechanismPtr mechanism, const ParameterSet &tolerances);

    const Mechanism &mechanism() const { return *m_mechanism; }
    const ParameterSet &tolerances() const { return m_tolerances; }

    FirstOrder firstOrder(const Pose &pose) const;
    /// The derivative ∂x/∂p_i by the direct method alone (for tests and as the fallback);
    /// empty on failure.
    std::optional<Coordinates> directDerivative(const Pose &pose, std::size_t parameter) const;
    MonteCarlo monteCarlo(const Pose &pose, const MonteCarloOptions &options,
                          const std::atomic<bool> *cancel = nullptr, const Progress &progress = {}) const;

private:
    struct Perturbed {
        std::string name;
        double tolerance = 0.0;
        double step = 0.0;      ///< h, core units (from p − h to p + h: a central difference)
        MechanismPtr minus, plus; ///< p − h and p + h; one may be null (domain edge): one-sided
    };
    MechanismPtr m_mechanism;
    ParameterSet m_tolerances;
    std::vector<Perturbed> m_perturbed;
    std::vector<int> m_rows; ///< the actuated inputs that move the platform (not the O-X glide's z)
};

} // namespace pkm::tolerance
