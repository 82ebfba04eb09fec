#pragma once
/// The one interface every mechanism implements, so that the GUI, the CLI and the tests are
/// generic. A Mechanism is an immutable design (dimensions, limits, actuator): solving takes
/// the design and the joint variables and returns a Pose value. No hidden mutable state, so
/// one Mechanism may be used from many threads at once.
///
/// Units: core units (mm, rad, N, N·m, s); ParameterInfo/VariableInfo carry the display unit.

#include "kinematicchain.h"
#include "result.h"
#include "scene.h"
#include "scene3d.h"
#include "units.h"

#include <Eigen/Core>

#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <initializer_list>
#include <utility>
#include <vector>

namespace pkm {

/// Named design parameter values in core units (the stored, independent ones).
using ParameterSet = std::map<std::string, double, std::less<>>;

/// Joint coordinates of one kind (inputs or outputs); at most 6, never on the heap.
using Coordinates = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 6, 1>;

struct Interval {
    double min = 0.0;
    double max = 0.0;
    bool contains(double v, double tolerance = 0.0) const { return v >= min - tolerance && v <= max + tolerance; }
    double clamp(double v) const { return v < min ? min : (v > max ? max : v); }
};

enum class ParameterGroup { Geometry, Range, Actuator, Drawing, Mode };
/// The group's key in files and reports: "geometry", "range", "actuator", "drawing", "mode".
std::string_view parameterGroupKey(ParameterGroup group);

struct ParameterInfo {
    std::string name;        ///< key in files, CLI and JSON ("a", "theta_min")
    std::string symbol;      ///< as printed ("a", "θ_min")
    std::string label;       ///< English source, QT_TRANSLATE_NOOP("core", …) ("crank (lever) length")
    Unit unit;               ///< display unit
    ParameterGroup group = ParameterGroup::Geometry;
    Interval domain;         ///< allowed values, core units
    bool openMin = false;    ///< domain.min itself is not allowed
    bool openMax = false;    ///< domain.max itself is not allowed
    bool stored = true;      ///< false: derived from the stored ones (k = b/a), still settable
    int decimals = 2;        ///< display decimals
    double displayStep = 1;  ///< spin-box step, display units
    /// Named values of a mode parameter ({"O", +1}, {"X", -1}): files and the command line
    /// may give the name instead of the number.
    std::vector<std::pair<std::string, double>> choices = {};
    /// How the choices read on screen, in their order, where not as their names: the leg
    /// types' "R̲RR" with the actuated joint underlined for the names "RRR" of files.
    std::vector<std::string> choiceLabels = {};
    /// The label where the choices are offered as a list (the Design panel), when `label`
    /// spells out their numeric codes for the command line; empty: `label` (English source,
    /// QT_TRANSLATE_NOOP("core", …)).
    std::string listLabel = {};
    /// The command line's JSON gives the mode as its number even where it has choices: MOMA's
    /// β_i and σ were ±1 there before they had words, and scripts read them so.
    bool numberInJson = false;
};

struct VariableInfo {
    std::string name;   ///< "theta", "d"
    std::string symbol; ///< "θ", "d"
    std::string label;  ///< "output angle" (English source, QT_TRANSLATE_NOOP("core", …))
    Unit unit;
    bool actuated = false; ///< true: an input (driven by an actuator); false: an output
    int decimals = 2;
    /// An actuated axis that carries the whole mechanism (the O-X glide's z): the outputs do
    /// not determine it, so it may be given together with them.
    bool independent = false;
};

/// One pose: the actuated inputs and the outputs, consistent with each other.
struct Pose {
    Coordinates inputs;
    Coordinates outputs;
    int mode = 0; ///< assembly/working mode index where the mechanism has several
};

enum class ReportGroup { Pose, Jacobian, Derived };

/// What a reported quantity is exactly at a singular pose, where its formula divides by a
/// vanishing determinant: J = J_q⁻¹·J_x is unbounded at an inverse singularity and det J is 0 at
/// a direct one. Near one the formula still gives a finite number (det J = 10¹³ a micrometre
/// from the stretched leg), which means nothing; at a pose classified singular the exact value
/// replaces it.
enum class AtSingularity : unsigned char { Computed, Zero, Infinite };

/// Where one named quantity sits in the flat value buffer filled by Mechanism::evaluate().
struct ReportEntry {
    ReportGroup group = ReportGroup::Derived;
    std::string name;   ///< JSON key
    std::string symbol; ///< as printed
    std::string label;  ///< English source, QT_TRANSLATE_NOOP("core", …)
    Unit unit;
    int rows = 1;
    int cols = 1;
    int offset = 0; ///< index of the first value (row-major) in the buffer
    int decimals = 3;
    AtSingularity atInverse = AtSingularity::Computed; ///< at an inverse singularity
    AtSingularity atDirect = AtSingularity::Computed;  ///< at a direct singularity
};

/// A reported quantity that is a word ("mode": "X").
struct ReportText {
    ReportGroup group = ReportGroup::Pose;
    std::string name;  ///< JSON key
    std::string text;  ///< English source (also the JSON value), QT_TRANSLATE_NOOP("core", …)
    std::string label; ///< English source, QT_TRANSLATE_NOOP("core", …)
};

struct ReportLayout {
    std::vector<ReportEntry> entries;
    int size = 0; ///< number of doubles the buffer needs

