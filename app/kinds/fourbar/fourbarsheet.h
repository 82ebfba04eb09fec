#pragma once
/// The planar four-bar's sections of the parameter sheet (sheet::KindSections).

#include "export/sheet.h"

namespace pkm::fourbarkind {

void addSheetSections(const Mechanism &mechanism, const Pose &pose, sheet::detail::Parts &parts);

} // namespace pkm::fourbarkind
