#pragma once
// pkm workspace and pkm map (in progress).
