#!/usr/bin/env bash
# The main job: install what is missing, fetch + verify + patch Bullet, build, run the Charpy test headless
# with default parameters and write its report and frames to build/charpy-report/:
#   summary.txt, result.json, history.csv   the console runner (energy balance, per-step history)
#   browser/frame<n>.png                    the ExampleBrowser app through OSMesa, GUI and energy panel
#   figures/<method>_<moment>.png, figures/contact-sheet.png   thesis figures 3.1-3.7, every method
#   charpy.gif, energy.png, moment-rotation.png   the run as an animation (browser frames), its energies
#                                           against time and its joint's moment against rotation
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/deps.sh
bash ci/configure.sh -DBP_BUILD_TESTS=OFF -DBP_BUILD_BROWSER=ON
build="${BUILD_DIR:-build}"
cmake --build "$build" --target charpy plasticity_browser charpy_figures
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
