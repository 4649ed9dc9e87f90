#include "Section.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastic
{
namespace
{
bool positive(double value) { return value > 0 && std::isfinite(value); }

// "name: value is not in range m", as every refusal of a dimension reads
std::string notIn(const char* name, double value, const std::string& range)
{
	std::ostringstream out;
	out << name << ": " << value << " is not in " << range << " m";
	return out.str();
}

std::string notPositive(const char* name, double value) { return notIn(name, value, "(0, inf)"); }

// a section a factory refused: every property 0, the reason in error
SectionProperties refused(const char* shape, std::string error)
{
	SectionProperties s;
	s.shape = shape;
	s.error = std::move(error);
	return s;
}
}  // namespace

double webAxialFraction(const SectionProperties& section)
{
	if (section.axial_interaction != AxialInteraction::ISection) return 1.0;
	const double webArea_m2 = section.web_thickness_m * (section.depth_m - 2.0 * section.flange_thickness_m);
	return webArea_m2 / section.area_m2;
}

double flangeMomentFraction(const SectionProperties& section)
{
	if (section.axial_interaction != AxialInteraction::ISection) return 0.0;
	const double tf = section.flange_thickness_m;
	return section.width_m * tf * (section.depth_m - tf) / section.plastic_modulus_y_m3;
}

std::vector<std::string> validate(const SectionProperties& section)
{
	if (section.error.empty()) return {};
	return {section.error};
}

double rectangleTorsionConstant_m4(double side1_m, double side2_m)
{
	const double a = std::max(side1_m, side2_m), b = std::min(side1_m, side2_m);
	const double r = b / a;
	const double beta = (1.0 - 0.63 * r + 0.052 * std::pow(r, 5)) / 3.0;
	return beta * a * b * b * b;
}

SectionProperties rectangle(double width_m, double depth_m)
{
	if (!positive(width_m)) return refused("rectangle", notPositive("width", width_m));
	if (!positive(depth_m)) return refused("rectangle", notPositive("depth", depth_m));
	const double b = width_m, h = depth_m;
	const double a = std::max(b, h), t = std::min(b, h);
	SectionProperties s;
	s.shape = "rectangle";
	s.biaxial_interaction = BiaxialInteraction::Rectangle;
	s.axial_interaction = AxialInteraction::Rectangle;
	s.width_m = b;
	s.depth_m = h;
	s.area_m2 = b * h;
	s.shear_area_m2 = s.area_m2;
	s.second_moment_y_m4 = b * h * h * h / 12.0;
	s.second_moment_z_m4 = h * b * b * b / 12.0;
	s.plastic_modulus_y_m3 = b * h * h / 4.0;
	s.plastic_modulus_z_m3 = h * b * b / 4.0;
	s.torsion_constant_m4 = rectangleTorsionConstant_m4(b, h);
	s.plastic_torsion_modulus_m3 = t * t * (3.0 * a - t) / 6.0;  // sand-heap analogy
	return s;
}

SectionProperties notchedRectangle(double width_m, double depth_m, double notch_depth_m)
{
	if (!positive(depth_m)) return refused("notched rectangle", notPositive("depth", depth_m));
	if (!(notch_depth_m >= 0) || !(notch_depth_m < depth_m))
	{
		std::ostringstream range;
		range << "[0, depth = " << depth_m << ")";
		return refused("notched rectangle", notIn("notch depth", notch_depth_m, range.str()));
	}
	SectionProperties s = rectangle(width_m, depth_m - notch_depth_m);
	s.shape = "notched rectangle";
	return s;
}

SectionProperties roundBar(double diameter_m)
{
	if (!positive(diameter_m)) return refused("round bar", notPositive("diameter", diameter_m));
	const double d = diameter_m;
	SectionProperties s;
	s.shape = "round bar";
	s.biaxial_interaction = BiaxialInteraction::Circle;
	s.torsion_interaction = TorsionInteraction::Circle;
	s.width_m = s.depth_m = d;
	s.area_m2 = M_PI * d * d / 4.0;
	s.shear_area_m2 = s.area_m2;
	s.second_moment_y_m4 = s.second_moment_z_m4 = M_PI * std::pow(d, 4) / 64.0;
	s.plastic_modulus_y_m3 = s.plastic_modulus_z_m3 = d * d * d / 6.0;
	s.torsion_constant_m4 = M_PI * std::pow(d, 4) / 32.0;
	s.plastic_torsion_modulus_m3 = M_PI * d * d * d / 12.0;
	return s;
}

SectionProperties tube(double outer_diameter_m, double wall_m)
{
	if (!positive(outer_diameter_m)) return refused("tube", notPositive("outer diameter", outer_diameter_m));
	if (!(wall_m > 0) || !(2.0 * wall_m < outer_diameter_m))
	{
		std::ostringstream range;
		range << "(0, outer diameter / 2 = " << outer_diameter_m / 2.0 << ")";
		return refused("tube", notIn("wall", wall_m, range.str()));
	}
	const double D = outer_diameter_m, d = outer_diameter_m - 2.0 * wall_m;
	SectionProperties s;
	s.shape = "tube";
	s.wall_m = wall_m;
	s.biaxial_interaction = BiaxialInteraction::Circle;
	s.torsion_interaction = TorsionInteraction::Circle;
	s.width_m = s.depth_m = D;
	s.area_m2 = M_PI * (D * D - d * d) / 4.0;
	s.shear_area_m2 = 2.0 * s.area_m2 / M_PI;
	s.second_moment_y_m4 = s.second_moment_z_m4 = M_PI * (std::pow(D, 4) - std::pow(d, 4)) / 64.0;
	s.plastic_modulus_y_m3 = s.plastic_modulus_z_m3 = (D * D * D - d * d * d) / 6.0;
	s.torsion_constant_m4 = M_PI * (std::pow(D, 4) - std::pow(d, 4)) / 32.0;
	s.plastic_torsion_modulus_m3 = M_PI * (D * D * D - d * d * d) / 12.0;
	return s;
}

SectionProperties iSection(double depth_m, double flange_width_m, double web_thickness_m, double flange_thickness_m)
{
	if (!positive(depth_m)) return refused("I section", notPositive("depth", depth_m));
	if (!positive(flange_width_m)) return refused("I section", notPositive("flange width", flange_width_m));
	if (!(flange_thickness_m > 0) || !(2.0 * flange_thickness_m < depth_m))
	{
		std::ostringstream range;
		range << "(0, depth / 2 = " << depth_m / 2.0 << ")";
		return refused("I section", notIn("flange thickness", flange_thickness_m, range.str()));
	}
	if (!(web_thickness_m > 0) || !(web_thickness_m <= flange_width_m))
	{
		std::ostringstream range;
		range << "(0, flange width = " << flange_width_m << "]";
		return refused("I section", notIn("web thickness", web_thickness_m, range.str()));
	}
	const double h = depth_m, b = flange_width_m, tw = web_thickness_m, tf = flange_thickness_m;
	const double hw = h - 2.0 * tf;  // clear web depth
	SectionProperties s;
	s.shape = "I section";
	s.flange_thickness_m = tf;
	s.web_thickness_m = tw;
	s.biaxial_interaction = BiaxialInteraction::ISection;
	s.axial_interaction = AxialInteraction::ISection;
	s.width_m = b;
	s.depth_m = h;
	s.area_m2 = 2.0 * b * tf + hw * tw;
	s.shear_area_m2 = hw * tw;
	s.second_moment_y_m4 = b * h * h * h / 12.0 - (b - tw) * hw * hw * hw / 12.0;
	s.second_moment_z_m4 = 2.0 * tf * b * b * b / 12.0 + hw * tw * tw * tw / 12.0;
	s.plastic_modulus_y_m3 = b * tf * (h - tf) + tw * hw * hw / 4.0;
	s.plastic_modulus_z_m3 = tf * b * b / 2.0 + hw * tw * tw / 4.0;
	// thin-walled open section: J = sum of l t^3 / 3, plastic torque = sum of l t^2 / 2 (times tau_y)
	s.torsion_constant_m4 = (2.0 * b * tf * tf * tf + (h - tf) * tw * tw * tw) / 3.0;
	s.plastic_torsion_modulus_m3 = (2.0 * b * tf * tf + hw * tw * tw) / 2.0;
	return s;
}

SectionCapacities capacities(const SectionProperties& s, const Material& m)
{
	SectionCapacities c;
	c.axial_n = m.yield_stress_pa * s.area_m2;
	c.shear_n = m.shearYieldStress_pa() * s.shear_area_m2;
	c.plastic_moment_y_nm = m.yield_stress_pa * s.plastic_modulus_y_m3;
	c.plastic_moment_z_nm = m.yield_stress_pa * s.plastic_modulus_z_m3;
	c.torque_nm = m.shearYieldStress_pa() * s.plastic_torsion_modulus_m3;
	return c;
}

SegmentStiffness stiffness(const SectionProperties& s, const Material& m, double segment_length_m)
{
	SegmentStiffness k;
	if (!positive(segment_length_m)) return k;
	const double L = segment_length_m;
	k.axial_n_m = m.youngs_modulus_pa * s.area_m2 / L;
	k.shear_n_m = m.shearModulus_pa() * s.shear_area_m2 / L;
	k.bending_y_nm_rad = m.youngs_modulus_pa * s.second_moment_y_m4 / L;
	k.bending_z_nm_rad = m.youngs_modulus_pa * s.second_moment_z_m4 / L;
	k.torsion_nm_rad = m.shearModulus_pa() * s.torsion_constant_m4 / L;
	return k;
}
}  // namespace plastic
