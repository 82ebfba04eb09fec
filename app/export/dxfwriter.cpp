#include "export/dxfwriter.h"
#include "mechanism.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <system_error>

// The reference for everything written here is the AutoCAD Release 12 DXF specification:
// group codes right-aligned in three columns, one value per line, LF line ends (which every
// reader accepts), no handles ($HANDLING 0), so no object or class sections are needed.

namespace pkm::dxf {

namespace {

using Vec = Eigen::Vector2d;
constexpr double pi = std::numbers::pi;

void appendGroup(std::string &out, int code, std::string_view value)
{
    char buffer[16];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, code);
    const std::size_t digits = static_cast<std::size_t>(result.ptr - buffer);
    if (digits < 3)
        out.append(3 - digits, ' ');
    out.append(buffer, digits).append("\n").append(value).append("\n");
}

/// The number of glyphs an encoded text shows: an escape \U+XXXX or %%d is one.
std::size_t glyphCount(std::string_view encoded)
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < encoded.size(); ++count) {
        if (encoded.compare(i, 3, "\\U+") == 0 && i + 7 <= encoded.size())
            i += 7;
        else if (encoded.compare(i, 2, "%%") == 0 && i + 3 <= encoded.size())
            i += 3;
        else
            ++i;
    }
    return count;
}

void appendEscape(std::string &out, char32_t codePoint)
{
    constexpr const char *hex = "0123456789ABCDEF";
    out.append("\\U+");
    for (int shift = 12; shift >= 0; shift -= 4)
        out.push_back(hex[(codePoint >> shift) & 0xF]);
}

} // namespace

const std::vector<LayerInfo> &linkageLayers()
{
    static const std::vector<LayerInfo> layers = {
        {layerGround, 8},
        {layerLinks, 5},
        {layerActuators, 30},
        {layerGuides, 4},
        {layerJoints, 250},
        {layerDimensions, 3},
        {layerText, 7},
        {layerPaths, 1},
    };
    return layers;
}

std::string formatReal(double value)
{
    if (!(std::abs(value) >= 5e-11))
        return "0.0"; // also -0 and the tiny values that would print as -0.0000000000
    char buffer[400]; // the largest double has 309 digits before the point
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 10);
    if (result.ec != std::errc())
        return "0.0";
    std::string text(buffer, result.ptr);
    const std::size_t point = text.find('.');
    if (point == std::string::npos)
        return text.append(".0");
    while (text.size() > point + 2 && text.back() == '0')
        text.pop_back();
    return text;
}

std::string encodeText(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        std::size_t length = 1;
        char32_t codePoint = byte;
        char32_t least = 0;
        if (byte >= 0x80) {
            if ((byte & 0xE0) == 0xC0) {
                length = 2;
                codePoint = byte & 0x1F;
                least = 0x80;
            } else if ((byte & 0xF0) == 0xE0) {
                length = 3;
                codePoint = byte & 0x0F;
                least = 0x800;
            } else if ((byte & 0xF8) == 0xF0) {
                length = 4;
                codePoint = byte & 0x07;
                least = 0x10000;
            } else {
                out.push_back('?'); // a continuation byte without a lead, or an invalid byte
                ++i;
                continue;
            }
            bool valid = i + length <= text.size();
            for (std::size_t k = 1; valid && k < length; ++k) {
                const auto next = static_cast<unsigned char>(text[i + k]);
                valid = (next & 0xC0) == 0x80;
                codePoint = (codePoint << 6) | (next & 0x3F);
            }
            if (!valid || codePoint < least || (codePoint >= 0xD800 && codePoint <= 0xDFFF) || codePoint > 0x10FFFF) {
                out.push_back('?');
                ++i; // resynchronise on the next byte
                continue;
            }
        }
        i += length;
        if (codePoint < 0x20 || codePoint == 0x7F || (codePoint >= 0x80 && codePoint < 0xA0))
            out.push_back(' ');
        else if (codePoint == U'\\' || codePoint == U'^' || codePoint == U'%')
            appendEscape(out, codePoint); // never the start of a control sequence
        else if (codePoint < 0x80)
            out.push_back(static_cast<char>(codePoint));
        else if (codePoint == 0xB0) // °
            out.append("%%d");
        else if (codePoint == 0xB1) // ±
            out.append("%%p");
        else if (codePoint == 0x2300) // ⌀
            out.append("%%c");
        else if (codePoint <= 0xFFFF)
            appendEscape(out, codePoint);
        else
            out.push_back('?'); // \U+ takes four hex digits: no room beyond the BMP
    }
    return out;
}

// -- Writer ------------------------------------------------------------------------------

void Writer::addLayer(std::string name, int colour, std::string linetype)
{
    m_layers.push_back({std::move(name), colour, std::move(linetype)});
}

void Writer::setLinetypePeriod(double period)
{
    if (std::isfinite(period) && period > 0.0)
        m_period = period;
}

void Writer::setTextSize(double height)
{
    if (std::isfinite(height) && height > 0.0)
        m_textSize = height;
}

void Writer::setComment(std::string_view comment)
{
    m_comment = encodeText(comment);
}

bool Writer::finite(std::initializer_list<Vec> points, std::initializer_list<double> values)
{
    const bool ok = std::all_of(points.begin(), points.end(), [](const Vec &p) { return p.allFinite(); })
        && std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
    if (!ok)
        ++m_skipped;
    return ok;
}

void Writer::group(int code, std::string_view value)
{
    appendGroup(m_entities, code, value);
}

void Writer::real(int code, double value)
{
    appendGroup(m_entities, code, formatReal(value));
}

void Writer::point(int code, const Vec &p)
{
    real(code, p.x());
    real(code + 10, p.y());
    real(code + 20, 0.0);
}

void Writer::begin(const char *type, const char *layer, const char *linetype)
{
    group(0, type);
    group(8, layer);
    if (linetype)
        group(6, linetype);
    ++m_count;
}

void Writer::line(const char *layer, const Vec &a, const Vec &b, const char *linetype)
{
    if (!finite({a, b}))
        return;
    begin("LINE", layer, linetype);
    point(10, a);
    point(11, b);
    m_box.extend(a).extend(b);
}

void Writer::circle(const char *layer, const Vec &centre, double radius)
{
    if (!finite({centre}, {radius}) || !(radius > 0.0))
        return;
    begin("CIRCLE", layer);
    point(10, centre);
    real(40, radius);
    m_box.extend(centre - Vec::Constant(radius)).extend(centre + Vec::Constant(radius));
}

void Writer::arc(const char *layer, const Vec &centre, double radius, double startDegrees, double endDegrees)
{
    if (!finite({centre}, {radius, startDegrees, endDegrees}) || !(radius > 0.0))
        return;
    begin("ARC", layer);
    point(10, centre);
    real(40, radius);
    real(50, startDegrees);
    real(51, endDegrees);
    // the end points and every quadrant point the counter-clockwise sweep passes
    const double start = startDegrees - 360.0 * std::floor(startDegrees / 360.0);
    double sweep = endDegrees - startDegrees;
    sweep -= 360.0 * std::floor(sweep / 360.0);
    if (sweep == 0.0)
        sweep = 360.0;
    const auto at = [&](double degrees) {
        const double r = degrees * pi / 180.0;
        return Vec(centre + radius * Vec(std::cos(r), std::sin(r)));
    };
    m_box.extend(at(start)).extend(at(start + sweep));
    for (double quadrant = 0.0; quadrant < 720.0; quadrant += 90.0) {
        if (quadrant > start && quadrant < start + sweep)
            m_box.extend(at(quadrant));
    }
}

