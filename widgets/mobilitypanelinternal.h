// What the mobility panel's files share: the panel (mobilitypanel.cpp) shows the parts that
// mobilitydisplay.cpp words for an analysed chain.
#pragma once

#include "mobilitypanel.h"

#include <QString>

#include <map>

namespace pkm::mobilitypanel {

/// The house colour of quiet notes (designpanel.cpp), shared by the display and the placeholder.
inline constexpr const char *quietColour = "#555555";

/// The texts of the display for `report` of `chain`: one HTML fragment per part.
std::map<MobilityPanel::Part, QString> displayParts(const KinematicChain &chain, const MobilityReport &report,
    MobilityPanel::Subject subject);

} // namespace pkm::mobilitypanel
