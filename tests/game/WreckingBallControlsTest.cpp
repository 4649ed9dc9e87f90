#include <gtest/gtest.h>

#include "WreckingBallControls.h"

using namespace game;

// The example starts where the runner does: the same parameters, so the same scene.
TEST(WreckingBallControls, StartAtTheRunnersDefaults)
{
	const WreckingBallParameters p = wreckingBallFromSliders(scene::initialValues(wreckingBallControls()), plastic::JointMethod::PlasticHinge);
	const WreckingBallParameters d;
	EXPECT_FLOAT_EQ(float(p.release_angle_rad), float(d.release_angle_rad));
	EXPECT_EQ(p.ball_mass_kg, d.ball_mass_kg);
	EXPECT_EQ(p.yield_stress_pa, d.yield_stress_pa);
	EXPECT_FLOAT_EQ(float(p.max_plastic_rotation_rad), float(d.max_plastic_rotation_rad));
	EXPECT_EQ(p.chain_length_m, d.chain_length_m);
	EXPECT_EQ(p.impact_height_m, d.impact_height_m);
	EXPECT_EQ(p.solver.solver, d.solver.solver);
	EXPECT_EQ(p.solver.iterations, d.solver.iterations);
}

TEST(WreckingBallControls, EverySliderRangeBuilds)
{
	const scene::ControlledScene scene = wreckingBallControls();
	for (size_t i = 0; i < scene.sliders.size(); i++)
		for (float v : {scene.sliders[i].min, scene.sliders[i].max})
		{
			std::vector<float> values = scene::initialValues(scene);
			values[i] = v;
			EXPECT_NO_THROW(scene.build(values, "plastic-hinge")) << scene.sliders[i].label << " = " << v;
		}
}

// The building example: the wrecking ball's sliders and their defaults, then storeys and bays (5 and 4 at the start);
// every slider's range builds.
TEST(BuildingControls, StartAtFiveStoreysAndFourBaysAndEveryRangeBuilds)
{
	const scene::ControlledScene scene = buildingControls();
	const std::vector<float> start = scene::initialValues(scene);
	const WreckingBallParameters p = buildingFromSliders(start, plastic::JointMethod::PlasticHinge);
	const WreckingBallParameters d;
	EXPECT_EQ(p.storeys, 5);
	EXPECT_EQ(p.bays, 4);
	EXPECT_FLOAT_EQ(float(p.release_angle_rad), float(d.release_angle_rad));
	EXPECT_EQ(p.solver.solver, d.solver.solver);
	EXPECT_THROW(buildingFromSliders(std::vector<float>(start.begin(), start.begin() + 8), plastic::JointMethod::PlasticHinge), std::invalid_argument);
	for (size_t i = 0; i < scene.sliders.size(); i++)
		for (float v : {scene.sliders[i].min, scene.sliders[i].max})
		{
			std::vector<float> values = start;
			values[i] = v;
			EXPECT_NO_THROW(scene.build(values, "plastic-hinge")) << scene.sliders[i].label << " = " << v;
		}
}
