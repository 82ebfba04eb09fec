#pragma once
/// The active П-joint's sections of the parameter sheet (sheet::KindSections).

#include "export/sheet.h"

namespace pkm::pjointkind {

void addSheetSections(const Mechanism &mechanism, const Pose &pose, sheet::detail::Parts &parts);

} // namespace pkm::pjointkind