void Writer::solid(const char *layer, const Vec &a, const Vec &b, const Vec &c, const Vec &d)
{
    if (!finite({a, b, c, d}))
        return;
    begin("SOLID", layer);
    point(10, a);
    point(11, b);
    point(12, c);
    point(13, d);
    m_box.extend(a).extend(b).extend(c).extend(d);
}

void Writer::polyline(const char *layer, const std::vector<Vec> &points, bool closed, const char *linetype)
{
    if (points.size() < 2 || !std::all_of(points.begin(), points.end(), [](const Vec &p) { return p.allFinite(); })) {
        ++m_skipped;
        return;
    }
    begin("POLYLINE", layer, linetype);
    group(66, "1"); // vertices follow
    point(10, Vec::Zero());
    group(70, closed ? "1" : "0");
    for (const Vec &p : points) {
        group(0, "VERTEX");
        group(8, layer);
        point(10, p);
        m_box.extend(p);
    }
    group(0, "SEQEND");
    group(8, layer);
}

void Writer::text(const char *layer, const Vec &position, double height, std::string_view utf8, double rotationDegrees,
    HAlign horizontal, VAlign vertical)
{
    const std::string encoded = encodeText(utf8);
    if (encoded.empty() || !finite({position}, {height, rotationDegrees}) || !(height > 0.0))
        return;
    begin("TEXT", layer);
    point(10, position);
    real(40, height);
    group(1, encoded);
    if (rotationDegrees != 0.0)
        real(50, rotationDegrees);
    group(7, "STANDARD");
    const bool aligned = horizontal != HAlign::Left || vertical != VAlign::Baseline;
    if (aligned) {
        group(72, std::to_string(static_cast<int>(horizontal)));
        point(11, position);
        group(73, std::to_string(static_cast<int>(vertical)));
    }
    // an estimate of the text's box for the extents: STANDARD's glyphs are narrower than this
    const double width = 0.85 * height * static_cast<double>(glyphCount(encoded));
    const double left = horizontal == HAlign::Left ? 0.0 : (horizontal == HAlign::Center ? -0.5 * width : -width);
    double bottom = -0.35 * height;
    if (vertical == VAlign::Bottom)
        bottom = 0.0;
    else if (vertical == VAlign::Middle)
        bottom = -0.65 * height;
    else if (vertical == VAlign::Top)
        bottom = -1.3 * height;
    const double r = rotationDegrees * pi / 180.0;
    const Vec u(std::cos(r), std::sin(r)), v(-u.y(), u.x());
    for (const double x : {left, left + width}) {
        for (const double y : {bottom, bottom + 1.3 * height})
            m_box.extend(Vec(position + x * u + y * v));
    }
}

std::string Writer::finish() const
{
    std::string out;
    out.reserve(m_entities.size() + 4096);
    const auto g = [&out](int code, std::string_view value) { appendGroup(out, code, value); };
    const auto r = [&out](int code, double value) { appendGroup(out, code, formatReal(value)); };
    const Vec low = m_box.isEmpty() ? Vec::Zero() : Vec(m_box.min());
    const Vec high = m_box.isEmpty() ? Vec::Zero() : Vec(m_box.max());

    if (!m_comment.empty())
        g(999, m_comment);
    g(0, "SECTION");
    g(2, "HEADER");
    g(9, "$ACADVER");
    g(1, "AC1009");
    g(9, "$DWGCODEPAGE");
    g(3, "ANSI_1252"); // the text is plain ASCII anyway
    g(9, "$INSBASE");
    r(10, 0.0);
    r(20, 0.0);
    r(30, 0.0);
    g(9, "$EXTMIN");
    r(10, low.x());
    r(20, low.y());
    r(30, 0.0);
    g(9, "$EXTMAX");
    r(10, high.x());
    r(20, high.y());
    r(30, 0.0);
    g(9, "$LIMMIN");
    r(10, low.x());
    r(20, low.y());
    g(9, "$LIMMAX");
    r(10, high.x());
    r(20, high.y());
    g(9, "$LTSCALE");
    r(40, 1.0);
    g(9, "$TEXTSIZE");
    r(40, m_textSize);
    g(9, "$TEXTSTYLE");
    g(7, "STANDARD");
    g(9, "$CLAYER");
    g(8, "0");
    g(9, "$LUNITS");
    g(70, "2"); // decimal
    g(9, "$LUPREC");
    g(70, "4");
    g(9, "$AUNITS");
    g(70, "0"); // decimal degrees
    g(9, "$INSUNITS");
    g(70, "4"); // millimetres (read by R2000 and later; older readers skip it)
    g(9, "$MEASUREMENT");
    g(70, "1"); // metric
    g(9, "$HANDLING");
    g(70, "0");
    g(0, "ENDSEC");

    g(0, "SECTION");
    g(2, "TABLES");
    // the view AutoCAD and LibreCAD open with: the whole drawing with a margin
    g(0, "TABLE");
    g(2, "VPORT");
    g(70, "1");
    g(0, "VPORT");
    g(2, "*ACTIVE");
    g(70, "0");
    r(10, 0.0);
    r(20, 0.0);
    r(11, 1.0);
    r(21, 1.0);
    const Vec size = (high - low).cwiseMax(Vec::Constant(1.0));
    const Vec centre = 0.5 * (low + high);
    r(12, centre.x());
    r(22, centre.y());
    r(13, 0.0);
    r(23, 0.0);
    r(14, 1.0);
    r(24, 1.0);
    r(15, 10.0);
    r(25, 10.0);
    r(16, 0.0);
    r(26, 0.0);
    r(36, 1.0);
    r(17, 0.0);
    r(27, 0.0);
    r(37, 0.0);
    r(40, 1.1 * std::max(size.y(), size.x() / 1.5)); // view height, for a 3:2 window
    r(41, 1.5);
    r(42, 50.0);
    r(43, 0.0);
    r(44, 0.0);
    r(50, 0.0);
    r(51, 0.0);
    g(71, "0");
    g(72, "100");
    g(73, "1");
    g(74, "3");
    g(75, "0");
    g(76, "0");
    g(77, "0");
    g(78, "0");
    g(0, "ENDTAB");

    g(0, "TABLE");
    g(2, "LTYPE");
    g(70, "3");
    const auto linetype = [&](const char *name, const char *description, std::initializer_list<double> pattern) {
        g(0, "LTYPE");
        g(2, name);
        g(70, "0");
        g(3, description);
        g(72, "65");
        g(73, std::to_string(pattern.size()));
        double total = 0.0;
        for (const double element : pattern)
            total += std::abs(element);
        r(40, total * m_period);
        for (const double element : pattern)
            r(49, element * m_period);
    };
    linetype("CONTINUOUS", "Solid line", {});
    linetype("DASHED", "Dashed __ __ __ __", {0.6, -0.4});
    linetype("CENTER", "Center ____ _ ____ _", {0.6, -0.15, 0.1, -0.15});
    g(0, "ENDTAB");

    g(0, "TABLE");
    g(2, "LAYER");
    g(70, std::to_string(m_layers.size() + 1));
    const auto layer = [&](std::string_view name, int colour, std::string_view type) {
        g(0, "LAYER");
        g(2, name);
        g(70, "0");
        g(62, std::to_string(colour));
        g(6, type);
    };
    layer("0", 7, "CONTINUOUS");
    for (const Layer &entry : m_layers)
        layer(entry.name, entry.colour, entry.linetype);
    g(0, "ENDTAB");

    g(0, "TABLE");
    g(2, "STYLE");
    g(70, "1");
    g(0, "STYLE");
    g(2, "STANDARD");
    g(70, "0");
    r(40, 0.0); // not fixed: each TEXT gives its height
    r(41, 1.0);
    r(50, 0.0);
    g(71, "0");
    r(42, m_textSize);
    g(3, "txt");
    g(4, "");
    g(0, "ENDTAB");
    g(0, "ENDSEC");

    g(0, "SECTION");
    g(2, "BLOCKS");
    g(0, "ENDSEC");

    g(0, "SECTION");
    g(2, "ENTITIES");
    out.append(m_entities);
    g(0, "ENDSEC");
    g(0, "EOF");
    return out;
}

