// The outline of a workspace on a grid as an SVG document (`pkm workspace -o FILE.svg`): the
// boundary edges of the reachable cells joined into closed loops, in mm.

#include "report/workspaceoutline.h"

#include "report/numberformat.h"
#include "report/workspaceanalysis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace pkm::report {

namespace {


std::string xmlEscaped(std::string_view text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace

std::string workspaceSvg(const MapGrid &grid, std::span<const float> values, const std::string &title)
{
    // workspaceOutline() merges the edges along a grid line into long segments, and two cells
    // that touch at a corner put a vertex in the middle of such a segment. So the segments are
    // cut into unit edges between grid vertices (integer coordinates) and joined into closed
    // loops; where four edges meet the walk turns left, so that the loops touch without
    // crossing, and only the corners of a loop are written.
    const std::vector<Eigen::Vector2d> segments = workspaceOutline(grid, values);
    const double x0 = grid.bounds.min().x(), y0 = grid.bounds.min().y(), dx = grid.dx(), dy = grid.dy();
    using Vertex = std::array<std::int64_t, 2>;
    const auto toVertex = [&](const Eigen::Vector2d &p) {
        return Vertex {std::llround((p.x() - x0) / dx), std::llround((p.y() - y0) / dy)};
    };
    const auto keyOf = [&](const Vertex &v) { return v[1] * (static_cast<std::int64_t>(grid.columns) + 1) + v[0]; };
    std::vector<std::array<Vertex, 2>> edges;
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
        const Vertex a = toVertex(segments[s]), b = toVertex(segments[s + 1]);
        const int axis = a[0] != b[0] ? 0 : 1;
        const std::int64_t step = b[axis] > a[axis] ? 1 : -1;
        for (Vertex v = a; v[axis] != b[axis]; v[axis] += step) {
            Vertex w = v;
            w[axis] += step;
            edges.push_back({v, w});
        }
    }
    std::unordered_map<std::int64_t, std::vector<std::size_t>> at;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        at[keyOf(edges[e][0])].push_back(e);
        at[keyOf(edges[e][1])].push_back(e);
    }
    std::vector<bool> used(edges.size(), false);
    std::string path;
    const auto point = [&](char command, const Vertex &v) {
        path += command;
        appendNumber(path, cleanCoordinate(x0 + static_cast<double>(v[0]) * dx));
        path += ',';
        appendNumber(path, cleanCoordinate(-(y0 + static_cast<double>(v[1]) * dy))); // SVG's y points down
    };
    for (std::size_t first = 0; first < edges.size(); ++first) {
        if (used[first])
            continue;
        used[first] = true;
        const Vertex start = edges[first][0];
        Vertex current = edges[first][1];
        Vertex heading {current[0] - start[0], current[1] - start[1]};
        point('M', start);
        while (current != start) {
            std::size_t next = edges.size();
            std::int64_t best = -2; // left turn 1, straight 0, right turn −1
            for (std::size_t e : at[keyOf(current)]) {
                if (used[e])
                    continue;
                const Vertex &other = edges[e][0] == current ? edges[e][1] : edges[e][0];
                const Vertex out {other[0] - current[0], other[1] - current[1]};
                const std::int64_t cross = heading[0] * out[1] - heading[1] * out[0];
                if (cross > best) {
                    best = cross;
                    next = e;
                }
            }
            if (next == edges.size())
                break; // cannot happen: every vertex of an outline joins an even number of edges
            used[next] = true;
            const Vertex other = edges[next][0] == current ? edges[next][1] : edges[next][0];
            const Vertex out {other[0] - current[0], other[1] - current[1]};
            if (out != heading)
                point('L', current); // a corner
            heading = out;
            current = other;
        }
        path += 'Z';
    }

    // The view: the reachable cells with a margin of two cells, in mm, y up.
    Eigen::AlignedBox2d box = reachableBounds(grid, values);
    if (box.isEmpty())
        box = grid.bounds;
    const Eigen::Vector2d margin(2 * dx, 2 * dy);
    box.min() -= margin;
    box.max() += margin;
    const Eigen::Vector2d size = box.sizes();
    const double stroke = std::max(size.x(), size.y()) / 400.0;
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"";
    appendNumber(svg, cleanCoordinate(size.x()));
    svg += "mm\" height=\"";
    appendNumber(svg, cleanCoordinate(size.y()));
    svg += "mm\" viewBox=\"";
    appendNumber(svg, cleanCoordinate(box.min().x()));
    svg += ' ';
    appendNumber(svg, cleanCoordinate(-box.max().y()));
    svg += ' ';
    appendNumber(svg, cleanCoordinate(size.x()));
    svg += ' ';
    appendNumber(svg, cleanCoordinate(size.y()));
    svg += "\">\n  <title>" + xmlEscaped(title) + "</title>\n";
    svg += "  <path fill=\"#a6cee3\" fill-rule=\"evenodd\" stroke=\"#1f4e79\" stroke-linejoin=\"round\" "
           "stroke-width=\"";
    appendNumber(svg, stroke);
    svg += "\" d=\"" + path + "\"/>\n</svg>\n";
    return svg;
}

} // namespace pkm::report
