#pragma once
/// The workspace and the maps of a planar design as pictures (QImage), for `pkm workspace -o`,
/// `pkm map -o` and the parameter sheet; savePng() writes one atomically.

#include "report/workspaceanalysis.h"

#include <QImage>

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pkm::pictures {

/// The picture of `pkm workspace -o FILE.png`: reachable cells (finite or infinite values,
/// not NaN) light blue on white with a darker outline, y up, at least 400 pixels along the
/// longer side (a whole number of pixels per cell), and the singular `curves` over them.
QImage workspaceImage(const MapGrid &grid, std::span<const float> values, std::span<const SingularCurve> curves = {});
/// Regions on one grid (a flag per cell) painted over each other, later layers over earlier
/// ones, with the boundary of their union: the workspaces of a design's modes (fig. 5 of the
/// O-X glide), as `pkm workspace -o FILE.png` draws them for a mechanism with named modes.
QImage regionsImage(const MapGrid &grid, const std::vector<std::pair<const std::vector<char> *, QRgb>> &layers);

/// The picture of `pkm map -o FILE.png`: one pixel per cell, y up, unreachable cells
/// transparent. Determinant: a diverging blue–white–red scale over [−limit, limit];
/// condition number: a sequential scale over log₁₀ κ from 0 to log₁₀ limit. The singular
/// `curves` over it as the map view draws them: inverse ones solid dark red, direct ones
/// dashed black.
QImage mapImage(const MapGrid &grid, std::span<const float> values, MapQuantity quantity, double limit,
                std::span<const SingularCurve> curves = {});

/// The picture of `pkm workspace -o FILE.png` for a mechanism with named modes: every mode's
/// workspace over each other, larger ones first, the design's own darker, the union outlined.
QImage modeRegionsImage(const report::ModeRegions &regions);

/// `image` encoded as PNG (with its text keys, e.g. "Title"), written atomically
/// (files::saveBytes).
std::optional<std::string> savePng(const std::string &path, const QImage &image);

} // namespace pkm::pictures
