// The Charpy example: sliders and a method choice build CharpyParameters, CharpyScene does the
// physics, the browser draws the world. Rendering only reads the world.
#include "CharpyExample.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "btBulletDynamicsCommon.h"
#include "CommonInterfaces/CommonExampleInterface.h"
#include "CommonInterfaces/CommonGUIHelperInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"
#include "CommonInterfaces/CommonParameterInterface.h"
#include "CommonInterfaces/CommonRenderInterface.h"

#include "CharpyScene.h"
#include "CharpyView.h"

namespace
{
const char* kMethodNames[kCharpyMethodCount];

class CharpyExample : public CommonExampleInterface
{
public:
	CharpyExample(GUIHelperInterface* guiHelper, int methodNumber)
		: m_guiHelper(guiHelper), m_method(methodNumber >= 1 && methodNumber <= kCharpyMethodCount ? methodNumber : 6)
	{
	}

	void initPhysics() override
	{
		m_guiHelper->setUpAxis(1);
		registerControls();
		rebuild();
	}

	void exitPhysics() override
	{
		m_guiHelper->removeAllGraphicsInstances();
		m_scene.reset();
	}

	// deltaTime_s of browser time advances slow_motion * deltaTime_s of simulated time.
	void stepSimulation(float deltaTime_s) override
	{
		if (controlsChanged()) rebuild();
		if (!m_scene) return;
		m_targetTime_s += double(deltaTime_s) * m_simulatedPerRealSecond;
		const double end_s = m_scene->parameters().duration_s;
		while (m_scene->time_s() < m_targetTime_s && m_scene->time_s() < end_s && m_scene->finite()) m_scene->step();
	}

	void renderScene() override
	{
		if (m_scene) m_guiHelper->syncPhysicsToGraphics(m_scene->world());
		if (m_scene) m_guiHelper->render(m_scene->world());
		drawEnergyPanel();
	}

	void physicsDebugDraw(int debugFlags) override
	{
		if (m_scene && m_scene->world()->getDebugDrawer())
		{
			m_scene->world()->getDebugDrawer()->setDebugMode(debugFlags);
			m_scene->world()->debugDrawWorld();
		}
	}

	void resetCamera() override
	{
		const CharpyCamera camera = charpyCamera(m_parameters);
		m_guiHelper->resetCamera(camera.distance_m, camera.yaw_deg, camera.pitch_deg, camera.target_m[0], camera.target_m[1], camera.target_m[2]);
	}

	bool mouseMoveCallback(float, float) override { return false; }
	bool mouseButtonCallback(int, int, float, float) override { return false; }
	bool keyboardCallback(int, int) override { return false; }

private:
	// Slider values (btScalar, as the parameter interface wants), in the units their names say.
	struct Controls
	{
		btScalar yieldStress_MPa = 400;
		btScalar friction = 0;
		btScalar releaseAngle_rad = 2.8;
		btScalar maxPlasticRotation_rad = 3;
		btScalar frameStep_ms = 0.1;
		btScalar solverIterations = 10;
		btScalar partPairs = 1;
		btScalar anvilGap_mm = 40;
		bool operator!=(const Controls& o) const
		{
			return yieldStress_MPa != o.yieldStress_MPa || friction != o.friction || releaseAngle_rad != o.releaseAngle_rad ||
				   maxPlasticRotation_rad != o.maxPlasticRotation_rad || frameStep_ms != o.frameStep_ms ||
				   solverIterations != o.solverIterations || partPairs != o.partPairs || anvilGap_mm != o.anvilGap_mm;
		}
	};

