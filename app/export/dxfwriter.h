#pragma once
/// DXF drawings of a linkage for CAD programs: our own small writer of AutoCAD R12 (AC1009)
/// ASCII DXF — no third-party code — and the drawing of a Scene with it. Plain C++ (Eigen for
/// the scene's points, no Qt): `pkm dxf` and the GUI's File ▸ Export Drawing (DXF)… share it.
///
/// The file: a HEADER ($ACADVER AC1009, $INSUNITS 4 = mm, $EXTMIN/$EXTMAX of what is drawn),
/// TABLES (VPORT *ACTIVE fitted to the drawing; LTYPE CONTINUOUS, DASHED and CENTER; one
/// LAYER per role, each with its own ACI colour; STYLE STANDARD), an empty BLOCKS section and
/// the ENTITIES: LINE, CIRCLE, ARC, SOLID (arrowheads), POLYLINE/VERTEX/SEQEND and TEXT.
///
/// Text: R12 text is in a code page, so every character outside printable ASCII is written as
/// AutoCAD's \U+XXXX escape (θ → \U+03B8, П → \U+041F, ₁ → \U+2081), which AutoCAD, BricsCAD,
/// LibreCAD and ezdxf decode; °, ± and ⌀ become the DXF control codes %%d, %%p and %%c. A
/// backslash, '^' and '%' are escaped the same way so that they never start a control
/// sequence; control characters become spaces; characters beyond U+FFFF and malformed UTF-8
/// become '?'.
///
/// Numbers: locale-independent ('.' whatever LC_NUMERIC says), fixed-point with up to 10
/// decimals (0.1 nm: far below any machining tolerance, and exact for the checks' 1e-6 mm).

#include "scene.h"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace pkm::dxf {

/// The layers of a linkage drawing, one per role.
inline constexpr const char *layerGround = "GROUND"; ///< the frame: ground links, ground symbols
inline constexpr const char *layerLinks = "LINKS"; ///< bars: centre line joint to joint, outline
inline constexpr const char *layerActuators = "ACTUATORS"; ///< motor bodies, screws, their axes
inline constexpr const char *layerGuides = "GUIDES"; ///< rails: axis, edges, end stops, hatching
inline constexpr const char *layerJoints = "JOINTS"; ///< pin circles, slider carriages, points
inline constexpr const char *layerDimensions = "DIMENSIONS"; ///< dimensions and angle arcs with their text
inline constexpr const char *layerText = "TEXT"; ///< names of joints, links, guides; the caption
inline constexpr const char *layerPaths = "PATHS"; ///< coupler curves, trajectories

/// A layer: its name and AutoCAD Color Index.
struct LayerInfo {
    const char *name;
    int colour;
};
/// Every layer of a linkage drawing with its colour: GROUND 8 (grey), LINKS 5 (blue),
/// ACTUATORS 30 (orange), GUIDES 4 (cyan), JOINTS 250 (near black), DIMENSIONS 3 (green),
/// TEXT 7 (black on white, white on black), PATHS 1 (red).
const std::vector<LayerInfo> &linkageLayers();

/// `value` as a DXF real: fixed-point, '.' as separator, at most 10 decimals, at least one
/// ("160.0", "-0.3333333333"); -0 and values that round to 0 are "0.0". The caller keeps
/// non-finite values out.
std::string formatReal(double value);

/// UTF-8 `text` as the ASCII text of an R12 TEXT entity (see the file comment).
std::string encodeText(std::string_view text);

/// Text alignment of TEXT (group codes 72 and 73).
enum class HAlign { Left = 0, Center = 1, Right = 2 };
enum class VAlign { Baseline = 0, Bottom = 1, Middle = 2, Top = 3 };

/// An R12 ASCII DXF file built entity by entity; finish() gives the whole file. Entities with
/// a non-finite coordinate or size are left out (and counted).
class Writer
{
public:
    /// Adds a layer to the LAYER table ("0" is always there).
    void addLayer(std::string name, int colour, std::string linetype = "CONTINUOUS");
    /// The DASHED and CENTER line types' pattern is scaled so that one period is `period` mm.
    void setLinetypePeriod(double period);
    /// The default text height of the drawing ($TEXTSIZE).
    void setTextSize(double height);
    /// A comment (group 999) at the top of the file; ASCII-encoded like text.
    void setComment(std::string_view comment);

