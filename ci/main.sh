#!/usr/bin/env bash
# The main job: install what is missing, fetch + verify + patch Bullet, build, run the Charpy test headless
# with default parameters and write its report and frames to build/charpy-report/:
#   summary.txt, result.json, history.csv   the console runner (energy balance, per-step history)
#   browser/frame<n>.png                    the ExampleBrowser app through OSMesa, GUI and energy panel
#   figures/<method>_<moment>.png, figures/contact-sheet.png   thesis figures 3.1-3.7, every method
#   charpy.gif, energy.png, moment-rotation.png   the run as an animation (browser frames), its energies
#                                           against time and its joint's moment against rotation
# and the game scene (a wrecking ball hits a steel frame at 60 Hz frames) to build/wrecking-ball-report/:
#   summary.txt, result.json, joints.csv, history.csv   the console runner (energy balance measured from the
#                                           bodies, per-joint plastic energies, broken joints, real-time factor)
#   frames/frame<n>.png, wrecking-ball.gif  the ExampleBrowser app through OSMesa, every second 60 Hz frame
#   energy.png, joint-energy.png            energies against time, plastic energy per joint
# and the same ball against a building of five storeys and four bays (200 plastic joints) to build/building-report/
#   (the same files; the animation is building.gif)
# and the paper clip (a wire bent +-45 degrees until it breaks by low-cycle fatigue) to build/paper-clip-report/:
#   summary.txt, result.json, hysteresis.svg   the structures runner (cycles to break beside Coffin-Manson's)
#   frames/frame<n>.png                       the ExampleBrowser app through OSMesa, every 15th 60 Hz frame
# and the city (100 steel frames, 10 hit by wrecking balls) run just in time, jointed and rigid in one run to
# build/city-report/: summary.txt, result.json (each mode's costs and energies, and their ratios), and the City example
#   (9 buildings, 3 hit) rendered in each mode: frames-jit/, frames-jointed/, frames-rigid/ (every third 60 Hz frame),
#   city.gif (just in time) and city-modes.gif (the three side by side, scaled to 0.6)
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
# preset main (CMakePresets.json): build/, no tests; its build preset builds the console runners (charpy, structures,
# wrecking_ball, city), plasticity_browser and charpy_figures
cmake --preset main
cmake --build --preset main
build=build
out="$build/charpy-report"
rm -rf "$out"
mkdir -p "$out/browser"
"$build/bin/charpy" --history="$out/history.csv" | tee "$out/summary.txt"
"$build/bin/charpy" --json > "$out/result.json.tmp" && mv "$out/result.json.tmp" "$out/result.json"
# 10 ms of simulated time in 100 frames (0.1 ms each: 0.01 s browser step x 0.01 slow motion), every 20th written
bin=$(cd "$build/bin" && pwd)
(cd "$out/browser" && "$bin/plasticity_browser" --window_backend=osmesa --start_demo_name=Charpy \
	--png_file=frame --png_skip_frames=19 --fixed_timestep=0.01 --max_frames=101 --width=1024 --height=768 >/dev/null)
# the whole run (60 ms) for the animation: 0.4 ms a frame, every second one written, 480 x 360
mkdir -p "$out/animation"
(cd "$out/animation" && "$bin/plasticity_browser" --window_backend=osmesa --start_demo_name=Charpy --nogui \
	--png_file=frame --png_skip_frames=1 --fixed_timestep=0.04 --max_frames=150 --width=480 --height=360 >/dev/null)
"$build/bin/charpy_figures" --out="$out/figures" | tail -1
python3 ci/charpy_pictures.py --history="$out/history.csv" --frames="$out/animation" --out-dir="$out" --fps=12
echo "report written to $out/ (summary.txt, result.json, history.csv, browser/, figures/, charpy.gif, energy.png, moment-rotation.png)"

