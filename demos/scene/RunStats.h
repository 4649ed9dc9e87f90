// What a scene's run took, the part every scene's result shares (each result derives from it): its internal steps,
// its simulated and wall time, the solver's fallbacks, and whether every body stayed finite.
#pragma once

namespace scene
{
struct RunStats
{
	long internal_steps = 0;   // world steps
	double simulated_s = 0;
	double wall_s = 0;         // from the scene's start: building (the structures) or not (the game scenes), and stepping
	int solver_fallbacks = 0;  // internal steps in which a direct or MLCP solver fell back to sequential impulse
	bool finite = true;        // every body's position and velocity stayed finite
};
}  // namespace scene
