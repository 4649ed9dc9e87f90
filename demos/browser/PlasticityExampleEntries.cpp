// The project's example list for the upstream OpenGLExampleBrowser: the plasticity examples only.
// Implements upstream's ExampleEntriesAll interface (ExampleBrowser/ExampleEntries.h), the way
// upstream's own ExampleEntries.cpp does for Bullet's examples.
#include "ExampleEntries.h"

#include "LinearMath/btAlignedObjectArray.h"

#include "SceneExample.h"

namespace
{
struct ExampleEntry
{
	int m_menuLevel;
	const char* m_name;
	const char* m_description;
	CommonExampleInterface::CreateFunc* m_createFunc;
	int m_option;
};

// Option: the Charpy method number (thesis order).
const ExampleEntry kPlasticityExamples[] = {
	{0, "Plasticity", "Plastic deformation and ductile breaking of rigid-body joints.", 0, 0},
	{1, "Charpy",
	 "Charpy impact test: a 19.5 kg hammer breaks a notched 10 x 10 x 55 mm steel specimen. "
	 "Choose the joining method and the parameters with the controls; the energy balance is shown on screen.",
	 CharpyExampleCreateFunc, 6},
	{1, "Charpy rigid", "Method 1: the specimen is one rigid body.", CharpyExampleCreateFunc, 1},
	{1, "Charpy brittle", "Method 2: btGeneric6DofConstraint with zero limits and a breaking impulse.", CharpyExampleCreateFunc, 2},
	{1, "Charpy spring", "Method 3: btGeneric6DofSpringConstraint (elastic only).", CharpyExampleCreateFunc, 3},
	{1, "Charpy spring2", "Method 4: btGeneric6DofSpring2Constraint (elastic only).", CharpyExampleCreateFunc, 4},
	{1, "Charpy hinge-motor", "Method 5: btHingeConstraint with a motor capped at the plastic moment.", CharpyExampleCreateFunc, 5},
	{1, "Charpy plastic-hinge", "Method 6: btPlasticHingeConstraint.", CharpyExampleCreateFunc, 6},
	{1, "Charpy elastic-plastic", "Method 7: bt6DofElasticPlasticConstraint.", CharpyExampleCreateFunc, 7},
	{1, "Charpy elastic-plastic2", "Method 8: bt6DofElasticPlastic2Constraint.", CharpyExampleCreateFunc, 8},
	{0, "Structures", "Structures with textbook answers, built by the scenes build/bin/structures runs.", 0, 0},
	{1, "Cantilever",
	 "A tip-loaded cantilever in segments: collapse at P = Mp / L at the root; a dead load above it stops where "
	 "P L sin(theta) = Mp theta. Yielded joints turn orange, broken ones red; the ledger is on screen.",
	 CantileverExampleCreateFunc, 0},
	{1, "Portal frame",
	 "A fixed-base portal frame under H at the left knee and V at mid-span, the load factor ramped until the "
	 "beam, sway or combined mechanism forms.",
	 PortalExampleCreateFunc, 0},
	{1, "Drop weight", "A ball strikes a simply supported or clamped beam: kinetic energy after the impact = Mp x hinge rotations.",
	 DropWeightExampleCreateFunc, 0},
	{1, "Paper clip",
	 "A steel wire bent back and forth by a hand until it breaks by low-cycle fatigue: Coffin-Manson with Miner's rule "
	 "over the joint's plastic half-cycles gives the cycles. build/bin/structures --scene=paper-clip runs it.",
	 PaperClipExampleCreateFunc, 0},
	{0, "Game", "A steel frame at 60 Hz frames with the toolkit's game solver settings.", 0, 0},
	{1, "Wrecking ball",
	 "A wrecking ball on a chain hits a steel portal frame of plastic I-section joints: it bends, keeps its "
	 "shape and breaks where a joint passes its plastic rotation. The scene build/bin/wrecking_ball runs.",
	 WreckingBallExampleCreateFunc, 0},
	{1, "Building",
	 "The wrecking ball hits a steel frame of five storeys and four bays (200 plastic joints in one island), "
	 "solved by btDirectJointSolver at 60 Hz frames. build/bin/wrecking_ball --storeys=5 --bays=4 runs it.",
	 BuildingExampleCreateFunc, 0},
	{1, "City",
	 "Steel frames on a grid, the first few hit by wrecking balls, simulated just in time: each building is one static "
	 "body until a blow that can yield it comes, then its jointed self, and one body again once at rest. Choose jit, "
	 "jointed or rigid to compare. build/bin/city --mode=all runs the three.",
	 CityExampleCreateFunc, 0},
	{1, "City jointed", "The city with every building always jointed.", CityExampleCreateFunc, 2},
	{1, "City rigid", "The city with every building one rigid body: no plastic joints (the balls bounce off).", CityExampleCreateFunc, 3},
};
}  // namespace

struct ExampleEntriesInternalData
{
	btAlignedObjectArray<ExampleEntry> m_allExamples;
};

ExampleEntriesAll::ExampleEntriesAll() { m_data = new ExampleEntriesInternalData; }

ExampleEntriesAll::~ExampleEntriesAll() { delete m_data; }

void ExampleEntriesAll::initOpenCLExampleEntries() {}

void ExampleEntriesAll::initExampleEntries()
{
	m_data->m_allExamples.clear();
	for (const ExampleEntry& e : kPlasticityExamples) m_data->m_allExamples.push_back(e);
}

void ExampleEntriesAll::registerExampleEntry(int, const char*, const char*, CommonExampleInterface::CreateFunc*, int) {}

int ExampleEntriesAll::getNumRegisteredExamples() { return m_data->m_allExamples.size(); }

CommonExampleInterface::CreateFunc* ExampleEntriesAll::getExampleCreateFunc(int index) { return m_data->m_allExamples[index].m_createFunc; }

int ExampleEntriesAll::getExampleOption(int index) { return m_data->m_allExamples[index].m_option; }

const char* ExampleEntriesAll::getExampleName(int index) { return m_data->m_allExamples[index].m_name; }

const char* ExampleEntriesAll::getExampleDescription(int index) { return m_data->m_allExamples[index].m_description; }
