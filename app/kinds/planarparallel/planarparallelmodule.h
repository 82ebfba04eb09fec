#pragma once
/// The leg library's module for the registry (kinds.cpp): its panel (the legs editor above the
/// workspace map) and its templates.

#include "kinds/kindmodule.h"

namespace pkm::planarparallelkind {

KindModule module();

} // namespace pkm::planarparallelkind
