#pragma once
// The det J / condition-number map of a planar workspace (in progress).
