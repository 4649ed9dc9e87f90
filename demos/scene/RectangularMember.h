// A steel member of rectangular section as the structures scenes take it: its section and its material, with units.
// A scene's parameters derive from it (as Box2D's joint definitions embed their base); validate it once and build
// the toolkit's beam spec from it.
#pragma once

#include <string>
#include <vector>

#include "plastic/BeamBuilder.h"
#include "plastic/JointFactory.h"

namespace scene
{
struct RectangularMember
{
	double section_width_m = 0.05;  // along the bending axis
	double section_depth_m = 0.10;  // in the bending plane: Mp = fy b d^2 / 4
	double yield_stress_pa = 400e6;
	double youngs_modulus_pa = 200e9;
	double density_kg_m3 = 7800;
};

// Appends "name: value is not in range" for every field out of its range (named as the runners' flags).
void validateMember(const RectangularMember& member, std::vector<std::string>& errors);

// The toolkit's spec of a beam of such a member from start_m to end_m in segments, bending about z, joined by method;
// its bodies kept awake (the scenes' loads change on resting bodies).
plastic::BeamSpec memberBeamSpec(const RectangularMember& member, const btVector3& start_m, const btVector3& end_m, int segments,
								 plastic::JointMethod method);
}  // namespace scene
