#pragma once
/// The planar four-bar's module for the registry (kinds.cpp).

#include "kinds/kindmodule.h"

namespace pkm::fourbarkind {

KindModule module();

} // namespace pkm::fourbarkind