// -- the drawing of a scene --------------------------------------------------------------

std::string dimensionText(std::string_view sceneText, double distance)
{
    std::string name;
    std::optional<double> stated;
    if (const std::size_t equals = sceneText.find('='); equals != std::string_view::npos) {
        std::string_view left = sceneText.substr(0, equals);
        while (!left.empty() && left.back() == ' ')
            left.remove_suffix(1);
        name = std::string(left);
        std::string_view right = sceneText.substr(equals + 1);
        while (!right.empty() && right.front() == ' ')
            right.remove_prefix(1);
        std::string number(right);
        // "−" (U+2212), as typeset minus signs are, reads as '-'
        if (number.starts_with("\xE2\x88\x92"))
            number.replace(0, 3, "-");
        double value = 0.0;
        const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
        if (result.ec == std::errc() && std::isfinite(value))
            stated = value;
    } else {
        std::string_view whole = sceneText;
        while (!whole.empty() && whole.back() == ' ')
            whole.remove_suffix(1);
        name = std::string(whole);
        double value = 0.0;
        const auto result = std::from_chars(whole.data(), whole.data() + whole.size(), value);
        if (result.ec == std::errc() && result.ptr == whole.data() + whole.size())
            name.clear(); // the text is the number alone
    }
    // a signed coordinate (p₁ = −20.0) keeps its sign when its magnitude is the distance
    const bool negative = stated && *stated < 0.0 && std::abs(std::abs(*stated) - distance) <= 0.5 + 1e-6 * distance;
    char buffer[400];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, distance, std::chars_format::fixed, 2);
    const std::string_view digits(
        buffer, static_cast<std::size_t>((result.ec == std::errc() ? result.ptr : buffer) - buffer));
    const std::string_view sign = negative && digits != "0.00" ? "-" : "";
    return name.empty() ? joinText({sign, digits}) : joinText({name, " = ", sign, digits});
}

namespace {

Vec xy(const Eigen::Vector3d &p)
{
    return p.head<2>();
}

Vec leftOf(const Vec &u)
{
    return {-u.y(), u.x()};
}

double degrees(double radians)
{
    return radians * 180.0 / pi;
}

Vec direction(double radians)
{
    return {std::cos(radians), std::sin(radians)};
}

/// Text along `u` that is never upside down: degrees in (−90, 90].
double readableDegrees(const Vec &u)
{
    double angle = degrees(std::atan2(u.y(), u.x()));
    if (angle > 90.0 + 1e-9)
        angle -= 180.0;
    else if (angle <= -90.0 + 1e-9)
        angle += 180.0;
    return angle;
}

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

/// Half the extent along unit `u` of a w × h box centred on the origin.
double support(const Vec &u, double width, double height)
{
    return 0.5 * (std::abs(u.x()) * width + std::abs(u.y()) * height);
}

/// A guide in scene units: the 2D view's GuideShape (widgets/sceneprimitives.cpp) in mm.
struct Rail {
    Vec start = Vec::Zero();
    Vec u {1.0, 0.0};
    Vec outer {0.0, -1.0}; ///< towards the hatched (ground) side
    double stroke = 0.0;
    double half = 0.0;
    double overrun = 0.0;
    double stop = 0.0;
    double stopHalf = 0.0;
    double hatch = 0.0;
    double carriageLength = 0.0;
    double carriageHalfWidth = 0.0;