    const ReportEntry *find(std::string_view name) const;
    /// Appends an entry of rows × cols values after the last one.
    void add(ReportGroup group, const char *name, const char *symbol, const char *label, Unit unit, int decimals,
             int rows = 1, int cols = 1);
    /// Declares what entry `name` (added before) is at inverse and at direct singular poses.
    void atSingularity(const char *name, AtSingularity inverse, AtSingularity direct);
    /// The marks of J = J_q⁻¹·J_x as most kinds report it: "J", "det_J" and "cond" unbounded at
    /// an inverse singularity; "det_J" 0 and "cond" unbounded at a direct one; the inputs'
    /// determinant `inputDeterminant` ("det_Jq", MOMA's "det_Jp") 0 at an inverse and
    /// "det_Jx" 0 at a direct one.
    void atSingularityOfJ(const char *inputDeterminant);
};

/// The Jacobians of a pose, from the constraint F(x, q) = 0 with inputs q and outputs x:
/// J_q·q̇ = J_x·ẋ, so q̇ = J·ẋ with J = J_q⁻¹·J_x. det J_q = 0: inverse-kinematic singularity;
/// det J_x = 0: direct-kinematic singularity.
struct Jacobians {
    Eigen::MatrixXd inputs;  ///< J_q (the П-joint's J_d)
    Eigen::MatrixXd outputs; ///< J_x (the П-joint's J_θ)
    Eigen::MatrixXd full;    ///< J = J_q⁻¹·J_x
};

enum class SingularityType { None, Inverse, Direct, Combined };
std::string_view singularityName(SingularityType type); ///< "none", "inverse", "direct", "combined"

struct Singularity {
    SingularityType type = SingularityType::None;
    double margin = 1.0; ///< dimensionless distance from the nearest singularity, 0 at it
    double directMargin = 1.0; ///< the same from the nearest direct singularity alone
};

/// The class of a pose from its scale-free margins from the inverse and the direct
/// singularities (0 at them): below `tolerance` it is singular of that kind; the margin is the
/// smaller one.
Singularity classifySingularity(double inverseMargin, double directMargin, double tolerance);

/// Puts the exact values of a singular pose of class `type` into `values` (filled by
/// evaluate()), as each entry of `layout` declares (AtSingularity): 0, +∞ (unbounded, for every
/// element of a matrix: the matrix does not exist), or, at a combined singularity where one
/// mark says 0 and the other ∞, NaN (undefined). Nothing changes at a regular pose. Every
/// kind's evaluate() ends with it; it does not allocate.
void settleSingularValues(const ReportLayout &layout, std::span<double> values, SingularityType type);

class Mechanism;
class PlanarWorkspace;
using MechanismPtr = std::shared_ptr<const Mechanism>;

/// The same pose seen in another working or assembly mode of the design: what the GUI draws as
/// a ghost and switches to only when the user asks (never silently).
struct ModeAlternative {
    std::string label;      ///< "other assembly mode" (English source, QT_TRANSLATE_NOOP("core", …))
    ParameterSet changes;   ///< the mode parameters that select it
    MechanismPtr mechanism; ///< the design with `changes` applied
    bool sameInputs = true; ///< the alternative keeps the inputs (else the outputs) of the pose
    Pose pose;              ///< the pose in that mode (empty for a neighbour not yet solved)
};

class Mechanism : public std::enable_shared_from_this<Mechanism>
{
public:
    virtual ~Mechanism() = default;

