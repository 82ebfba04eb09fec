#pragma once
/// The pieces sheet.cpp builds a parameter sheet from, shared with the generic planar sections
/// (sheetplanar.cpp) and with the sections a kind's module adds (app/kinds/<kind>/…sheet.cpp,
/// sheet::KindSections). For other users sheet.h is the interface.

#include "scenepainter.h"
#include "export/sheet.h"

#include <span>
#include <string_view>
#include <vector>

namespace pkm {
class PlanarWorkspace;
} // namespace pkm

namespace pkm::sheet::detail {

/// The sections of a sheet while it is built, in the order of the PDF. Empty ones are left out.
struct Parts {
    Section parameters;
    Section dimensions;
    Section ranges;
    Section keyPoses;
    Section checks;
    Section capability; ///< what the actuators deliver at the sheet's pose
    Section workspace;
    Section singular;
    Section plots;
    Section drawing;
    Section notes;
};

QString utf8(std::string_view text);

/// The report of one pose (Mechanism::evaluate).
struct Evaluation {
    std::vector<double> values;
    Singularity singularity;
};
Evaluation evaluateAt(const Mechanism &mechanism, const Pose &pose);

/// A scalar report quantity as a column, an item or a cell (display unit and decimals); an
/// entry that is not in the layout gives an empty column and a NaN cell.
Column columnOf(const ReportEntry &entry);
Cell cellOf(const ReportEntry &entry, const Evaluation &evaluation);
Item itemOf(const ReportEntry &entry, const Evaluation &evaluation);
/// The value of `name` (a scalar report entry) in display units, NaN if there is none.
double displayValue(const Mechanism &mechanism, std::string_view name, const Evaluation &evaluation);

Column variableColumn(const VariableInfo &info);
Cell variableCell(const Mechanism &mechanism, const Pose &pose, int variable);

/// "none", "inverse", … as a cell with the translated word.
Cell singularityCell(SingularityType type);
QString verdictText(Verdict verdict);

/// A number for people (the PDF, sentences): `decimals` decimals in the current locale
/// (QLocale(): "116.20", Russian "116,20"), without group separators, never "-0.00".
QString numberText(double value, int decimals);
/// A display unit ("mm", "steps/s") as the current language writes it ("мм"): the unit
/// symbols of core (units.h) and the few of the sheet, marked QT_TRANSLATE_NOOP("Sheet", …).
/// The English symbol stays the key in JSON and CSV.
QString unitShown(std::string_view unit);
/// "60.00°", "116.20 mm", "0.40": a number and its unit for sentences.
QString quantityText(double value, int decimals, std::string_view unit);

/// An item of a number.
Item numberItem(std::string key, QString symbol, QString label, double value, int decimals, std::string unit);

/// A row of the key-pose table of a mechanism: its variables and the report quantities
/// `names` (scalar entries; missing ones are left out of the columns by keyPoseColumns).
std::vector<Column> keyPoseColumns(const Mechanism &mechanism, std::span<const std::string_view> names);
Row keyPoseRow(const Mechanism &mechanism, const Pose &pose, std::span<const std::string_view> names, std::string key,
    QString label);

/// Samples of report quantities over the range of one input variable, solved by direct
/// kinematics from one end to the other, each step from the last (the mechanism keeps its
/// modes); steps that cannot be solved are NaN.
/// The "capability" section (sheetcapability.cpp): what the actuators deliver at `pose`.
void addCapability(const Mechanism &mechanism, const Pose &pose, Parts &parts);
/// The actuator checks of the capability section (sheetactuatorchecks.cpp): the design's load
/// within every actuator's limit at the pose, and each stated requirement at the pose and over
/// the workspace.
void addActuatorChecks(const Mechanism &mechanism, const Pose &pose,
                       const std::vector<capability::Requirement> &requirements, Parts &parts);

struct Sweep {
    std::vector<double> input; ///< display unit
    std::vector<Pose> poses; ///< empty Pose (no inputs) where a step failed
    std::vector<Evaluation> evaluations;
};
Sweep sweepInput(const Mechanism &mechanism, int variable, int steps);
/// A plot of report quantity `name` from a sweep over `variable`.
Figure sweepPlot(const Mechanism &mechanism, const Pose &pose, int variable, const Sweep &sweep, std::string_view name,
    std::string key, QString title);
/// An axis range over `values` with a little headroom; never below 0 when no value is.
std::pair<double, double> valueAxis(const std::vector<double> &values);

/// The box the dimensioned drawing of `scene` covers on paper at `ratio` paper mm per mm —
/// the mechanism with its labels, dimensions and arcs, which keep their size on paper — in
/// paper mm with the scene's origin at (0, 0), y up. None without a QGuiApplication (fonts).
std::optional<Eigen::AlignedBox2d> drawnBounds(const Scene &scene, double ratio);
/// The style the sheet's drawing uses, for a device of `unitsPerMillimetre`.
SceneStyle drawingStyle(double unitsPerMillimetre);
/// The dimensioned drawing of `pose` at the largest standard scale that fits A4
/// (sheetdrawing.cpp); `poseDescription` names the pose in its caption.
void addDrawing(const Mechanism &mechanism, const Pose &pose, const QString &poseDescription, Parts &parts);

/// The scalar report entries among `names`, in the order given: the columns of a table.
std::vector<const ReportEntry *> reportEntries(const Mechanism &mechanism, std::span<const std::string_view> names);
/// A row of a table of report entries at `pose`.
Row reportRow(const Mechanism &mechanism, const Pose &pose, const std::vector<const ReportEntry *> &columns,
    std::string key, QString label, bool highlight = false);

/// Workspace, singular poses and strokes of a mechanism whose outputs are a point of the plane
/// (MOMA, the O-X glide, the five-bar, any new one), with the areas its workspace knows exactly
/// (PlanarWorkspace::exactAreas) beside the grid's.
void addPlanar(const Mechanism &mechanism, const PlanarWorkspace &workspace, const Pose &pose, Parts &parts);

} // namespace pkm::sheet::detail
