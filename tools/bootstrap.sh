#!/usr/bin/env bash
# tools/bootstrap.sh — install what is missing (Debian 12, as root), configure, build.
#
# Idempotent: packages already installed are not touched, so a second run only rebuilds.
# Usage: bash tools/bootstrap.sh [extra cmake -D options...]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake make g++ pkg-config                 # toolchain
  libvulkan-dev mesa-vulkan-drivers         # Vulkan loader + headers, Mesa lavapipe (CPU device)
  vulkan-validationlayers glslang-tools     # Khronos validation layer; GLSL -> SPIR-V at build time
  libglm-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev
  libassimp-dev                             # OBJ and PLY models (research scans)
  libpugixml-dev                            # SVG input: an XML parser, not a tag tokenizer
  libpng-dev libopenexr-dev                 # PNG and EXR files (engine/io)
  libopenimageio-dev                        # other image formats, in a module loaded on first use
  libglfw3-dev libimgui-dev                 # the viewer: window, input and its Dear ImGui panel
  xvfb xauth                                # viewer tests: xvfb-run, a display without a screen
  libcgal-dev                               # Delaunay triangulations, fills, intersection lines
  libembree-dev                             # ray casting of occlusion levels
  libfftw3-dev                              # FFTs of the SLAM synthesizer (fftw3f)
  libeigen3-dev                             # its small dense linear algebra (eigen-decompositions, solves)
  libgtest-dev libbenchmark-dev
  python3-dev python3-pybind11 python3-numpy  # the Python module (python/) and its arrays
  python3-pytest                            # its tests (tests/python)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "bootstrap: run as root (or install the packages above with sudo apt-get install)" >&2
    exit 1
  fi
  apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j"$(nproc)"
