// The city (issue 24): its buildings simulated just in time book the plastic work of the always-jointed city, cost the
// world nothing but the balls before the first impact, and subdivide only the buildings that are hit; rigid buildings
// book nothing. Internal steps and bodies are counted, not timed (build/bin/city times them).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "City.h"

using namespace game;

namespace
{
CityParameters city(CityMode mode)
{
	CityParameters p;
	p.mode = mode;
	p.buildings = 6;
	p.hit = 2;
	p.building.duration_s = 2.5;
	return p;
}
}  // namespace

TEST(City, JustInTimeBooksTheJointedCitysPlasticWork)
{
	const CityResult jit = runCity(city(CityMode::JustInTime)), jointed = runCity(city(CityMode::Jointed)), rigid = runCity(city(CityMode::Rigid));
	const CityParameters p = city(CityMode::JustInTime);
	const int chain = p.hit * (p.building.chain_links + 1);  // the balls and their links
	ASSERT_TRUE(jit.finite && jointed.finite && rigid.finite);
	EXPECT_GT(jointed.plastic_energy_j, 0.5 * jointed.impact_energy_j) << "the balls bend the frames";
	EXPECT_NEAR(jit.plastic_energy_j, jointed.plastic_energy_j, 0.05 * jointed.plastic_energy_j);
	EXPECT_EQ(rigid.plastic_energy_j, 0.0);
	// only the hit buildings subdivide, just before the balls reach them: until the first impact the world holds the balls,
	// their chains and at most the hit buildings' segments (12 each) and joints (13 each)
	// every member of a hit building (two columns and a beam), which a ball's blow loads through its joints
	EXPECT_EQ(jit.subdivisions, 3 * p.hit);
	EXPECT_LE(jit.idle_bodies_max, chain + p.hit * 12);
	EXPECT_LE(jit.idle_joints_max, chain + p.hit * 13);
	EXPECT_EQ(rigid.bodies_max, chain);
	EXPECT_GT(jointed.idle_bodies_max, chain + 6 * 12 - 1);  // every segment of every building
	EXPECT_LT(jit.bodies_max, jointed.bodies_max / 2);
	EXPECT_NEAR(jit.first_impact_s, jointed.first_impact_s, 1e-9);
	std::printf("[ info     ] plastic work: jit %.1f J, jointed %.1f J (balls %.1f J); bodies at most: jit %d, jointed %d, rigid %d\n", jit.plastic_energy_j,
				jointed.plastic_energy_j, jointed.impact_energy_j, jit.bodies_max, jointed.bodies_max, rigid.bodies_max);
}

TEST(City, BadParametersAreNamed)
{
	CityParameters p;
	p.hit = 11;
	p.spacing_m = 3;
	const std::vector<std::string> e = validateCityParameters(p);
	ASSERT_EQ(e.size(), 2u);
	EXPECT_EQ(e[0], "hit: 11 is not in [0, 10]");
	EXPECT_EQ(e[1].rfind("spacing: 3 is not in [", 0), 0u) << e[1];
}

// The ledger the example shows: the hit buildings' joints' Mp x rotations, measured from their bodies, against what the
// joints booked, in every mode that has joints; the balls' descent against the energy it went to.
TEST(City, TheLedgerMeasuresWhatTheJointsBooked)
{
	for (CityMode mode : {CityMode::JustInTime, CityMode::Jointed})
	{
		CityScene scene(city(mode));
		while (!scene.done()) scene.step();
		const scene::SceneLedger l = scene.ledger();
		std::printf("[ info     ] %s: booked %.1f J, Mp x rotations %.1f J, the balls' descent %.1f J, kinetic %.1f J\n", cityModeName(mode), l.plastic_booked_j,
					l.plastic_measured_j, l.load_work_j, l.kinetic_j);
		EXPECT_GT(l.plastic_booked_j, 1000.0) << cityModeName(mode);
		EXPECT_NEAR(l.plastic_measured_j, l.plastic_booked_j, 0.02 * l.plastic_booked_j) << cityModeName(mode);
		EXPECT_LT(l.plastic_booked_j + l.kinetic_j, 1.01 * l.load_work_j) << cityModeName(mode) << ": no energy from nothing";
	}
}

// The hit buildings' permanent sets: every joint's plastic rotation and every segment's displacement, just in time against
// always jointed, within 5 % of the largest of the building (measured from the bodies where they stopped; a whole
// member's bodies are out of the world where they stopped).
TEST(City, JustInTimeLeavesTheJointedCitysSets)
{
	CityScene jit(city(CityMode::JustInTime)), jointed(city(CityMode::Jointed));
	const std::vector<scene::JointView> before = jointed.joints();
	std::vector<btVector3> start;
	for (const scene::JointView& j : before) start.push_back(j.body_b->getCenterOfMassPosition());
	while (!jit.done()) jit.step();
	while (!jointed.done()) jointed.step();
	const std::vector<scene::JointView> a = jit.joints(), b = jointed.joints();
	ASSERT_EQ(a.size(), b.size());
	const size_t perBuilding = a.size() / size_t(city(CityMode::Jointed).buildings);
	for (int building = 0; building < city(CityMode::Jointed).hit; building++)
	{
		double largestRotation = 0, largestMove = 0;
		for (size_t i = building * perBuilding; i < (building + 1) * perBuilding; i++)
		{
			largestRotation = std::max(largestRotation, std::fabs(b[i].plastic_rotation_rad));
			largestMove = std::max(largestMove, double((b[i].body_b->getCenterOfMassPosition() - start[i]).length()));
		}
		ASSERT_GT(largestRotation, 0.01) << "building " << building << " is bent";
		double worstRotation = 0, worstMove = 0;
		for (size_t i = building * perBuilding; i < (building + 1) * perBuilding; i++)
		{
			worstRotation = std::max(worstRotation, std::fabs(a[i].plastic_rotation_rad - b[i].plastic_rotation_rad));
			const btVector3 moveJit = a[i].body_b->getCenterOfMassPosition() - start[i], moveJointed = b[i].body_b->getCenterOfMassPosition() - start[i];
			worstMove = std::max(worstMove, double((moveJit - moveJointed).length()));
		}
		std::printf("[ info     ] building %d: largest plastic rotation %.4f rad, differs by at most %.2e rad; largest move %.4f m, differs by at most %.2e m\n",
					building, largestRotation, worstRotation, largestMove, worstMove);
		EXPECT_LE(worstRotation, 0.05 * largestRotation) << "building " << building;
		EXPECT_LE(worstMove, 0.05 * largestMove) << "building " << building;
	}
}