    Vec at(double along, double across) const { return start + along * u + across * outer; }
    double reach(double side) const { return side > 0.0 ? std::max(half + hatch, stopHalf) : stopHalf; }
};

/// A carriage's length per rail width, as in the 2D view.
constexpr double carriagePerWidth = 1.8;

/// A text's box for the label layout: centred, along unit `u`.
struct TextBox {
    Vec centre = Vec::Zero();
    Vec u {1.0, 0.0};
    double halfWidth = 0.0;
    double halfHeight = 0.0;
};

/// Whether segment a–b crosses or lies in `box` (Liang–Barsky in the box's frame).
bool segmentHitsBox(const Vec &a, const Vec &b, const TextBox &box)
{
    const Vec v = leftOf(box.u);
    const Vec p((a - box.centre).dot(box.u), (a - box.centre).dot(v));
    const Vec q((b - box.centre).dot(box.u), (b - box.centre).dot(v));
    const Vec d = q - p;
    double t0 = 0.0, t1 = 1.0;
    const std::array<std::pair<double, double>, 4> edges = {{{-d.x(), p.x() + box.halfWidth},
        {d.x(), box.halfWidth - p.x()}, {-d.y(), p.y() + box.halfHeight}, {d.y(), box.halfHeight - p.y()}}};
    for (const auto &[den, num] : edges) {
        if (std::abs(den) < 1e-15) {
            if (num < 0.0)
                return false;
            continue;
        }
        const double t = num / den;
        if (den < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return false;
    }
    return true;
}

bool circleHitsBox(const Vec &centre, double radius, const TextBox &box)
{
    const Vec v = leftOf(box.u);
    const Vec local((centre - box.centre).dot(box.u), (centre - box.centre).dot(v));
    const Vec nearest(
        std::clamp(local.x(), -box.halfWidth, box.halfWidth), std::clamp(local.y(), -box.halfHeight, box.halfHeight));
    return (local - nearest).norm() < radius;
}

bool boxesOverlap(const TextBox &a, const TextBox &b)
{
    const Vec between = b.centre - a.centre;
    for (const Vec &axis : {a.u, Vec(leftOf(a.u)), b.u, Vec(leftOf(b.u))}) {
        const auto reach = [&axis](const TextBox &box) {
            return box.halfWidth * std::abs(box.u.dot(axis)) + box.halfHeight * std::abs(leftOf(box.u).dot(axis));
        };
        if (std::abs(between.dot(axis)) >= reach(a) + reach(b))
            return false;
    }
    return true;
}

class Draft
{
public:
    Draft(const Scene &scene, const DrawingOptions &options)
        : m_scene(scene)
        , m_options(options)
    {
        chooseShownJoints();
        chooseSizes();
        findGuides();
        for (const LayerInfo &layer : linkageLayers())
            m_writer.addLayer(layer.name, layer.colour);
        m_writer.setTextSize(m_text);
        m_writer.setLinetypePeriod(std::max(4.0 * m_text, 1.0));
        m_writer.setComment("PKM Studio linkage drawing, DXF R12, mm");
    }

    Drawing draw()
    {
        // the geometry first; the texts then find room among it
        for (const ScenePolyline &polyline : m_scene.polylines)
            drawPolyline(polyline);
        for (std::size_t g = 0; g < m_rails.size(); ++g)
            drawGuide(g);
        for (const SceneActuator &actuator : m_scene.actuators)
            drawActuator(actuator);
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
            drawJoint(j);
        for (const SceneBar &bar : m_scene.bars)
            drawBar(bar);
        for (const SceneDimension &dimension : m_scene.dimensions)
            drawDimension(dimension);
        for (const SceneAngle &angle : m_scene.angles)
            drawAngle(angle);

        for (const PendingDimension &dimension : m_dimensionTexts)
            labelDimension(dimension);
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
            labelJoint(j);
        for (const SceneAngle &angle : m_scene.angles)
            labelAngle(angle);
        for (const SceneBar &bar : m_scene.bars)
            labelBar(bar);
        for (const SceneActuator &actuator : m_scene.actuators)
            labelActuator(actuator);
        for (std::size_t g = 0; g < m_rails.size(); ++g)
            labelGuide(g);
        drawCaption();

        Drawing drawing;
        drawing.dxf = m_writer.finish();
        drawing.entities = m_writer.entityCount();
        drawing.skipped = m_writer.skippedCount() + m_skipped;
        drawing.extents = m_writer.extents();
        return drawing;
    }

private:
    /// A dimension's text, placed once all geometry is drawn.
    struct PendingDimension {
        Vec d1, d2; ///< the dimension line
        std::string text;
        double clear; ///< how far the text keeps from the line: the member's half width on it
    };

    bool valid(int joint) const
    {
        return joint >= 0 && joint < static_cast<int>(m_scene.joints.size()) && m_shown[static_cast<std::size_t>(joint)]
            && m_scene.joints[static_cast<std::size_t>(joint)].position.head<2>().allFinite();
    }
    Vec at(int joint) const { return xy(m_scene.joints[static_cast<std::size_t>(joint)].position); }
    const Rail *railOf(int joint) const
    {
        const int guide = m_jointGuide[static_cast<std::size_t>(joint)];
        return guide >= 0 ? &m_rails[static_cast<std::size_t>(guide)] : nullptr;
    }
    const Rail *carriageRail(int joint) const
    {
        return m_scene.joints[static_cast<std::size_t>(joint)].kind == JointKind::Slider ? railOf(joint) : nullptr;
    }

    // -- drawing, with the label layout learning what to keep off --------------------------

    void line(const char *layer, const Vec &a, const Vec &b, const char *linetype = nullptr)
    {
        m_writer.line(layer, a, b, linetype);
        m_segments.emplace_back(a, b);
    }
    void circle(const char *layer, const Vec &centre, double radius)
    {
        m_writer.circle(layer, centre, radius);
        m_circles.emplace_back(centre, radius);
    }
    void arc(const char *layer, const Vec &centre, double radius, double startDegrees, double endDegrees)
    {
        m_writer.arc(layer, centre, radius, startDegrees, endDegrees);
        constexpr int pieces = 12;
        for (int k = 0; k < pieces; ++k) {
            const double a = startDegrees + (endDegrees - startDegrees) * k / pieces;
            const double b = startDegrees + (endDegrees - startDegrees) * (k + 1) / pieces;
            m_segments.emplace_back(
                centre + radius * direction(a * pi / 180.0), centre + radius * direction(b * pi / 180.0));
        }
    }
    void polyline(const char *layer, const std::vector<Vec> &points, bool closed)
    {
        m_writer.polyline(layer, points, closed);
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
            m_segments.emplace_back(points[i], points[i + 1]);
        if (closed && points.size() > 2)
            m_segments.emplace_back(points.back(), points.front());
    }
    void arrowhead(const char *layer, const Vec &tip, const Vec &pointing)
    {
        const Vec base = tip - m_arrow * pointing, across = leftOf(pointing) * (m_arrow / 6.0);
        m_writer.solid(layer, tip, Vec(base + across), Vec(base - across), Vec(base - across));
        m_segments.emplace_back(tip, base);
    }

    /// The width of `text` at the drawing's text height (an estimate: see Writer::text).
    double textWidth(std::string_view text) const
    {
        return 0.85 * m_text * static_cast<double>(glyphCount(encodeText(text)));
    }

    /// How badly a text at `box` would cover what is drawn and written already.
    double crowding(const TextBox &box) const
    {
        double cost = 0.0;
        for (const auto &[a, b] : m_segments) {
            if (segmentHitsBox(a, b, box))
                cost += 1.0;
        }
        for (const auto &[centre, radius] : m_circles) {
            if (circleHitsBox(centre, radius, box))
                cost += 1.0;
        }
        for (const TextBox &text : m_texts) {
            if (boxesOverlap(text, box))
                cost += 12.0; // text over text is unreadable; over a line it is not
        }
        return cost;
    }

    /// Writes `text` (centred on its middle) at the first of `centres` that covers the least,
    /// earlier ones preferred; it is then an obstacle for the texts after it.
    void placeText(const char *layer, std::string_view text, double rotationDegrees, const std::vector<Vec> &centres)
    {
        if (text.empty() || centres.empty())
            return;
        const Vec u = direction(rotationDegrees * pi / 180.0);
        const double pad = 0.15 * m_text;
        TextBox best;
        double bestCost = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < centres.size(); ++i) {
            if (!centres[i].allFinite())
                continue;
            const TextBox box {centres[i], u, 0.5 * textWidth(text) + pad, 0.6 * m_text + pad};
            const double cost = crowding(box) + 0.01 * static_cast<double>(i);
            if (cost < bestCost) {
                bestCost = cost;
                best = box;
            }
        }
        if (!std::isfinite(bestCost))
            return;
        m_writer.text(layer, best.centre, m_text, text, rotationDegrees, HAlign::Center, VAlign::Middle);
        m_texts.push_back(best);
    }

    // -- choices -----------------------------------------------------------------------------

    /// A free point (an instant centre) far outside the range of motion is left out, as the
    /// 3D model leaves it out (shownJoints, scene.h).
    void chooseShownJoints() { m_shown = shownJoints(m_scene); }

    /// Text height, pin radius and the rest from the size of the range of motion, so that a
    /// 130 mm glide and a 1 m П-joint both read well at their natural size, and every pose of
    /// a design gets the same ones.
    void chooseSizes()
    {
        Eigen::AlignedBox2d box;
        if (!m_scene.extent.isEmpty() && m_scene.extent.min().head<2>().allFinite()
            && m_scene.extent.max().head<2>().allFinite()) {
            box.extend(Vec(m_scene.extent.min().head<2>())).extend(Vec(m_scene.extent.max().head<2>()));
        } else {
            for (int j = 0; j < static_cast<int>(m_scene.joints.size()); ++j) {
                if (valid(j))
                    box.extend(at(j));
            }
            for (const SceneGuide &guide : m_scene.guides) {
                if (guide.start.head<2>().allFinite() && guide.end.head<2>().allFinite())
                    box.extend(xy(guide.start)).extend(xy(guide.end));
            }
        }
        const double size = box.isEmpty() ? 100.0 : std::max(box.sizes().maxCoeff(), 1e-3);
        double shortest = std::numeric_limits<double>::infinity();
        const auto member = [&](int from, int to) {
            if (valid(from) && valid(to)) {
                const double length = (at(to) - at(from)).norm();
                if (length > 1e-9)
                    shortest = std::min(shortest, length);
            }
        };
        for (const SceneBar &bar : m_scene.bars)
            member(bar.from, bar.to);
        for (const SceneActuator &actuator : m_scene.actuators)
            member(actuator.from, actuator.to);

        m_text = m_options.textHeight > 0.0 ? m_options.textHeight : isoTextHeight(size / 50.0);
        if (m_options.pinRadius > 0.0) {
            m_pin = m_options.pinRadius;
        } else {
            m_pin = std::max(0.5, std::round(2.0 * size / 100.0) / 2.0); // in steps of 0.5 mm
            if (std::isfinite(shortest))
                m_pin = std::min(m_pin, 0.2 * shortest);
            m_pin = std::max(m_pin, 1e-3);
        }
        m_arrow = 0.8 * m_text;
        m_outline = 1.3 * m_pin;
    }

    /// The guides in mm and the joints that ride them (the 2D view's jointsOnGuides and
    /// guideShapes, without its pixel minimums).
    void findGuides()
    {
        const std::size_t n = m_scene.joints.size();
        m_jointGuide.assign(n, -1);
        for (std::size_t j = 0; j < n; ++j) {
            const SceneJoint &joint = m_scene.joints[j];
            if (joint.kind != JointKind::Slider && joint.kind != JointKind::Point)
                continue;
            const Vec p = xy(joint.position);
            double best = 1e300;
            for (std::size_t g = 0; g < m_scene.guides.size(); ++g) {
                const SceneGuide &guide = m_scene.guides[g];
                const Vec a = xy(guide.start), b = xy(guide.end);
                const double span = (b - a).norm();
                if (!std::isfinite(span) || !p.allFinite())
                    continue;
                const double width = std::max(guide.width, 0.0);
                const Vec u = span > 1e-12 ? Vec((b - a) / span) : Vec(1.0, 0.0);
                const double along = u.dot(p - a);
                const double across = std::abs(u.x() * (p - a).y() - u.y() * (p - a).x());
                const double tolerance = std::max({0.25 * width, 1e-6 * span, 1e-9});
                const double overrun = 0.5 * carriagePerWidth * width + tolerance;
                if (across <= tolerance && along >= -overrun && along <= span + overrun && across < best) {
                    best = across;
                    m_jointGuide[j] = static_cast<int>(g);
                }
            }
        }
        for (std::size_t g = 0; g < m_scene.guides.size(); ++g) {
            const SceneGuide &guide = m_scene.guides[g];
            Rail rail;
            rail.start = xy(guide.start);
            const Vec end = xy(guide.end);
            rail.stroke = (end - rail.start).norm();
            if (!std::isfinite(rail.stroke))
                rail.stroke = 0.0;
            if (rail.stroke > 1e-12)
                rail.u = (end - rail.start) / rail.stroke;
            rail.half = std::max(0.5 * std::max(guide.width, 0.0), 0.5 * m_pin);
            rail.carriageLength = std::max(carriagePerWidth * 2.0 * rail.half, 2.0 * m_pin + 1.5 * m_text);
            rail.carriageHalfWidth = std::max({1.3 * rail.half, rail.half + 0.5 * m_text, m_pin + 0.6 * m_text});
            rail.overrun = 0.5 * rail.carriageLength;
            rail.stop = std::clamp(0.3 * rail.half, 0.4 * m_text, 1.2 * m_text);
            rail.stopHalf = rail.half + std::clamp(0.35 * rail.half, 0.4 * m_text, 1.2 * m_text);
            rail.hatch = std::clamp(0.4 * rail.half, 0.8 * m_text, 1.3 * m_text);

            // hatching (ground) away from the links leaving the guide's joints; with none,
            // away from the rest of the mechanism; with nothing at all, below
            const Vec left = leftOf(rail.u), middle = rail.at(0.5 * rail.stroke, 0.0);
            const auto onGuide = [&](int joint) {
                return joint >= 0 && static_cast<std::size_t>(joint) < n
                    && m_jointGuide[static_cast<std::size_t>(joint)] == static_cast<int>(g);
            };
            double towards = 0.0;
            for (const SceneBar &bar : m_scene.bars) {
                if (bar.kind == BarKind::Ground || !valid(bar.from) || !valid(bar.to)
                    || onGuide(bar.from) == onGuide(bar.to))
                    continue;
                const Vec on = at(onGuide(bar.from) ? bar.from : bar.to);
                const Vec off = at(onGuide(bar.from) ? bar.to : bar.from);
                towards += (off - on).dot(left);
            }
            if (std::abs(towards) <= 1e-9) {
                Vec sum = Vec::Zero();
                int count = 0;
                for (std::size_t j = 0; j < n; ++j) {
                    if (!onGuide(static_cast<int>(j)) && valid(static_cast<int>(j))) {
                        sum += at(static_cast<int>(j));
                        ++count;
                    }
                }
                towards = count > 0 ? (sum / count - middle).dot(left) : 0.0;
            }
            if (std::abs(towards) > 1e-9)
                rail.outer = towards > 0.0 ? Vec(-left) : left;
            else
                rail.outer = left.y() <= 0.0 ? left : Vec(-left);
            m_rails.push_back(rail);
        }
    }

    /// The directions of everything drawn from `joint` (links, actuators, its rail, the ground
    /// symbol), for placing its name and the legs of angles.
    std::vector<Vec> membersAt(int joint) const
    {
        std::vector<Vec> directions;
        const auto add = [&](int from, int to) {
            if (!valid(from) || !valid(to) || (from != joint && to != joint))
                return;
            const Vec v = from == joint ? Vec(at(to) - at(from)) : Vec(at(from) - at(to));
            if (v.norm() > 1e-9)
                directions.push_back(v.normalized());
        };
        for (const SceneBar &bar : m_scene.bars)
            add(bar.from, bar.to);
        for (const SceneActuator &actuator : m_scene.actuators)
            add(actuator.from, actuator.to);
        if (const Rail *rail = railOf(joint)) {
            directions.push_back(rail->u);
            directions.push_back(-rail->u);
        }
        if (m_scene.joints[static_cast<std::size_t>(joint)].kind == JointKind::Ground)
            directions.emplace_back(0.0, -1.0);
        return directions;
    }

    /// The centroid of the drawn joints: "away from it" is outside the mechanism.
    Vec centroid() const
    {
        Vec sum = Vec::Zero();
        int count = 0;
        for (int j = 0; j < static_cast<int>(m_scene.joints.size()); ++j) {
            if (valid(j)) {
                sum += at(j);
                ++count;
            }
        }
        return count > 0 ? Vec(sum / count) : Vec::Zero();
    }

    /// Beside a member from `p` to `q` at `clear` from its axis: the middle first, on the
    /// side away from the mechanism's middle first, then further along and on the other side.
    std::vector<Vec> besideMember(const Vec &p, const Vec &q, double clear, double rotationDegrees) const
    {
        const Vec up = direction((rotationDegrees + 90.0) * pi / 180.0);
        const Vec middle = 0.5 * (p + q);
        const double side = (middle - centroid()).dot(up) >= 0.0 ? 1.0 : -1.0;
        std::vector<Vec> centres;
        for (const double t : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8}) {
            const Vec on = p + t * (q - p);
            centres.push_back(on + side * clear * up);
            centres.push_back(on - side * clear * up);
        }
        return centres;
    }

