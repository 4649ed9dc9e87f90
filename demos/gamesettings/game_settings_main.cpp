// build/bin/game_settings: the means that hold a jointed structure at game settings, side by side on the same cases
// (StructureProbe.h), as a markdown report. ci/game_settings.sh writes report/GAME_SETTINGS.md with it.
//   game_settings [--out=FILE] [--quick]   (--quick: two settings, the 4-segment cantilever; for the smoke test)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "StructureProbe.h"

using namespace plastic;

namespace
{
std::string fmt(const char* f, double v)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, f, v);
	return buf;
}

// Upstream: Bullet's defaults at four internal steps per 60 Hz frame.
ProbeSetting upstream()
{
	ProbeSetting s;
	s.name = "upstream defaults (SI, 10 it)";
	s.world = upstreamWorldSolverSettings();
	s.joint = upstreamJointSolverSettings();
	return s;
}

std::vector<ProbeSetting> settings(bool quick)
{
	std::vector<ProbeSetting> out;
	out.push_back(upstream());
	auto with = [&](const std::string& name, auto change) {
		ProbeSetting s = upstream();
		s.name = name;
		change(s);
		out.push_back(s);
	};
	if (!quick)
	{
		with("joint iterations 50 (override)", [](ProbeSetting& s) { s.joint.override_iterations = 50; });
		with("joint iterations 200 (override)", [](ProbeSetting& s) { s.joint.override_iterations = 200; });
		with("world iterations 1000 (converged)", [](ProbeSetting& s) { s.world.iterations = 1000; });
		with("internal step 1/960 s (16 per frame)", [](ProbeSetting& s) { s.world.internal_step_s = 1.0 / 960.0; });
		with("split position correction (0002)", [](ProbeSetting& s) { s.joint.split_position_correction = true; });
		with("ERP 0.8", [](ProbeSetting& s) { s.world.erp = 0.8; });
		with("randomized order", [](ProbeSetting& s) { s.world.randomize_order = true; });
		with("btMLCPSolver + Dantzig", [](ProbeSetting& s) { s.world.solver = SolverKind::MlcpDantzig; });
		with("btMLCPSolver + PGS", [](ProbeSetting& s) { s.world.solver = SolverKind::MlcpProjectedGaussSeidel; });
		with("multibody, capped joint motors", [](ProbeSetting& s) { s.multibody = true; });
		with("multibody, capped joint motors, 1000 it", [](ProbeSetting& s) {
			s.multibody = true;
			s.world.iterations = 1000;
		});
		with("btMLCPSolver + Dantzig + joint warm start 1.0", [](ProbeSetting& s) {
			s.world.solver = SolverKind::MlcpDantzig;
			s.warm_starting_factor = 1.0;
		});
		with("joint warm start 0.85 (0020)", [](ProbeSetting& s)
			 { s.warm_starting_factor = 0.85; });
	}
	with("joint warm start 1.0 (0020)", [](ProbeSetting& s)
		 { s.warm_starting_factor = 1.0; });
	if (!quick)
	{
		with("warm start 1.0 + split correction", [](ProbeSetting& s)
			 {
			s.warm_starting_factor = 1.0;
			s.joint.split_position_correction = true; });
		with("warm start 1.0 + joint iterations 20", [](ProbeSetting& s)
			 {
			s.warm_starting_factor = 1.0;
			s.joint.override_iterations = 20; });
	}
	return out;
}

struct Row
{
	double factor, hinge105, rest105_pct, other105, rot09, creep09, gain_pct, us_step, us_frame;
	int steps_per_frame, fallbacks;
	bool books;
};

constexpr double kLowestFactor = 0.3;  // the bisection's lower end: it moves already there

Row measure(const ProbeCase& c, JointMethod m, const ProbeSetting& s)
{
	Row r{};
	r.factor = collapseFactor(c, m, s, kLowestFactor, 1.6);
	const ProbeRun above = runProbe(c, m, s, 1.05, 1.0);
	const ProbeRun below = runProbe(c, m, s, 0.9, 3.0);
	r.hinge105 = above.hinge_rotation_rad;
	r.rest105_pct = 100 * (above.hinge_rotation_rad / restRotation_rad(1.05) - 1);
	r.other105 = above.max_other_rotation_rad;
	r.rot09 = below.max_rotation_rad;
	r.creep09 = below.max_rotation_rad - below.max_rotation_after_1s_rad;
	r.books = above.books;
	r.fallbacks = above.solver_fallbacks + below.solver_fallbacks;
	r.gain_pct = above.books && above.load_work_j > 0
					 ? 100.0 * (above.kinetic_j + above.elastic_j + above.plastic_j - above.load_work_j) / above.load_work_j
					 : NAN;
	r.steps_per_frame = int(std::lround((1.0 / 60.0) / s.world.internal_step_s));
	// wall time from the longer run (3 s below collapse)
	r.us_step = 1e6 * below.wall_s_per_step;
	r.us_frame = r.us_step * r.steps_per_frame;
	return r;
}

std::string iterations(const ProbeSetting& s)
{
	if (s.world.solver == SolverKind::MlcpDantzig) return "direct (Dantzig)";
	std::string it = std::to_string(s.world.iterations);
	if (s.joint.override_iterations > 0) it += " (joints " + std::to_string(s.joint.override_iterations) + ")";
	return it;
}