    /// `linetype` empty: the layer's (BYLAYER).
    void line(const char *layer, const Eigen::Vector2d &a, const Eigen::Vector2d &b, const char *linetype = nullptr);
    void circle(const char *layer, const Eigen::Vector2d &centre, double radius);
    /// Counter-clockwise from `startDegrees` to `endDegrees`.
    void arc(const char *layer, const Eigen::Vector2d &centre, double radius, double startDegrees, double endDegrees);
    /// A filled triangle or quadrilateral (SOLID; a triangle repeats its third corner).
    void solid(const char *layer, const Eigen::Vector2d &a, const Eigen::Vector2d &b, const Eigen::Vector2d &c,
        const Eigen::Vector2d &d);
    /// POLYLINE with VERTEX and SEQEND; at least two points.
    void polyline(
        const char *layer, const std::vector<Eigen::Vector2d> &points, bool closed, const char *linetype = nullptr);
    /// TEXT of `height` at `position` (its alignment point), rotated counter-clockwise by
    /// `rotationDegrees`; `text` is UTF-8 and is encoded by encodeText().
    void text(const char *layer, const Eigen::Vector2d &position, double height, std::string_view text,
        double rotationDegrees = 0.0, HAlign horizontal = HAlign::Left, VAlign vertical = VAlign::Baseline);

    /// The whole file: HEADER, TABLES, BLOCKS, ENTITIES, EOF.
    std::string finish() const;

    int entityCount() const { return m_count; }
    /// Entities left out for a non-finite coordinate.
    int skippedCount() const { return m_skipped; }
    /// The box of everything drawn so far (text estimated from its length and height);
    /// empty when nothing is.
    const Eigen::AlignedBox2d &extents() const { return m_box; }

private:
    bool finite(std::initializer_list<Eigen::Vector2d> points, std::initializer_list<double> values = {});
    void begin(const char *type, const char *layer, const char *linetype = nullptr);
    void group(int code, std::string_view value);
    void real(int code, double value);
    void point(int code, const Eigen::Vector2d &p);

    struct Layer {
        std::string name;
        int colour;
        std::string linetype;
    };
    std::vector<Layer> m_layers;
    std::string m_entities;
    std::string m_comment;
    Eigen::AlignedBox2d m_box;
    double m_period = 10.0;
    double m_textSize = 2.5;
    int m_count = 0;
    int m_skipped = 0;
};

/// How a Scene is drawn; zero sizes are chosen from the scene's size.
struct DrawingOptions {
    std::string caption; ///< a line of text under the drawing ("pjoint-prototype — θ = 30.00°"), UTF-8
    bool barOutlines = true; ///< each link's outline (two lines and end arcs) around its centre line
    double textHeight = 0.0; ///< mm; 0: an ISO 3098 height about 1/50 of the drawing's size
    double pinRadius = 0.0; ///< mm; 0: about 1/100 of the drawing's size, at most 1/5 of the shortest link
};

/// What sceneDrawing() produced.
struct Drawing {
    std::string dxf; ///< the file
    int entities = 0;
    int skipped = 0; ///< elements left out because a coordinate is not finite
    Eigen::AlignedBox2d extents; ///< $EXTMIN/$EXTMAX, mm
};

/// The DXF drawing of `scene`, in mm, y up, in the scene's own frame (the joints' coordinates
/// are the drawing's): what the 2D view draws, as CAD geometry on the linkage layers —
///  - LINKS: a LINE from joint to joint for every link, plus its outline (barOutlines);
///    ground links (the frame) on GROUND;
///  - JOINTS: a CIRCLE (pin) at every joint — revolute, ground and slider joints at the pin
///    radius, a spherical joint with a small inner circle, a point (a coupler or reference
///    point) at half the radius — and the carriage of a slider on a guide as a rectangle;
///  - GROUND: under each ground pivot the ground symbol, a triangle with a hatched base;
///  - GUIDES: each rail's axis (CENTER), its two edges, end stops and hatching on the ground
///    side (away from the links leaving it, as the 2D view);
///  - ACTUATORS: the motor body as a closed rectangle, the screw's two edges, the axis (CENTER);
///  - DIMENSIONS: per SceneDimension a dimension line as long as the distance between its two
///    joints, at the scene's offset with extension lines (without an offset — the 2D view
///    then writes only the text beside the member — on the member's axis from joint to
///    joint), two arrowheads (SOLID) and a TEXT "name = 160.00": the measured distance in mm,
///    the name taken from the scene's text (a negative value there — MOMA's p₁ — keeps its
///    sign); per SceneAngle an ARC with an arrowhead, dashed legs where no link shows the
///    angle's sides, and its label;
///  - TEXT: the names of joints, links, guides and actuators, and the caption;
///  - PATHS: each polyline (a coupler curve) as a POLYLINE, split where a point is not finite.
/// Texts are centred (TEXT alignment middle-centre) where they cover the least of what is drawn
/// and written before them: a small label layout, in the spirit of the 2D view's. A free point
/// (JointKind::Point used by no link, dimension or angle — the four-bar's instant centre) that
/// lies far outside the scene's extent is left out rather than stretch the drawing.
Drawing sceneDrawing(const Scene &scene, const DrawingOptions &options = {});

/// The text of a dimension between two joints `distance` mm apart, from the scene's text
/// ("a = 170.0 mm" → "a = 170.00"): the name before '=' and the distance with 2 decimals;
/// the sign of the scene's number is kept when its magnitude is the distance.
std::string dimensionText(std::string_view sceneText, double distance);

} // namespace pkm::dxf
