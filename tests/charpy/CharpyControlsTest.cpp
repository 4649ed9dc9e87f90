// The Charpy example's controls stand for valid scene parameters for every method, at their
// defaults and at both ends of every slider; they build the scene.
#include <gtest/gtest.h>

#include <stdexcept>

#include "CharpyControls.h"
#include "CharpyParameters.h"

namespace
{
std::string errorsOf(const CharpyControls& controls, CharpyMethod method)
{
	std::string text;
	for (const std::string& e : validateCharpyParameters(charpyParametersFromControls(controls, method))) text += e + "; ";
	return text;
}
}  // namespace

TEST(CharpyControls, DefaultsAreValidForEveryMethod)
{
	const scene::ControlledScene c = charpyControls();
	ASSERT_EQ(size_t(kCharpyMethodCount), c.methods.size());
	for (int n = 1; n <= kCharpyMethodCount; n++)
	{
		const CharpyMethod method = charpyMethodByNumber(n);
		EXPECT_EQ(errorsOf(charpyControlsFromSliders(scene::initialValues(c)), method), "") << charpyMethodName(method);
		EXPECT_EQ(c.methods[size_t(n - 1)], charpyMethodName(method));
	}
}

TEST(CharpyControls, BothEndsOfEverySliderAreValid)
{
	const scene::ControlledScene c = charpyControls();
	for (size_t i = 0; i < c.sliders.size(); i++)
	{
		for (float end : {c.sliders[i].min, c.sliders[i].max})
		{
			std::vector<float> values = scene::initialValues(c);
			values[i] = end;
			EXPECT_EQ(errorsOf(charpyControlsFromSliders(values), CharpyMethod::PlasticHinge), "") << c.sliders[i].label << " = " << end;
		}
	}
}

TEST(CharpyControls, ParametersCarryTheControlsInSceneUnits)
{
	CharpyControls controls;
	controls.yieldStress_MPa = 200;
	controls.frameStep_ms = 1;
	controls.partPairs = 3;
	controls.anvilGap_mm = 30;
	const CharpyParameters p = charpyParametersFromControls(controls, CharpyMethod::ElasticPlastic2);
	EXPECT_EQ(p.method, CharpyMethod::ElasticPlastic2);
	EXPECT_DOUBLE_EQ(p.yield_stress_pa, 200e6);
	EXPECT_NEAR(p.dt_s, 1e-3, 1e-12);
	EXPECT_EQ(p.parts, 6);
	EXPECT_NEAR(p.anvil_gap_m, 0.03, 1e-9);
}

// the example's scene is the runner's: the same parameters step the same world
TEST(CharpyControls, TheyBuildTheSceneOfTheirMethod)
{
	const scene::ControlledScene c = charpyControls();
	std::unique_ptr<scene::SteppedScene> built = c.build(scene::initialValues(c), "elastic-plastic2");
	ASSERT_TRUE(built);
	EXPECT_NE(built->ledger().title.find("elastic-plastic2"), std::string::npos) << built->ledger().title;
	EXPECT_EQ(1u, built->joints().size());  // one part pair: one joint
	EXPECT_THROW(c.build(scene::initialValues(c), "welded"), std::invalid_argument);
	EXPECT_THROW(c.build({1, 2}, "plastic-hinge"), std::invalid_argument);
}
