// A material from (strain, stress) pairs and a section's response to it (issue 23), against closed forms that do not
// come from the layering: the elastic-perfectly plastic rectangle's M = Mp (1 - (kappa_y / kappa)^2 / 3), the sections'
// elastic stiffness E I and fully plastic moments fy W_pl (Section.cpp's formulas), the shape factors, and a bilinear
// rectangle integrated by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plastic/SectionResponse.h"

using namespace plastic;

namespace
{
const double kE = 200e9, kFy = 400e6;

// M (N m) of a b x h rectangle of a bilinear material (E, fy, hardening alpha E) at a curvature past first yield: the
// elastic core |z| < c = eps_y / kappa and the hardening zones beyond it, integrated in closed form
double bilinearRectangleMoment(double b, double h, double alpha, double kappa)
{
	const double ey = kFy / kE, c = ey / kappa, t = h / 2;
	const double core = kE * kappa * c * c * c / 3;
	const double zones = kFy / 2 * (t * t - c * c) + alpha * kE * (kappa / 3 * (t * t * t - c * c * c) - ey / 2 * (t * t - c * c));
	return 2 * b * (core + zones);
}
}  // namespace

// CSV text: a header and comments are skipped, a line that is not two numbers is named, then the pairs are checked
TEST(StressStrain, ACsvCurveIsReadLineByLine)
{
	std::vector<std::string> errors;
	const StressStrainCurve curve = parseStressStrainCsv("# steel\nstrain,stress_pa\n\n0.002,400e6\n0.2, 796e6\n", errors);
	EXPECT_TRUE(errors.empty()) << (errors.empty() ? "" : errors.front());
	ASSERT_EQ(curve.pairs.size(), 2u);
	EXPECT_EQ(curve.pairs[1].stress_pa, 796e6);
	errors.clear();
	EXPECT_TRUE(parseStressStrainCsv("strain,stress\n0.002,400e6\n0.004;410e6\n", errors).pairs.empty());
	ASSERT_EQ(errors.size(), 1u);
	EXPECT_NE(errors[0].find("line 3: '0.004;410e6' is not two numbers"), std::string::npos) << errors[0];
	errors.clear();
	parseStressStrainCsv("0.002,400e6\n0.001,500e6\n", errors);
	ASSERT_FALSE(errors.empty());
	EXPECT_NE(errors[0].find("pair 2"), std::string::npos) << errors[0];
	errors.clear();
	parseStressStrainCsv("", errors);
	EXPECT_FALSE(errors.empty()) << "no pairs";
}

TEST(StressStrain, CurvesAreCheckedPairByPair)
{
	EXPECT_TRUE(validate(bilinear(kE, kFy, 0.02)).empty());
	EXPECT_TRUE(validate(elasticPerfectlyPlastic(steel())).empty());
	EXPECT_FALSE(validate(StressStrainCurve{}).empty());
	const StressStrainCurve decreasingStrain{{{0.002, 4e8}, {0.01, 4.2e8}, {0.005, 4.3e8}}};
	ASSERT_EQ(1u, validate(decreasingStrain).size());
	EXPECT_NE(validate(decreasingStrain).front().find("pair 3"), std::string::npos) << validate(decreasingStrain).front();
	const StressStrainCurve falling{{{0.002, 4e8}, {0.01, 3.9e8}}};
	EXPECT_NE(validate(falling).front().find("pair 2"), std::string::npos) << validate(falling).front();
	const StressStrainCurve stiffer{{{0.002, 4e8}, {0.003, 7e8}}};  // 300 GPa after a 200 GPa start
	EXPECT_NE(validate(stiffer).front().find("steeper"), std::string::npos) << validate(stiffer).front();
	const StressStrainCurve notANumber{{{0.002, std::nan("")}}};
	EXPECT_NE(validate(notANumber).front().find("not finite"), std::string::npos);
	// odd in strain, linear between pairs, flat past the last
	const StressStrainCurve c = bilinear(kE, kFy, 0.05, 0.1);
	EXPECT_DOUBLE_EQ(stress_pa(c, 0.001), 2e8);
	EXPECT_DOUBLE_EQ(stress_pa(c, -0.001), -2e8);
	EXPECT_NEAR(stress_pa(c, 0.012), kFy + 0.05 * kE * (0.012 - 0.002), 1);
	EXPECT_DOUBLE_EQ(stress_pa(c, 0.5), stress_pa(c, 0.1));
}