# the game scene: the default run (3 s of 60 Hz frames), then the same run rendered, every second frame written
game="$build/wrecking-ball-report"
rm -rf "$game"
mkdir -p "$game/frames"
"$build/bin/wrecking_ball" --joints-csv="$game/joints.csv" --history="$game/history.csv" | tee "$game/summary.txt"
"$build/bin/wrecking_ball" --json > "$game/result.json.tmp" && mv "$game/result.json.tmp" "$game/result.json"
(cd "$game/frames" && "$bin/plasticity_browser" --window_backend=osmesa "--start_demo_name=Wrecking ball" --nogui \
	--png_file=frame --png_skip_frames=1 --fixed_timestep=0.0166667 --max_frames=180 --width=640 --height=400 >/dev/null)
python3 ci/game_pictures.py --history="$game/history.csv" --joints="$game/joints.csv" --frames="$game/frames" --out-dir="$game" --fps=30
echo "report written to $game/ (summary.txt, result.json, joints.csv, history.csv, frames/, wrecking-ball.gif, energy.png, joint-energy.png)"

# the building: the same ball against five storeys and four bays (200 plastic joints in one island)
building="$build/building-report"
rm -rf "$building"
mkdir -p "$building/frames"
"$build/bin/wrecking_ball" --storeys=5 --bays=4 --joints-csv="$building/joints.csv" --history="$building/history.csv" > "$building/summary.txt"
head -n 3 "$building/summary.txt"
"$build/bin/wrecking_ball" --storeys=5 --bays=4 --json > "$building/result.json.tmp" && mv "$building/result.json.tmp" "$building/result.json"
(cd "$building/frames" && "$bin/plasticity_browser" --window_backend=osmesa "--start_demo_name=Building" --nogui \
	--png_file=frame --png_skip_frames=1 --fixed_timestep=0.0166667 --max_frames=180 --width=640 --height=400 >/dev/null)
python3 ci/game_pictures.py --history="$building/history.csv" --joints="$building/joints.csv" --frames="$building/frames" --out-dir="$building" --fps=30 --gif-name=building.gif
echo "report written to $building/ (summary.txt, result.json, joints.csv, history.csv, frames/, building.gif, energy.png, joint-energy.png)"

# the paper clip: bent until it breaks (4.5 cycles of 1 s), its moment-rotation loops, and the run rendered
clip="$build/paper-clip-report"
rm -rf "$clip"
mkdir -p "$clip/frames"
"$build/bin/structures" --scene=paper-clip --hysteresis="$clip/hysteresis.svg" | tee "$clip/summary.txt"
"$build/bin/structures" --scene=paper-clip --json > "$clip/result.json.tmp" && mv "$clip/result.json.tmp" "$clip/result.json"
(cd "$clip/frames" && "$bin/plasticity_browser" --window_backend=osmesa "--start_demo_name=Paper clip" \
	--png_file=frame --png_skip_frames=14 --fixed_timestep=0.0166667 --max_frames=300 --width=800 --height=600 >/dev/null)
echo "report written to $clip/ (summary.txt, result.json, hysteresis.svg, frames/)"

# the city: 100 buildings, 10 hit, the three ways in one run (the costs' ratios are from one process)
city="$build/city-report"
rm -rf "$city"
mkdir -p "$city"
"$build/bin/city" --buildings=100 --hit=10 --mode=all | tee "$city/summary.txt"
"$build/bin/city" --buildings=100 --hit=10 --mode=all --json > "$city/result.json.tmp" && mv "$city/result.json.tmp" "$city/result.json"
for mode in jit jointed rigid; do
	demo=City
	[ "$mode" = jit ] || demo="City $mode"
	mkdir -p "$city/frames-$mode"
	(cd "$city/frames-$mode" && "$bin/plasticity_browser" --window_backend=osmesa "--start_demo_name=$demo" --nogui \
		--png_file=frame --png_skip_frames=2 --fixed_timestep=0.0166667 --max_frames=180 --width=720 --height=540 >/dev/null)
done
python3 ci/city_pictures.py --frames="$city/frames-jit,$city/frames-jointed,$city/frames-rigid" --out-dir="$city" --fps=20 --scale=0.6
echo "report written to $city/ (summary.txt, result.json, frames-*/, city.gif, city-modes.gif)"
