#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "CityControls.h"
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

// The city example: its method choice is the mode; it starts just in time with nine buildings, three hit, the
// runner's building and ball; every slider's range builds (with no more buildings hit than there are: more is
// refused by name, and the example shows the message).
TEST(CityControls, StartJustInTimeAndEveryRangeBuilds)
{
	const scene::ControlledScene scene = cityControls();
	const std::vector<float> start = scene::initialValues(scene);
	const CityParameters p = cityFromSliders(start, scene.method);
	const CityParameters d;
	EXPECT_EQ(p.mode, CityMode::JustInTime);
	EXPECT_EQ(p.buildings, 9);
	EXPECT_EQ(p.hit, 3);
	EXPECT_EQ(p.spacing_m, d.spacing_m);
	EXPECT_FLOAT_EQ(float(p.building.release_angle_rad), float(d.building.release_angle_rad));
	EXPECT_EQ(p.building.ball_mass_kg, d.building.ball_mass_kg);
	for (const std::string& mode : scene.methods) EXPECT_NO_THROW(scene.build(start, mode)) << mode;
	EXPECT_THROW(cityFromSliders(start, "fast"), std::invalid_argument);
	for (size_t i = 0; i < scene.sliders.size(); i++)
		for (float v : {scene.sliders[i].min, scene.sliders[i].max})
		{
			std::vector<float> values = start;
			values[i] = v;
			if (std::string(scene.sliders[i].label) == "hit") values[0] = std::max(v, 1.0f);        // buildings
			if (std::string(scene.sliders[i].label) == "buildings") values[1] = std::min(values[1], v);  // hit
			EXPECT_NO_THROW(scene.build(values, scene.method)) << scene.sliders[i].label << " = " << v;
		}
	std::vector<float> values = start;
	values[1] = values[0] + 1;
	try
	{
		scene.build(values, scene.method);
		ADD_FAILURE() << "more hit buildings than buildings built";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("hit: 10 is not in [0, 9]"), std::string::npos) << e.what();
	}
}