	void registerControls()
	{
		CommonParameterInterface* parameters = m_guiHelper->getParameterInterface();
		if (!parameters) return;
		for (int i = 0; i < kCharpyMethodCount; i++) kMethodNames[i] = charpyMethodName(charpyMethodByNumber(i + 1)).data();
		ComboBoxParams combo;
		combo.m_numItems = kCharpyMethodCount;
		combo.m_items = kMethodNames;
		combo.m_startItem = m_method - 1;
		combo.m_userPointer = this;
		combo.m_callback = [](int, const char* item, void* self) {
			if (auto method = parseCharpyMethod(item)) static_cast<CharpyExample*>(self)->m_method = int(*method);
		};
		parameters->registerComboBox(combo);
		slider(parameters, "yield stress (MPa)", &m_controls.yieldStress_MPa, 50, 2000, false);
		slider(parameters, "friction", &m_controls.friction, 0, 1, false);
		slider(parameters, "release angle (rad)", &m_controls.releaseAngle_rad, 0.5, 3.0, false);
		slider(parameters, "max plastic rotation (rad)", &m_controls.maxPlasticRotation_rad, 0.5, 6, false);
		slider(parameters, "frame step (ms)", &m_controls.frameStep_ms, 0.01, 2, false);
		slider(parameters, "solver iterations", &m_controls.solverIterations, 1, 100, true);
		slider(parameters, "specimen part pairs", &m_controls.partPairs, 1, 8, true);
		slider(parameters, "anvil gap (mm)", &m_controls.anvilGap_mm, 20, 50, false);
		slider(parameters, "slow motion (sim s per s)", &m_simulatedPerRealSecond, 0.001, 0.1, false);
	}

	static void slider(CommonParameterInterface* parameters, const char* name, btScalar* value, float min, float max, bool integers)
	{
		SliderParams params(name, value);
		params.m_minVal = min;
		params.m_maxVal = max;
		params.m_clampToIntegers = integers;
		parameters->registerSliderFloatParameter(params);
	}

	bool controlsChanged() const { return m_controls != m_applied || m_method != int(m_parameters.method); }

	void rebuild()
	{
		m_applied = m_controls;
		CharpyParameters p;
		p.method = charpyMethodByNumber(m_method);
		p.yield_stress_pa = double(m_controls.yieldStress_MPa) * 1e6;
		p.friction = double(m_controls.friction);
		p.release_angle_rad = double(m_controls.releaseAngle_rad);
		p.max_plastic_rotation_rad = double(m_controls.maxPlasticRotation_rad);
		p.dt_s = double(m_controls.frameStep_ms) * 1e-3;
		p.solver_iterations = int(std::lround(double(m_controls.solverIterations)));
		p.parts = p.method == CharpyMethod::RigidBody ? 1 : 2 * int(std::lround(double(m_controls.partPairs)));
		p.anvil_gap_m = double(m_controls.anvilGap_mm) * 1e-3;
		m_parameters = p;
		m_guiHelper->removeAllGraphicsInstances();
		m_scene.reset();
		m_error.clear();
		m_targetTime_s = 0;
		try
		{
			m_scene = std::make_unique<CharpyScene>(p);
		}
		catch (const std::invalid_argument& e)
		{
			m_error = e.what();  // shown on screen; the previous scene is gone, nothing is simulated
			return;
		}
		createCharpyGraphics(m_guiHelper, *m_scene);
		resetCamera();
	}

	void drawEnergyPanel()
	{
		CommonGraphicsApp* app = m_guiHelper->getAppInterface();
		if (!app) return;
		const std::string text = m_scene ? charpyEnergyPanel(*m_scene) : "invalid parameters:\n" + m_error;
		drawCharpyPanel(app, text);
	}

	GUIHelperInterface* m_guiHelper;
	int m_method;
	Controls m_controls;
	Controls m_applied;
	btScalar m_simulatedPerRealSecond = 0.01;
	CharpyParameters m_parameters;
	std::unique_ptr<CharpyScene> m_scene;
	std::string m_error;
	double m_targetTime_s = 0;
};
}  // namespace

CommonExampleInterface* CharpyExampleCreateFunc(CommonExampleOptions& options)
{
	return new CharpyExample(options.m_guiHelper, options.m_option);
}