    // -- the elements ----------------------------------------------------------------------

    void drawPolyline(const ScenePolyline &path)
    {
        std::vector<Vec> run;
        bool broken = false;
        const auto flush = [&] {
            if (run.size() >= 2)
                polyline(layerPaths, run, path.closed && !broken);
            run.clear();
        };
        for (const Eigen::Vector3d &p : path.points) {
            if (p.head<2>().allFinite()) {
                run.push_back(xy(p));
            } else {
                broken = true;
                flush();
            }
        }
        if (broken)
            ++m_skipped; // the undefined points
        flush();
    }

    void drawGuide(std::size_t index)
    {
        const Rail &rail = m_rails[index];
        const double begin = -rail.overrun, end = rail.stroke + rail.overrun;
        // the axis, a little past the end stops, as centre lines are
        line(layerGuides, rail.at(begin - rail.stop - 0.8 * m_text, 0.0), rail.at(end + rail.stop + 0.8 * m_text, 0.0),
            "CENTER");
        line(layerGuides, rail.at(begin, rail.half), rail.at(end, rail.half));
        line(layerGuides, rail.at(begin, -rail.half), rail.at(end, -rail.half));
        // end stops: closed blocks across both ends, a little wider than the rail
        for (const double from : {begin - rail.stop, end}) {
            polyline(layerGuides,
                {rail.at(from, -rail.stopHalf), rail.at(from + rail.stop, -rail.stopHalf),
                    rail.at(from + rail.stop, rail.stopHalf), rail.at(from, rail.stopHalf)},
                true);
        }
        // hatching along the outer edge: the mark of a part fixed to the ground
        const double pitch = std::max(0.8 * rail.hatch, 1e-3 * (end - begin));
        int strokes = 0;
        for (double x = end; x >= begin + rail.hatch && strokes < 4000; x -= pitch, ++strokes)
            line(layerGuides, rail.at(x, rail.half), rail.at(x - rail.hatch, rail.half + rail.hatch));
    }

