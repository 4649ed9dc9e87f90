#include "RectangularMember.h"

#include "Ranges.h"
#include "plastic/Section.h"

namespace scene
{
void validateMember(const RectangularMember& member, std::vector<std::string>& errors)
{
	requireRange(errors, "section-width", member.section_width_m, 1e-4, 10, "m");
	requireRange(errors, "section-depth", member.section_depth_m, 1e-4, 10, "m");
	requireRange(errors, "fy", member.yield_stress_pa, 1e3, 1e11, "Pa");
	requireRange(errors, "youngs-modulus", member.youngs_modulus_pa, 1e3, 1e13, "Pa");
	requireRange(errors, "density", member.density_kg_m3, 1, 1e5, "kg/m3");
}

plastic::BeamSpec memberBeamSpec(const RectangularMember& member, const btVector3& start_m, const btVector3& end_m, int segments,
								 plastic::JointMethod method)
{
	plastic::BeamSpec spec;
	spec.may_sleep = false;
	spec.start_m = start_m;
	spec.end_m = end_m;
	spec.segments = segments;
	spec.bending_axis = btVector3(0, 0, 1);
	spec.joint.section = plastic::rectangle(member.section_width_m, member.section_depth_m);
	spec.joint.material.yield_stress_pa = member.yield_stress_pa;
	spec.joint.material.youngs_modulus_pa = member.youngs_modulus_pa;
	spec.joint.material.density_kg_m3 = member.density_kg_m3;
	spec.joint.method = method;
	return spec;
}
}  // namespace scene
