// The Charpy example's controls stand for valid scene parameters for every method, at their
// defaults and at both ends of every slider.
#include <gtest/gtest.h>

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
	for (int n = 1; n <= kCharpyMethodCount; n++)
	{
		const CharpyMethod method = charpyMethodByNumber(n);
		EXPECT_EQ(errorsOf(CharpyControls{}, method), "") << charpyMethodName(method);
	}
}

TEST(CharpyControls, BothEndsOfEverySliderAreValid)
{
	for (const CharpySlider& s : kCharpySliders)
	{
		for (float end : {s.min, s.max})
		{
			CharpyControls controls;
			controls.*s.value = btScalar(end);
			EXPECT_EQ(errorsOf(controls, CharpyMethod::PlasticHinge), "") << s.label << " = " << end;
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
	EXPECT_TRUE(controls != CharpyControls{});
	EXPECT_TRUE(CharpyControls{} == CharpyControls{});
}
