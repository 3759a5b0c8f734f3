#!/usr/bin/env bash
# Installs exactly the Debian 12 packages fapcast needs to build, test and run.
# Idempotent: when every package is already present it asks apt nothing and returns at once.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev
  # libraries
  libeigen3-dev libboost-dev libopenmesh-dev libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libsndfile1-dev libespeak-ng-dev libtinygltf-dev
  # run time: the text front-end, the recording script's pronunciations, format checks in tests
  espeak-ng festlex-cmu sox tshark xz-utils gzip
  # tests: the layer check (tools/check-layers.py)
  python3
  # tests: a standard glTF viewer (three.js r111 and its GLTFLoader) run by Node, no network
  nodejs libjs-three
  # the BVH export's cross-check: Blender's own importer, run headless (tests/codec/bvh_blender_test.cpp)
  blender
  # the rig outputs' consumers (tests/cli/rig_cli_test.cpp): headless Chromium renders an avatar,
  # liblo's oscdump decodes the live VMC stream; npm installs tests/viewer's packages (below)
  chromium liblo-tools
)
# npm, when Node came without it (Debian's nodejs does; NodeSource's carries its own)
command -v npm >/dev/null 2>&1 || packages+=(npm)

# tests/viewer's npm packages (three.js, @pixiv/three-vrm, three-vrm-animation, node-osc), exactly as
# its package-lock.json pins them; again only when they are missing or the lock changed.
install_viewer_packages() {
  local viewer stamp lock
  viewer="$(cd "$(dirname "${BASH_SOURCE[0]}")/../tests/viewer" && pwd)"
  stamp="$viewer/node_modules/.fapcast-package-lock.sha256"
  lock="$(sha256sum "$viewer/package-lock.json" | cut -d' ' -f1)"
  [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$lock" ] && return 0
  echo "setup: npm ci in tests/viewer" >&2
  (cd "$viewer" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  echo "$lock" > "$stamp"
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  install_viewer_packages
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
# tshark asks whether non-root users may capture; answer no without a prompt.
echo "wireshark-common wireshark-common/install-setuid boolean false" | $sudo debconf-set-selections
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_viewer_packages
