// The workspace and the singularity maps of a planar design as pictures: the reachable cells,
// the regions of several modes over each other (the O-X glide document's fig. 5) and the det J
// or condition-number colour map, for `pkm workspace -o`, `pkm map -o` and the parameter sheet.

#include "export/workspacepictures.h"

#include "document/savefile.h"

#include <QBuffer>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace pkm::pictures {

namespace {
/// Pictures of the workspace have at least this many pixels along the longer side.
constexpr int minPicturePixels = 400;

bool reachable(float value)
{
    return report::reachableCell(value);
}

struct Colour {
    double r, g, b;
};

QRgb interpolate(std::span<const Colour> stops, double t)
{
    t = std::clamp(std::isnan(t) ? 0.5 : t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - static_cast<double>(i);
    const Colour &a = stops[i], &b = stops[i + 1];
    const auto channel = [f](double x, double y) { return static_cast<int>(std::lround(x + (y - x) * f)); };
    return qRgb(channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b));
}

/// Blue (negative) – white (0) – red (positive), ColorBrewer RdBu.
constexpr std::array<Colour, 7> diverging
    = {{{5, 48, 97}, {33, 102, 172}, {146, 197, 222}, {247, 247, 247}, {244, 165, 130}, {178, 24, 43}, {103, 0, 31}}};
/// Dark (well conditioned) to yellow (near singular), viridis.
constexpr std::array<Colour, 5> sequential
    = {{{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};

constexpr QRgb workspaceFill = qRgb(166, 206, 227);
constexpr QRgb workspaceLine = qRgb(31, 78, 121);
constexpr QRgb currentModeFill = qRgb(43, 92, 143); ///< the design's own mode among the others
constexpr QRgb specificationMet = qRgb(46, 158, 79);     ///< a green, where every requirement holds
constexpr QRgb specificationFailed = qRgb(214, 214, 214); ///< the rest of the workspace, grey
constexpr QRgb inverseCurve = qRgb(165, 15, 21); ///< dark red, as the map view draws them
constexpr QRgb directCurve = qRgb(17, 17, 17);   ///< black, dashed

/// The singular curves over a picture of `grid` at `scale` pixels per cell (y up): inverse
/// ones solid dark red, direct ones dashed black, lines a little wider than a cell of the
/// larger grids so that they show at any size. Only pixels `inside` the workspace take them,
/// so what lies outside stays as it was (white, or transparent in a map).
void drawSingularCurves(QImage &image, const MapGrid &grid, int scale, std::span<const SingularCurve> curves,
                        bool (*inside)(QRgb))
{
    if (curves.empty() || image.isNull())
        return;
    QImage overlay(image.size(), QImage::Format_ARGB32_Premultiplied);
    overlay.fill(Qt::transparent);
    {
        QPainter painter(&overlay);
        painter.setRenderHint(QPainter::Antialiasing);
        const double width = std::max(1.5, std::max(image.width(), image.height()) / 250.0);
        const auto pixel = [&](const Eigen::Vector2d &p) {
            return QPointF((p.x() - grid.bounds.min().x()) / grid.dx() * scale,
                           (grid.rows - (p.y() - grid.bounds.min().y()) / grid.dy()) * scale);
        };
        // a white halo under every curve first, as the map view has, so that a dark red curve
        // shows on a dark red map
        for (const bool halo : {true, false}) {
            for (const SingularCurve &curve : curves) {
                if (curve.points.size() < 2)
                    continue;
                QPainterPath path(pixel(curve.points.front()));
                for (std::size_t k = 1; k < curve.points.size(); ++k)
                    path.lineTo(pixel(curve.points[k]));
                const bool inverse = curve.type == SingularCurve::Type::Inverse;
                QPen pen(QColor(inverse ? inverseCurve : directCurve), width, inverse ? Qt::SolidLine : Qt::CustomDashLine);
                if (halo)
                    pen = QPen(QColor(255, 255, 255, 200), 2.0 * width);
                else if (!inverse)
                    pen.setDashPattern({4.0, 2.5});
                painter.setPen(pen);
                painter.drawPath(path);
            }
        }
    }
    // the overlay (premultiplied) over the opaque pixels inside
    for (int y = 0; y < image.height(); ++y) {
        QRgb *line = reinterpret_cast<QRgb *>(image.scanLine(y));
        const QRgb *over = reinterpret_cast<const QRgb *>(overlay.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            const int alpha = qAlpha(over[x]);
            if (alpha == 0 || !inside(line[x]))
                continue;
            const auto channel = [&](int top, int below) { return top + below * (255 - alpha) / 255; };
            line[x] = qRgba(channel(qRed(over[x]), qRed(line[x])), channel(qGreen(over[x]), qGreen(line[x])),
                            channel(qBlue(over[x]), qBlue(line[x])), qAlpha(line[x]));
        }
    }
}

bool opaque(QRgb pixel)
{
    return qAlpha(pixel) == 255;
}

bool notWhite(QRgb pixel)
{
    return (pixel & 0xffffffu) != 0xffffffu;
}
} // namespace

QImage regionsImage(const MapGrid &grid, const std::vector<std::pair<const std::vector<char> *, QRgb>> &layers)
{
    if (grid.columns <= 0 || grid.rows <= 0 || layers.empty())
        return {};
    const int longer = std::max(grid.columns, grid.rows);
    const int scale = std::max(1, (minPicturePixels + longer - 1) / longer);
    const int thickness = std::max(1, scale / 4);
    const int width = grid.columns * scale, height = grid.rows * scale;
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    const auto index = [&](int c, int r) {
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(grid.columns) + static_cast<std::size_t>(c);
    };
    const auto inUnion = [&](int c, int r) {
        if (c < 0 || r < 0 || c >= grid.columns || r >= grid.rows)
            return false;
        return std::any_of(layers.begin(), layers.end(), [&](const auto &layer) { return (*layer.first)[index(c, r)] != 0; });
    };
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            QRgb fill = 0;
            for (const auto &[reached, colour] : layers) {
                if ((*reached)[index(c, r)])
                    fill = colour;
            }
            if (!fill)
                continue;
            const bool left = !inUnion(c - 1, r), right = !inUnion(c + 1, r), below = !inUnion(c, r - 1),
                       above = !inUnion(c, r + 1);
            const int top = (grid.rows - 1 - r) * scale; // row 0 is the bottom row: y up
            for (int iy = 0; iy < scale; ++iy) {
                QRgb *line = reinterpret_cast<QRgb *>(image.scanLine(top + iy));
                for (int ix = 0; ix < scale; ++ix) {
                    const bool edge = (left && ix < thickness) || (right && ix >= scale - thickness)
                        || (above && iy < thickness) || (below && iy >= scale - thickness);
                    line[c * scale + ix] = edge ? workspaceLine : fill;
                }
            }
        }
    }
    return image;
}

