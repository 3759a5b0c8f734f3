#!/usr/bin/env bash
# Installs the Debian 12 packages fapcast needs, in two profiles:
#   tools/setup.sh           building and running `fapcast` (the main job, tools/main-job.sh)
#   tools/setup.sh --tests   that, plus what the tests, benchmarks and fuzz targets use
#                            (tools/run-tests.sh)
# Idempotent: when every package of the profile is present it asks apt nothing and returns at once.
# To add a package: one line in the right list, with what needs it.
set -euo pipefail

tests=false
case "${1:-}" in
  "") ;;
  --tests) tests=true ;;
  *) echo "usage: tools/setup.sh [--tests]" >&2; exit 2 ;;
esac

# Building and running fapcast.
run_packages=(
  build-essential       # g++ 12, make, libc headers
  cmake                 # the build (CMakeLists.txt)
  ninja-build           # the generator tools/build.sh uses
  pkg-config            # finds sndfile, espeak-ng, libsrtp2
  libeigen3-dev         # matrices: PCA, RBF, the unit search's features
  libboost-dev          # Boost.Asio: UDP sockets of the RTP transport
  libopenmesh-dev       # model adaptation (deformation transfer over the mesh)
  nlohmann-json3-dev    # manifests, JSON export, glTF extras
  libcli11-dev          # the command line
  libsndfile1-dev       # WAV read/write
  libdeflate-dev        # CRC-32 (the voice file's section checksums)
  libtinygltf-dev       # glTF binary export/import
  libespeak-ng-dev      # the text front-end (speech and phone timing of `say`)
  espeak-ng             # its voices and phoneme data (espeak-ng-data) and the espeak-ng command
  festlex-cmu           # syllabified CMU lexicon: the recording script of the default voice
  libpocketsphinx-dev   # forced alignment of recorded speech (`animate SPEECH.wav --transcript`)
  libsphinxbase-dev     # its feature, grammar and log-math library
  pocketsphinx-en-us    # its US English acoustic model and pronouncing dictionary
  libsamplerate0-dev    # recorded speech resampled to the model's 16 kHz
  libsrtp2-dev          # SRTP/SRTCP of the RTP transport (stream/recv --srtp-key-file)
  libjs-three           # three.js and its GLTFLoader: the avatar page `fapcast serve` serves (and tests/viewer)
)

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

# The tests, benchmarks and fuzz targets, on top.
test_packages=(
  clang                 # the test build (tools/configure-ci.sh): suites and libFuzzer targets
  libclang-rt-14-dev    # clang's sanitizer and libFuzzer runtimes
  lld                   # LLVM's linker: the test build links its 86 programs with it (tools/configure-ci.sh)
  libgtest-dev          # GoogleTest suites
  libgmock-dev          # GTest::gmock, which the suites link
  libbenchmark-dev      # Google Benchmark programs (tests/bench, FAPCAST_BENCH=ON)
  zlib1g-dev            # zlib's crc32_z, the CRC-32 libdeflate's is measured against (tests/bench/crc32_bench)
  libexpat1-dev         # reads back the mouth cues' XML (tests/cues)
  python3               # the layer check (tools/check-layers.py, CTest layers.check)
  nodejs                # runs three.js's GLTFLoader on fapcast's .glb (tests/viewer)
  blender               # the BVH export's cross-check by Blender's importer (tests/codec/bvh_blender_test)
  tshark                # dissects captured RTP/RTCP on loopback (tests/transport/loopback_test)
  sox                   # writes WAV variants the reader must accept (tests/core/wav_audio_test)
  xz-utils              # xz -9, the size baseline of the FBA benchmark (tests/bench/fba_bench)
  gzip                  # gzip -9, the other baseline there (Essential in Debian; listed for clarity)
  chromium              # headless Chromium renders an avatar the rig outputs drive (tests/cli/rig_cli_test), and
                        # plays `fapcast serve`'s avatar page over the DevTools pipe (tests/browser)
  liblo-tools           # liblo's oscdump decodes the live VMC stream (tests/cli/rig_cli_test)
)

packages=("${run_packages[@]}")
$tests && packages+=("${test_packages[@]}")
# npm for tests/viewer, when Node came without it (Debian's nodejs does; NodeSource's carries its own)
$tests && ! command -v npm >/dev/null 2>&1 && packages+=(npm)

# One dpkg-query for the whole list; a package it does not know is simply not printed.
installed=$(dpkg-query -W -f='${Package} ${Status}\n' "${packages[@]}" 2>/dev/null |
  awk '$NF == "installed" && $(NF-1) == "ok" { print $1 }' || true)
missing=()
for p in "${packages[@]}"; do
  grep -qx "$p" <<<"$installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  $tests && install_viewer_packages
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
# tshark asks whether non-root users may capture; answer no without a prompt.
if printf '%s\n' "${missing[@]}" | grep -qx tshark; then
  echo "wireshark-common wireshark-common/install-setuid boolean false" | $sudo debconf-set-selections
fi
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
$tests && install_viewer_packages
exit 0