    void labelGuide(std::size_t index)
    {
        const Rail &rail = m_rails[index];
        const SceneGuide &guide = m_scene.guides[index];
        if (guide.label.empty())
            return;
        // along the rail, beyond the end that comes first in reading direction, else the other
        const double begin = -rail.overrun - rail.stop, end = rail.stroke + rail.overrun + rail.stop;
        const double rotation = readableDegrees(rail.u);
        const Vec reading = direction(rotation * pi / 180.0);
        const double gap = 1.2 * m_text + 0.5 * textWidth(guide.label);
        const Vec first = reading.dot(rail.u) > 0.0 ? rail.at(begin, 0.0) : rail.at(end, 0.0);
        const Vec last = reading.dot(rail.u) > 0.0 ? rail.at(end, 0.0) : rail.at(begin, 0.0);
        placeText(layerText, guide.label, rotation, {Vec(first - gap * reading), Vec(last + gap * reading)});
    }

    void drawActuator(const SceneActuator &actuator)
    {
        if (!valid(actuator.from) || !valid(actuator.to)) {
            ++m_skipped;
            return;
        }
        const Vec p = at(actuator.from), q = at(actuator.to);
        const double distance = (q - p).norm();
        if (distance < 1e-9)
            return;
        const Vec u = (q - p) / distance, n = leftOf(u);
        const auto point = [&](double along, double across) { return Vec(p + along * u + across * n); };
        const double body = std::min(std::max(actuator.bodyLength, 0.0), distance);
        const double bodyHalf = bodyHalfWidth(actuator);
        const double screwHalf = 0.5 * std::max(actuator.rodDiameter, 0.2 * m_pin);
        line(layerActuators, p, q, "CENTER"); // the axis, joint to joint
        if (body > 0.0) {
            polyline(layerActuators,
                {point(0.0, -bodyHalf), point(body, -bodyHalf), point(body, bodyHalf), point(0.0, bodyHalf)}, true);
        }
        if (body < distance) {
            // the screw leaves the body and runs into the joint's pin
            const double into = std::clamp(distance - m_pin, body, distance);
            line(layerActuators, point(body, screwHalf), point(into, screwHalf));
            line(layerActuators, point(body, -screwHalf), point(into, -screwHalf));
        }
    }

    double bodyHalfWidth(const SceneActuator &actuator) const
    {
        return 0.5 * std::max(actuator.bodyWidth, 2.0 * m_pin);
    }

    void labelActuator(const SceneActuator &actuator)
    {
        if (actuator.label.empty() || !valid(actuator.from) || !valid(actuator.to))
            return;
        // the 2D view drops the name of an actuator whose length is dimensioned
        const bool dimensioned
            = std::any_of(m_scene.dimensions.begin(), m_scene.dimensions.end(), [&](const SceneDimension &d) {
                  return (d.from == actuator.from && d.to == actuator.to)
                      || (d.from == actuator.to && d.to == actuator.from);
              });
        const Vec p = at(actuator.from), q = at(actuator.to);
        if (dimensioned || (q - p).norm() < 1e-9)
            return;
        const double rotation = readableDegrees(q - p);
        placeText(
            layerText, actuator.label, rotation, besideMember(p, q, bodyHalfWidth(actuator) + 0.8 * m_text, rotation));
    }

