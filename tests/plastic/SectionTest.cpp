// The section toolkit against textbook formulas and steel catalogue values (which include root fillets, so the
// toolkit's fillet-free I section is a few percent below them).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "plastic/Section.h"

using namespace plastic;

TEST(Section, CharpyLigamentHasTheThesisPlasticMoment)
{
	// 10 mm wide, 10 mm deep, 2 mm notch: ligament 10 x 8 mm, Mp = 400 MPa * 10 * 8^2 / 4 mm^3 = 64 N m
	const SectionProperties s = notchedRectangle(0.010, 0.010, 0.002);
	EXPECT_NEAR(capacities(s, steel()).plastic_moment_y_nm, 64.0, 1e-9);
	EXPECT_NEAR(capacities(s, steel()).plastic_moment_z_nm, 80.0, 1e-9);  // 400 MPa * 8 * 10^2 / 4
}

TEST(Section, ShapeFactorsOfTextbookSections)
{
	// plastic modulus / elastic modulus: 1.5 for a rectangle, 16 / (3 pi) for a round bar
	const SectionProperties r = rectangle(0.02, 0.05);
	EXPECT_NEAR(r.plastic_modulus_y_m3 / (r.second_moment_y_m4 / 0.025), 1.5, 1e-12);
	const SectionProperties c = roundBar(0.03);
	EXPECT_NEAR(c.plastic_modulus_y_m3 / (c.second_moment_y_m4 / 0.015), 16.0 / (3.0 * M_PI), 1e-12);
	// a thin tube tends to 4 / pi
	const SectionProperties t = tube(0.5, 0.001);
	EXPECT_NEAR(t.plastic_modulus_y_m3 / (t.second_moment_y_m4 / 0.25), 4.0 / M_PI, 0.005);
}

TEST(Section, TorsionConstantsOfRectangles)
{
	// Timoshenko & Goodier's series values of beta in J = beta a b^3: 0.141 (a/b = 1), 0.196 (1.5), 0.263 (3)
	EXPECT_NEAR(rectangleTorsionConstant_m4(1, 1), 0.141, 0.001);
	EXPECT_NEAR(rectangleTorsionConstant_m4(1.5, 1) / 1.5, 0.196, 0.002);
	EXPECT_NEAR(rectangleTorsionConstant_m4(3, 1) / 3, 0.263, 0.002);
	// the Charpy ligament (10 x 8 mm) is not a square: beta 0.171, not the square's 0.141
	EXPECT_NEAR(notchedRectangle(0.010, 0.010, 0.002).torsion_constant_m4 / (0.010 * std::pow(0.008, 3)), 0.171, 0.001);
	// round bar: J = 2 I; fully plastic torque tau_y * pi d^3 / 12
	const SectionProperties c = roundBar(0.02);
	EXPECT_NEAR(c.torsion_constant_m4, 2 * c.second_moment_y_m4, 1e-20);
	EXPECT_NEAR(capacities(c, steel()).torque_nm, 400e6 / std::sqrt(3.0) * M_PI * 8e-6 / 12, 1e-6);
}

TEST(Section, TubeMatchesACatalogueCircularHollowSection)
{
	// CHS 114.3 x 6.3: A 21.4 cm^2, I 313 cm^4, W_pl 73.6 cm^3, I_T 625 cm^4
	const SectionProperties s = tube(0.1143, 0.0063);
	EXPECT_NEAR(s.area_m2 * 1e4, 21.4, 0.1);
	EXPECT_NEAR(s.second_moment_y_m4 * 1e8, 313, 1.5);
	EXPECT_NEAR(s.plastic_modulus_y_m3 * 1e6, 73.6, 0.3);
	EXPECT_NEAR(s.torsion_constant_m4 * 1e8, 625, 3);
}

TEST(Section, ISectionIsAFewPercentBelowACatalogueIpeWithItsFillets)
{
	// IPE 200: A 28.5 cm^2, I_y 1943 cm^4, W_pl,y 220.6 cm^3, I_z 142.4 cm^4, W_pl,z 44.61 cm^3 (root radius 12 mm)
	const SectionProperties s = iSection(0.200, 0.100, 0.0056, 0.0085);
	auto below = [](double ours, double catalogue, double within) {
		EXPECT_LE(ours, catalogue);
		EXPECT_GE(ours, catalogue * (1 - within));
	};
	below(s.area_m2 * 1e4, 28.5, 0.06);
	below(s.second_moment_y_m4 * 1e8, 1943, 0.06);
	below(s.plastic_modulus_y_m3 * 1e6, 220.6, 0.06);
	below(s.second_moment_z_m4 * 1e8, 142.4, 0.02);
	below(s.plastic_modulus_z_m3 * 1e6, 44.61, 0.02);
	EXPECT_NEAR(s.shear_area_m2, (0.200 - 2 * 0.0085) * 0.0056, 1e-12);
}

TEST(Section, StiffnessPerSegment)
{
	const SectionProperties s = rectangle(0.01, 0.02);
	const SegmentStiffness k = stiffness(s, steel(), 0.5);
	EXPECT_NEAR(k.axial_n_m, 200e9 * 2e-4 / 0.5, 1);
	EXPECT_NEAR(k.bending_y_nm_rad, 200e9 * (0.01 * 8e-6 / 12) / 0.5, 1e-3);
	EXPECT_NEAR(k.shear_n_m, 200e9 / 2.6 * 2e-4 / 0.5, 1);
	EXPECT_NEAR(k.torsion_nm_rad, 200e9 / 2.6 * s.torsion_constant_m4 / 0.5, 1e-6);
}

// The toolkit throws nothing: a refused section comes back with its error and every property 0.
TEST(Section, InvalidDimensionsAreRefusedByName)
{
	auto message = [](const SectionProperties& s)
	{
		const std::vector<std::string> errors = validate(s);
		if (!errors.empty())
		{
			EXPECT_EQ(0, s.area_m2) << s.error;
			EXPECT_EQ(0, s.plastic_modulus_y_m3) << s.error;
		}
		return errors.empty() ? std::string("no error") : errors.front();
	};
	EXPECT_NE(message(rectangle(-0.01, 0.02)).find("width: -0.01 is not in (0, inf) m"), std::string::npos);
	EXPECT_NE(message(roundBar(NAN)).find("diameter: "), std::string::npos);
	EXPECT_NE(message(tube(0.1, 0.06)).find("wall: 0.06"), std::string::npos);
	EXPECT_NE(message(notchedRectangle(0.01, 0.01, 0.01)).find("notch depth: "), std::string::npos);
	EXPECT_NE(message(iSection(0.2, 0.1, 0.2, 0.0085)).find("web thickness: "), std::string::npos);
	EXPECT_EQ("no error", message(rectangle(0.01, 0.02)));
	EXPECT_EQ(0, stiffness(rectangle(0.01, 0.01), steel(), 0).axial_n_m);  // JointSpec's validate names the segment length
}
