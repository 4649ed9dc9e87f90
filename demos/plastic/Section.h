// Cross-sections of a member: geometric properties, plastic capacities and elastic stiffness per length.
// The member runs along its local x; the section lies in y-z. "About y" is bending in the x-z plane (the
// depth along z resists it), "about z" bending in the x-y plane. Every length is in m, every result carries
// its unit in its name. Invalid dimensions are refused, not thrown: the section comes back with every property 0 and
// its error naming the parameter and its valid range (validate(section)).
#pragma once

#include <string>
#include <vector>

#include "Material.h"

namespace plastic
{
// The fully plastic interaction of a section's two bending moments (u = M / Mp about each axis): the curve on which
// a bt6DofElasticPlastic2Constraint yields when a joint asks for it (JointSpec::yield_surface).
enum class BiaxialInteraction
{
	None,       // not known: each axis yields alone
	Circle,     // round bar, tube: uy^2 + uz^2 = 1
	Rectangle,  // uy + 3/4 uz^2 = 1 for uz <= uy (and the other way round)
	ISection,   // uz + uy^2 = 1 (weak axis z, strong axis y; EN 1993-1-1 6.2.9.1 (6) without axial force)
};

// The fully plastic interaction of the main bending moment (about y, u = My / Mp_y) with the axial force
// (n = N / Np): the curve on which a bt6DofElasticPlastic2Constraint yields with JointSpec::yield_surface =
// YieldSurface::BendingAxial.
enum class AxialInteraction
{
	None,       // not known: each yields alone
	Rectangle,  // u + n^2 = 1 (the stress blocks of a fully plastic rectangle)
	ISection,   // strong-axis bending: u = 1 - (1 - f) (n / w)^2 while the neutral axis is in the web (n <= w), then
				// the flanges' stress blocks (w = webAxialFraction, f = flangeMomentFraction of the section)
};

// The fully plastic interaction of the main bending moment (u = My / Mp_y) with the torque (t = T / Tp): the curve on
// which a bt6DofElasticPlastic2Constraint yields with JointSpec::yield_surface = YieldSurface::BendingTorsion.
enum class TorsionInteraction
{
	None,    // not known: each yields alone
	Circle,  // u^2 + t^2 = 1: the torque's shear, uniform over a thin wall, leaves the bending sqrt(fy^2 - 3 tau^2)
			 // (von Mises): exact for a thin tube, a lower bound for a thick tube or a round bar
};

struct SectionProperties
{
	std::string shape;
	double width_m = 0;   // bounding box along y
	double depth_m = 0;   // bounding box along z
	double area_m2 = 0;
	double shear_area_m2 = 0;            // area that carries shear in the plastic shear capacity
	double second_moment_y_m4 = 0;       // I about y
	double second_moment_z_m4 = 0;       // I about z
	double plastic_modulus_y_m3 = 0;     // W_pl about y: Mp_y = fy * W_pl_y
	double plastic_modulus_z_m3 = 0;
	double torsion_constant_m4 = 0;      // St Venant J: torsional stiffness G J / L
	double plastic_torsion_modulus_m3 = 0;  // fully plastic torque = tau_y * this
	double wall_m = 0;                      // tube: its wall (0 for the other shapes)
	double flange_thickness_m = 0;          // I section: its flanges' and web's thickness (0 for the other shapes)
	double web_thickness_m = 0;
	BiaxialInteraction biaxial_interaction = BiaxialInteraction::None;
	AxialInteraction axial_interaction = AxialInteraction::None;
	TorsionInteraction torsion_interaction = TorsionInteraction::None;
	std::string error;  // empty for a valid section; else why the factory refused it (its properties are 0)
};

// An I section's moment-axial curve (AxialInteraction::ISection): the web's share of the area, t_w (h - 2 t_f) / A,
// and the flanges' share of the plastic modulus about y, b t_f (h - t_f) / W_pl_y. 1 and 0 for the other shapes.
double webAxialFraction(const SectionProperties& section);
double flangeMomentFraction(const SectionProperties& section);

// the section's error, if it has one (a message naming the parameter and its valid range)
std::vector<std::string> validate(const SectionProperties& section);

// Capacities (N, N m) of a section of a material: the forces and moments at which it is fully plastic.
struct SectionCapacities
{
	double axial_n = 0;
	double shear_n = 0;
	double plastic_moment_y_nm = 0;
	double plastic_moment_z_nm = 0;
	double torque_nm = 0;
};

// Elastic stiffness of a segment of length L (N/m, N m/rad): EA/L, GA/L, EI/L, GJ/L.
struct SegmentStiffness
{
	double axial_n_m = 0;
	double shear_n_m = 0;
	double bending_y_nm_rad = 0;
	double bending_z_nm_rad = 0;
	double torsion_nm_rad = 0;
};

// Solid rectangle: width along y, depth along z.
SectionProperties rectangle(double width_m, double depth_m);
// The rectangle at a notch of notch_depth_m cut into its depth: the ligament width x (depth - notch).
SectionProperties notchedRectangle(double width_m, double depth_m, double notch_depth_m);
// Solid round bar.
SectionProperties roundBar(double diameter_m);
// Circular tube (outer diameter, wall thickness); the shear area is 2 A / pi.
SectionProperties tube(double outer_diameter_m, double wall_m);
// Doubly symmetric I section: depth along z, flange width along y; without root fillets (catalogue values,
// which include them, are a few percent higher). The shear area is the web's, (depth - 2 flange) x web.
SectionProperties iSection(double depth_m, double flange_width_m, double web_thickness_m, double flange_thickness_m);

SectionCapacities capacities(const SectionProperties& section, const Material& material);
// all 0 for a segment length that is not in (0, inf) m (JointSpec's validate names it)
SegmentStiffness stiffness(const SectionProperties& section, const Material& material, double segment_length_m);

// St Venant torsion constant of a solid rectangle with sides a >= b: beta a b^3, beta = 1/3 (1 - 0.63 b/a +
// 0.052 (b/a)^5) (Roark): 0.141 for a square, 0.196 for 8 x 10 mm, -> 1/3 for a thin strip.
double rectangleTorsionConstant_m4(double side1_m, double side2_m);
}  // namespace plastic