    void drawJoint(std::size_t index)
    {
        const SceneJoint &joint = m_scene.joints[index];
        const int j = static_cast<int>(index);
        if (!m_shown[index])
            return;
        if (!valid(j)) {
            ++m_skipped;
            return;
        }
        const Vec p = at(j);
        switch (joint.kind) {
        case JointKind::Ground:
            drawGround(p);
            circle(layerJoints, p, m_pin);
            break;
        case JointKind::Revolute:
            circle(layerJoints, p, m_pin);
            break;
        case JointKind::Spherical:
            circle(layerJoints, p, m_pin);
            circle(layerJoints, p, 0.35 * m_pin);
            break;
        case JointKind::Slider:
            if (const Rail *rail = carriageRail(j)) {
                const double l = 0.5 * rail->carriageLength, w = rail->carriageHalfWidth;
                const auto corner
                    = [&](double along, double across) { return Vec(p + along * rail->u + across * rail->outer); };
                polyline(layerJoints, {corner(-l, -w), corner(l, -w), corner(l, w), corner(-l, w)}, true);
            } else {
                polyline(layerJoints,
                    {p + Vec(-1.6 * m_pin, -m_pin), p + Vec(1.6 * m_pin, -m_pin), p + Vec(1.6 * m_pin, m_pin),
                        p + Vec(-1.6 * m_pin, m_pin)},
                    true);
            }
            circle(layerJoints, p, m_pin);
            break;
        case JointKind::Point:
            circle(layerJoints, p, 0.5 * m_pin);
            break;
        }
    }

    /// The ground symbol under a pivot: a triangle from the pin down to a base with hatching
    /// below it (the 2D view's drawGround, in mm).
    void drawGround(const Vec &pivot)
    {
        const double w = 4.4 * m_pin, h = 2.5 * m_pin, hatch = 1.1 * m_pin, pitch = 1.0 * m_pin;
        const Vec left(pivot.x() - 0.5 * w, pivot.y() - h), right(pivot.x() + 0.5 * w, pivot.y() - h);
        // the legs start on the pin circle
        line(layerGround, Vec(pivot + m_pin * (left - pivot).normalized()), left);
        line(layerGround, Vec(pivot + m_pin * (right - pivot).normalized()), right);
        const Vec baseLeft(left.x() - 0.3 * w, left.y()), baseRight(right.x() + 0.3 * w, right.y());
        line(layerGround, baseLeft, baseRight);
        for (double x = baseRight.x(); x > baseLeft.x() + 0.5 * hatch; x -= pitch)
            line(layerGround, Vec(x, baseLeft.y()), Vec(x - hatch, baseLeft.y() - hatch));
    }

    void drawBar(const SceneBar &bar)
    {
        if (!valid(bar.from) || !valid(bar.to)) {
            ++m_skipped;
            return;
        }
        const Vec p = at(bar.from), q = at(bar.to);
        const bool ground = bar.kind == BarKind::Ground;
        const char *layer = ground ? layerGround : layerLinks;
        const double length = (q - p).norm();
        if (length < 1e-9)
            return;
        line(layer, p, q); // the link's centre line: its length is the link's
        if (m_options.barOutlines && !ground) {
            const Vec u = (q - p) / length, n = leftOf(u);
            const double w = m_outline;
            line(layer, Vec(p + w * n), Vec(q + w * n));
            line(layer, Vec(p - w * n), Vec(q - w * n));
            const double angle = degrees(std::atan2(u.y(), u.x()));
            arc(layer, p, w, angle + 90.0, angle + 270.0);
            arc(layer, q, w, angle - 90.0, angle + 90.0);
        }
    }

    void labelBar(const SceneBar &bar)
    {
        if (bar.label.empty() || !valid(bar.from) || !valid(bar.to))
            return;
        const Vec p = at(bar.from), q = at(bar.to);
        if ((q - p).norm() < 1e-9)
            return;
        const double rotation = readableDegrees(q - p);
        const bool outlined = m_options.barOutlines && bar.kind != BarKind::Ground;
        placeText(
            layerText, bar.label, rotation, besideMember(p, q, (outlined ? m_outline : 0.0) + 0.9 * m_text, rotation));
    }

    /// How far from joint `joint` an extension line towards `side` starts: clear of the pin,
    /// and of the rail and carriage of a joint on a guide the dimension runs along.
    double extensionGap(int joint, const Vec &side) const
    {
        double gap = m_pin + 0.4 * m_text;
        if (const Rail *rail = railOf(joint); rail && std::abs(side.dot(rail->u)) < 0.5) {
            gap = std::max(gap, rail->reach(side.dot(rail->outer)) + 0.4 * m_text);
            if (carriageRail(joint))
                gap = std::max(gap, rail->carriageHalfWidth + 0.4 * m_text);
        }
        return gap;
    }

    /// Half the width of what is drawn along a dimension's two joints: an actuator's body, a
    /// link's outline.
    double memberClearance(const SceneDimension &dimension) const
    {
        const auto joins = [&](int from, int to) {
            return (from == dimension.from && to == dimension.to) || (from == dimension.to && to == dimension.from);
        };
        double clear = 0.0;
        for (const SceneActuator &actuator : m_scene.actuators) {
            if (joins(actuator.from, actuator.to))
                clear = std::max(clear, bodyHalfWidth(actuator));
        }
        for (const SceneBar &bar : m_scene.bars) {
            if (joins(bar.from, bar.to) && m_options.barOutlines && bar.kind != BarKind::Ground)
                clear = std::max(clear, m_outline);
        }
        return clear;
    }

    void drawDimension(const SceneDimension &dimension)
    {
        if (!valid(dimension.from) || !valid(dimension.to)) {
            ++m_skipped;
            return;
        }
        const Vec p = at(dimension.from), q = at(dimension.to);
        const double span = (q - p).norm();
        if (span < 1e-9)
            return;
        const Vec u = (q - p) / span;
        const double offset = std::isfinite(dimension.offset) ? dimension.offset : 0.0;
        if (std::abs(offset) < 0.5 * m_pin) {
            // The 2D view writes a dimension without offset beside its member (an actuator
            // across a parallelogram, where any parallel line would cross the links): here the
            // dimension line runs on the member's axis from joint to joint, its arrowheads on
            // the pins, without extension lines.
            line(layerDimensions, p, q);
            if (span > 2.0 * m_pin + 2.5 * m_arrow) {
                arrowhead(layerDimensions, Vec(p + m_pin * u), -u);
                arrowhead(layerDimensions, Vec(q - m_pin * u), u);
            }
            m_dimensionTexts.push_back({p, q, dimensionText(dimension.text, span), memberClearance(dimension)});
            return;
        }
        const Vec side = leftOf(u) * (offset > 0.0 ? 1.0 : -1.0);
        const double distance = std::abs(offset);
        const Vec d1 = p + distance * side, d2 = q + distance * side;
        const double overshoot = 0.6 * m_text;
        const double gapFrom = extensionGap(dimension.from, side), gapTo = extensionGap(dimension.to, side);
        if (distance > gapFrom)
            line(layerDimensions, Vec(p + gapFrom * side), Vec(d1 + overshoot * side));
        if (distance > gapTo)
            line(layerDimensions, Vec(q + gapTo * side), Vec(d2 + overshoot * side));
        line(layerDimensions, d1, d2); // the dimension line: as long as the measured distance
        arrowhead(layerDimensions, d1, -u);
        arrowhead(layerDimensions, d2, u);
        m_dimensionTexts.push_back({d1, d2, dimensionText(dimension.text, span), 0.0});
    }