TEST(SectionResponse, ElasticPerfectlyPlasticRectangleFollowsItsClosedForm)
{
	const SectionProperties s = rectangle(0.05, 0.10);
	const StressStrainCurve c = elasticPerfectlyPlastic(kE, kFy);
	const std::vector<SectionLayer> layers = sectionLayers(s);
	const double mp = kFy * s.plastic_modulus_y_m3;
	const double ky = 2 * (kFy / kE) / s.depth_m;
	for (double r : {0.5, 1.0, 1.5, 2.0, 4.0, 10.0})
	{
		const double expected = r <= 1 ? kE * s.second_moment_y_m4 * r * ky : mp * (1 - 1 / (3 * r * r));
		EXPECT_NEAR(sectionForces(layers, c, 0, r * ky).moment_nm, expected, 0.005 * expected) << "kappa / kappa_y = " << r;
	}
	// no axial force in pure bending, and a uniform strain gives A sigma
	EXPECT_NEAR(sectionForces(layers, c, 0, 3 * ky).axial_n, 0, 1e-6 * mp);
	EXPECT_NEAR(sectionForces(layers, c, 0.001, 0).axial_n, s.area_m2 * 2e8, 1e-6 * s.area_m2 * 2e8);
}

TEST(SectionResponse, EverySectionHasItsStiffnessItsPlasticMomentAndItsShapeFactor)
{
	const StressStrainCurve c = elasticPerfectlyPlastic(kE, kFy);
	struct Case
	{
		const char* name;
		SectionProperties section;
		double shape_factor;  // W_pl / W_el, from the geometry alone
	};
	const double D = 0.1, d = D - 2 * 0.008;
	const Case cases[] = {
		{"rectangle", rectangle(0.05, 0.10), 1.5},
		{"round bar", roundBar(0.05), 16 / (3 * M_PI)},
		{"tube", tube(D, 0.008), ((D * D * D - d * d * d) / 6) / (M_PI * (std::pow(D, 4) - std::pow(d, 4)) / (32 * D))},
		{"I section", iSection(0.2, 0.1, 0.0056, 0.0085), 0},
	};
	for (const Case& k : cases)
	{
		const SectionProperties& s = k.section;
		const std::vector<SectionLayer> layers = sectionLayers(s);
		const double ky = 2 * (kFy / kE) / s.depth_m;
		const double elastic = sectionForces(layers, c, 0, 0.5 * ky).moment_nm;
		EXPECT_NEAR(elastic, kE * s.second_moment_y_m4 * 0.5 * ky, 0.005 * elastic) << k.name << ": E I";
		const double plastic = sectionForces(layers, c, 0, 1000 * ky).moment_nm;
		EXPECT_NEAR(plastic, kFy * s.plastic_modulus_y_m3, 0.005 * plastic) << k.name << ": fy W_pl";
		const double my = kFy * s.second_moment_y_m4 / (s.depth_m / 2);
		if (k.shape_factor > 0)
		{
			EXPECT_NEAR(plastic / my, k.shape_factor, 0.005 * k.shape_factor) << k.name << ": shape factor";
		}
		std::printf("[ info     ] %s: shape factor %.4f\n", k.name, plastic / my);
	}
}

TEST(SectionResponse, BilinearRectangleFollowsItsClosedForm)
{
	const SectionProperties s = rectangle(0.05, 0.10);
	for (double alpha : {0.01, 0.05})
	{
		const StressStrainCurve c = bilinear(kE, kFy, alpha);
		const std::vector<MomentCurvaturePoint> mk = momentCurvature(s, c, 20 * 2 * (kFy / kE) / s.depth_m, 40);
		ASSERT_EQ(41u, mk.size());
		for (const MomentCurvaturePoint& p : mk)
		{
			const double ky = 2 * (kFy / kE) / s.depth_m;
			if (p.curvature_1_m <= ky) continue;
			const double expected = bilinearRectangleMoment(0.05, 0.10, alpha, p.curvature_1_m);
			EXPECT_NEAR(p.moment_nm, expected, 0.005 * expected) << "alpha " << alpha << ", kappa " << p.curvature_1_m;
		}
		// it hardens: at 20 kappa_y the moment is above Mp by about alpha E I kappa
		EXPECT_GT(mk.back().moment_nm, kFy * s.plastic_modulus_y_m3);
	}
	EXPECT_TRUE(sectionLayers(rectangle(-1, 0.1)).empty());  // a refused section has no layers
}