QImage modeRegionsImage(const report::ModeRegions &regions)
{
    // the modes over each other, larger ones first so that every one shows, the design's own
    // darker (fig. 5 of the O-X glide)
    std::vector<std::size_t> order(regions.reached.size());
    std::iota(order.begin(), order.end(), std::size_t {0});
    const auto cells = [&](std::size_t i) { return std::count(regions.reached[i].begin(), regions.reached[i].end(), 1); };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cells(a) > cells(b); });
    std::vector<std::pair<const std::vector<char> *, QRgb>> layers;
    for (const std::size_t i : order)
        layers.emplace_back(&regions.reached[i], regions.current[i] ? currentModeFill : workspaceFill);
    return regionsImage(regions.grid, layers);
}

QImage workspaceImage(const MapGrid &grid, std::span<const float> values, std::span<const SingularCurve> curves)
{
    if (grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells())
        return {};
    std::vector<char> reached(grid.cells());
    for (std::size_t i = 0; i < reached.size(); ++i)
        reached[i] = reachable(values[i]) ? 1 : 0;
    QImage image = regionsImage(grid, {{&reached, workspaceFill}});
    drawSingularCurves(image, grid, image.width() / grid.columns, curves, notWhite);
    return image;
}

QImage mapImage(const MapGrid &grid, std::span<const float> values, MapQuantity quantity, double limit,
                std::span<const SingularCurve> curves)
{
    if (grid.columns <= 0 || grid.rows <= 0 || values.size() < grid.cells())
        return {};
    QImage image(grid.columns, grid.rows, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    const double logLimit = std::log(std::max(limit, 1.0 + 1e-9));
    for (int r = 0; r < grid.rows; ++r) {
        QRgb *line = reinterpret_cast<QRgb *>(image.scanLine(grid.rows - 1 - r)); // y up
        const float *row = values.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(grid.columns);
        for (int c = 0; c < grid.columns; ++c) {
            const double value = row[c];
            if (std::isnan(value))
                continue;
            if (quantity == MapQuantity::Condition) {
                const double t = std::isinf(value) ? 1.0 : std::log(std::max(value, 1.0)) / logLimit;
                line[c] = interpolate(sequential, t);
            } else if (quantity == MapQuantity::Specification) {
                line[c] = value > 0.5 ? specificationMet : specificationFailed;
            } else if (quantity == MapQuantity::OrientationRange || isPoseValue(quantity)) {
                // what the actuators deliver and the error run from 0 (none: at a singularity) upwards; an
                // infinite value (the resolution at a direct singularity) takes the top colour
                line[c] = interpolate(sequential, std::isinf(value) ? 1.0 : std::clamp(value / limit, 0.0, 1.0));
            } else {
                const double t = 0.5 + 0.5 * std::clamp(value / limit, -1.0, 1.0);
                line[c] = interpolate(diverging, t);
            }
        }
    }
    drawSingularCurves(image, grid, 1, curves, opaque);
    return image;
}

std::optional<std::string> savePng(const std::string &path, const QImage &image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (image.isNull() || !image.save(&buffer, "PNG"))
        return "Cannot write '" + path + "': the PNG picture could not be encoded.";
    return files::saveBytes(path, bytes);
}

} // namespace pkm::pictures
