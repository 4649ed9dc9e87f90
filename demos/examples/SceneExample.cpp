// One example class for every scene (scene::ControlledScene: the structures, the game scene, Charpy): sliders and a
// method choice build the scene, the browser's clock steps it (time scale: simulated seconds per browser second), the
// browser draws its world. The camera frames the scene's view envelope in the part of the window the GUI and the
// ledger leave free (ViewFraming.h), again whenever the window's size changes.
#include "SceneExample.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "CommonInterfaces/CommonExampleInterface.h"
#include "CommonInterfaces/CommonGUIHelperInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"
#include "CommonInterfaces/CommonParameterInterface.h"
#include "CommonInterfaces/CommonRenderInterface.h"

#include "CharpyControls.h"
#include "CityControls.h"
#include "SceneControls.h"
#include "StructureView.h"
#include "ViewFraming.h"
#include "WreckingBallControls.h"

namespace
{
const int kLedgerStatusLines = 3;
const int kLedgerSpareCharacters = 6;

class SceneExample : public CommonExampleInterface
{
public:
	SceneExample(GUIHelperInterface* guiHelper, scene::ControlledScene kind, int methodNumber)
		: m_guiHelper(guiHelper), m_kind(std::move(kind)), m_timeScale(m_kind.time_scale)
	{
		const std::vector<float> initial = scene::initialValues(m_kind);
		m_sliderValues.assign(initial.begin(), initial.end());  // fixed size from here on: the sliders point into it
		for (const std::string& name : m_kind.methods) m_methodNames.push_back(name.c_str());
		const int count = int(m_kind.methods.size());
		m_method = methodNumber >= 1 && methodNumber <= count ? m_kind.methods[size_t(methodNumber - 1)] : m_kind.method;
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

	void stepSimulation(float deltaTime_s) override
	{
		if (values() != m_applied || m_method != m_appliedMethod) rebuild();
		if (!m_scene) return;
		m_targetTime_s += double(deltaTime_s) * double(m_timeScale);
		while (m_scene->time_s() < m_targetTime_s - 1e-6 && !m_scene->done()) m_scene->step();
	}

	void renderScene() override
	{
		if (windowSize() != m_framedSize) resetCamera();
		if (m_scene && m_scene->worldChanges() != m_shownWorldChanges)
		{
			// bodies entered or left the world (a structure made one body, or its jointed self again): show it anew
			m_shownWorldChanges = m_scene->worldChanges();
			showStructure(m_guiHelper, *m_scene);
		}
		if (m_scene)
		{
			colourStructure(m_guiHelper, *m_scene);
			m_guiHelper->syncPhysicsToGraphics(&m_scene->world());
			m_guiHelper->render(&m_scene->world());
			drawJointMarkers(m_guiHelper, *m_scene, m_kind.joint_marker_px);
		}
		if (CommonGraphicsApp* app = m_guiHelper->getAppInterface())
			drawTextLines(app, m_scene ? scene::ledgerText(m_scene->ledger()) : m_kind.name + ": invalid parameters:\n" + m_error, m_framing.ledger_left_px,
						  m_framing.ledger_top_px);
	}

	void physicsDebugDraw(int debugFlags) override
	{
		if (m_scene && m_scene->world().getDebugDrawer())
		{
			m_scene->world().getDebugDrawer()->setDebugMode(debugFlags);
			m_scene->world().debugDrawWorld();
		}
	}

	// the scene's view envelope framed for the window as it is now, the ledger above or beside it
	void resetCamera() override
	{
		m_framedSize = windowSize();
		FramingRequest request;
		if (m_scene) request.envelope = m_scene->viewEnvelope();
		request.yaw_deg = m_kind.camera_yaw_deg;
		request.pitch_deg = m_kind.camera_pitch_deg;
		request.ledger_lines = m_ledgerLines;
		request.ledger_characters = m_ledgerCharacters;
		m_framing = frameScene(request, m_framedSize.first, m_framedSize.second, browserGuiShown());
		if (!m_scene) return;  // invalid parameters: the camera stays, the message goes where the ledger would
		const ViewCamera& c = m_framing.camera;
		m_guiHelper->resetCamera(c.distance_m, c.yaw_deg, c.pitch_deg, c.target_m[0], c.target_m[1], c.target_m[2]);
	}

	bool mouseMoveCallback(float, float) override { return false; }
	bool mouseButtonCallback(int, int, float, float) override { return false; }
	bool keyboardCallback(int, int) override { return false; }

private:
	std::pair<int, int> windowSize() const
	{
		const CommonGraphicsApp* app = m_guiHelper->getAppInterface();
		if (!app || !app->m_window) return {0, 0};
		return {app->m_window->getWidth(), app->m_window->getHeight()};
	}

	std::vector<float> values() const { return std::vector<float>(m_sliderValues.begin(), m_sliderValues.end()); }

	void registerControls()
	{
		CommonParameterInterface* parameters = m_guiHelper->getParameterInterface();
		if (!parameters) return;
		ComboBoxParams combo;
		combo.m_numItems = int(m_methodNames.size());
		combo.m_items = m_methodNames.data();
		combo.m_startItem = 0;
		for (size_t i = 0; i < m_kind.methods.size(); i++)
			if (m_kind.methods[i] == m_method) combo.m_startItem = int(i);
		combo.m_userPointer = this;
		combo.m_callback = [](int item, const char*, void* self)
		{
			SceneExample* example = static_cast<SceneExample*>(self);
			if (item >= 0 && item < int(example->m_kind.methods.size())) example->m_method = example->m_kind.methods[size_t(item)];
		};
		parameters->registerComboBox(combo);
		for (size_t i = 0; i < m_kind.sliders.size(); i++)
		{
			const scene::SliderSpec& s = m_kind.sliders[i];
			SliderParams params(s.label, &m_sliderValues[i]);
			params.m_minVal = s.min;
			params.m_maxVal = s.max;
			params.m_clampToIntegers = s.integers;
			parameters->registerSliderFloatParameter(params);
		}
		SliderParams pace("time scale (sim s per s)", &m_timeScale);
		pace.m_minVal = 0.01f;
		pace.m_maxVal = 4;
		parameters->registerSliderFloatParameter(pace);
	}

	void rebuild()
	{
		m_applied = values();
		m_appliedMethod = m_method;
		m_guiHelper->removeAllGraphicsInstances();
		m_scene.reset();
		m_error.clear();
		m_targetTime_s = 0;
		try
		{
			m_scene = m_kind.build(m_applied, m_method);
		}
		catch (const std::invalid_argument& e)
		{
			m_error = e.what();  // shown on screen; nothing is simulated
			return;
		}
		showStructure(m_guiHelper, *m_scene);
		m_shownWorldChanges = m_scene->worldChanges();
		// room for the ledger as it starts, the status lines the run adds (collapse, stop, broken joints) and longer numbers
		const ScreenRect start = textRect(scene::ledgerText(m_scene->ledger()), 0, 0);
		m_ledgerLines = (start.height() - kTextLineHeight_px) / kTextLine_px + 1 + kLedgerStatusLines;
		m_ledgerCharacters = start.width() / kTextChar_px + kLedgerSpareCharacters;
		resetCamera();
	}

	GUIHelperInterface* m_guiHelper;
	scene::ControlledScene m_kind;
	std::vector<btScalar> m_sliderValues;  // what the sliders say (their own storage)
	std::vector<float> m_applied;          // what the scene was built from
	std::vector<const char*> m_methodNames;  // the combo box's items (m_kind owns the strings)
	std::string m_method;
	std::string m_appliedMethod;
	btScalar m_timeScale;
	std::unique_ptr<scene::SteppedScene> m_scene;
	std::string m_error;
	double m_targetTime_s = 0;
	int m_ledgerLines = 12;
	int m_ledgerCharacters = 40;
	SceneFraming m_framing;
	std::pair<int, int> m_framedSize{0, 0};
	long m_shownWorldChanges = 0;
};
}  // namespace

CommonExampleInterface* CharpyExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, charpyControls(), options.m_option);
}

CommonExampleInterface* CantileverExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, structures::cantileverControls(), options.m_option);
}

CommonExampleInterface* PortalExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, structures::portalControls(), options.m_option);
}

CommonExampleInterface* DropWeightExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, structures::dropWeightControls(), options.m_option);
}

CommonExampleInterface* PaperClipExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, structures::paperClipControls(), options.m_option);
}

CommonExampleInterface* WreckingBallExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, game::wreckingBallControls(), options.m_option);
}

CommonExampleInterface* BuildingExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, game::buildingControls(), options.m_option);
}

CommonExampleInterface* CityExampleCreateFunc(CommonExampleOptions& options)
{
	return new SceneExample(options.m_guiHelper, game::cityControls(), options.m_option);
}
