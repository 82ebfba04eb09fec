#include "export/dxfwriter.h"

#include "drawlist.h"
#include "scenelabels.h"
#include "scenelayout.h"
#include "scenestyle.h"

#include <QFontMetricsF>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

// The DXF medium of the drawing pipeline: it picks the zoom at which the screen's layout
// becomes a drawing with ISO text heights, and writes each primitive as R12 entities. Where
// things go is the layout's decision alone (scenelayout.h).

namespace pkm::dxf {

namespace {

using Vec = Eigen::Vector2d;

/// The largest ISO 3098 text height not above `wanted` (1.8 mm at least).
double isoTextHeight(double wanted)
{
    constexpr std::array<double, 14> heights = {1.8, 2.5, 3.5, 5, 7, 10, 14, 20, 28, 40, 56, 80, 112, 160};
    if (!(wanted > heights.front()))
        return heights.front();
    if (wanted >= heights.back())
        return std::floor(wanted);
    double chosen = heights.front();
    for (const double height : heights) {
        if (height <= wanted)
            chosen = height;
    }
    return chosen;
}

/// The size of the drawing, mm: of the range of motion, so that every pose of a design gets the
/// same text height; without one, of the joints and guides.
double drawingSize(const Scene &scene)
{
    Eigen::AlignedBox2d box;
    const auto add = [&box](const Eigen::Vector3d &p) {
        if (p.head<2>().allFinite())
            box.extend(Vec(p.head<2>()));
    };
    if (!scene.extent.isEmpty() && scene.extent.min().head<2>().allFinite() && scene.extent.max().head<2>().allFinite()) {
        add(scene.extent.min());
        add(scene.extent.max());
    } else {
        for (const SceneJoint &joint : scene.joints)
            add(joint.position);
        for (const SceneGuide &guide : scene.guides) {
            add(guide.start);
            add(guide.end);
        }
    }
    return box.isEmpty() ? 100.0 : std::max(box.sizes().maxCoeff(), 1e-3);
}

const char *layerName(drawing::Layer layer)
{
    switch (layer) {
    case drawing::Layer::Ground:
        return layerGround;
    case drawing::Layer::Links:
        return layerLinks;
    case drawing::Layer::Actuators:
        return layerActuators;
    case drawing::Layer::Guides:
        return layerGuides;
    case drawing::Layer::Joints:
        return layerJoints;
    case drawing::Layer::Dimensions:
        return layerDimensions;
    case drawing::Layer::Text:
        return layerText;
    case drawing::Layer::Paths:
        return layerPaths;
    }
    return layerLinks;
}

const char *lineType(drawing::Dash dash)
{
    switch (dash) {
    case drawing::Dash::Solid:
        return nullptr;
    case drawing::Dash::Dashed:
    case drawing::Dash::Ghost:
        return "DASHED";
    case drawing::Dash::Centre:
        return "CENTER";
    }
    return nullptr;
}

/// Writes primitives in millimetres: device points through the layout's mapping.
class Serialiser
{
public:
    Serialiser(Writer &writer, const ViewMapping &mapping, const DrawingOptions &options)
        : m_writer(writer)
        , m_mapping(mapping)
        , m_options(options)
    {
    }

    void write(const drawing::Primitive &item)
    {
        if (!drawing::shownInCad(item.medium))
            return;
        const char *layer = layerName(item.layer);
        std::visit([this, layer](const auto &shape) { write(layer, shape); }, item.shape);
    }

private:
    Vec mm(const QPointF &device) const { return m_mapping.toScene(device); }
    double mm(double device) const { return device / m_mapping.scale; }

    void line(const char *layer, const QPointF &a, const QPointF &b, const char *type = nullptr)
    {
        m_writer.line(layer, mm(a), mm(b), type);
    }
    void arrow(const char *layer, const QPointF &tip, const QPointF &direction, const drawing::ArrowShape &head)
    {
        // a plain triangle: R12 fills a SOLID, but not its notch
        const std::array<QPointF, 4> corners = drawing::arrowCorners(tip, direction, head);
        m_writer.solid(layer, mm(corners[0]), mm(corners[1]), mm(corners[3]), mm(corners[3]));
    }

