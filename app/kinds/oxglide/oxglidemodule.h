#pragma once
/// The O-X glide's module for the registry (kinds.cpp).

#include "kinds/kindmodule.h"

namespace pkm::oxglidekind {

KindModule module();

} // namespace pkm::oxglidekind
