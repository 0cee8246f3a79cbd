#!/usr/bin/env bash
# examples/embed-glfw handles its own mouse: under a virtual X server (run through xvfb-run),
# xdotool drags in the app's quad and presses Esc; the app (--wait-events --check: one frame per
# batch of input) must have passed the drag to its toyhost session (the picture differs from the
# same frames without input), kept its GL state and shown what a headless run with the same events
# renders. Usage: embed_glfw_mouse.sh EMBED_GLFW_BINARY SHADERTOY OUTPUT_DIR
set -euo pipefail
app="$1" shadertoy="$2" out="$3"
mkdir -p "$out"
log="$out/embed-glfw-mouse.log"
"$app" "$shadertoy" --size 160x90 --fps 60 --wait-events --check >"$log" 2>&1 &
pid=$!
window="$(timeout 20 xdotool search --sync --onlyvisible --name '^embed-glfw$' | sed -n 1p)"
xdotool windowfocus --sync "$window"
# The quad starts 16 pixels in: window (56, 61) is canvas pixel (40, 45) from the bottom left.
xdotool mousemove --window "$window" 56 61 mousedown 1
for x in 66 76 86 96 106; do xdotool mousemove --window "$window" "$x" 61; done
xdotool mouseup 1
xdotool key --window "$window" Escape 2>/dev/null || true
status=0
timeout 120 tail --pid="$pid" -f /dev/null || status=$?
wait "$pid" || status=$?
cat "$log"
if [[ $status -ne 0 ]]; then echo "FAIL: embed-glfw exited with $status"; exit 1; fi
grep -q "the mouse changed the picture" "$log" || { echo "FAIL: the drag did not reach the shadertoy"; exit 1; }
grep -q "PSNR inf dB, max diff 0" "$log" || { echo "FAIL: the quad differs from the headless frame"; exit 1; }
echo "PASS"