    void write(const char *layer, const drawing::Lines &lines)
    {
        for (const QLineF &l : lines.lines)
            line(layer, l.p1(), l.p2(), lineType(lines.pen.dash));
    }
    void write(const char *layer, const drawing::Band &band)
    {
        const QPointF d = band.b - band.a;
        const double length = std::hypot(d.x(), d.y());
        const QPointF n = length > 0.0 ? QPointF(d.y(), -d.x()) * (0.5 * band.width / length) : QPointF();
        m_writer.polyline(layer, {mm(band.a + n), mm(band.b + n), mm(band.b - n), mm(band.a - n)}, true);
    }
    void write(const char *layer, const drawing::Member &member)
    {
        line(layer, member.a, member.b); // the centre line: exactly the link's length
        const QPointF d = member.b - member.a;
        const double length = std::hypot(d.x(), d.y());
        if (!m_options.barOutlines || !(member.width > 0.0) || length <= member.trimA + member.trimB)
            return;
        const QPointF u = d / length, n = QPointF(u.y(), -u.x()) * (0.5 * member.width);
        const QPointF from = member.a + member.trimA * u, to = member.b - member.trimB * u;
        line(layer, from + n, to + n);
        line(layer, from - n, to - n);
    }
    void write(const char *layer, const drawing::Polygon &polygon)
    {
        std::vector<Vec> points;
        points.reserve(std::size_t(polygon.points.size()));
        for (const QPointF &p : polygon.points)
            points.push_back(mm(p));
        if (points.size() >= 2)
            m_writer.polyline(layer, points, polygon.closed, lineType(polygon.pen.dash));
    }
    void write(const char *layer, const drawing::Circle &circle)
    {
        m_writer.circle(layer, mm(circle.centre), mm(circle.radius));
    }
    void write(const char *layer, const drawing::Arc &arc)
    {
        // scene angles are the drawing's: counter-clockwise, y up
        const double end = arc.start + arc.sweep;
        constexpr double toDegrees = 180.0 / 3.14159265358979323846;
        m_writer.arc(layer, mm(arc.centre), mm(arc.radius), std::min(arc.start, end) * toDegrees,
            std::max(arc.start, end) * toDegrees);
        if (arc.arrow) {
            const auto [tip, direction] = drawing::arcArrow(arc);
            arrow(layer, tip, direction, arc.head);
        }
    }
    void write(const char *layer, const drawing::DimensionLine &dimension)
    {
        const QPointF d = dimension.to - dimension.from;
        const double span = std::hypot(d.x(), d.y());
        if (!(span > 0.0))
            return;
        const QPointF u = d / span;
        if (dimension.gap > 0.0 && dimension.gap < span) {
            const QPointF middle = 0.5 * (dimension.from + dimension.to);
            line(layer, dimension.from, middle - 0.5 * dimension.gap * u);
            line(layer, middle + 0.5 * dimension.gap * u, dimension.to);
        } else {
            line(layer, dimension.from, dimension.to);
        }
        const double pointing = dimension.arrowsInside ? 1.0 : -1.0;
        if (!dimension.arrowsInside) {
            line(layer, dimension.from - dimension.tail * u, dimension.from);
            line(layer, dimension.to, dimension.to + dimension.tail * u);
        }
        arrow(layer, dimension.from, -pointing * u, dimension.head);
        arrow(layer, dimension.to, pointing * u, dimension.head);
    }
    void write(const char *layer, const drawing::Text &text)
    {
        const double height = mm(QFontMetricsF(text.font).capHeight());
        const std::string content = text.cad.empty() ? text.text.toStdString() : text.cad;
        // QPainter turns clockwise on screen (y down); DXF counter-clockwise (y up)
        const double rotation = text.rotationDegrees == 0.0 ? 0.0 : -text.rotationDegrees;
        m_writer.text(layer, mm(text.centre), height, content, rotation, HAlign::Center, VAlign::Middle);
    }

    Writer &m_writer;
    const ViewMapping &m_mapping;
    const DrawingOptions &m_options;
};

} // namespace

DrawingLayout drawingLayout(const Scene &scene, const DrawingOptions &options)
{
    // The zoom at which the screen's text (its capital height) is an ISO text height of about
    // 1/50 of the drawing, and every symbol keeps its proportion to the text.
    DrawingLayout result;
    result.textHeight = options.textHeight > 0.0 ? options.textHeight : isoTextHeight(drawingSize(scene) / 50.0);
    SceneStyle style;
    style.pixelSize = 1.0;
    style.showHandles = false;
    const double capHeight = QFontMetricsF(detail::labelFont(style.fontPixels, false)).capHeight();
    result.mapping.scale = (capHeight > 0.0 ? capHeight : 0.7 * style.fontPixels) / result.textHeight;
    drawing::LayoutOptions layout;
    layout.farPointMargin = 0.5;
    result.list = drawing::layoutScene(scene, result.mapping, style, layout);
    drawing::addCaption(result.list, QString::fromStdString(options.caption), style);
    return result;
}

Drawing sceneDrawing(const Scene &scene, const DrawingOptions &options)
{
    const DrawingLayout layout = drawingLayout(scene, options);
    Writer writer;
    for (const LayerInfo &layer : linkageLayers())
        writer.addLayer(layer.name, layer.colour);
    writer.setTextSize(layout.textHeight);
    writer.setLinetypePeriod(std::max(4.0 * layout.textHeight, 1.0));
    writer.setComment("PKM Studio linkage drawing, DXF R12, mm");
    Serialiser serialiser(writer, layout.mapping, options);
    for (const drawing::Primitive &item : layout.list.items)
        serialiser.write(item);

    Drawing drawing;
    drawing.dxf = writer.finish();
    drawing.entities = writer.entityCount();
    drawing.skipped = writer.skippedCount() + layout.list.skipped;
    drawing.extents = writer.extents();
    return drawing;
}

} // namespace pkm::dxf
