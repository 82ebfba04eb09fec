#pragma once
/// DXF drawings of a linkage for CAD programs: our own small writer of AutoCAD R12 (AC1009)
/// ASCII DXF — no third-party code — and the drawing of a Scene with it. The Writer is plain
/// C++; sceneDrawing() (dxfdrawing.cpp) serialises the scene's one layout (pkm_drawing), so the
/// DXF shows what the screen shows, labels where the screen puts them. `pkm dxf` and the GUI's
/// File ▸ Export Drawing (DXF)… share it.
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

#include "drawlist.h"
#include "scene.h"
#include "scenestyle.h"

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

/// How a Scene is drawn.
struct DrawingOptions {
    std::string caption; ///< a line of text under the drawing ("pjoint-prototype — θ = 30.00°"), UTF-8
    bool barOutlines = true; ///< each link's edges beside its centre line
    double textHeight = 0.0; ///< mm; 0: an ISO 3098 height about 1/50 of the drawing's size
};

/// What sceneDrawing() produced.
struct Drawing {
    std::string dxf; ///< the file
    int entities = 0;
    int skipped = 0; ///< elements left out because a coordinate is not finite
    Eigen::AlignedBox2d extents; ///< $EXTMIN/$EXTMAX, mm
};

/// What sceneDrawing() writes: the scene laid out at the DXF's zoom (the caption included),
/// and that zoom: `mapping` takes the list's device units to the drawing's mm.
struct DrawingLayout {
    drawing::DrawList list;
    ViewMapping mapping;
    double textHeight = 0.0; ///< mm
};
DrawingLayout drawingLayout(const Scene &scene, const DrawingOptions &options = {});

/// The DXF drawing of `scene`, in mm, y up, in the scene's own frame (the joints' coordinates
/// are the drawing's). The scene is laid out as on the screen, at the zoom at which the
/// screen's text is `textHeight` tall, and every primitive becomes CAD geometry on the linkage
/// layers:
///  - LINKS: a LINE from joint to joint for every link (exactly its length), and its edges
///    outside the pins (barOutlines); ground links (the frame) on GROUND;
///  - JOINTS: a CIRCLE (pin) at every joint — a spherical joint with a small inner circle, a
///    point (a coupler or reference point) at half the radius — and carriages as rectangles;
///  - GROUND: the ground symbol under each ground pivot, a triangle with a hatched base;
///  - GUIDES: each rail's axis (CENTER), edges, end stops and hatching;
///  - ACTUATORS: the motor body's and the screw's outlines and the axis (CENTER);
///  - DIMENSIONS: every dimension line with its arrowheads (SOLID), whose tips are exactly the
///    measured distance apart, broken where its text sits on it, with extension lines; a
///    dimension along a member also as a dimension line on the member's axis; the text states
///    the measured distance ("a = 170.00", dimensionText()); every angle an ARC of its whole
///    sweep with an arrowhead, dashed legs where no link shows its sides, and its label;
///  - TEXT: the names of joints, links, guides and actuators, and the caption;
///  - PATHS: each polyline (a coupler curve) as a POLYLINE, split where a point is not finite.
/// Texts are TEXT entities centred (middle-centre) where the screen's label layout put them.
/// A free point (an instantaneous centre) far outside the range of motion is left out rather
/// than stretch the drawing.
Drawing sceneDrawing(const Scene &scene, const DrawingOptions &options = {});

} // namespace pkm::dxf
