#pragma once
/// The active П-joint's module for the registry (kinds.cpp).

#include "kinds/kindmodule.h"

namespace pkm::pjointkind {

KindModule module();

} // namespace pkm::pjointkind
