#!/usr/bin/env bash
# Installs the Debian packages toyhost needs to build and test, only those that are missing.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri   # EGL + OpenGL ES 3 (Mesa llvmpipe)
  libglfw3-dev libglm-dev nlohmann-json3-dev libcli11-dev
  libpng-dev libopenexr-dev                              # image I/O: PNG in and out, EXR
  libjpeg62-turbo-dev                                    # JPEG in (libjpeg-turbo, the decoder browsers use)
  libdeflate-dev                                         # PNG capture: the fast deflate behind --png-level
  libfftw3-dev                                           # the music/mic texture (FFT, as WebAudio's analyser)
  libgtest-dev                                           # tests
  ffmpeg                                                 # video output (--out x.mp4); ffprobe for its tests
  libfreetype-dev                                        # the font stand-in (Font 1) drawn from DejaVu
  libimgui-dev libstb-dev fonts-dejavu-core             # the window's overlay (errors, F2 inspector): Dear ImGui, its font
  xvfb xauth xdotool libx11-dev                          # window-mode tests: a virtual X server, real X input, screen grabs
  parallel                                               # the render-farm shard test (GNU parallel)
  slurm-wlm munge                                        # the render-farm test's temporary Slurm cluster (tests/farm)
  python3-distributed                                    # toyhost.farm on Dask (python/tests/test_farm.py)
  cpp                                                    # preprocessing as browsers do, where Mesa's preprocessor refuses a shader
  python3 python3-numpy groff-base                       # man page and completion generators, package tests
  dpkg-dev file lintian                                  # cpack -G DEB: dpkg-shlibdeps computes Depends; lintian checks the .debs
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
  jupyter-nbconvert python3-ipykernel                    # the notebook test (python/tests/test_notebook.py)
  mypy                                                   # the module's types checked (python/tests/test_types.py)
  python3-pil                                            # ../shared/tools/gallery_truth.py (the gallery's truth test)
)

# `install-deps.sh fuzz` adds what the libFuzzer targets need (tests/fuzz): clang and its
# libFuzzer runtime, which clang-14 only recommends.
if [ "${1:-}" = "fuzz" ]; then
  packages+=(clang libclang-rt-14-dev)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]})); then
  echo "toyhost: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
