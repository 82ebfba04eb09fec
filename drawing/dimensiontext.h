#pragma once
/// The text of a length dimension in a CAD drawing. Plain C++.

#include <string>
#include <string_view>

namespace pkm::drawing {

/// The text of a dimension between two joints `distance` mm apart, from the scene's text
/// ("a = 170.0 mm" → "a = 170.00"): the name before '=' and the distance with 2 decimals;
/// the sign of the scene's number is kept when its magnitude is the distance (MOMA's slider
/// coordinates p₁ and p₂ are signed).
std::string dimensionText(std::string_view sceneText, double distance);

} // namespace pkm::drawing