    virtual std::string_view kind() const = 0; ///< "pjoint", "moma", …

    // -- design ---------------------------------------------------------------------------
    virtual const std::vector<ParameterInfo> &parameterInfo() const = 0;
    /// Whether parameter `name` has a say in this design (a third leg's length does not when
    /// the platform has two legs): the design panel shows only those. Every parameter is still
    /// stored, saved and settable.
    virtual bool parameterApplies(std::string_view name) const
    {
        (void)name;
        return true;
    }
    /// All parameter values (stored and derived), core units.
    virtual ParameterSet parameters() const = 0;
    /// A new design with one parameter changed, validated; the failure names the culprit.
    virtual Result<MechanismPtr> withParameter(std::string_view name, double value) const = 0;
    /// A new design with several parameters changed at once, validated once, so that the order
    /// does not matter (θ_min and θ_max moved together, k given with a). The default applies
    /// them one by one.
    virtual Result<MechanismPtr> withParameters(const ParameterSet &changes) const;
    /// Warnings about a valid but questionable design (interference, poor transmission),
    /// translated (text::translate).
    virtual std::vector<std::string> designWarnings() const { return {}; }

    // -- joint variables ------------------------------------------------------------------
    virtual const std::vector<VariableInfo> &variableInfo() const = 0; ///< inputs first
    int inputCount() const;
    int outputCount() const;
    /// Allowed interval of variable i (index into variableInfo()), core units.
    virtual Interval variableRange(int variable) const = 0;
    virtual Pose homePose() const = 0;
    /// Why variable `variable` cannot go past its upper (or lower) limit when the limit is not
    /// simply the design's range (an assembly limit, a dead point): a clause for "α stops at its
    /// upper limit 109.08°: …", translated (text::translate); empty for a design range.
    virtual std::string rangeLimitReason(int variable, bool upper) const
    {
        (void)variable;
        (void)upper;
        return {};
    }

    /// Direct kinematics: outputs from inputs. `near` picks the assembly mode to stay in.
    virtual Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const = 0;
    /// Inverse kinematics: inputs from outputs.
    virtual Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const = 0;
    /// Solve with one variable (index into variableInfo()) set and the others of its kind
    /// taken from `current`, the pose moving from `current` (followDirect()).
    Result<Pose> solveWith(const Pose &current, int variable, double value) const;
    /// Direct kinematics as the inputs move from `current`'s to `inputs`: where several
    /// assembly modes lie close, the one `current` is in, or a failure where it ends on the way
    /// (solveDirect() takes `near` as a hint of the pose wanted, not as a path's start).
    virtual Result<Pose> followDirect(const Coordinates &inputs, const Pose &current) const { return solveDirect(inputs, &current); }
    /// Index into variableInfo() of the named variable, or -1.
    int variableIndex(std::string_view name) const;
    /// The design parameter called `name` (parameterInfo()), or nullptr.
    const ParameterInfo *findParameter(std::string_view name) const;
    double variableValue(const Pose &pose, int variable) const;

