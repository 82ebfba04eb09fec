#pragma once
/// The outline of the reachable cells of a map (`pkm workspace -o FILE.svg`), without Qt.

#include "planarworkspace.h"

#include <span>
#include <string>

namespace pkm::report {

/// The outline of the reachable cells as an SVG document, in mm (viewBox), y up.
std::string workspaceSvg(const MapGrid &grid, std::span<const float> values, const std::string &title);

} // namespace pkm::report