    /// Above the dimension line (in reading direction) in its middle, as ISO 129 has it; where
    /// that is crowded, below it or further along.
    void labelDimension(const PendingDimension &dimension)
    {
        const double rotation = readableDegrees(dimension.d2 - dimension.d1);
        const Vec up = direction((rotation + 90.0) * pi / 180.0);
        const double lift = dimension.clear + 0.9 * m_text;
        std::vector<Vec> centres;
        for (const double t : {0.5, 0.35, 0.65, 0.25, 0.75}) {
            const Vec on = dimension.d1 + t * (dimension.d2 - dimension.d1);
            centres.push_back(on + lift * up);
        }
        for (const double t : {0.5, 0.35, 0.65}) {
            const Vec on = dimension.d1 + t * (dimension.d2 - dimension.d1);
            centres.push_back(on - lift * up);
        }
        placeText(layerDimensions, dimension.text, rotation, centres);
    }

    /// The arc's radius: the scene's, or one that clears the pin and fits an arrowhead.
    double angleRadius(const SceneAngle &angle) const
    {
        return std::max(std::isfinite(angle.radius) ? angle.radius : 0.0, 2.5 * m_pin + m_arrow);
    }

    void drawAngle(const SceneAngle &angle)
    {
        if (!valid(angle.vertex) || !std::isfinite(angle.start) || !std::isfinite(angle.sweep)) {
            ++m_skipped;
            return;
        }
        const Vec p = at(angle.vertex);
        const double radius = angleRadius(angle);
        const double end = angle.start + angle.sweep;
        if (std::abs(angle.sweep) > 1e-9) {
            const double from = std::min(angle.start, end), to = std::max(angle.start, end);
            arc(layerDimensions, p, radius, degrees(from), degrees(to));
            // the arrowhead at the end of the sweep, along the arc
            const Vec tangent = direction(end + (angle.sweep > 0.0 ? 0.5 : -0.5) * pi);
            if (std::abs(angle.sweep) * radius > 1.5 * m_arrow)
                arrowhead(layerDimensions, Vec(p + radius * direction(end)), tangent);
        }
        // dashed legs where no member shows the angle's sides
        const std::vector<Vec> members = membersAt(angle.vertex);
        for (const double leg : {angle.start, end}) {
            const Vec d = direction(leg);
            const bool shown = std::any_of(
                members.begin(), members.end(), [&](const Vec &m) { return m.dot(d) > std::cos(0.5 * pi / 180.0); });
            if (!shown)
                line(layerDimensions, Vec(p + (m_pin + 0.3 * m_text) * d), Vec(p + (radius + m_text) * d), "DASHED");
        }
    }

    /// Outside the arc, horizontal: at its middle first, then along it, then further out; a
    /// (nearly) zero angle also looks to either side of its leg.
    void labelAngle(const SceneAngle &angle)
    {
        if (angle.label.empty() || !valid(angle.vertex) || !std::isfinite(angle.start) || !std::isfinite(angle.sweep))
            return;
        const Vec p = at(angle.vertex);
        const double radius = angleRadius(angle);
        const double width = textWidth(angle.label);
        std::vector<double> directions;
        for (const double t : {0.5, 0.35, 0.65, 0.2, 0.8})
            directions.push_back(angle.start + t * angle.sweep);
        for (const double turn : {20.0, -20.0, 40.0, -40.0})
            directions.push_back(angle.start + 0.5 * angle.sweep + turn * pi / 180.0);
        std::vector<Vec> centres;
        for (const double further : {0.0, 1.5 * m_text, 3.0 * m_text}) {
            for (const double a : directions) {
                const Vec d = direction(a);
                centres.push_back(p + (radius + 0.4 * m_text + further + support(d, width, 1.2 * m_text)) * d);
            }
        }
        placeText(layerDimensions, angle.label, 0.0, centres);
    }

    /// A joint's name beside it, clear of its pin (or carriage), in the direction farthest
    /// from its members that is not crowded.
    void labelJoint(std::size_t index)
    {
        const SceneJoint &joint = m_scene.joints[index];
        const int j = static_cast<int>(index);
        if (joint.label.empty() || !valid(j))
            return;
        const std::vector<Vec> members = membersAt(j);
        const double diagonal = std::sqrt(0.5);
        std::vector<Vec> candidates = {Vec(diagonal, diagonal), Vec(-diagonal, diagonal), Vec(diagonal, -diagonal),
            Vec(-diagonal, -diagonal), Vec(0.0, 1.0), Vec(1.0, 0.0), Vec(-1.0, 0.0), Vec(0.0, -1.0)};
        const auto freedom = [&](const Vec &candidate) {
            double least = 2.0; // the least angular distance to a member, as 1 − cos
            for (const Vec &m : members)
                least = std::min(least, 1.0 - m.dot(candidate));
            return least;
        };
        std::stable_sort(candidates.begin(), candidates.end(),
            [&](const Vec &a, const Vec &b) { return freedom(a) > freedom(b) + 1e-9; });
        double clear = m_pin;
        if (const Rail *rail = carriageRail(j))
            clear = std::hypot(0.5 * rail->carriageLength, rail->carriageHalfWidth);
        const double width = textWidth(joint.label);
        std::vector<Vec> centres;
        for (const double further : {0.0, 1.0 * m_text, 2.0 * m_text}) {
            for (const Vec &d : candidates)
                centres.push_back(at(j) + (clear + 0.4 * m_text + further + support(d, width, 1.2 * m_text)) * d);
        }
        placeText(layerText, joint.label, 0.0, centres);
    }

    void drawCaption()
    {
        if (m_options.caption.empty() || m_writer.extents().isEmpty())
            return;
        const Eigen::AlignedBox2d box = m_writer.extents();
        m_writer.text(layerText, Vec(box.min().x(), box.min().y() - 1.8 * m_text), m_text, m_options.caption);
    }

    const Scene &m_scene;
    const DrawingOptions &m_options;
    Writer m_writer;
    std::vector<bool> m_shown; ///< per joint: drawn (a far free point is not)
    std::vector<int> m_jointGuide;
    std::vector<Rail> m_rails;
    std::vector<PendingDimension> m_dimensionTexts;
    std::vector<std::pair<Vec, Vec>> m_segments; ///< what the texts keep off
    std::vector<std::pair<Vec, double>> m_circles;
    std::vector<TextBox> m_texts;
    double m_text = 2.5; ///< text height, mm
    double m_pin = 1.0; ///< pin radius, mm
    double m_arrow = 2.0; ///< arrowhead length, mm
    double m_outline = 1.3; ///< half the width of a link's outline, mm
    int m_skipped = 0;
};

} // namespace

Drawing sceneDrawing(const Scene &scene, const DrawingOptions &options)
{
    return Draft(scene, options).draw();
}

} // namespace pkm::dxf
