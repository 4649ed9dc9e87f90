// The browser examples' controls: their starting values are the runner's defaults (solver aside), their scene is the
// runner's (a controls-built scene stepped to the end gives the runner's result), and bad values are named.
#include <gtest/gtest.h>

#include <stdexcept>

#include "SceneControls.h"

using namespace structures;

TEST(SceneControls, StartAtTheRunnersDefaults)
{
	const CantileverParameters c = cantileverFromSliders(scene::initialValues(cantileverControls()), plastic::JointMethod::PlasticHinge);
	const CantileverParameters cd;
	EXPECT_EQ(c.load_ratio, cd.load_ratio);
	EXPECT_EQ(c.segments, cd.segments);
	EXPECT_EQ(c.length_m, cd.length_m);
	EXPECT_NEAR(c.section_depth_m, cd.section_depth_m, 1e-9);
	EXPECT_EQ(c.yield_stress_pa, cd.yield_stress_pa);
	EXPECT_EQ(c.follower_load, cd.follower_load);
	const PortalParameters p = portalFromSliders(scene::initialValues(portalControls()), plastic::JointMethod::PlasticHinge);
	const PortalParameters pd;
	EXPECT_EQ(p.horizontal_load_n, pd.horizontal_load_n);
	EXPECT_EQ(p.vertical_load_n, pd.vertical_load_n);
	EXPECT_EQ(p.span_m, pd.span_m);
	EXPECT_EQ(p.height_m, pd.height_m);
	EXPECT_NEAR(p.ramp_rate_per_s, pd.ramp_rate_per_s, 1e-9);
	EXPECT_EQ(p.knee_load_n, pd.knee_load_n);
	EXPECT_EQ(p.sway_drifts, pd.sway_drifts);
	const DropWeightParameters d = dropWeightFromSliders(scene::initialValues(dropWeightControls()), plastic::JointMethod::ElasticPlastic2);
	const DropWeightParameters dd;
	EXPECT_EQ(d.weight_mass_kg, dd.weight_mass_kg);
	EXPECT_EQ(d.impact_speed_m_s, dd.impact_speed_m_s);
	EXPECT_EQ(d.span_m, dd.span_m);
	EXPECT_EQ(d.segments, dd.segments);
	EXPECT_EQ(d.clamped, dd.clamped);
	EXPECT_EQ(d.solver.method, plastic::JointMethod::ElasticPlastic2);
	EXPECT_NEAR(d.solver.world.internal_step_s, dd.solver.world.internal_step_s, 1e-9);
	EXPECT_EQ(d.solver.world.iterations, dd.solver.world.iterations);
	EXPECT_EQ(d.solver.world.solver, dd.solver.world.solver);
	const PaperClipParameters k = paperClipFromSliders(scene::initialValues(paperClipControls()), plastic::JointMethod::PlasticHinge);
	const PaperClipParameters kd;
	EXPECT_NEAR(k.bend_amplitude_rad, kd.bend_amplitude_rad, 1e-6);
	EXPECT_EQ(k.cycle_period_s, kd.cycle_period_s);
	EXPECT_NEAR(k.wire_diameter_m, kd.wire_diameter_m, 1e-12);
	EXPECT_NEAR(k.hinge_length_m, kd.hinge_length_m, 1e-12);
	EXPECT_NEAR(k.reduction_of_area, kd.reduction_of_area, 1e-7);
}

// Every slider at its minimum and at its maximum still builds a scene (the ranges are inside the parameters' ranges).
TEST(SceneControls, EverySliderRangeBuilds)
{
	for (const scene::ControlledScene& scene : {cantileverControls(), portalControls(), dropWeightControls(), paperClipControls()})
		for (size_t i = 0; i < scene.sliders.size(); i++)
			for (float v : {scene.sliders[i].min, scene.sliders[i].max})
			{
				std::vector<float> values = scene::initialValues(scene);
				values[i] = v;
				EXPECT_NO_THROW(scene.build(values, "plastic-hinge")) << scene.name << ": " << scene.sliders[i].label << " = " << v;
			}
}

TEST(SceneControls, BadValuesAreNamed)
{
	const scene::ControlledScene c = cantileverControls();
	std::vector<float> values = scene::initialValues(c);
	values[1] = 0;  // segments
	try
	{
		c.build(values, "plastic-hinge");
		FAIL() << "0 segments built";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_EQ(std::string(e.what()), "segments: 0 is not in [1, 1000]");
	}
	EXPECT_THROW(c.build({1, 2}, "plastic-hinge"), std::invalid_argument);
}

// The example's scene is the runner's: stepped to the end it gives runDropWeight's figures to the last bit, and its
// ledger shows them.
TEST(SceneControls, TheExampleSceneIsTheRunnersScene)
{
	const scene::ControlledScene c = dropWeightControls();
	const std::vector<float> values = scene::initialValues(c);
	std::unique_ptr<scene::SteppedScene> scene = c.build(values, "plastic-hinge");
	while (!scene->done()) scene->step();
	const DropWeightResult r = runDropWeight(dropWeightFromSliders(values, plastic::JointMethod::PlasticHinge));
	const scene::SceneLedger l = scene->ledger();
	EXPECT_EQ(l.plastic_booked_j, r.booked_plastic_work_j);
	EXPECT_EQ(l.plastic_measured_j, r.geometric_plastic_work_j);
	EXPECT_EQ(l.kinetic_j, r.kinetic_end_j);
	EXPECT_EQ(l.time_s, r.simulated_s);
	EXPECT_GT(l.plastic_booked_j, 0);
	const std::string text = scene::ledgerText(l);
	EXPECT_NE(text.find("drop weight, simply supported, plastic-hinge"), std::string::npos) << text;
	EXPECT_NE(text.find("analytic: after impact"), std::string::npos) << text;
	// the mid-span joint has yielded, the others not; no joint is broken
	int yielded = 0;
	for (const scene::JointView& j : scene->joints())
	{
		EXPECT_FALSE(j.broken);
		yielded += j.yielded;
	}
	EXPECT_EQ(yielded, 1);
}
