// A city of steel frames, some hit by wrecking balls (issue 24, just-in-time subdivision): N buildings on a grid, each
// one the wrecking ball scene's frame, the first few each hit by its own ball on a chain, at 60 Hz frames with the game
// solver settings. Three ways to simulate the buildings:
//   jit      static bodies (plastic::JitStructure, member by member) until a body that can yield a member's joints
//            comes at it, then those members jointed, and static again once they have come to rest (asleep)
//   jointed  always jointed (the frames may sleep when at rest, as any body)
//   rigid    always one static body: no plastic joints at all (the balls bounce off)
// The runner (build/bin/city) reports the cost of an internal step before the first impact and over the run, the
// balls' energy, the plastic work, and the most bodies and joints the world held.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "WreckingBall.h"
#include "scene/SteppedScene.h"

namespace game
{
enum class CityMode
{
	JustInTime,
	Jointed,
	Rigid
};
const char* cityModeName(CityMode mode);
bool parseCityMode(const std::string& text, CityMode& mode);

struct CityParameters
{
	// every building's frame and every ball (section, material, joint method, storeys, bays, ball, chain, release), and
	// the solver, frame rate and duration: the wrecking ball scene's parameters
	WreckingBallParameters building;
	CityMode mode = CityMode::JustInTime;
	int buildings = 10;     // on a square grid, row by row along +x
	int hit = 1;            // the first this many buildings are hit, each by its own ball
	double spacing_m = 12;  // grid pitch, foot to foot
};

std::vector<std::string> validateCityParameters(const CityParameters& p);

struct CityResult : scene::RunStats  // wall_s: stepping only; no solver fallbacks counted
{
	double idle_step_us = 0;  // median wall time of an internal step before the first impact
	double step_us = 0;       // median over the run
	double impact_energy_j = 0;   // the balls' kinetic energy at the bottom of their swing (m g drop of the release)
	double plastic_energy_j = 0;  // booked by the buildings' joints
	int bodies_max = 0;           // the most dynamic bodies in the world at once (balls and chain links included)
	int joints_max = 0;           // the most constraints in the world at once (the chains' included)
	int idle_bodies_max = 0;      // the same before the first impact
	int idle_joints_max = 0;
	int subdivisions = 0;         // jit: members subdivided and merged, one by one
	int merges = 0;
	double first_impact_s = 0;  // NaN: none
	long frames = 0;
};

// The city, one 60 Hz frame per step() (each frame: the solver settings' internal steps, each one timed: the
// just-in-time checks, the step). The console runner, the tests and the ExampleBrowser example step this class.
class CityScene : public scene::SteppedScene
{
public:
	explicit CityScene(const CityParameters& p);  // throws std::invalid_argument naming a bad parameter
	~CityScene() override;
	// joints(): every building's joints (a whole building's too: its bodies are out of the world, where they stopped)
	SCENE_STEPPED_SCENE_OVERRIDES;
	// the buildings' merges and subdivisions so far: bodies have entered or left the world when it changes
	long worldChanges() const override;
	// the whole buildings' static bodies (jit and rigid)
	std::vector<const btCollisionObject*> wholeStructures() const override;
	CityResult result() const;  // measured now (the medians over the steps so far)
	const CityParameters& parameters() const;

private:
	struct State;
	std::unique_ptr<State> m;
};

// Builds the city, steps it to the end, measures.
CityResult runCity(const CityParameters& p);
}  // namespace game
