#pragma once
/// The O-X glide hybrid mechanism (docs/mathematics.md): a planar parallel mechanism carried by a
/// serial longitudinal axis. Four rods of length l join a platform of width s (spherical
/// joints) to four sliders (revolute joints); the sliders run on four transverse guides of
/// length L stacked a apart, and are rigidly paired, AB and CD, so the planar mechanism has
/// two inputs x_AB, x_CD. Vertical compensation elements on the lower sliders bring every rod
/// joint into the plane y = 0, so the rods are alike and the pairs can pass each other: the
/// mechanism works extended (O) or crossed (X). The whole planar mechanism rides the
/// longitudinal guides (z), so the 3D workspace is the planar one extruded along z.
///
/// Frame: x along the transverse guides (slider positions 0…L), y from the rod-joint plane
/// towards the platform, z along the longitudinal guides. The platform centre T = (x, y) is
/// the planar output; w = √(l² − y²).
///   O form: x_AB = x − s/2 − w, x_CD = x + s/2 + w   (the rods splay outwards)
///   X form: x_AB = x − s/2 + w, x_CD = x + s/2 − w   (the rods cross once w > s/2)
///   direct, both forms: x = (x_AB + x_CD)/2, y = ½·√(4l² − (x_CD − x_AB − s)²)
/// The document prints "+ s" in the X form's direct kinematics, which contradicts its own
/// inverse kinematics (docs/mathematics.md): the form follows from the sign of x_CD − x_AB − s.
///
/// The form is a design parameter (`mode`, +1 O, −1 X): a pose of the design is always in it,
/// so the sliders never pass x_CD − x_AB = s (rods parallel and perpendicular to the guides,
/// where the platform can swing: a combined singularity) without the user asking.
///
/// Velocities: f_i = (x ∓ s/2 − x_i)² + y² − l² = 0; J_q·q̇ + J_x·ẋ = 0 with
/// J_q = diag(−2u₁, −2u₂), u₁ = x − s/2 − x_AB, u₂ = x + s/2 − x_CD, and J_x rows (2u_i, 2y);
/// q̇ = J·ẋ with J = −J_q⁻¹·J_x = [1, y/u₁; 1, y/u₂], det J = −2y/w (O) or +2y/w (X),
/// κ(J) = max(y/w, w/y). Units: mm, rad.

#include "actuatorparameters.h"

#include <array>
#include "planarworkspace.h"

namespace pkm {

struct OxGlideDesign {
    double rod = 80.0;          ///< l, mm
    double width = 20.0;        ///< s, platform width, mm
    double guideLength = 130.0; ///< L: slider positions 0…L, mm
    double spacing = 15.0;      ///< a: distance between neighbouring transverse guides, mm
    double zMin = 0.0;          ///< longitudinal travel, mm
    double zMax = 150.0;
    int form = +1;              ///< +1: extended (O), −1: crossed (X)
    /// The actuators of the slider pairs AB and CD (the serial z axis moves the whole mechanism and is left out) (assumed: the documents give none; actuatorparameters.h)
    std::array<ActuatorSpec, 2> actuators = {assumedLinear, assumedLinear};
    LoadSpec load; ///< the load whose deflection the capability group reports
};

namespace oxglide {
constexpr int formO = +1;
constexpr int formX = -1;
/// How far from the O↔X crossing (x_CD − x_AB = s, the rods parallel: a combined singularity)
/// a drag of a slider pair and the GUI's crossing animation stop: w/l, with w = |x_CD − x_AB − s|/2
/// the run of a rod along the guides. 0.05: the rods at about 87° to the guides.
constexpr double crossingStopMargin = 0.05;
/// "O" or "X".
const char *formName(int form);
/// "extended (O)" or "crossed (X)": English source, QT_TRANSLATE_NOOP("core", …).
const char *formTitle(int form);

/// The document's direct kinematics with the corrected sign, no limits checked: the platform
/// centre and the form the slider positions hold (+1 O, −1 X, 0 exactly at the crossing).
/// `valid` is false when the rods cannot reach each other (|x_CD − x_AB − s| > 2l).
struct DirectSolution {
    Eigen::Vector2d platform = Eigen::Vector2d::Zero();
    int form = 0;
    bool valid = false;
};
DirectSolution direct(double rod, double width, double xAB, double xCD);
/// The inverse kinematics of one form, no limits checked: (x_AB, x_CD); y must be in [−l, l].
Eigen::Vector2d inverse(double rod, double width, int form, const Eigen::Vector2d &platform);

/// The exact area (mm²) of the planar workspace of one form: the slider positions in [0, L]
/// and y in (0, l]. Integrates the width of each horizontal slice in closed form.
double exactArea(const OxGlideDesign &design, int form);
} // namespace oxglide

class OxGlide final : public TabledMechanism<OxGlide, OxGlideDesign>, public PlanarWorkspace
{
public:
    /// Validates the design; the failure names the culprit (s ≥ 2l, L ≤ s, z_min ≥ z_max…).
    static Result<MechanismPtr> create(const OxGlideDesign &design);
    /// The parameters and the design fields they read and write (createFrom(): missing values
    /// take the prototype's).
    static const ParameterTable<OxGlideDesign> &table();