    // -- analysis -------------------------------------------------------------------------
    virtual const ReportLayout &reportLayout() const = 0;
    /// Fills `values` (reportLayout().size doubles) for a solved pose. Never allocates.
    virtual Singularity evaluate(const Pose &pose, std::span<double> values) const = 0;
    /// The Jacobians as matrices (allocates: for analysis, not for sweeps).
    virtual Jacobians jacobians(const Pose &pose) const = 0;
    /// Facts of a pose that are words, not numbers (the O-X glide's form "X", a four-bar's
    /// Grashof class), for reports, in the group they belong to.
    virtual std::vector<ReportText> reportText(const Pose &) const { return {}; }

    /// The designs that differ from this one only in a working/assembly mode, in order of
    /// preference (poses left empty). Costly (it builds designs): callers keep the result for
    /// as long as the design lives.
    virtual std::vector<ModeAlternative> modeNeighbours() const { return {}; }
    /// The other modes the mechanism could be in at this pose: the neighbours solved at the
    /// pose's inputs (or outputs), one per label.
    std::vector<ModeAlternative> modeAlternatives(const Pose &pose) const;
    /// The same for neighbours computed before (cheap: one solve per neighbour). A neighbour
    /// whose pose is this one is dropped — unless `current`, the design the pose is in, is at a
    /// direct singularity there and the neighbour is another mode: that is where two assembly
    /// modes meet and the mechanism can go on in the other one.
    static std::vector<ModeAlternative> solveAlternatives(const std::vector<ModeAlternative> &neighbours,
                                                          const Pose &pose, const Mechanism *current = nullptr);
    /// Every real assembly mode at the inputs of `pose` (every solution of the direct
    /// kinematics in the design's working modes), `pose` among them, for `pkm eval
    /// --all-modes`. The default: `pose` and the neighbours that keep the inputs, solved there.
    virtual std::vector<Pose> assemblyModes(const Pose &pose) const;
    /// Workspace and singularity maps, for mechanisms whose outputs are a point of the plane.
    virtual const PlanarWorkspace *planarWorkspace() const { return nullptr; }
    /// The links and kinematic pairs with their axes at `pose`, for the mobility analysis
    /// (mobility.h). Every mechanism describes its real joints, actuators included.
    virtual KinematicChain kinematicChain(const Pose &pose) const = 0;

    // -- drawing --------------------------------------------------------------------------
    virtual Scene scene(const Pose &pose) const = 0;
    /// The solid model for the 3D view; the default extrudes scene() (flat links, pins, rails).
    virtual Scene3D scene3d(const Pose &pose) const;
    /// Dragging scene handle `handle` to `target` (scene plane, mm): the pose that follows.
    virtual Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const = 0;

    /// Validates `value` against the parameter's domain; the failure names it.
    static Result<double> checkDomain(const ParameterInfo &info, double value);
    /// A design made from `changes`: when a single change fails a check across parameters (a
    /// stroke order, a loop that cannot close), the failure names that change.
    static Result<MechanismPtr> blameChange(Result<MechanismPtr> made, const ParameterSet &changes);
};

/// Whether variable `i` of `mechanism` is an angle whose range is a whole turn (a crank that
/// turns fully): the two ends of its range are one pose, so neither is a limit.
bool turnsFully(const Mechanism &mechanism, int i);

/// Formats a number with up to `decimals` decimals, trailing zeros removed, always with a '.':
/// for files, JSON and keys. Sentences a person reads use text::number().
std::string formatNumber(double value, int decimals = 3);
/// A length for messages: "12.5 mm" (two decimals at most), as text::millimetres(): the
/// locale's decimal point once text hooks are installed. Not for files.
std::string formatMillimetres(double value);
/// Concatenates message parts (GCC 12 warns falsely, -Wrestrict, on chains of operator+).
std::string joinText(std::initializer_list<std::string_view> parts);

} // namespace pkm
