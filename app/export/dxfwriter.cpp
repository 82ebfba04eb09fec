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

} // namespace pkm::dxf