    const OxGlideDesign &design() const { return m_design; }

    std::string_view kind() const override { return "oxglide"; }

    const std::vector<VariableInfo> &variableInfo() const override;
    Interval variableRange(int variable) const override;
    Pose homePose() const override { return m_home; }
    /// The inputs are x_AB, x_CD and z; the slider positions must hold the design's form.
    Result<Pose> solveDirect(const Coordinates &inputs, const Pose *near = nullptr) const override;
    /// The outputs are x, y; z is kept from `near` (else the home pose's).
    Result<Pose> solveInverse(const Coordinates &outputs, const Pose *near = nullptr) const override;

    const ReportLayout &reportLayout() const override;
    Singularity evaluate(const Pose &pose, std::span<double> values) const override;
    Jacobians jacobians(const Pose &pose) const override;
    std::vector<ReportText> reportText(const Pose &pose) const override;
    /// The other form at the same platform position.
    std::vector<ModeAlternative> modeNeighbours() const override;
    /// The hybrid as built, in the frame of scene3d(): ground, the longitudinal carriage
    /// (actuated prismatic z), the slider pairs AB and CD (actuated prismatic x on the
    /// carriage), four rods hinged to them (revolute, axis z, in the rod planes z + (k − 1.5)·a
    /// for the guides D, A, B, C) and the platform on four spherical joints. Spatial: the
    /// rank, not a formula, gives its mobility (mobility.h).
    KinematicChain kinematicChain(const Pose &pose) const override;
    const PlanarWorkspace *planarWorkspace() const override { return this; }

    Scene scene(const Pose &pose) const override;
    Scene3D scene3d(const Pose &pose) const override;
    /// Handle 0 (the platform centre T) solves the inverse problem; handles 1 and 2 (the rod
    /// joints of the pairs AB and CD) move a slider pair along the guides.
    Result<Pose> dragHandle(const Pose &current, int handle, const Eigen::Vector2d &target) const override;

    Singularity singularity(const Pose &pose) const;
    /// The slider positions at which the current form meets the other one for a platform at x:
    /// x_AB = x − s/2, x_CD = x + s/2 (rods parallel, y = l).
    Eigen::Vector2d crossingInputs(double x) const;

    // PlanarWorkspace: the workspace of the design's form.
    Eigen::AlignedBox2d workspaceBounds() const override { return m_bounds; }
    void fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                    std::span<float> margins) const override;
    bool fillsCapabilityRows() const override { return true; }
    void fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                           std::span<float> values, std::span<float> margins) const override;
    std::vector<SingularCurve> singularCurves() const override;
    /// This form's area and both forms', integrated in closed form (oxglide::exactArea).
    std::vector<ExactArea> exactAreas() const override;
    std::string singularityMeaning(SingularCurve::Type type) const override
    {
        return type == SingularCurve::Type::Inverse ? QT_TRANSLATE_NOOP("core", "rods ⟂ guides")
                                                    : QT_TRANSLATE_NOOP("core", "rods along the guides");
    }
    /// A box holding the workspaces of both forms (the X form's holds the O form's).
    Eigen::AlignedBox2d unionBounds() const;

    static constexpr int variableXAB = 0;
    static constexpr int variableXCD = 1;
    static constexpr int variableZ = 2;
    static constexpr int variableX = 3;
    static constexpr int variableY = 4;
    static constexpr double singularTolerance = 1e-7;

private:
    explicit OxGlide(const OxGlideDesign &design);
    Result<Pose> inverse(const Eigen::Vector2d &platform, double z) const;
    Eigen::AlignedBox2d formBounds(int form) const;

    OxGlideDesign m_design;
    Eigen::AlignedBox2d m_bounds;
    Pose m_home;
};

} // namespace pkm
