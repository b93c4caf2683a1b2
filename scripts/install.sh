#!/usr/bin/env bash
# Installs agrirecipe and everything it runs with into ./.venv on a fresh
# Debian machine with Python 3.11: system libraries for Blender-as-a-module,
# the CPU build of torch, a lean source build of llama-cpp-python (cached by
# pip's wheel cache afterwards) and the package with all extras.
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}

# bpy needs X11/EGL client libraries even headless (reference/engines.md).
need_apt=()
for lib in libX11.so.6 libXrender.so.1 libXfixes.so.3 libXi.so.6 libxkbcommon.so.0 libxcb.so.1 libEGL.so.1 libGL.so.1 libSM.so.6 libXxf86vm.so.1 libXext.so.6; do
  ldconfig -p | grep -q "$lib" || need_apt+=("$lib")
done
if [ ${#need_apt[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    libx11-6 libxrender1 libxfixes3 libxi6 libxkbcommon0 libxcb1 libsm6 libxxf86vm1 libxext6 \
    libegl1 libegl-mesa0 libgl1 libgl1-mesa-dri >/dev/null
fi

# The app's browser tests drive Debian's chromium with Playwright (which cannot
# download a browser build of its own here).
if [ ! -x /usr/bin/chromium ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    chromium >/dev/null
fi

# The SDFormat XSDs (Debian's sdformat-sdf) and libsdformat itself (the parser gz-sim
# loads worlds with) check the Gazebo backend's worlds in the tests (issue 13).
if ! ls /usr/share/sdformat*/1.7/root.xsd >/dev/null 2>&1 || ! pkg-config --exists sdformat12; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    sdformat-sdf libsdformat-dev pkg-config >/dev/null
fi

[ -x .venv/bin/python ] || "$PY" -m venv .venv
VPIP=".venv/bin/python -m pip"
$VPIP install -q --upgrade pip wheel
# Pin torch first: an unpinned torch pulls several GB of CUDA wheels.
$VPIP install -q "torch==2.13.0"
# llama.cpp: CPU only, no examples/tools/server/tests, no curl; the wheel is
# cached by pip so later installs reuse it.
export CMAKE_ARGS="${CMAKE_ARGS:--DGGML_NATIVE=OFF -DGGML_BLAS=OFF -DGGML_OPENMP=ON -DLLAMA_BUILD_TESTS=OFF -DLLAMA_BUILD_EXAMPLES=OFF -DLLAMA_BUILD_SERVER=OFF -DLLAMA_BUILD_TOOLS=OFF -DLLAMA_CURL=OFF -DLLAVA_BUILD=OFF -DMTMD_BUILD=OFF}"
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
$VPIP install -q -e ".[all,test]"