const char* kHeader =
	"| setting | case | collapse factor (error) | hinge rot. at 1.05 after 1 s (error) | other joints at 1.05 | largest rot. at 0.9, 3 s | creep at 0.9, 1-3 s | energy gain at 1.05 | "
	"steps/frame | iterations | us/step | us/frame |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";

std::string line(const ProbeSetting& s, const ProbeCase& c, const Row& r)
{
	std::ostringstream o;
	o << "| " << s.name << " | " << c.name() << " | "
	  << (r.factor <= kLowestFactor ? std::string("< 0.30 (< -70 %)") : fmt("%.3f", r.factor) + " (" + fmt("%+.1f %%", 100 * (r.factor - 1)) + ")") << " | " << fmt("%.3f rad", r.hinge105) << " (" << fmt("%+.1f %%", r.rest105_pct) << ")"
	  << " | " << fmt("%.4f rad", r.other105) << " | " << fmt("%.4f rad", r.rot09) << " | " << fmt("%.4f rad", r.creep09) << " | "
	  << (std::isnan(r.gain_pct) ? std::string("n/a (not booked)") : fmt("%+.2f %%", r.gain_pct)) << " | " << r.steps_per_frame << " | " << iterations(s) << (r.fallbacks ? ", " + std::to_string(r.fallbacks) + " SI fallbacks" : std::string()) << " | "
	  << fmt("%.1f", r.us_step) << " | " << fmt("%.0f", r.us_frame) << " |\n";
	return o.str();
}
}  // namespace

int main(int argc, char** argv)
{
	std::string outPath;
	bool quick = false, firstCase = false;
	for (int i = 1; i < argc; i++)
	{
		if (std::strncmp(argv[i], "--out=", 6) == 0)
			outPath = argv[i] + 6;
		else if (std::strcmp(argv[i], "--quick") == 0)
			quick = true;
		else if (std::strcmp(argv[i], "--first-case") == 0)
			firstCase = true;
		else if (std::strcmp(argv[i], "--help") == 0)
		{
			std::printf("game_settings [--out=FILE] [--quick]\n  the means that hold jointed structures at game settings, side by side (markdown)\n");
			return 0;
		}
		else
		{
			std::fprintf(stderr, "game_settings: unknown argument %s (try --help)\n", argv[i]);
			return 2;
		}
	}
	std::vector<ProbeCase> cases = {{Structure::Cantilever, 4}, {Structure::Cantilever, 8}, {Structure::LFrame, 4}};
	if (quick || firstCase) cases.resize(1);
	if (const char* only = std::getenv("GAME_SETTINGS_ONLY"))  // a setting's name (exploration)
	{
		for (const ProbeSetting& s : settings(false))
			if (s.name.find(only) != std::string::npos)
				for (const ProbeCase& c : cases) std::cout << line(s, c, measure(c, JointMethod::PlasticHinge, s));
		return 0;
	}
	std::ostringstream md;
	md << "## Plastic hinge: every setting\n\n" << kHeader;
	for (const ProbeSetting& s : settings(quick))
		for (const ProbeCase& c : cases)
		{
			const std::string l = line(s, c, measure(c, JointMethod::PlasticHinge, s));
			std::cerr << l;
			md << l;
		}
	if (!quick)
	{
		md << "\n## Every joint method: upstream defaults against the toolkit default\n\n" << kHeader;
		ProbeSetting toolkit;
		toolkit.name = "toolkit default";  // WorldSolverSettings{} and JointSolverSettings{}: btDirectJointSolver
		for (JointMethod m : {JointMethod::HingeMotor, JointMethod::PlasticHinge, JointMethod::ElasticPlastic, JointMethod::ElasticPlastic2})
			for (const ProbeSetting& s : {upstream(), toolkit})
				for (const ProbeCase& c : cases)
				{
					ProbeSetting named = s;
					named.name = std::string(jointMethodName(m)) + ": " + s.name;
					const std::string l = line(named, c, measure(c, m, s));
					std::cerr << l;
					md << l;
				}
	}
	if (!quick)
	{
		md << "\n## The toolkit default at other internal steps (plastic hinge)\n\n" << kHeader;
		for (double step : {1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0, 1.0 / 480.0})
		{
			ProbeSetting s;
			s.world.internal_step_s = step;
			s.name = "toolkit default, 1/" + std::to_string(int(std::lround(1 / step))) + " s";
			for (const ProbeCase& c : cases)
			{
				const std::string l = line(s, c, measure(c, JointMethod::PlasticHinge, s));
				std::cerr << l;
				md << l;
			}
		}
	}
	if (!quick)
	{
		md << "\n## Longer chains: the direct solve's cost (plastic hinge, 1/240 s)\n\n" << kHeader;
		for (int segments : {16, 32})
			for (const ProbeSetting& s : {upstream(), ProbeSetting{"toolkit default", false, WorldSolverSettings(), JointSolverSettings()}})
			{
				const ProbeCase c{Structure::Cantilever, segments};
				const std::string l = line(s, c, measure(c, JointMethod::PlasticHinge, s));
				std::cerr << l;
				md << l;
			}
	}
	if (outPath.empty())
		std::cout << md.str();
	else
	{
		std::ofstream f(outPath + ".tmp");
		f << md.str();
		f.close();
		if (!f || std::rename((outPath + ".tmp").c_str(), outPath.c_str()) != 0)
		{
			std::fprintf(stderr, "game_settings: cannot write %s\n", outPath.c_str());
			return 1;
		}
	}
	return 0;
}
