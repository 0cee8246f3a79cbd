#!/usr/bin/env bash
# examples/render-to-memory prints each frame's mean RGBA; they must be the means of the CLI's raw
# frames for the same shadertoy, size, rate and date.
# Usage: check_render_to_memory.sh SOURCE_DIR EXAMPLE TOYHOST
set -euo pipefail
src="$1" example="$2" toyhost="$3"
shadertoy="$src/shadertoys/caustics-pool"
library="$("$example" "$shadertoy" 3)"
echo "$library"
expected="$("$toyhost" run "$shadertoy" --headless --size 320x180 --frames 3 --fps 60 --date 2026-01-01T00:00:00 \
  --quiet --out - | /usr/bin/python3 -c '
import sys, numpy
frames = numpy.frombuffer(sys.stdin.buffer.read(), numpy.uint8).reshape(-1, 320 * 180, 4)
for i, f in enumerate(frames):
    m = f.astype(numpy.float64).mean(axis=0)
    print("frame %d: mean %.3f %.3f %.3f %.3f" % (i, *m))')"
[[ "$library" == "$expected" ]] || { echo "the CLI's frames give:"; echo "$expected"; exit 1; }
[[ "$(wc -l <<<"$library")" == 3 ]] || { echo "expected 3 frames"; exit 1; }
